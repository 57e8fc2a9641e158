// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nprOneFetchPass.h"

#include "nprOneFetchFS.h"

#include "vtkObjectFactory.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderUtilities.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

vtkStandardNewMacro(nprOneFetchPass);

nprOneFetchPass::~nprOneFetchPass()
{
  delete this->Quad;
  if (this->Framebuffer)
  {
    this->Framebuffer->Delete();
  }
  if (this->Color)
  {
    this->Color->Delete();
  }
}

void nprOneFetchPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Color texture: " << (this->Color ? "made" : "(none)") << "\n";
}

void nprOneFetchPass::PrepareTarget(vtkOpenGLRenderWindow* window, int width, int height)
{
  if (!this->Color)
  {
    this->Color = vtkTextureObject::New();
    this->Color->SetContext(window);
    this->Color->SetMinificationFilter(vtkTextureObject::Nearest);
    this->Color->SetMagnificationFilter(vtkTextureObject::Nearest);
    this->Color->Allocate2D(width, height, 4, VTK_UNSIGNED_CHAR);
  }
  this->Color->Resize(width, height);
  if (!this->Framebuffer)
  {
    this->Framebuffer = vtkOpenGLFramebufferObject::New();
    this->Framebuffer->SetContext(window);
  }
}

bool nprOneFetchPass::ReadyProgram(vtkOpenGLRenderWindow* window)
{
  if (!this->Quad)
  {
    this->Quad = new vtkOpenGLQuadHelper(
      window, vtkOpenGLRenderUtilities::GetFullScreenQuadVertexShader().c_str(), nprOneFetchFS, "");
  }
  else
  {
    window->GetShaderCache()->ReadyShaderProgram(this->Quad->Program);
  }
  return this->Quad->Program && this->Quad->Program->GetCompiled();
}

void nprOneFetchPass::Render(const vtkRenderState* state)
{
  this->NumberOfRenderedProps = 0;
  if (!this->DelegatePass)
  {
    vtkWarningMacro("no delegate pass: nothing drawn.");
    return;
  }
  vtkRenderer* renderer = state->GetRenderer();
  auto* window = static_cast<vtkOpenGLRenderWindow*>(renderer->GetRenderWindow());
  int width, height, x, y;
  renderer->GetTiledSizeAndOrigin(&width, &height, &x, &y);
  this->PrepareTarget(window, width, height);
  vtkOpenGLState* glState = window->GetState();
  glState->PushFramebufferBindings();
  this->RenderDelegate(state, width, height, width, height, this->Framebuffer, this->Color);
  glState->PopFramebufferBindings();
  // After the delegate, as VTK's image passes do: readied before it, the frame came out zoomed.
  if (!this->ReadyProgram(window))
  {
    vtkErrorMacro("the copy program did not build: nothing drawn.");
    return;
  }

  vtkOpenGLState::ScopedglEnableDisable blend(glState, GL_BLEND);
  vtkOpenGLState::ScopedglEnableDisable depthTest(glState, GL_DEPTH_TEST);
  glState->vtkglDisable(GL_BLEND);
  glState->vtkglDisable(GL_DEPTH_TEST);
  glState->vtkglViewport(x, y, width, height);
  glState->vtkglScissor(x, y, width, height);
  this->Color->Activate();
  this->Quad->Program->SetUniformi("source", this->Color->GetTextureUnit());
  this->Quad->Render();
  this->Color->Deactivate();
}

void nprOneFetchPass::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Superclass::ReleaseGraphicsResources(window);
  delete this->Quad;
  this->Quad = nullptr;
  if (this->Framebuffer)
  {
    this->Framebuffer->ReleaseGraphicsResources(window);
  }
  if (this->Color)
  {
    this->Color->ReleaseGraphicsResources(window);
  }
}
