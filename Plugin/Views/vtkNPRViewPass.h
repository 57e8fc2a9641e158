// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkNPRViewPass
 * @brief   The vtkNPR styles in the image-processing slot of a ParaView render view.
 *
 * vtkPVSynchronizedRenderer puts this pass where it puts image-processing passes
 * (SetImageProcessingPass()): the renderer's pass is this one (after FXAA when that is on) and
 * the delegate it is given renders the scene:
 * - in one process (builtin session, pvbatch or pvserver on one rank) the delegate is a
 *   vtkCameraPass drawing through vtkPVDefaultPass. This pass then renders the scene itself
 *   through its vtkNPRPass, which draws the full G-buffer (colour, depth, normals, object ids).
 * - under MPI with IceT the delegate is IceT's composite pass, which renders each rank's piece,
 *   composites and pastes the composited premultiplied colour and depth into the framebuffer.
 *   No normals or ids exist for the composited image, so the vtkNPRPass's G-buffer pass is put
 *   in depth-only mode (vtkNPRGBufferPass::SetDepthOnly): it draws the delegate and derives
 *   view depth and normals from the depth buffer. Silhouettes come from depth as before,
 *   creases from the reconstructed normals, and contours fall back to coverage (the outline
 *   against the background; no object ids separate touching objects). Toon shading is per
 *   fragment, so it is applied inside IceT, to each rank's piece, by the pass
 *   GetSceneRenderPass() returns (the view makes it vtkPVSynchronizedRenderer's render pass).
 *   The inked wireframe cannot be applied to an image, and a rank's object-space lines would
 *   miss the other ranks' pieces: INKED and DRAWING draw the depth lines instead.
 *   Since the composited image has no seams, no line appears where ranks' pieces meet.
 *
 * Composited input is detected from the delegate (a vtkCameraPass over a vtkIceTCompositePass);
 * ForceDepthOnly makes a single process render the same way.
 *
 * @sa vtkPVNPRView vtkNPRPass vtkNPRGBufferPass
 */
#ifndef vtkNPRViewPass_h
#define vtkNPRViewPass_h

#include "vtkImageProcessingPass.h"
#include "vtkNPRViewsModule.h" // for export macro

class vtkNPRPass;
class vtkNPRToonPass;

class VTKNPRVIEWS_EXPORT vtkNPRViewPass : public vtkImageProcessingPass
{
public:
  static vtkNPRViewPass* New();
  vtkTypeMacro(vtkNPRViewPass, vtkImageProcessingPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  void Render(const vtkRenderState* state) override;
  void ReleaseGraphicsResources(vtkWindow* window) override;

  /**
   * The façade whose style and passes this pass renders with.
   */
  vtkGetObjectMacro(NPRPass, vtkNPRPass);

  /**
   * The pass that should render each rank's piece of the scene for the current style (a toon
   * pass over vtkPVDefaultPass for the toon styles), or nullptr for ParaView's default. It
   * shades as the façade's toon pass does.
   */
  vtkRenderPass* GetSceneRenderPass();

  ///@{
  /**
   * Derive the lines from the delegate's depth even in one process (off by default), to see
   * what a parallel render gives.
   */
  vtkSetMacro(ForceDepthOnly, bool);
  vtkGetMacro(ForceDepthOnly, bool);
  vtkBooleanMacro(ForceDepthOnly, bool);
  ///@}

  /**
   * The last frame used the depth-only mode.
   */
  bool GetLastRenderWasDepthOnly() const { return this->LastRenderWasDepthOnly; }

protected:
  vtkNPRViewPass();
  ~vtkNPRViewPass() override;

  bool DelegateIsComposited() const;

  vtkNPRPass* NPRPass;
  vtkNPRToonPass* RankToonPass;
  bool ForceDepthOnly = false;
  bool LastRenderWasDepthOnly = false;

private:
  vtkNPRViewPass(const vtkNPRViewPass&) = delete;
  void operator=(const vtkNPRViewPass&) = delete;
};

#endif
