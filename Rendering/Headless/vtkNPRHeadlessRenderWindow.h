// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkNPRHeadlessRenderWindow
 * @brief   Base of the render windows that draw with no display server.
 *
 * A headless window owns an off-screen OpenGL context (EGL, OSMesa) instead of a window of a
 * window system. Subclasses create, bind and destroy that context; this class does the rest:
 *
 * - GLEW initialisation without GLX. Debian's VTK 9.1 is built against GLEW 2.2, whose
 *   glewInit() also initialises GLX and fails when there is no X display; the OpenGL part has
 *   succeeded by then, so those GLX-only failures are accepted here.
 * - A Render() that reports a context that cannot be made, once and clearly, and draws nothing,
 *   instead of crashing or producing a black image.
 * - The strings of the context actually in use (GL_VENDOR, GL_RENDERER, GL_VERSION), checked:
 *   a null GL_RENDERER after the context is current means this process resolves OpenGL calls
 *   from a library that does not see the context (a link-order problem), which is an error.
 *
 * VTK renders into its own framebuffer objects (frame blit mode NoBlit); read the pixels with
 * vtkWindowToImageFilter (ReadFrontBufferOff) or GetPixelData as usual.
 *
 * @sa vtkNPREGLRenderWindow vtkNPROSMesaRenderWindow vtkNPRRenderWindowFactory
 */
#ifndef vtkNPRHeadlessRenderWindow_h
#define vtkNPRHeadlessRenderWindow_h

#include "vtkGenericOpenGLRenderWindow.h"
#include "vtkNPRHeadlessModule.h" // for export macro

#include <string> // for std::string

class VTKNPRHEADLESS_EXPORT vtkNPRHeadlessRenderWindow : public vtkGenericOpenGLRenderWindow
{
public:
  vtkTypeMacro(vtkNPRHeadlessRenderWindow, vtkGenericOpenGLRenderWindow);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Create the OpenGL context now rather than at the first Render() and initialise OpenGL in it.
   * Returns false when that fails; GetContextError() then says why. Cheap once it succeeded.
   */
  bool InitializeContext();

  /**
   * True once a context exists and OpenGL was initialised in it.
   */
  bool HasValidContext() const { return this->ContextValid; }

  /**
   * Why the last attempt to create or initialise the context failed ("" when it did not).
   */
  const char* GetContextError() const { return this->ContextError.c_str(); }

  ///@{
  /**
   * The GL_VENDOR, GL_RENDERER and GL_VERSION strings of the context ("" before one exists).
   */
  const char* GetGLVendor() const { return this->GLVendor.c_str(); }
  const char* GetGLRenderer() const { return this->GLRenderer.c_str(); }
  const char* GetGLVersion() const { return this->GLVersion.c_str(); }
  ///@}

  /**
   * Short name of the backend ("egl", "osmesa").
   */
  virtual const char* GetBackendName() = 0;

  /**
   * Renders when a context exists; otherwise reports why (once) and draws nothing.
   */
  void Render() override;

  /**
   * Bits per channel of the framebuffer VTK renders into (its own framebuffer object: a
   * surfaceless context's default framebuffer has no colour buffer). vtkHardwareSelector
   * checks them before picking.
   */
  int GetColorBufferSizes(int* rgba) override;

  /**
   * Same as InitializeContext(), for code that calls vtkRenderWindow::Initialize().
   */
  void Initialize() override { this->InitializeContext(); }

  /**
   * Makes the context current, creating it first if needed.
   */
  void MakeCurrent() override;

  int SupportsOpenGL() override { return this->ContextValid ? 1 : 0; }
  vtkTypeBool IsDirect() override { return 1; }
  void OpenGLInit() override;
  void OpenGLInitContext() override;

protected:
  vtkNPRHeadlessRenderWindow();
  ~vtkNPRHeadlessRenderWindow() override;

  /**
   * Create the context (not yet current). Return false and call SetContextError() on failure.
   */
  virtual bool CreateContext() = 0;

  /**
   * Make the context current; return false if that failed.
   */
  virtual bool MakeContextCurrent() = 0;

  /**
   * Release and destroy the context. Called by the subclass destructor after Finalize().
   */
  virtual void DestroyContext() = 0;

  /**
   * True while a context exists (created, not destroyed).
   */
  virtual bool ContextExists() = 0;

  void SetContextError(const std::string& message) { this->ContextError = message; }

  /**
   * Subclass destructors call this first: releases VTK's GL resources while the context is still
   * current, then destroys the context, and makes every later MakeCurrent() a no-op.
   */
  void ShutDown();

private:
  vtkNPRHeadlessRenderWindow(const vtkNPRHeadlessRenderWindow&) = delete;
  void operator=(const vtkNPRHeadlessRenderWindow&) = delete;

  bool ContextValid = false;
  bool ContextFailed = false;
  bool FailureReported = false;
  bool ShutDownDone = false;
  std::string ContextError;
  std::string GLVendor;
  std::string GLRenderer;
  std::string GLVersion;
};

#endif
