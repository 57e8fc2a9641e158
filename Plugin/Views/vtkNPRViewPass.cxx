#include "vtkNPRViewPass.h"

#include "vtkCameraPass.h"
#include "vtkNPREdgePass.h"
#include "vtkNPRGBufferPass.h"
#include "vtkNPRPass.h"
#include "vtkNPRSketchPass.h"
#include "vtkObjectFactory.h"
#include "vtkRenderState.h"

vtkStandardNewMacro(vtkNPRViewPass);

vtkNPRViewPass::vtkNPRViewPass()
{
  this->NPRPass = vtkNPRPass::New();
}

vtkNPRViewPass::~vtkNPRViewPass()
{
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

void vtkNPRViewPass::Render(const vtkRenderState* state)
{
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
      effect = this->NPRPass->GetEdgePass();
      break;
    case vtkNPRPass::SKETCH:
      effect = this->NPRPass->GetSketchPass();
      break;
    default: // SHADED, TOON: the image as composited
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
}

void vtkNPRViewPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ForceDepthOnly: " << this->ForceDepthOnly << "\n";
  os << indent << "LastRenderWasDepthOnly: " << this->LastRenderWasDepthOnly << "\n";
  os << indent << "NPRPass:\n";
  this->NPRPass->PrintSelf(os, indent.GetNextIndent());
}
