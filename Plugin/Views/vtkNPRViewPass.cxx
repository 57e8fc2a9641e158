// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNPRViewPass.h"

#include "vtkCameraPass.h"
#include "vtkNPREdgePass.h"
#include "vtkNPRGBufferPass.h"
#include "vtkNPRPass.h"
#include "vtkNPRSketchPass.h"
#include "vtkNPRToonPass.h"
#include "vtkObjectFactory.h"
#include "vtkPVDefaultPass.h"
#include "vtkRenderState.h"

vtkStandardNewMacro(vtkNPRViewPass);

vtkNPRViewPass::vtkNPRViewPass()
{
  this->NPRPass = vtkNPRPass::New();
  this->RankToonPass = vtkNPRToonPass::New();
  vtkPVDefaultPass* rankScene = vtkPVDefaultPass::New();
  this->RankToonPass->SetDelegatePass(rankScene);
  rankScene->Delete();
}

vtkNPRViewPass::~vtkNPRViewPass()
{
  this->RankToonPass->Delete();
  this->NPRPass->Delete();
}

bool vtkNPRViewPass::DelegateIsComposited() const
{
  // ParaView gives this pass a vtkCameraPass. Under IceT (vtkIceTSynchronizedRenderers) the camera
  // pass's delegate is the vtkIceTCompositePass, which leaves the composited colour and depth.
  auto* camera = vtkCameraPass::SafeDownCast(this->DelegatePass);
  vtkRenderPass* inner = camera ? camera->GetDelegatePass() : this->DelegatePass;
  return inner && inner->IsA("vtkIceTCompositePass");
}

vtkRenderPass* vtkNPRViewPass::GetSceneRenderPass()
{
  const int style = this->NPRPass->GetStyle();
  const bool toon = style == vtkNPRPass::TOON || style == vtkNPRPass::TOON_EDGES ||
    (style == vtkNPRPass::SKETCH && this->NPRPass->GetSketchToonShading());
  return toon ? this->RankToonPass : nullptr;
}

void vtkNPRViewPass::Render(const vtkRenderState* state)
{
  // The per-rank toon pass shades as the façade's does.
  vtkNPRToonPass* toon = this->NPRPass->GetToonPass();
  this->RankToonPass->SetNumberOfBands(toon->GetNumberOfBands());
  this->RankToonPass->SetSpecular(toon->GetSpecular());
  this->RankToonPass->SetPerVertex(toon->GetPerVertex());
  this->RankToonPass->SetTable(toon->GetTable());

  this->NumberOfRenderedProps = 0;
  const bool composited = this->DelegateIsComposited();
  const bool depthOnly = this->DelegatePass && (composited || this->ForceDepthOnly);
  this->LastRenderWasDepthOnly = depthOnly;
  if (!depthOnly)
  {
    // The whole scene through the façade: the full G-buffer (normals, ids) and every style.
    this->NPRPass->Render(state);
    this->NumberOfRenderedProps = this->NPRPass->GetNumberOfRenderedProps();
    return;
  }

  // Depth-only: the delegate's image, lines from its depth.
  vtkNPRGBufferPass* gbuffer = this->NPRPass->GetGBufferPass();
  vtkRenderPass* effect = nullptr;
  switch (this->NPRPass->GetStyle())
  {
    case vtkNPRPass::EDGES:
    case vtkNPRPass::TOON_EDGES:
    case vtkNPRPass::INKED:
    case vtkNPRPass::DRAWING: // each rank sees its own pieces only: the depth lines instead
      effect = this->NPRPass->GetEdgePass();
      break;
    case vtkNPRPass::SKETCH:
      effect = this->NPRPass->GetSketchPass();
      break;
    default: // SHADED, TOON: the image as composited (toon shaded by GetSceneRenderPass())
      break;
  }
  if (!effect)
  {
    this->DelegatePass->Render(state);
    this->NumberOfRenderedProps = this->DelegatePass->GetNumberOfRenderedProps();
    return;
  }
  vtkRenderPass* sceneDelegate = gbuffer->GetDelegatePass();
  if (sceneDelegate)
  {
    sceneDelegate->Register(this);
  }
  gbuffer->SetDepthOnly(true);
  gbuffer->SetDelegatePass(this->DelegatePass);
  gbuffer->Render(state);
  if (gbuffer->GetHasContent())
  {
    effect->Render(state);
  }
  this->NumberOfRenderedProps = gbuffer->GetNumberOfRenderedProps();
  gbuffer->SetDelegatePass(sceneDelegate);
  gbuffer->SetDepthOnly(false);
  if (sceneDelegate)
  {
    sceneDelegate->UnRegister(this);
  }
}

void vtkNPRViewPass::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Superclass::ReleaseGraphicsResources(window);
  this->NPRPass->ReleaseGraphicsResources(window);
  this->RankToonPass->ReleaseGraphicsResources(window);
}

void vtkNPRViewPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ForceDepthOnly: " << this->ForceDepthOnly << "\n";
  os << indent << "LastRenderWasDepthOnly: " << this->LastRenderWasDepthOnly << "\n";
  os << indent << "NPRPass:\n";
  this->NPRPass->PrintSelf(os, indent.GetNextIndent());
}
