// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkNPRImageEffectPass
 * @brief   The frame of a pass that reads a G-buffer and composites an image over the view.
 *
 * vtkNPREdgePass, vtkNPRSketchPass and vtkNPRDrawingPass share one frame, which Render() runs:
 * 1. the guard: nothing is drawn after a picking render or when the G-buffer is empty;
 * 2. the effect's intermediate images (line image, noise, strokes), brought up to date with the
 *    G-buffer (UpdateImages(): each is recomputed only when what it is made from changed);
 * 3. an unchanged frame: the composite kept from the last frame copied back
 * (KeepUnchangedComposite);
 * 4. otherwise the composite: the effect's full-screen program over the view, with the depth of
 *    every pixel it writes (a depth sprite, vtkNPRCompositeState), then kept for the next frame.
 * A subclass supplies the steps (GetGBuffer, UpdateImages, GetCompositeKey, GetCompositeRectangle,
 * DrawComposite) and nothing of the frame around them; it frees its own textures and programs in
 * ReleaseGraphicsResources(), after this class's.
 *
 * @sa vtkNPREdgePass vtkNPRSketchPass vtkNPRDrawingPass vtkNPRGBufferPass
 */
#ifndef vtkNPRImageEffectPass_h
#define vtkNPRImageEffectPass_h

#include "vtkNPRPassesModule.h" // for export macro
#include "vtkRenderPass.h"

#include <memory> // for std::unique_ptr
#include <string> // for std::string

class vtkNPRGBufferPass;
class vtkRenderer;

class VTKNPRPASSES_EXPORT vtkNPRImageEffectPass : public vtkRenderPass
{
public:
  vtkTypeMacro(vtkNPRImageEffectPass, vtkRenderPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Runs the frame described above into the current framebuffer.
   */
  void Render(const vtkRenderState* state) override;
  /**
   * Releases the kept composite (a subclass adds its own resources).
   */
  void ReleaseGraphicsResources(vtkWindow* window) override;

  ///@{
  /**
   * Draw a frame in which nothing changed by copying back the last composited image instead of
   * compositing again (on by default). Nothing changed means: the G-buffer kept its content
   * (vtkNPRGBufferPass::ReuseUnchangedFrames), the effect's images and settings, the renderer's
   * background, the viewport and the framebuffer drawn into are those of the last frame. The copy
   * (colour and depth of the composite's rectangle, glBlitFramebuffer) is taken only while frames
   * are being reused (one of the last 8 was unchanged), so a scene in motion pays nothing for it,
   * and only where it comes back bit for bit: a renderer that clears its own colour and depth,
   * into a framebuffer without multisampling, with 8-bit colour and a standard depth format.
   */
  vtkSetMacro(KeepUnchangedComposite, bool);
  vtkGetMacro(KeepUnchangedComposite, bool);
  vtkBooleanMacro(KeepUnchangedComposite, bool);
  ///@}

  /**
   * Number of frames drawn by copying back the kept composite (KeepUnchangedComposite).
   */
  vtkGetMacro(NumberOfKeptCompositeRestores, int);

protected:
  vtkNPRImageEffectPass();
  ~vtkNPRImageEffectPass() override;

  // The G-buffer the effect reads (drawn earlier in the frame); null: nothing is drawn (the
  // subclass says why, once).
  virtual vtkNPRGBufferPass* GetGBuffer() = 0;
  // Brings the intermediate images up to date with the G-buffer; false: nothing can be drawn
  // (the subclass reported the error).
  virtual bool UpdateImages(const vtkRenderState* state) = 0;
  // Everything the composite depends on beside the G-buffer's content and the renderer's clear
  // (settings, the images' versions), or empty where this frame's composite cannot be kept.
  virtual std::string GetCompositeKey(vtkRenderer* renderer) = 0;
  // The rectangle x0, y0, x1, y1 (inclusive, in the G-buffer's pixels) that the composite writes.
  virtual void GetCompositeRectangle(vtkRenderer* renderer, int rect[4]) = 0;
  // Draws the composite into the current framebuffer, whose state vtkNPRCompositeState applied
  // (the viewport at `origin`, the scissor at the rectangle); false: the program did not compile.
  virtual bool DrawComposite(const vtkRenderState* state, const int origin[2]) = 0;

  // The frame's guard and first step, for Render() and a subclass's other outputs: the G-buffer,
  // with content and not from a picking render, once UpdateImages() succeeded; null otherwise.
  vtkNPRGBufferPass* GetReadyGBuffer(const vtkRenderState* state);
  // The whole G-buffer as a rectangle x0, y0, x1, y1.
  static void GetWholeRectangle(vtkNPRGBufferPass* gbuffer, int rect[4]);

  bool KeepUnchangedComposite = true;
  int NumberOfKeptCompositeRestores = 0;

private:
  vtkNPRImageEffectPass(const vtkNPRImageEffectPass&) = delete;
  void operator=(const vtkNPRImageEffectPass&) = delete;

  // The key of a composite into the current framebuffer at windowRect, or empty.
  std::string FrameKey(vtkRenderer* renderer, const int windowRect[4]);
  bool RestoreUnchanged(vtkRenderer* renderer, const int windowRect[4]);
  void KeepComposite(vtkRenderer* renderer, const int windowRect[4]);

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
