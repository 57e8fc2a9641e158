// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNPRPass.h"

#include "vtkDualDepthPeelingPass.h"
#include "vtkNPRDrawingPass.h"
#include "vtkNPREdgePass.h"
#include "vtkNPRGBufferPass.h"
#include "vtkNPRInkPass.h"
#include "vtkNPRLinePrimitivesPass.h"
#include "vtkNPRMeshEdgesPass.h"
#include "vtkNPROpaquePass.h"
#include "vtkNPRSketchPass.h"
#include "vtkNPRToonPass.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpaquePass.h"
#include "vtkRenderPassCollection.h"
#include "vtkRenderState.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderer.h"
#include "vtkSequencePass.h"
#include "vtkTranslucentPass.h"

#include <cstring>

vtkStandardNewMacro(vtkNPRPass);

vtkNPRPass::vtkNPRPass()
{
  this->RenderStepsPass = vtkRenderStepsPass::New();
  this->OpaquePass = vtkNPROpaquePass::New();
  this->SurfacePass = vtkNPROpaquePass::New();
  this->SurfacePass->SetSurfacesOnly(true);
  this->GBufferPass = vtkNPRGBufferPass::New();
  this->GBufferPass->SetDelegatePass(this->SurfacePass);
  this->EdgePass = vtkNPREdgePass::New();
  this->EdgePass->SetGBufferPass(this->GBufferPass);
  this->ToonPass = vtkNPRToonPass::New();
  this->ToonPass->SetDelegatePass(this->OpaquePass);
  this->FlatPass = vtkNPRToonPass::New();
  this->FlatPass->SetDelegatePass(this->SurfacePass);
  this->FlatPass->SetNumberOfBands(1);
  this->FlatPass->SetSpecular(false);
  this->SketchPass = vtkNPRSketchPass::New();
  this->SketchPass->SetEdgePass(this->EdgePass);
  this->InkPass = vtkNPRInkPass::New();
  this->InkPass->SetDelegatePass(this->OpaquePass);
  this->DrawingPass = vtkNPRDrawingPass::New();
  this->DrawingPass->SetEdgePass(this->EdgePass);
  // Line and point primitives, left out of the G-buffer, drawn after the effect.
  this->LinePrimitivesPass = vtkNPRLinePrimitivesPass::New();
  this->LinePrimitivesPass->DelegatePass = this->OpaquePass;
  this->LinePrimitivesPass->GBufferPass = this->GBufferPass;
  this->LinePrimitivesPass->SurfacePass = this->SurfacePass;
  this->LinePrimitivesPass->EdgePass = this->EdgePass;
  this->EdgesSequence = vtkSequencePass::New();
  vtkNew<vtkRenderPassCollection> passes;
  passes->AddItem(this->GBufferPass);
  passes->AddItem(this->EdgePass);
  passes->AddItem(this->LinePrimitivesPass);
  this->EdgesSequence->SetPasses(passes);
  this->SketchSequence = vtkSequencePass::New();
  vtkNew<vtkRenderPassCollection> sketchPasses;
  sketchPasses->AddItem(this->GBufferPass);
  sketchPasses->AddItem(this->SketchPass);
  sketchPasses->AddItem(this->LinePrimitivesPass);
  this->SketchSequence->SetPasses(sketchPasses);
  // The drawing's faces are one colour: the mesh edges VTK draws into them are drawn again over it.
  this->MeshEdgesPass = vtkNPRMeshEdgesPass::New();
  this->DrawingSequence = vtkSequencePass::New();
  vtkNew<vtkRenderPassCollection> drawingPasses;
  drawingPasses->AddItem(this->GBufferPass);
  drawingPasses->AddItem(this->DrawingPass);
  drawingPasses->AddItem(this->MeshEdgesPass);
  drawingPasses->AddItem(this->LinePrimitivesPass);
  this->DrawingSequence->SetPasses(drawingPasses);
  this->TranslucentPass = vtkTranslucentPass::New();
  this->DepthPeelingPass = vtkDualDepthPeelingPass::New();
  this->DepthPeelingPass->SetTranslucentPass(this->TranslucentPass);
}

vtkNPRPass::~vtkNPRPass()
{
  this->RenderStepsPass->Delete();
  this->EdgesSequence->Delete();
  this->SketchSequence->Delete();
  this->DrawingSequence->Delete();
  this->DrawingPass->Delete();
  this->LinePrimitivesPass->Delete();
  this->MeshEdgesPass->Delete();
  this->SketchPass->Delete();
  this->InkPass->Delete();
  this->ToonPass->Delete();
  this->FlatPass->Delete();
  this->EdgePass->Delete();
  this->GBufferPass->Delete();
  this->OpaquePass->Delete();
  this->SurfacePass->Delete();
  this->DepthPeelingPass->Delete();
  this->TranslucentPass->Delete();
}

const char* vtkNPRPass::GetStyleName(int style)
{
  switch (style)
  {
    case SHADED:
      return "shaded";
    case EDGES:
      return "edges";
    case TOON:
      return "toon";
    case TOON_EDGES:
      return "toon+edges";
    case SKETCH:
      return "sketch";
    case INKED:
      return "inked";
    case DRAWING:
      return "drawing";
    default:
      return "unknown";
  }
}

void vtkNPRPass::SetHiddenLines(bool hidden)
{
  if (this->DrawingPass->GetHiddenLines() != hidden)
  {
    this->DrawingPass->SetHiddenLines(hidden);
    this->Modified();
  }
}

bool vtkNPRPass::GetHiddenLines()
{
  return this->DrawingPass->GetHiddenLines();
}

int vtkNPRPass::GetStyleFromName(const char* name)
{
  for (int style = SHADED; name && style <= DRAWING; ++style)
  {
    if (strcmp(name, GetStyleName(style)) == 0)
    {
      return style;
    }
  }
  return -1;
}

void vtkNPRPass::Render(const vtkRenderState* state)
{
  vtkRenderer* renderer = state->GetRenderer();
  // The drawing's lines come from the meshes: its G-buffer needs depth only.
  const bool imageLines = this->Style != DRAWING;
  this->GBufferPass->SetNormalsRequested(imageLines && this->EdgePass->GetNeedsNormals());
  this->GBufferPass->SetFaceNormalsRequested(
    imageLines && this->EdgePass->GetCreases() && this->EdgePass->GetFaceCreases());
  this->GBufferPass->SetObjectIdsRequested(imageLines && this->EdgePass->GetContours());
  this->GBufferPass->SetGeometryEncoding(this->EdgePass->GetEncoding());
  // The edge styles copy the surfaces back whole from it (vtkNPREdgePass::CopySurfacesBack).
  this->GBufferPass->SetWindowImageRequested(
    (this->Style == EDGES || this->Style == TOON_EDGES) && this->EdgePass->GetCopySurfacesBack());
  switch (this->Style)
  {
    case SHADED:
      this->RenderStepsPass->SetOpaquePass(this->OpaquePass);
      break;
    case TOON:
      this->ToonPass->SetDelegatePass(this->OpaquePass);
      this->RenderStepsPass->SetOpaquePass(this->ToonPass);
      break;
    case INKED:
      this->RenderStepsPass->SetOpaquePass(this->InkPass);
      break;
    case TOON_EDGES:
      this->ToonPass->SetDelegatePass(this->SurfacePass);
      this->GBufferPass->SetDelegatePass(this->ToonPass);
      this->RenderStepsPass->SetOpaquePass(this->EdgesSequence);
      break;
    case SKETCH:
      this->ToonPass->SetDelegatePass(this->SurfacePass);
      this->GBufferPass->SetDelegatePass(this->SketchToonShading ? this->ToonPass : this->FlatPass);
      this->RenderStepsPass->SetOpaquePass(this->SketchSequence);
      break;
    case DRAWING:
      this->GBufferPass->SetDelegatePass(this->FlatPass);
      this->RenderStepsPass->SetOpaquePass(this->DrawingSequence);
      break;
    default: // EDGES
      this->GBufferPass->SetDelegatePass(this->SurfacePass);
      this->RenderStepsPass->SetOpaquePass(this->EdgesSequence);
      break;
  }
  if (renderer->GetUseDepthPeeling())
  {
    this->DepthPeelingPass->SetMaximumNumberOfPeels(renderer->GetMaximumNumberOfPeels());
    this->DepthPeelingPass->SetOcclusionRatio(renderer->GetOcclusionRatio());
    this->RenderStepsPass->SetTranslucentPass(this->DepthPeelingPass);
  }
  else
  {
    this->RenderStepsPass->SetTranslucentPass(this->TranslucentPass);
  }
  this->RenderStepsPass->Render(state);
  this->NumberOfRenderedProps = this->RenderStepsPass->GetNumberOfRenderedProps();
}

void vtkNPRPass::ReleaseGraphicsResources(vtkWindow* window)
{
  this->RenderStepsPass->ReleaseGraphicsResources(window);
  this->GBufferPass->ReleaseGraphicsResources(window);
  this->EdgePass->ReleaseGraphicsResources(window);
  this->ToonPass->ReleaseGraphicsResources(window);
  this->FlatPass->ReleaseGraphicsResources(window);
  this->SketchPass->ReleaseGraphicsResources(window);
  this->InkPass->ReleaseGraphicsResources(window);
  this->DrawingPass->ReleaseGraphicsResources(window);
  this->LinePrimitivesPass->ReleaseGraphicsResources(window);
  this->MeshEdgesPass->ReleaseGraphicsResources(window);
  this->OpaquePass->ReleaseGraphicsResources(window);
  this->SurfacePass->ReleaseGraphicsResources(window);
  this->DepthPeelingPass->ReleaseGraphicsResources(window);
  this->TranslucentPass->ReleaseGraphicsResources(window);
}

void vtkNPRPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Style: " << GetStyleName(this->Style) << "\n";
  os << indent << "GBufferPass:\n";
  this->GBufferPass->PrintSelf(os, indent.GetNextIndent());
  os << indent << "SketchToonShading: " << this->SketchToonShading << "\n";
  os << indent << "EdgePass:\n";
  this->EdgePass->PrintSelf(os, indent.GetNextIndent());
  os << indent << "ToonPass:\n";
  this->ToonPass->PrintSelf(os, indent.GetNextIndent());
  os << indent << "SketchPass:\n";
  this->SketchPass->PrintSelf(os, indent.GetNextIndent());
  os << indent << "InkPass:\n";
  this->InkPass->PrintSelf(os, indent.GetNextIndent());
  os << indent << "DrawingPass:\n";
  this->DrawingPass->PrintSelf(os, indent.GetNextIndent());
}
