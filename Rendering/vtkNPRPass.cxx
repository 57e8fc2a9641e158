#include "vtkNPRPass.h"

#include "vtkDualDepthPeelingPass.h"
#include "vtkNPREdgePass.h"
#include "vtkNPRGBufferPass.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpaquePass.h"
#include "vtkRenderPassCollection.h"
#include "vtkRenderState.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderer.h"
#include "vtkSequencePass.h"
#include "vtkTranslucentPass.h"

vtkStandardNewMacro(vtkNPRPass);

vtkNPRPass::vtkNPRPass()
{
  this->RenderStepsPass = vtkRenderStepsPass::New();
  this->OpaquePass = vtkOpaquePass::New();
  this->GBufferPass = vtkNPRGBufferPass::New();
  this->GBufferPass->SetDelegatePass(this->OpaquePass);
  this->EdgePass = vtkNPREdgePass::New();
  this->EdgePass->SetGBufferPass(this->GBufferPass);
  this->EdgesSequence = vtkSequencePass::New();
  vtkNew<vtkRenderPassCollection> passes;
  passes->AddItem(this->GBufferPass);
  passes->AddItem(this->EdgePass);
  this->EdgesSequence->SetPasses(passes);
  this->TranslucentPass = vtkTranslucentPass::New();
  this->DepthPeelingPass = vtkDualDepthPeelingPass::New();
  this->DepthPeelingPass->SetTranslucentPass(this->TranslucentPass);
}

vtkNPRPass::~vtkNPRPass()
{
  this->RenderStepsPass->Delete();
  this->EdgesSequence->Delete();
  this->EdgePass->Delete();
  this->GBufferPass->Delete();
  this->OpaquePass->Delete();
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
    default:
      return "unknown";
  }
}

void vtkNPRPass::Render(const vtkRenderState* state)
{
  vtkRenderer* renderer = state->GetRenderer();
  if (this->Style == SHADED)
  {
    this->RenderStepsPass->SetOpaquePass(this->OpaquePass);
  }
  else
  {
    this->GBufferPass->SetNormalsRequested(this->EdgePass->GetCreases());
    this->GBufferPass->SetObjectIdsRequested(this->EdgePass->GetContours());
    this->RenderStepsPass->SetOpaquePass(this->EdgesSequence);
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
  this->OpaquePass->ReleaseGraphicsResources(window);
  this->DepthPeelingPass->ReleaseGraphicsResources(window);
  this->TranslucentPass->ReleaseGraphicsResources(window);
}

void vtkNPRPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Style: " << GetStyleName(this->Style) << "\n";
  os << indent << "GBufferPass:\n";
  this->GBufferPass->PrintSelf(os, indent.GetNextIndent());
  os << indent << "EdgePass:\n";
  this->EdgePass->PrintSelf(os, indent.GetNextIndent());
}
