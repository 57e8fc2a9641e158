/**
 * @class   vtkNPRPass
 * @brief   Non-photorealistic rendering for a renderer in one line: renderer->SetPass(npr).
 *
 * Builds and owns the whole chain of passes a renderer needs:
 *
 *   vtkRenderStepsPass: camera, lights,
 *     opaque: vtkNPRGBufferPass (drawing a vtkOpaquePass) then vtkNPREdgePass,
 *     translucent: vtkTranslucentPass, or vtkDualDepthPeelingPass when the renderer's
 *                  UseDepthPeeling is on (its MaximumNumberOfPeels and OcclusionRatio apply),
 *     volumes, overlay.
 *
 * The edge pass writes a depth sprite, so everything drawn after the opaque step (translucent
 * props, volumes, 2D actors, renderers on higher layers) composites as with VTK's own chain.
 *
 * Styles: EDGES (default: lines on the shaded surfaces) and SHADED (VTK's plain opaque step,
 * no G-buffer). The effect passes are exposed for tuning (GetEdgePass(), GetGBufferPass()); the
 * G-buffer channels follow what the enabled lines need.
 *
 * Renderer flags that VTK ignores once a pass is set (UseFXAA, UseSSAO, UseShadows) stay ignored;
 * UseDepthPeeling is honoured here.
 *
 * @sa vtkNPRGBufferPass vtkNPREdgePass
 */
#ifndef vtkNPRPass_h
#define vtkNPRPass_h

#include "vtkRenderPass.h"
#include "vtkRenderingNPRModule.h" // for export macro

class vtkDualDepthPeelingPass;
class vtkNPREdgePass;
class vtkNPRGBufferPass;
class vtkOpaquePass;
class vtkRenderStepsPass;
class vtkSequencePass;
class vtkTranslucentPass;

class VTKRENDERINGNPR_EXPORT vtkNPRPass : public vtkRenderPass
{
public:
  static vtkNPRPass* New();
  vtkTypeMacro(vtkNPRPass, vtkRenderPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  void Render(const vtkRenderState* state) override;
  void ReleaseGraphicsResources(vtkWindow* window) override;

  enum Styles
  {
    SHADED = 0,
    EDGES = 1
  };

  ///@{
  /**
   * The style (default EDGES).
   */
  vtkSetClampMacro(Style, int, SHADED, EDGES);
  vtkGetMacro(Style, int);
  void SetStyleToShaded() { this->SetStyle(SHADED); }
  void SetStyleToEdges() { this->SetStyle(EDGES); }
  static const char* GetStyleName(int style);
  ///@}

  ///@{
  /**
   * The passes this one owns, for tuning. Do not replace them inside the chain.
   */
  vtkGetObjectMacro(GBufferPass, vtkNPRGBufferPass);
  vtkGetObjectMacro(EdgePass, vtkNPREdgePass);
  vtkGetObjectMacro(RenderStepsPass, vtkRenderStepsPass);
  ///@}

protected:
  vtkNPRPass();
  ~vtkNPRPass() override;

  int Style = EDGES;
  vtkRenderStepsPass* RenderStepsPass;
  vtkOpaquePass* OpaquePass;
  vtkNPRGBufferPass* GBufferPass;
  vtkNPREdgePass* EdgePass;
  vtkSequencePass* EdgesSequence;
  vtkTranslucentPass* TranslucentPass;
  vtkDualDepthPeelingPass* DepthPeelingPass;

private:
  vtkNPRPass(const vtkNPRPass&) = delete;
  void operator=(const vtkNPRPass&) = delete;
};

#endif
