// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNPRPassUtilities.h"

#include "vtkActor.h"
#include "vtkHardwareSelector.h"
#include "vtkNPROpaquePass.h"
#include "vtkNPROpenGL.h"
#include "vtkObject.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLHelper.h"
#include "vtkOpenGLPolyDataMapper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPointGaussianMapper.h"
#include "vtkProperty.h"
#include "vtkRenderState.h"
#include "vtkRenderWindow.h"
#include "vtkRenderbuffer.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <mutex>
#include <set>

vtkTextureObject* vtkNPRNewTexture(vtkOpenGLRenderWindow* window, int filter, int wrap)
{
  vtkTextureObject* texture = vtkTextureObject::New();
  texture->SetContext(window);
  texture->SetMinificationFilter(filter);
  texture->SetMagnificationFilter(filter);
  texture->SetWrapS(wrap);
  texture->SetWrapT(wrap);
  texture->SetWrapR(wrap);
  return texture;
}

std::string vtkNPRLowerCase(std::string text)
{
  std::transform(text.begin(), text.end(), text.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

double vtkNPRWindowScale(vtkRenderer* renderer)
{
  if (!renderer || !renderer->GetRenderWindow())
  {
    return 1.0;
  }
  vtkWindow* window = renderer->GetRenderWindow();
  return std::max(1, window->GetDPI()) / 72.0 *
    std::max(1, std::max(window->GetTileScale()[0], window->GetTileScale()[1]));
}

bool vtkNPRInsertAfterShaderTag(
  std::string& source, const char* vtkTag, const char* tag, vtkObject* pass, const char* stage)
{
  if (vtkShaderProgram::Substitute(
        source, vtkTag, std::string(vtkTag) + "\n  " + tag + "\n", false))
  {
    return true;
  }
  if (source.find("//VTK::Color::Impl") != std::string::npos)
  {
    static std::mutex mutex;
    static std::set<std::string> reported;
    const std::lock_guard<std::mutex> lock(mutex);
    if (reported.insert(std::string(pass->GetClassName()) + vtkTag).second)
    {
      vtkErrorWithObjectMacro(pass, << "the " << stage << " shader has no " << vtkTag
                                    << " tag: this VTK release changed its poly-data shader "
                                       "templates, so "
                                    << pass->GetClassName() << " cannot add its effect");
    }
  }
  return false;
}

bool vtkNPRRenderSelection(const vtkRenderState* state, int& renderedProps)
{
  vtkRenderer* renderer = state->GetRenderer();
  vtkHardwareSelector* selector = renderer->GetSelector();
  if (!selector)
  {
    return false;
  }
  renderedProps = selector->Render(renderer, state->GetPropArray(), state->GetPropArrayCount());
  return true;
}

void vtkNPRTargetSize(const vtkRenderState* state, int& width, int& height)
{
  if (state->GetFrameBuffer())
  {
    state->GetFrameBuffer()->GetLastSize(width, height);
    return;
  }
  int x, y;
  state->GetRenderer()->GetTiledSizeAndOrigin(&width, &height, &x, &y);
}

void vtkNPRViewportOrigin(const vtkRenderState* state, int origin[2])
{
  int width, height;
  state->GetRenderer()->GetTiledSizeAndOrigin(&width, &height, origin, origin + 1);
  if (state->GetFrameBuffer())
  {
    origin[0] = origin[1] = 0;
  }
}

void vtkNPRTilePlacement(vtkRenderer* renderer, int offset[2], int tileSides[4])
{
  const double* viewport = renderer->GetViewport();
  vtkWindow* window = renderer->GetVTKWindow();
  const double* tile = window->GetTileViewport();
  for (int axis = 0; axis < 2; ++axis)
  {
    // vtkWindow::GetSize is the whole image's size: the window's times the tile scale.
    const double pixels = std::max(1, window->GetSize()[axis]);
    const double tolerance = 0.5 / pixels; // less than a pixel of the whole image
    offset[axis] = static_cast<int>(
      std::lround((std::max(viewport[axis], tile[axis]) - viewport[axis]) * pixels));
    tileSides[axis] = tile[axis] > viewport[axis] + tolerance ? 1 : 0;
    tileSides[axis + 2] = tile[axis + 2] < viewport[axis + 2] - tolerance ? 1 : 0;
  }
}

vtkNPRCompositeState::vtkNPRCompositeState(vtkOpenGLState* state)
  : State(state)
  , Viewport(state)
  , DepthTest(state, GL_DEPTH_TEST)
  , Blend(state, GL_BLEND)
  , ScissorTest(state, GL_SCISSOR_TEST)
  , Scissor(state)
  , DepthFunc(state)
  , DepthMask(state)
  , BlendFunc(state)
{
}

void vtkNPRCompositeState::Apply(const int origin[2], int width, int height)
{
  this->State->vtkglViewport(origin[0], origin[1], width, height);
  this->State->vtkglScissor(origin[0], origin[1], width, height);
  this->State->vtkglEnable(GL_SCISSOR_TEST);
  this->State->vtkglEnable(GL_DEPTH_TEST);
  this->State->vtkglDepthFunc(GL_LEQUAL);
  this->State->vtkglDepthMask(GL_TRUE);
  this->State->vtkglEnable(GL_BLEND);
  this->State->vtkglBlendFuncSeparate(
    GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
}

double vtkNPREffectiveLineWidth(vtkRenderer* renderer, double width)
{
  return std::min(std::max(width * vtkNPRWindowScale(renderer), 0.5), 32.0);
}

namespace
{
// The primitive a mapper has bound is a protected member of VTK 9.1-9.6; a pointer to member taken
// through a derived class reads them.
struct nprMapperAccess : public vtkOpenGLPolyDataMapper
{
  static int BoundMode(vtkOpenGLPolyDataMapper* mapper, int representation)
  {
    vtkOpenGLHelper* vtkOpenGLPolyDataMapper::*bound = &nprMapperAccess::LastBoundBO;
    const vtkOpenGLHelper* helper = mapper->*bound;
    if (!helper)
    {
      return -1;
    }
    int (vtkOpenGLPolyDataMapper::*mode)(int, int) = &nprMapperAccess::GetOpenGLMode;
    return (mapper->*mode)(representation, helper->PrimitiveType);
  }
};

}

vtkProp* vtkNPRUserProp(vtkProp* prop)
{
  vtkProp* drawn = vtkNPROpaquePass::GetPropBeingDrawn();
  return drawn ? drawn : prop;
}

bool vtkNPRIsAnnotation(vtkProp* prop)
{
  if (!prop)
  {
    return false;
  }
  // vtkActor subclasses that annotate (their labels are followers, drawn through inner actors).
  for (const char* annotation :
    { "vtkFollower", "vtkProp3DFollower", "vtkCubeAxesActor", "vtkPolarAxesActor", "vtkAxisActor" })
  {
    if (prop->IsA(annotation))
    {
      return true;
    }
  }
  return !(prop->IsA("vtkActor") || prop->IsA("vtkAssembly") || prop->IsA("vtkPropAssembly") ||
    prop->IsA("vtkLODProp3D"));
}

bool vtkNPRDrawsSplats(vtkActor* actor)
{
  return vtkPointGaussianMapper::SafeDownCast(actor->GetMapper()) != nullptr;
}

bool vtkNPRDrawsMeshEdges(vtkProperty* property)
{
  return property->GetEdgeVisibility() && property->GetRepresentation() == VTK_SURFACE;
}

bool vtkNPRKeepsOwnLook(vtkAbstractMapper* mapper, vtkProp* prop)
{
  auto* polyDataMapper = vtkOpenGLPolyDataMapper::SafeDownCast(mapper);
  auto* actor = vtkActor::SafeDownCast(prop);
  if (!polyDataMapper || !actor)
  {
    return false;
  }
  if (vtkNPRIsAnnotation(vtkNPRUserProp(prop)) || vtkNPRDrawsSplats(actor))
  {
    return true;
  }
  const int mode =
    nprMapperAccess::BoundMode(polyDataMapper, actor->GetProperty()->GetRepresentation());
  return mode == GL_LINES || mode == GL_POINTS;
}

namespace
{
// What one attachment of the bound draw framebuffer holds.
int nprAttachmentParameter(unsigned int attachment, unsigned int parameter)
{
  GLint value = 0;
  glGetFramebufferAttachmentParameteriv(GL_DRAW_FRAMEBUFFER, attachment, parameter, &value);
  return value;
}

}

bool vtkNPRDrawFramebufferFormats(
  vtkOpenGLState* state, unsigned int& colorFormat, unsigned int& depthFormat)
{
  unsigned int binding = 0, drawBuffer = 0;
  state->GetCurrentDrawFramebufferState(binding, drawBuffer);
  GLint samples = 0;
  glGetIntegerv(GL_SAMPLES, &samples);
  if (samples > 0)
  {
    return false;
  }
  unsigned int colorAttachment = drawBuffer, depthAttachment = GL_DEPTH_ATTACHMENT;
  if (binding == 0)
  {
    colorAttachment = drawBuffer == GL_FRONT ? GL_FRONT_LEFT : GL_BACK_LEFT;
    depthAttachment = GL_DEPTH;
  }
  if (nprAttachmentParameter(colorAttachment, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE) == GL_NONE ||
    nprAttachmentParameter(depthAttachment, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE) == GL_NONE)
  {
    return false;
  }
  const int red = nprAttachmentParameter(colorAttachment, GL_FRAMEBUFFER_ATTACHMENT_RED_SIZE);
  const int green = nprAttachmentParameter(colorAttachment, GL_FRAMEBUFFER_ATTACHMENT_GREEN_SIZE);
  const int blue = nprAttachmentParameter(colorAttachment, GL_FRAMEBUFFER_ATTACHMENT_BLUE_SIZE);
  const int alpha = nprAttachmentParameter(colorAttachment, GL_FRAMEBUFFER_ATTACHMENT_ALPHA_SIZE);
  const int colorType =
    nprAttachmentParameter(colorAttachment, GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE);
  // sRGB: a blit would convert to linear and back.
  const int encoding =
    nprAttachmentParameter(colorAttachment, GL_FRAMEBUFFER_ATTACHMENT_COLOR_ENCODING);
  if (red != 8 || green != 8 || blue != 8 || (alpha != 8 && alpha != 0) ||
    colorType != GL_UNSIGNED_NORMALIZED || encoding != GL_LINEAR)
  {
    return false;
  }
  colorFormat = alpha == 8 ? GL_RGBA8 : GL_RGB8;
  const int depth = nprAttachmentParameter(depthAttachment, GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE);
  const int stencil =
    nprAttachmentParameter(depthAttachment, GL_FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE);
  const int depthType =
    nprAttachmentParameter(depthAttachment, GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE);
  if (depth == 32 && depthType == GL_FLOAT)
  {
    depthFormat = stencil == 8 ? GL_DEPTH32F_STENCIL8 : GL_DEPTH_COMPONENT32F;
  }
  else if (depth == 32 && stencil == 0 && depthType == GL_UNSIGNED_NORMALIZED)
  {
    depthFormat = GL_DEPTH_COMPONENT32; // VTK's own render framebuffer
  }
  else if (depth == 24 && depthType == GL_UNSIGNED_NORMALIZED)
  {
    depthFormat = stencil == 8 ? GL_DEPTH24_STENCIL8 : GL_DEPTH_COMPONENT24;
  }
  else if (depth == 16 && stencil == 0 && depthType == GL_UNSIGNED_NORMALIZED)
  {
    depthFormat = GL_DEPTH_COMPONENT16;
  }
  else
  {
    return false;
  }
  return stencil == 0 || stencil == 8;
}

bool vtkNPRBlitRectangle(vtkOpenGLState* state, const int rect[4], const int to[2], bool depth)
{
  vtkOpenGLState::ScopedglEnableDisable scissorTestSaver(state, GL_SCISSOR_TEST);
  state->vtkglDisable(GL_SCISSOR_TEST); // and so a plain memory copy where the driver has one
  while (glGetError() != GL_NO_ERROR)
  {
  }
  const int width = rect[2] - rect[0] + 1, height = rect[3] - rect[1] + 1;
  state->vtkglBlitFramebuffer(rect[0], rect[1], rect[2] + 1, rect[3] + 1, to[0], to[1],
    to[0] + width, to[1] + height, GL_COLOR_BUFFER_BIT | (depth ? GL_DEPTH_BUFFER_BIT : 0),
    GL_NEAREST);
  return glGetError() == GL_NO_ERROR;
}

vtkNPRKeptImage::~vtkNPRKeptImage()
{
  this->ReleaseGraphicsResources(nullptr);
}

bool vtkNPRKeptImage::Capture(vtkOpenGLRenderWindow* window, const int rect[4])
{
  this->Valid = false;
  vtkOpenGLState* state = window->GetState();
  unsigned int colorFormat = 0, depthFormat = 0;
  if (rect[2] < rect[0] || rect[3] < rect[1] ||
    !vtkNPRDrawFramebufferFormats(state, colorFormat, depthFormat))
  {
    return false;
  }
  unsigned int binding = 0, drawBuffer = 0;
  state->GetCurrentDrawFramebufferState(binding, drawBuffer);
  state->PushFramebufferBindings();
  const int width = rect[2] + 1, height = rect[3] + 1; // the copy stays at its place
  if (!this->Framebuffer || colorFormat != this->ColorFormat || depthFormat != this->DepthFormat ||
    width > this->Size[0] || height > this->Size[1])
  {
    this->ReleaseGraphicsResources(window);
    this->Framebuffer = vtkOpenGLFramebufferObject::New();
    this->Framebuffer->SetContext(window);
    this->Color = vtkRenderbuffer::New();
    this->Color->SetContext(window);
    this->Depth = vtkRenderbuffer::New();
    this->Depth->SetContext(window);
    if (!this->Color->Create(colorFormat, width, height) ||
      !this->Depth->Create(depthFormat, width, height))
    {
      this->ReleaseGraphicsResources(window);
      state->PopFramebufferBindings();
      return false;
    }
    this->Framebuffer->Bind();
    this->Framebuffer->AddColorAttachment(0, this->Color);
    this->Framebuffer->AddDepthAttachment(this->Depth);
    this->ColorFormat = colorFormat;
    this->DepthFormat = depthFormat;
    this->Size[0] = width;
    this->Size[1] = height;
  }
  state->vtkglBindFramebuffer(GL_READ_FRAMEBUFFER, binding);
  state->vtkglReadBuffer(drawBuffer);
  this->Framebuffer->Bind(GL_DRAW_FRAMEBUFFER);
  this->Framebuffer->ActivateDrawBuffer(0);
  this->Valid = vtkNPRBlitRectangle(state, rect, rect, true);
  state->PopFramebufferBindings();
  std::copy_n(rect, 4, this->Rect);
  return this->Valid;
}

bool vtkNPRKeptImage::Restore(vtkOpenGLRenderWindow* window)
{
  if (!this->Valid)
  {
    return false;
  }
  vtkOpenGLState* state = window->GetState();
  state->PushReadFramebufferBinding();
  this->Framebuffer->Bind(GL_READ_FRAMEBUFFER);
  this->Framebuffer->ActivateReadBuffer(0);
  this->Valid = vtkNPRBlitRectangle(state, this->Rect, this->Rect, true);
  state->PopReadFramebufferBinding();
  return this->Valid;
}

void vtkNPRKeptImage::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Valid = false;
  if (this->Framebuffer)
  {
    if (window)
    {
      this->Framebuffer->ReleaseGraphicsResources(window);
    }
    this->Framebuffer->Delete();
    this->Framebuffer = nullptr;
  }
  for (vtkRenderbuffer** buffer : { &this->Color, &this->Depth })
  {
    if (*buffer)
    {
      if (window)
      {
        (*buffer)->ReleaseGraphicsResources(window);
      }
      (*buffer)->Delete();
      *buffer = nullptr;
    }
  }
  this->Size[0] = this->Size[1] = 0;
}
