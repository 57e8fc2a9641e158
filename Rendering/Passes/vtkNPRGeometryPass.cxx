// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNPRGeometryPass.h"

#include "vtkNPRPassUtilities.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLError.h"

vtkCxxSetObjectMacro(vtkNPRGeometryPass, DelegatePass, vtkRenderPass);

vtkNPRGeometryPass::~vtkNPRGeometryPass()
{
  this->SetDelegatePass(nullptr);
}

bool vtkNPRGeometryPass::StartRender(const vtkRenderState* state)
{
  vtkOpenGLClearErrorMacro();
  this->NumberOfRenderedProps = 0;
  if (!this->DelegatePass)
  {
    vtkWarningMacro("no delegate pass: nothing drawn");
    return false;
  }
  this->LastRenderWasSelection = vtkNPRRenderSelection(state, this->NumberOfRenderedProps);
  return !this->LastRenderWasSelection;
}

void vtkNPRGeometryPass::ReleaseGraphicsResources(vtkWindow* window)
{
  if (this->DelegatePass)
  {
    this->DelegatePass->ReleaseGraphicsResources(window);
  }
}

vtkMTimeType vtkNPRGeometryPass::GetShaderStageMTime()
{
  return this->ShaderStageTime.GetMTime();
}

void vtkNPRGeometryPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "DelegatePass: " << this->DelegatePass << "\n";
}
