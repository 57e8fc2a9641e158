// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNPRRenderTarget.h"

#include "vtkNPROpenGL.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkTextureObject.h"

#include <algorithm>

vtkNPRRenderTarget::~vtkNPRRenderTarget()
{
  // The framebuffer frees its OpenGL name through the window's resource callbacks.
  if (this->Framebuffer)
  {
    this->Framebuffer->Delete();
  }
}

void vtkNPRRenderTarget::ReleaseGraphicsResources(vtkWindow* window)
{
  if (this->Framebuffer)
  {
    this->Framebuffer->ReleaseGraphicsResources(window);
    this->Framebuffer->Delete();
    this->Framebuffer = nullptr;
  }
}

void vtkNPRRenderTarget::DrawInto(vtkOpenGLState* state, int drawn, int attached)
{
  // vtkOpenGLState keeps 10 draw buffers.
  unsigned int buffers[10];
  const int count = std::min(attached, 10);
  for (int i = 0; i < count; ++i)
  {
    buffers[i] = i < drawn ? GL_COLOR_ATTACHMENT0 + i : GL_NONE;
  }
  if (count > 0)
  {
    state->vtkDrawBuffers(static_cast<unsigned int>(count), buffers, this->Framebuffer);
  }
}

vtkNPRRenderTarget::Scope::Scope(vtkNPRRenderTarget& target, vtkOpenGLRenderWindow* window,
  std::initializer_list<vtkTextureObject*> colors, vtkTextureObject* depth, int width, int height)
  : State(window->GetState())
  , Viewport(this->State)
  , Scissor(this->State)
  , ClearColor(this->State)
  , DepthMask(this->State)
  , DepthTest(this->State, GL_DEPTH_TEST)
  , Blend(this->State, GL_BLEND)
  , ScissorTest(this->State, GL_SCISSOR_TEST)
  , ColorAttachments(static_cast<int>(colors.size()))
  , HasDepth(depth != nullptr)
{
  if (!target.Framebuffer)
  {
    target.Framebuffer = vtkOpenGLFramebufferObject::New();
    target.Framebuffer->SetContext(window);
  }
  this->Framebuffer = target.Framebuffer;
  this->State->PushFramebufferBindings();
  this->Framebuffer->Bind();
  unsigned int index = 0;
  for (vtkTextureObject* color : colors)
  {
    this->Framebuffer->AddColorAttachment(index++, color);
  }
  if (depth)
  {
    this->Framebuffer->AddDepthAttachment(depth);
  }
  this->Framebuffer->ActivateDrawBuffers(index);
  this->Framebuffer->StartNonOrtho(width, height); // checks completeness; sets no viewport
  this->State->vtkglViewport(0, 0, width, height);
  this->State->vtkglScissor(0, 0, width, height);
  // VTK leaves blending on in the opaque step; it would blend every attachment.
  this->State->vtkglDisable(GL_BLEND);
  this->State->vtkglDisable(GL_SCISSOR_TEST);
  if (depth)
  {
    this->State->vtkglEnable(GL_DEPTH_TEST);
    this->State->vtkglDepthMask(GL_TRUE);
  }
  else
  {
    this->State->vtkglDisable(GL_DEPTH_TEST);
  }
}

vtkNPRRenderTarget::Scope::~Scope()
{
  this->Framebuffer->RemoveColorAttachments(this->ColorAttachments);
  if (this->HasDepth)
  {
    this->Framebuffer->RemoveDepthAttachment();
  }
  this->State->PopFramebufferBindings();
}

void vtkNPRRenderTarget::Scope::Clear(double r, double g, double b, double a)
{
  vtkOpenGLState::ScopedglEnableDisable scissorTest(this->State, GL_SCISSOR_TEST);
  this->State->vtkglDisable(GL_SCISSOR_TEST);
  this->State->vtkglClearColor(r, g, b, a);
  unsigned int mask = GL_COLOR_BUFFER_BIT;
  if (this->HasDepth)
  {
    this->State->vtkglClearDepth(1.0);
    mask |= GL_DEPTH_BUFFER_BIT;
  }
  this->State->vtkglClear(mask);
}

void vtkNPRRenderTarget::Scope::ScissorTo(const int rect[4])
{
  this->State->vtkglEnable(GL_SCISSOR_TEST);
  this->State->vtkglScissor(
    rect[0], rect[1], std::max(0, rect[2] - rect[0] + 1), std::max(0, rect[3] - rect[1] + 1));
}
