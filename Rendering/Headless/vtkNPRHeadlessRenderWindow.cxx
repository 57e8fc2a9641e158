// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNPRHeadlessRenderWindow.h"

#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLState.h"
#include "vtkRendererCollection.h"
#include "vtk_glew.h"

void vtkNPRHeadlessRenderWindow::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Backend: " << this->GetBackendName() << "\n";
  os << indent << "HasValidContext: " << this->ContextValid << "\n";
  os << indent << "ContextError: " << this->ContextError << "\n";
  os << indent << "GLVendor: " << this->GLVendor << "\n";
  os << indent << "GLRenderer: " << this->GLRenderer << "\n";
  os << indent << "GLVersion: " << this->GLVersion << "\n";
}

vtkNPRHeadlessRenderWindow::vtkNPRHeadlessRenderWindow()
{
  // There is no default framebuffer to blit to: VTK's own framebuffer holds the image.
  this->SetFrameBlitModeToNoBlit();
}

vtkNPRHeadlessRenderWindow::~vtkNPRHeadlessRenderWindow() = default;

bool vtkNPRHeadlessRenderWindow::InitializeContext()
{
  if (this->ContextValid)
  {
    return true;
  }
  if (this->ContextFailed || this->ShutDownDone)
  {
    return false;
  }
  if (!this->ContextExists() && !this->CreateContext())
  {
    this->ContextFailed = true;
    return false;
  }
  if (!this->MakeContextCurrent())
  {
    if (this->ContextError.empty())
    {
      this->SetContextError("could not make the context current");
    }
    this->ContextFailed = true;
    return false;
  }
  // GLEW first: VTK's state set-up below calls OpenGL through it, and must not run without it.
  this->OpenGLInitContext();
  if (!this->ContextValid)
  {
    this->ContextFailed = true;
    return false;
  }
  this->Superclass::OpenGLInit();
  return true;
}

void vtkNPRHeadlessRenderWindow::MakeCurrent()
{
  if (this->ShutDownDone || this->ContextFailed)
  {
    return;
  }
  if (!this->ContextExists())
  {
    this->InitializeContext();
    return;
  }
  this->MakeContextCurrent();
}

int vtkNPRHeadlessRenderWindow::GetColorBufferSizes(int* rgba)
{
  rgba[0] = rgba[1] = rgba[2] = rgba[3] = 0;
  vtkOpenGLFramebufferObject* framebuffer = this->GetRenderFramebuffer();
  if (!this->ContextValid || !framebuffer || !framebuffer->GetFBOIndex())
  {
    return 0;
  }
  this->MakeCurrent();
  vtkOpenGLState* state = this->GetState();
  state->PushReadFramebufferBinding();
  framebuffer->Bind(GL_READ_FRAMEBUFFER);
  const GLenum names[4] = { GL_FRAMEBUFFER_ATTACHMENT_RED_SIZE,
    GL_FRAMEBUFFER_ATTACHMENT_GREEN_SIZE, GL_FRAMEBUFFER_ATTACHMENT_BLUE_SIZE,
    GL_FRAMEBUFFER_ATTACHMENT_ALPHA_SIZE };
  for (int i = 0; i < 4; ++i)
  {
    GLint size = 0;
    glGetFramebufferAttachmentParameteriv(
      GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, names[i], &size);
    rgba[i] = size;
  }
  state->PopReadFramebufferBinding();
  return rgba[0] + rgba[1] + rgba[2] + rgba[3];
}

void vtkNPRHeadlessRenderWindow::Render()
{
  if (!this->InitializeContext())
  {
    if (!this->FailureReported)
    {
      this->FailureReported = true;
      vtkErrorMacro(<< "cannot render: no " << this->GetBackendName()
                    << " OpenGL context: " << this->ContextError);
    }
    return;
  }
  // VTK 9.1's generic window saves the GL state before it makes its context current.
  this->MakeContextCurrent();
  this->Superclass::Render();
}

void vtkNPRHeadlessRenderWindow::OpenGLInit()
{
  // vtkOpenGLRenderWindow queries GL state here; the context must exist and be current first.
  if (!this->ContextValid)
  {
    this->InitializeContext(); // runs the superclass's OpenGLInit once the context is current
  }
  else if (this->MakeContextCurrent())
  {
    this->Superclass::OpenGLInit();
  }
}

void vtkNPRHeadlessRenderWindow::OpenGLInitContext()
{
  this->ContextCreationTime.Modified();
  if (this->Initialized)
  {
    return;
  }
  if (!this->MakeContextCurrent())
  {
    this->SetContextError("could not make the context current");
    return;
  }
  // Read through the same gl* symbols VTK calls: a null answer means they reach a library
  // that does not see this context.
  const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  if (!renderer)
  {
    this->SetContextError(std::string("glGetString(GL_RENDERER) returned null: this program's "
                                      "OpenGL calls do not reach the ") +
      this->GetBackendName() + " context (link order; see Documentation/backends.md)");
    return;
  }
  // GLEW 2.2: glewInit() = OpenGL entry points, then GLX; without an X display the GLX part
  // fails after the OpenGL part succeeded.
  const GLenum result = glewInit();
  if (result != GLEW_OK && result != GLEW_ERROR_GLX_VERSION_11_ONLY &&
    result != GLEW_ERROR_NO_GLX_DISPLAY)
  {
    this->SetContextError(
      std::string("glewInit failed: ") + reinterpret_cast<const char*>(glewGetErrorString(result)));
    return;
  }
  if (!GLEW_VERSION_3_2)
  {
    this->SetContextError(std::string("OpenGL 3.2 or later is required; the context offers ") +
      reinterpret_cast<const char*>(glGetString(GL_VERSION)));
    return;
  }
  this->GLVendor = reinterpret_cast<const char*>(glGetString(GL_VENDOR));
  this->GLRenderer = renderer;
  this->GLVersion = reinterpret_cast<const char*>(glGetString(GL_VERSION));
  this->GlewInitValid = true;
  this->Initialized = true;
  this->ContextValid = true;
  this->ContextError.clear();

  GLfloat range[2] = { 1.0f, 1.0f };
  glGetFloatv(GL_ALIASED_LINE_WIDTH_RANGE, range);
  this->MaximumHardwareLineWidth = glGetError() == GL_NO_ERROR ? range[1] : 1.0f;
}

void vtkNPRHeadlessRenderWindow::ShutDown()
{
  if (this->ShutDownDone)
  {
    return;
  }
  if (this->ContextExists())
  {
    if (this->MakeContextCurrent())
    {
      this->Finalize(); // free VTK's buffers, shaders and textures in this context
    }
    this->DestroyContext();
  }
  this->ShutDownDone = true;
  this->ContextValid = false;
}
