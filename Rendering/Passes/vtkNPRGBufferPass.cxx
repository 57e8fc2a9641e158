// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNPRGBufferPass.h"

#include "vtkCamera.h"
#include "vtkMatrix3x3.h"
#include "vtkMatrix4x4.h"
#include "vtkNPRFrameSignature.h"
#include "vtkNPROpenGL.h"
#include "vtkNPRPassUtilities.h"
#include "vtkNPRPropParts.h"
#include "vtkNPRShaderHook.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLCamera.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLPolyDataMapper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkProp.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include "vtkNPRCopyFS.h"
#include "vtkNPRDepthGeometryFS.h"
#include "vtkNPRGBufferDecl.h"
#include "vtkNPRGBufferImpl.h"
#include "vtkNPRPackNormal.h"
#include "vtkNPRQuadProgram.h"
#include "vtkNPRRenderTarget.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <utility>
#include <vector>

namespace
{
// `source` with the normal packing that the G-buffer output and the depth-only geometry share.
std::string WithPackNormal(const char* source)
{
  std::string text = source;
  vtkShaderProgram::Substitute(text, "//NPR::PackNormal", vtkNPRPackNormal);
  return text;
}

// The props the frame's mappers draw for: an assembly's parts each, in drawing order.
std::vector<vtkProp*> DrawnParts(const vtkRenderState* state)
{
  std::vector<vtkProp*> parts;
  for (int i = 0; i < state->GetPropArrayCount(); ++i)
  {
    for (const vtkNPRPropPart& part : vtkNPRPropParts(state->GetPropArray()[i]))
    {
      parts.push_back(part.Prop);
    }
  }
  return parts;
}
}

struct vtkNPRGBufferPass::Internals
{
  // Taken right after the last draw, so that what the draw itself touched counts as seen.
  vtkNPRFrameSignature Last;
  bool Valid = false;
  // The props drawn this frame, an assembly's parts each (its mappers' hooks see them); an
  // object id is the 1-based index of its prop here.
  std::vector<vtkProp*> FrameProps;
  // Depth-only mode: geometry from depth, and the copy back into the caller's framebuffer.
  vtkNPRQuadProgram DepthGeometry;
  vtkNPRQuadProgram Copy;
  vtkNPRRenderTarget Target;
  // The depth attachment's internal format.
  unsigned int DepthFormat = GL_DEPTH_COMPONENT32F;
  // This frame's colour started from the image of this draw framebuffer under the viewport at
  // this origin (WindowImageRequested); the framebuffer CopySurfacesBack() reads it from.
  bool HoldsWindowImage = false;
  unsigned int WindowFramebuffer = 0;
  unsigned int WindowDrawBuffer = 0;
  int WindowOrigin[2] = { 0, 0 };
  vtkNew<vtkOpenGLFramebufferObject> CopyBackSource;
  // The shaders with the shared normal packing in place.
  const std::string Decl = WithPackNormal(vtkNPRGBufferDecl);
  const std::string DepthGeometrySource = WithPackNormal(vtkNPRDepthGeometryFS);
};

vtkStandardNewMacro(vtkNPRGBufferPass);

// Our code after lighting, where the normal and position are in scope.
vtkNPRGBufferPass::vtkNPRGBufferPass()
  : vtkNPRGeometryPass("GBuffer", "//VTK::Light::Impl", "the G-buffer output")
  , Internal(new Internals)
{
  this->InverseProjection = vtkMatrix4x4::New();
  this->ShaderStageTime.Modified();
}

vtkNPRGBufferPass::~vtkNPRGBufferPass()
{
  this->InverseProjection->Delete();
  // Texture and framebuffer objects free their OpenGL names through the window's resource
  // callbacks when their context is still alive.
  for (vtkObject* object :
    { static_cast<vtkObject*>(this->ColorTexture), static_cast<vtkObject*>(this->GeometryTexture),
      static_cast<vtkObject*>(this->DepthTexture) })
  {
    if (object)
    {
      object->Delete();
    }
  }
}

namespace
{
vtkTextureObject* NewNearestTexture(vtkOpenGLRenderWindow* window)
{
  return vtkNPRNewTexture(window, vtkTextureObject::Nearest, vtkTextureObject::ClampToEdge);
}

// vtkTextureObject's name of a depth format that ChooseDepthFormat() gives.
int DepthTextureFormat(unsigned int depthFormat)
{
  switch (depthFormat)
  {
    case GL_DEPTH_COMPONENT16:
      return vtkTextureObject::Fixed16;
    case GL_DEPTH_COMPONENT24:
      return vtkTextureObject::Fixed24;
    case GL_DEPTH_COMPONENT32:
      return vtkTextureObject::Fixed32;
    default:
      return vtkTextureObject::Float32;
  }
}

// Above this far/near ratio the depth attachment holds log depth (see GetDepthRemapped()).
constexpr double MaximumPlainDepthRatio = 1e4;

// The geometry attachment's format for an encoding and a number of components.
struct GeometryFormat
{
  unsigned int InternalFormat;
  unsigned int Format;
  int DataType; // VTK type of the allocation
};
GeometryFormat GetGeometryFormat(int encoding, int components)
{
  switch (encoding)
  {
    case vtkNPRGBufferPass::HALF:
      return components == 1 ? GeometryFormat{ GL_R16F, GL_RED, VTK_FLOAT }
                             : GeometryFormat{ GL_RGBA16F, GL_RGBA, VTK_FLOAT };
    case vtkNPRGBufferPass::PACKED8:
      return { GL_R8, GL_RED, VTK_UNSIGNED_CHAR };
    case vtkNPRGBufferPass::PACKED16:
      return { GL_R16, GL_RED, VTK_UNSIGNED_SHORT };
    default:
      return components == 1 ? GeometryFormat{ GL_R32F, GL_RED, VTK_FLOAT }
        : components == 2    ? GeometryFormat{ GL_RG32F, GL_RG, VTK_FLOAT }
                             : GeometryFormat{ GL_RGBA32F, GL_RGBA, VTK_FLOAT };
  }
}
}

void vtkNPRGBufferPass::AllocateBuffers(vtkOpenGLRenderWindow* window, int width, int height,
  int components, int encoding, unsigned int depthFormat)
{
  if (!this->ColorTexture)
  {
    this->ColorTexture = NewNearestTexture(window);
    this->ColorTexture->Allocate2D(width, height, 4, VTK_UNSIGNED_CHAR);
  }
  if (this->DepthTexture && depthFormat != this->Internal->DepthFormat)
  {
    this->DepthTexture->ReleaseGraphicsResources(window);
    this->DepthTexture->Delete();
    this->DepthTexture = nullptr;
  }
  if (!this->DepthTexture)
  {
    this->DepthTexture = NewNearestTexture(window);
    this->DepthTexture->AllocateDepth(width, height, DepthTextureFormat(depthFormat));
    this->Internal->DepthFormat = depthFormat;
  }
  const GeometryFormat format = GetGeometryFormat(encoding, components);
  if (this->GeometryTexture &&
    static_cast<unsigned int>(this->GeometryTexture->GetInternalFormat(
      format.DataType, components, false)) != format.InternalFormat)
  {
    this->GeometryTexture->ReleaseGraphicsResources(window);
    this->GeometryTexture->Delete();
    this->GeometryTexture = nullptr;
  }
  if (!this->GeometryTexture)
  {
    this->GeometryTexture = NewNearestTexture(window);
    this->GeometryTexture->SetInternalFormat(format.InternalFormat);
    this->GeometryTexture->SetFormat(format.Format);
    this->GeometryTexture->Allocate2D(width, height,
      format.Format == GL_RGBA ? 4 : (format.Format == GL_RG ? 2 : 1), format.DataType);
  }
  // Resize() does nothing when the size is unchanged.
  this->ColorTexture->Resize(width, height);
  this->DepthTexture->Resize(width, height);
  this->GeometryTexture->Resize(width, height);
}

vtkMTimeType vtkNPRGBufferPass::GetSettingsTime()
{
  // The delegate's settings change the image too (vtkNPRToonPass: bands, table).
  return std::max(this->GetMTime(), this->DelegatePass ? this->DelegatePass->GetMTime() : 0);
}

bool vtkNPRGBufferPass::SceneUnchanged(const vtkRenderState* state, int width, int height)
{
  if (!this->Internal->Valid || !this->ReuseUnchangedFrames || !this->HasContent)
  {
    return false;
  }
  return vtkNPRTakeFrameSignature(state, width, height, this->WritesNormals, this->WritesObjectIds,
           this->GetSettingsTime()) == this->Internal->Last;
}

void vtkNPRGBufferPass::ComputeContentRectangle(const vtkRenderState* state, int width, int height)
{
  vtkNPRScreenRectangleOfProps(state, width, height, this->ContentRectangle);
}

const char* vtkNPRGBufferPass::GetEncodingName(int encoding)
{
  switch (encoding)
  {
    case FLOAT:
      return "float";
    case HALF:
      return "half";
    case PACKED8:
      return "packed8";
    case PACKED16:
      return "packed16";
    default:
      return "unknown";
  }
}

int vtkNPRGBufferPass::GetEncodingFromName(const char* name)
{
  for (int encoding = FLOAT; name && encoding <= PACKED16; ++encoding)
  {
    if (strcmp(name, GetEncodingName(encoding)) == 0)
    {
      return encoding;
    }
  }
  return -1;
}

void vtkNPRGBufferPass::Render(const vtkRenderState* state)
{
  this->Internal->HoldsWindowImage = false; // until this frame's draw copies it in
  if (!this->StartRender(state))
  {
    return; // no delegate, or a picking render: no G-buffer
  }
  int width = 0, height = 0;
  vtkNPRTargetSize(state, width, height);
  if (this->DepthOnly)
  {
    this->RenderDepthOnly(state, width, height);
    return;
  }
  std::vector<vtkProp*> parts = DrawnParts(state);
  const int opaqueProps = CountOpaqueProps(parts);
  if (opaqueProps == 0)
  {
    // Nothing to draw: no buffers, no effects.
    this->HasContent = false;
    this->Internal->Valid = false;
    return;
  }
  this->UpdateOutputs(opaqueProps);
  if (width < 1 || height < 1)
  {
    this->HasContent = false;
    return;
  }
  if (this->SceneUnchanged(state, width, height))
  {
    this->NumberOfRenderedProps = opaqueProps;
    return;
  }
  auto* window = static_cast<vtkOpenGLRenderWindow*>(state->GetRenderer()->GetRenderWindow());
  const int components =
    this->WritesObjectIds || this->WritesFaceNormals ? 4 : (this->WritesNormals ? 2 : 1);
  this->UpdateProjection(state->GetRenderer(), width, height, true);
  bool windowImage = false;
  const unsigned int depthFormat = this->ChooseDepthFormat(state, windowImage);
  this->AllocateBuffers(window, width, height, components, this->WrittenEncoding, depthFormat);
  this->ComputeContentRectangle(state, width, height);
  this->Internal->FrameProps = std::move(parts);
  this->DrawGeometry(state, width, height, windowImage);
  this->Internal->Last = vtkNPRTakeFrameSignature(
    state, width, height, this->WritesNormals, this->WritesObjectIds, this->GetSettingsTime());
  this->Internal->Valid = true;
  vtkOpenGLCheckErrorMacro("failed after vtkNPRGBufferPass::Render");
}

int vtkNPRGBufferPass::CountOpaqueProps(const std::vector<vtkProp*>& parts)
{
  int opaqueProps = 0;
  for (vtkProp* part : parts)
  {
    opaqueProps += part->HasOpaqueGeometry() ? 1 : 0;
  }
  return opaqueProps;
}

void vtkNPRGBufferPass::UpdateOutputs(int opaqueProps)
{
  const int encoding = this->GeometryEncoding;
  const bool packed = encoding == PACKED8 || encoding == PACKED16;
  const bool normals = this->NormalsRequested;
  const bool ids = this->ObjectIdsRequested && opaqueProps > 1 && !packed;
  const bool faceNormals = normals && this->FaceNormalsRequested && encoding == FLOAT;
  this->SetOutputs(normals, ids, faceNormals, encoding);
}

void vtkNPRGBufferPass::SetOutputs(bool normals, bool ids, bool faceNormals, int encoding)
{
  if (normals != this->WritesNormals || ids != this->WritesObjectIds ||
    faceNormals != this->WritesFaceNormals || encoding != this->WrittenEncoding)
  {
    this->WritesNormals = normals;
    this->WritesFaceNormals = faceNormals;
    this->WritesObjectIds = ids;
    this->WrittenEncoding = encoding;
    this->ShaderStageTime.Modified(); // the mappers rebuild their shaders with the new outputs
  }
}

void vtkNPRGBufferPass::UpdateProjection(
  vtkRenderer* renderer, int width, int height, bool mayRemapDepth)
{
  this->Viewport[0] = 0.0f;
  this->Viewport[1] = 0.0f;
  this->Viewport[2] = 1.0f / width;
  this->Viewport[3] = 1.0f / height;
  vtkMatrix4x4 *worldToView, *viewToDevice, *worldToDevice;
  vtkMatrix3x3* normalMatrix;
  vtkCamera* camera = renderer->GetActiveCamera();
  static_cast<vtkOpenGLCamera*>(camera)->GetKeyMatrices(
    renderer, worldToView, normalMatrix, viewToDevice, worldToDevice);
  vtkMatrix4x4::Invert(viewToDevice, this->InverseProjection); // stays in GLSL's layout
  if (this->Perspective == static_cast<bool>(camera->GetParallelProjection()))
  {
    this->Perspective = !camera->GetParallelProjection();
    this->ShaderStageTime.Modified(); // compiled into the shaders
  }
  const double* clippingRange = camera->GetClippingRange();
  this->PackedDepthRange[0] = static_cast<float>(clippingRange[0]);
  this->PackedDepthRange[1] = static_cast<float>(clippingRange[1]);
  const bool remap = mayRemapDepth && this->Perspective && clippingRange[0] > 0.0 &&
    clippingRange[1] > MaximumPlainDepthRatio * clippingRange[0];
  if (remap != this->DepthRemapped)
  {
    this->DepthRemapped = remap;
    this->ShaderStageTime.Modified();
  }
  this->DepthRemap[0] = static_cast<float>(clippingRange[0]);
  this->DepthRemap[1] = static_cast<float>(std::log(clippingRange[1] / clippingRange[0]));
}

void vtkNPRGBufferPass::DrawGeometry(
  const vtkRenderState* state, int width, int height, bool windowImage)
{
  auto* window = static_cast<vtkOpenGLRenderWindow*>(state->GetRenderer()->GetRenderWindow());
  unsigned int framebuffer = 0, drawBuffer = 0; // the one the effects draw into after this
  window->GetState()->GetCurrentDrawFramebufferState(framebuffer, drawBuffer);
  int origin[2];
  vtkNPRViewportOrigin(state, origin);
  this->HasLinePrimitives = false; // SetShaderParameters() sees them
  this->PreRender(state);          // the mappers now call this pass's shader hooks
  {
    vtkNPRRenderTarget::Scope target(this->Internal->Target, window,
      { this->ColorTexture, this->GeometryTexture }, this->DepthTexture, width, height);
    target.Clear(0.0, 0.0, 0.0, 0.0); // geometry depth 0 = background
    this->Internal->HoldsWindowImage =
      windowImage && this->CopyWindowImageIn(window->GetState(), framebuffer, drawBuffer, origin);
    this->DelegatePass->Render(state);
    this->NumberOfRenderedProps = this->DelegatePass->GetNumberOfRenderedProps();
  }
  this->PostRender(state);
  this->HasContent = true;
  ++this->NumberOfGeometryDraws;
  ++this->ContentVersion;
}

unsigned int vtkNPRGBufferPass::ChooseDepthFormat(
  const vtkRenderState* state, bool& windowImage) const
{
  windowImage = false;
  vtkRenderer* renderer = state->GetRenderer();
  auto* window = static_cast<vtkOpenGLRenderWindow*>(renderer->GetRenderWindow());
  unsigned int colorFormat = 0, depthFormat = 0;
  if (this->DepthRemapped ||
    !vtkNPRDrawFramebufferFormats(window->GetState(), colorFormat, depthFormat))
  {
    return GL_DEPTH_COMPONENT32F;
  }
  switch (depthFormat)
  {
    case GL_DEPTH_COMPONENT16:
    case GL_DEPTH_COMPONENT24:
    case GL_DEPTH_COMPONENT32:
    case GL_DEPTH_COMPONENT32F:
      break;
    default:
      return GL_DEPTH_COMPONENT32F; // with stencil: no texture format of vtkTextureObject's
  }
  // The copy back is exact only over the far plane the renderer's clear leaves.
  windowImage = this->WindowImageRequested && colorFormat == GL_RGBA8 && renderer->GetErase() &&
    !renderer->GetPreserveDepthBuffer();
  return depthFormat;
}

bool vtkNPRGBufferPass::CopyWindowImageIn(
  vtkOpenGLState* state, unsigned int framebuffer, unsigned int buffer, const int origin[2])
{
  Internals& internal = *this->Internal;
  const int* rect = this->ContentRectangle; // the copy back covers no more
  if (rect[2] < rect[0] || rect[3] < rect[1])
  {
    return false;
  }
  const int from[4] = { origin[0] + rect[0], origin[1] + rect[1], origin[0] + rect[2],
    origin[1] + rect[3] };
  state->PushReadFramebufferBinding();
  state->vtkglBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer);
  state->vtkglReadBuffer(buffer);
  internal.Target.DrawInto(state, 1, 2); // the colour attachment alone
  const bool copied = vtkNPRBlitRectangle(state, from, rect, false);
  internal.Target.DrawInto(state, 2, 2);
  state->PopReadFramebufferBinding();
  internal.WindowFramebuffer = framebuffer;
  internal.WindowDrawBuffer = buffer;
  std::copy_n(origin, 2, internal.WindowOrigin);
  return copied;
}

bool vtkNPRGBufferPass::GetHoldsWindowImage() const
{
  return this->HasContent && this->Internal->HoldsWindowImage;
}

bool vtkNPRGBufferPass::CopySurfacesBack(vtkOpenGLRenderWindow* window, const int origin[2])
{
  Internals& internal = *this->Internal;
  vtkOpenGLState* state = window->GetState();
  unsigned int framebuffer = 0, drawBuffer = 0;
  state->GetCurrentDrawFramebufferState(framebuffer, drawBuffer);
  if (!this->GetHoldsWindowImage() || framebuffer != internal.WindowFramebuffer ||
    drawBuffer != internal.WindowDrawBuffer || origin[0] != internal.WindowOrigin[0] ||
    origin[1] != internal.WindowOrigin[1])
  {
    return false;
  }
  const int* rect = this->ContentRectangle; // where CopyWindowImageIn() put the window's image
  vtkOpenGLFramebufferObject* source = internal.CopyBackSource;
  source->SetContext(window);
  state->PushReadFramebufferBinding();
  source->Bind(GL_READ_FRAMEBUFFER); // attachments go to the binding it has
  source->AddColorAttachment(0, this->ColorTexture);
  source->AddDepthAttachment(this->DepthTexture);
  source->ActivateReadBuffer(0);
  const int to[2] = { origin[0] + rect[0], origin[1] + rect[1] };
  const bool copied = vtkNPRBlitRectangle(state, rect, to, true);
  source->RemoveColorAttachment(0); // holds no texture between frames
  source->RemoveDepthAttachment();
  state->PopReadFramebufferBinding();
  return copied;
}

void vtkNPRGBufferPass::RenderDepthOnly(const vtkRenderState* state, int width, int height)
{
  this->Internal->Valid = false;   // a depth-only frame is never reused, nor a later one from it
  this->HasLinePrimitives = false; // drawn by the delegate, with the rest
  if (width < 1 || height < 1)
  {
    this->HasContent = false;
    return;
  }
  vtkRenderer* renderer = state->GetRenderer();
  auto* window = static_cast<vtkOpenGLRenderWindow*>(renderer->GetRenderWindow());
  // The rebuilt normals are face normals; no ids.
  this->SetOutputs(true, false, false, FLOAT);
  this->AllocateBuffers(window, width, height, 2, FLOAT, GL_DEPTH_COMPONENT32F);
  this->ContentRectangle[0] = this->ContentRectangle[1] = 0;
  this->ContentRectangle[2] = width - 1;
  this->ContentRectangle[3] = height - 1;
  this->Internal->FrameProps.clear();
  {
    // The delegate draws colour and depth (no shader hooks).
    vtkNPRRenderTarget::Scope target(
      this->Internal->Target, window, { this->ColorTexture }, this->DepthTexture, width, height);
    target.Clear(0.0, 0.0, 0.0, 0.0);
    this->DelegatePass->Render(state);
    this->NumberOfRenderedProps = this->DelegatePass->GetNumberOfRenderedProps();
  }
  // The delegate set the camera: the projection it drew with; it wrote the usual depth.
  this->UpdateProjection(renderer, width, height, false);
  this->DeriveGeometryFromDepth(window, width, height);
  this->CopyBack(state, width, height);
  this->HasContent = true;
  ++this->NumberOfGeometryDraws;
  ++this->ContentVersion;
  vtkOpenGLCheckErrorMacro("failed after vtkNPRGBufferPass::RenderDepthOnly");
}

void vtkNPRGBufferPass::DeriveGeometryFromDepth(
  vtkOpenGLRenderWindow* window, int width, int height)
{
  vtkShaderProgram* program =
    this->Internal->DepthGeometry.Ready(window, this->Internal->DepthGeometrySource, "");
  if (!program)
  {
    vtkErrorMacro("the depth-only geometry shader did not compile");
    return;
  }
  vtkNPRRenderTarget::Scope target(
    this->Internal->Target, window, { this->GeometryTexture }, nullptr, width, height);
  this->DepthTexture->Activate();
  program->SetUniformi("depthTexture", this->DepthTexture->GetTextureUnit());
  program->SetUniformMatrix("inverseProjection", this->InverseProjection);
  this->Internal->DepthGeometry.Render();
  this->DepthTexture->Deactivate();
}

void vtkNPRGBufferPass::CopyBack(const vtkRenderState* state, int width, int height)
{
  auto* window = static_cast<vtkOpenGLRenderWindow*>(state->GetRenderer()->GetRenderWindow());
  vtkShaderProgram* copy = this->Internal->Copy.Ready(window, vtkNPRCopyFS, "");
  if (!copy)
  {
    vtkErrorMacro("the depth-only copy shader did not compile");
    return;
  }
  vtkOpenGLState* glState = window->GetState();
  int origin[2];
  vtkNPRViewportOrigin(state, origin);
  vtkNPRCompositeState compositeState(glState);
  compositeState.Apply(origin, width, height);
  // Replaces what is there, as the delegate drawing here would have: nobody cleared it.
  glState->vtkglDisable(GL_BLEND);
  glState->vtkglDepthFunc(GL_ALWAYS);
  this->ColorTexture->Activate();
  this->DepthTexture->Activate();
  copy->SetUniformi("colorTexture", this->ColorTexture->GetTextureUnit());
  copy->SetUniformi("depthTexture", this->DepthTexture->GetTextureUnit());
  this->Internal->Copy.Render();
  this->ColorTexture->Deactivate();
  this->DepthTexture->Deactivate();
}

void vtkNPRGBufferPass::FillShaderCode(std::string& vertexShader, std::string& geometryShader,
  std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop)
{
  if (vtkNPRKeepsOwnLook(mapper, prop))
  {
    // Not geometry: drawn after the effect (vtkNPRPass), so left out here.
    this->Hook->Fill(fragmentShader, "", "  discard;\n");
    return;
  }
  const std::string defines = vtkNPRShaderHook::Defines({
    { "NPR_WRITE_NORMALS", this->WritesNormals },
    { "NPR_WRITE_OBJECT_IDS", this->WritesObjectIds },
    { "NPR_WRITE_FACE_NORMALS", this->WritesFaceNormals },
    { "NPR_HAVE_MAPPER_NORMAL", fragmentShader.find("normalVCVSOutput") != std::string::npos },
    { "NPR_HAVE_VERTEX_VC", fragmentShader.find("in vec4 vertexVCVSOutput;") != std::string::npos },
    { "NPR_ENCODING", this->WrittenEncoding },
    { "NPR_REMAPPED_DEPTH", this->DepthRemapped },
    { "NPR_PERSPECTIVE", this->Perspective },
  });
  // If not: colour and depth as VTK draws them; the effects see what it covers as background.
  this->Hook->Apply(this, prop, { vertexShader, geometryShader, fragmentShader },
    defines + this->Internal->Decl, vtkNPRGBufferImpl);
}

bool vtkNPRGBufferPass::SetShaderParameters(
  vtkShaderProgram* program, vtkAbstractMapper* mapper, vtkProp* prop, vtkOpenGLVertexArrayObject*)
{
  vtkOpenGLFramebufferObject* framebuffer = this->Internal->Target.GetFramebuffer();
  if (!framebuffer)
  {
    return true;
  }
  if (vtkOpenGLPolyDataMapper::SafeDownCast(mapper))
  {
    this->HasLinePrimitives = this->HasLinePrimitives || vtkNPRKeepsOwnLook(mapper, prop);
    framebuffer->ActivateDrawBuffers(2);
    // The compiler drops the uniforms a variant does not read.
    if (program->IsUniformUsed("nprObjectId"))
    {
      const std::vector<vtkProp*>& props = this->Internal->FrameProps;
      const auto found = std::find(props.begin(), props.end(), prop);
      program->SetUniformf("nprObjectId",
        static_cast<float>(found - props.begin() + 1)); // props.size() + 1 when not found
    }
    if (program->IsUniformUsed("nprInverseProjection"))
    {
      program->SetUniformMatrix("nprInverseProjection", this->InverseProjection);
    }
    if (program->IsUniformUsed("nprViewport"))
    {
      program->SetUniform4f("nprViewport", this->Viewport);
    }
    if (program->IsUniformUsed("nprDepthRange"))
    {
      program->SetUniform2f("nprDepthRange", this->PackedDepthRange);
    }
    if (program->IsUniformUsed("nprDepthRemap"))
    {
      program->SetUniform2f("nprDepthRemap", this->DepthRemap);
    }
  }
  else
  {
    // Mappers without the G-buffer outputs write colour and depth only.
    framebuffer->ActivateDrawBuffers(1);
  }
  return true;
}

void vtkNPRGBufferPass::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Superclass::ReleaseGraphicsResources(window);
  for (vtkTextureObject** texture :
    { &this->ColorTexture, &this->GeometryTexture, &this->DepthTexture })
  {
    if (*texture)
    {
      (*texture)->ReleaseGraphicsResources(window);
      (*texture)->Delete();
      *texture = nullptr;
    }
  }
  this->Internal->Target.ReleaseGraphicsResources(window);
  this->Internal->CopyBackSource->ReleaseGraphicsResources(window);
  this->Internal->HoldsWindowImage = false;
  this->Internal->DepthGeometry.Release(window);
  this->Internal->Copy.Release(window);
  this->HasContent = false;
  this->Internal->Valid = false;
}

void vtkNPRGBufferPass::GetPixelCentrePoints(double nearPoints[3][3], double farPoints[3][3]) const
{
  // The inverse projection is kept in GLSL's layout: element (i, j) multiplies component i.
  auto unproject = [this](double x, double y, double z, double point[3])
  {
    double h[4];
    for (int j = 0; j < 4; ++j)
    {
      h[j] = this->InverseProjection->GetElement(0, j) * x +
        this->InverseProjection->GetElement(1, j) * y +
        this->InverseProjection->GetElement(2, j) * z + this->InverseProjection->GetElement(3, j);
    }
    for (int j = 0; j < 3; ++j)
    {
      point[j] = h[j] / h[3];
    }
  };
  // The centres of pixels (0, 0), (1, 0) and (0, 1): a ray's points there are affine in the pixel.
  const double centres[3][2] = { { 0.5, 0.5 }, { 1.5, 0.5 }, { 0.5, 1.5 } };
  for (int c = 0; c < 3; ++c)
  {
    const double x = 2.0 * centres[c][0] * this->Viewport[2] - 1.0;
    const double y = 2.0 * centres[c][1] * this->Viewport[3] - 1.0;
    unproject(x, y, -1.0, nearPoints[c]);
    unproject(x, y, 1.0, farPoints[c]);
  }
}

void vtkNPRGBufferPass::GetViewRay(float origin[3], float perPixelX[3], float perPixelY[3]) const
{
  double nearPoints[3][3], farPoints[3][3], rays[3][3];
  this->GetPixelCentrePoints(nearPoints, farPoints);
  for (int c = 0; c < 3; ++c)
  {
    for (int j = 0; j < 3; ++j)
    {
      rays[c][j] = this->Perspective ? nearPoints[c][j] : farPoints[c][j] - nearPoints[c][j];
    }
  }
  for (int j = 0; j < 3; ++j)
  {
    origin[j] = static_cast<float>(rays[0][j]);
    perPixelX[j] = static_cast<float>(rays[1][j] - rays[0][j]);
    perPixelY[j] = static_cast<float>(rays[2][j] - rays[0][j]);
  }
}

void vtkNPRGBufferPass::GetViewPixelStep(float stepX[3], float stepY[3]) const
{
  double nearPoints[3][3], farPoints[3][3];
  this->GetPixelCentrePoints(nearPoints, farPoints);
  for (int j = 0; j < 3; ++j)
  {
    stepX[j] = static_cast<float>(nearPoints[1][j] - nearPoints[0][j]);
    stepY[j] = static_cast<float>(nearPoints[2][j] - nearPoints[0][j]);
  }
}

void vtkNPRGBufferPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NormalsRequested: " << this->NormalsRequested << "\n";
  os << indent << "ObjectIdsRequested: " << this->ObjectIdsRequested << "\n";
  os << indent << "FaceNormalsRequested: " << this->FaceNormalsRequested << "\n";
  os << indent << "GeometryEncoding: " << this->GeometryEncoding << "\n";
  os << indent << "DepthOnly: " << this->DepthOnly << "\n";
  os << indent << "WindowImageRequested: " << this->WindowImageRequested << "\n";
  os << indent << "ReuseUnchangedFrames: " << this->ReuseUnchangedFrames << "\n";
  os << indent << "WritesNormals: " << this->WritesNormals << "\n";
  os << indent << "WritesFaceNormals: " << this->WritesFaceNormals << "\n";
  os << indent << "WritesObjectIds: " << this->WritesObjectIds << "\n";
  os << indent << "NumberOfGeometryDraws: " << this->NumberOfGeometryDraws << "\n";
}
