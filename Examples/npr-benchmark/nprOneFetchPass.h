// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class nprOneFetchPass
 * @brief The least any image effect costs: the delegate drawn into a texture, then one
 * full-screen pass that fetches each pixel once.
 *
 * npr-benchmark --speed's `one-fetch` bound. The delegate's frame (usually a vtkRenderStepsPass)
 * is drawn into an RGBA8 texture with a depth renderbuffer (vtkImageProcessingPass's
 * RenderDelegate), then copied into the window by a full-screen quad whose fragment shader is one
 * `texelFetch` and one write, with neither depth nor blending. Any screen-space style draws at
 * least this: its own image of the scene and one pass over the view. Its depth is not carried, so
 * it bounds from below even an effect that keeps VTK's depth buffer.
 */
#ifndef nprOneFetchPass_h
#define nprOneFetchPass_h

#include "vtkImageProcessingPass.h"

class vtkOpenGLFramebufferObject;
class vtkOpenGLQuadHelper;
class vtkTextureObject;

class nprOneFetchPass : public vtkImageProcessingPass
{
public:
  static nprOneFetchPass* New();
  vtkTypeMacro(nprOneFetchPass, vtkImageProcessingPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  void Render(const vtkRenderState* state) override;
  void ReleaseGraphicsResources(vtkWindow* window) override;

protected:
  nprOneFetchPass() = default;
  ~nprOneFetchPass() override;

private:
  nprOneFetchPass(const nprOneFetchPass&) = delete;
  void operator=(const nprOneFetchPass&) = delete;

  // The colour texture at this size and the framebuffer, made on first use.
  void PrepareTarget(vtkOpenGLRenderWindow* window, int width, int height);
  // Makes or binds the copy program; false if it did not build.
  bool ReadyProgram(vtkOpenGLRenderWindow* window);

  vtkOpenGLFramebufferObject* Framebuffer = nullptr;
  vtkTextureObject* Color = nullptr;
  vtkOpenGLQuadHelper* Quad = nullptr;
};

#endif
