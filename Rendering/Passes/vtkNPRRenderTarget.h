// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// A framebuffer object that the passes draw their intermediate images into. Private to the module.
#ifndef vtkNPRRenderTarget_h
#define vtkNPRRenderTarget_h

#include "vtkOpenGLState.h" // for the scoped state savers

#include <initializer_list> // for the attachments

class vtkOpenGLFramebufferObject;
class vtkOpenGLRenderWindow;
class vtkTextureObject;
class vtkWindow;

/**
 * Owns one framebuffer object; a Scope draws into textures attached to it. The textures stay the
 * caller's: a pass attaches whichever of its images a step writes.
 *
 * @code
 * vtkNPRRenderTarget::Scope scope(this->Target, window, { lineTexture }, nullptr, width, height);
 * scope.Clear(0.0, 0.0, 0.0, 0.0);
 * scope.ScissorTo(rect);
 * quad.Render();
 * @endcode
 */
class vtkNPRRenderTarget
{
public:
  vtkNPRRenderTarget() = default;
  ~vtkNPRRenderTarget();
  vtkNPRRenderTarget(const vtkNPRRenderTarget&) = delete;
  vtkNPRRenderTarget& operator=(const vtkNPRRenderTarget&) = delete;

  // The framebuffer object (made on first use), for a delegate's per-mapper draw buffers.
  vtkOpenGLFramebufferObject* GetFramebuffer() const { return this->Framebuffer; }

  // While the framebuffer is bound with `attached` colour attachments, draws into the first `drawn`
  // of them only. The others are named GL_NONE instead of left off the list: vtkOpenGLState's
  // cache compares only as many entries as it is given, so a shorter list would not reach OpenGL.
  void DrawInto(vtkOpenGLState* state, int drawn, int attached);
  void ReleaseGraphicsResources(vtkWindow* window);

  /**
   * Draws into `colors` (draw buffers 0, 1, ...) and `depth` (may be null) while it lives: binds
   * the target, sets the viewport to width x height, turns blending and the scissor test off and
   * the depth test on only with a depth attachment. On leaving, detaches them and restores the
   * framebuffer bindings, viewport, scissor, clear values and the enables it changed.
   */
  class Scope
  {
  public:
    Scope(vtkNPRRenderTarget& target, vtkOpenGLRenderWindow* window,
      std::initializer_list<vtkTextureObject*> colors, vtkTextureObject* depth, int width,
      int height);
    ~Scope();
    Scope(const Scope&) = delete;
    Scope& operator=(const Scope&) = delete;

    // Clears the colour attachments to this value and the depth attachment, if any, to far.
    void Clear(double r, double g, double b, double a);
    // Limits what is drawn next to the rectangle x0, y0, x1, y1 (inclusive).
    void ScissorTo(const int rect[4]);

  private:
    vtkOpenGLState* State;
    vtkOpenGLState::ScopedglViewport Viewport;
    vtkOpenGLState::ScopedglScissor Scissor;
    vtkOpenGLState::ScopedglClearColor ClearColor;
    vtkOpenGLState::ScopedglDepthMask DepthMask;
    vtkOpenGLState::ScopedglEnableDisable DepthTest;
    vtkOpenGLState::ScopedglEnableDisable Blend;
    vtkOpenGLState::ScopedglEnableDisable ScissorTest;
    vtkOpenGLFramebufferObject* Framebuffer;
    int ColorAttachments;
    bool HasDepth;
  };

private:
  vtkOpenGLFramebufferObject* Framebuffer = nullptr;
};

#endif
