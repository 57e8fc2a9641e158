// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// STAND-IN, to be replaced by main's vtkNPRDrawingPass.cxx: the settings only (what
// vtkNPRMakeStrokeStyle and vtkNPRDrawingExporter read); Render() draws nothing.
#include "vtkNPRDrawingPass.h"

#include "vtkNPRDrawingLines.h"
#include "vtkNPREdgePass.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"

struct vtkNPRDrawingPass::Internals
{
  vtkNew<vtkNPRDrawingLines> Lines;
  vtkIdType Updates = 0;
};

vtkStandardNewMacro(vtkNPRDrawingPass);
vtkCxxSetObjectMacro(vtkNPRDrawingPass, EdgePass, vtkNPREdgePass);

vtkNPRDrawingPass::vtkNPRDrawingPass()
  : Internal(new Internals)
{
}

vtkNPRDrawingPass::~vtkNPRDrawingPass()
{
  this->SetEdgePass(nullptr);
}

void vtkNPRDrawingPass::Render(const vtkRenderState*) {}

void vtkNPRDrawingPass::ReleaseGraphicsResources(vtkWindow*) {}

vtkNPRDrawingLines* vtkNPRDrawingPass::GetDrawingLines()
{
  return this->Internal->Lines;
}

vtkPolyData* vtkNPRDrawingPass::GetStrokes()
{
  return this->Internal->Lines->GetStrokes();
}

vtkIdType vtkNPRDrawingPass::GetNumberOfStrokeUpdates() const
{
  return this->Internal->Updates;
}

void vtkNPRDrawingPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "HiddenLines: " << this->HiddenLines << "\n";
}
