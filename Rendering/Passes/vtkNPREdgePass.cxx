// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNPREdgePass.h"

#include "vtkMath.h"
#include "vtkNPRGBufferPass.h"
#include "vtkNPROpenGL.h"
#include "vtkNPRPassUtilities.h"
#include "vtkNPRQuadProgram.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTexture.h"
#include "vtkTextureObject.h"
#include "vtkVersionMacros.h"

#include "vtkNPREdgeCompositeFS.h"
#include "vtkNPREdgeDetectFS.h"
#include "vtkNPRLineColor.h"
#include "vtkNPRNearestDepth.h"
#include "vtkNPRWindowDepth.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

namespace
{
// Gaussian filter of the line image as bilinear taps, and the coverage mapping of its result.
struct LineFilter
{
  std::vector<float> Taps; // x, y, weight
  int Radius = 1;          // texels
  float CoverageLevel = 0.5f;
  float CoverageSlope = 1.0f;
  double Width = -1.0; // the width the taps were computed for

  void Compute(double width)
  {
    if (width == this->Width)
    {
      return;
    }
    this->Width = width;
    const double sigma = std::max(0.6, 0.3 * width);
    this->Radius = std::max(1, static_cast<int>(std::floor(0.5 * width + 0.5)));
    std::vector<double> g(this->Radius + 2, 0.0);
    double sum = 0.0;
    for (int j = 0; j <= this->Radius; ++j)
    {
      g[j] = std::exp(-j * j / (2.0 * sigma * sigma));
      sum += j == 0 ? g[j] : 2.0 * g[j];
    }
    for (double& value : g)
    {
      value /= sum;
    }
    // One dimension: offsets and weights of bilinear taps reproducing the discrete kernel.
    std::vector<std::pair<double, double>> taps1D;
    if (this->Radius == 1)
    {
      // [a b a] = two taps at +-2a of weight 1/2.
      taps1D = { { -2.0 * g[1], 0.5 }, { 2.0 * g[1], 0.5 } };
    }
    else
    {
      taps1D.push_back({ 0.0, g[0] });
      for (int i = 1; i <= this->Radius; i += 2)
      {
        const double weight = g[i] + g[i + 1];
        const double offset = i + g[i + 1] / weight;
        taps1D.push_back({ offset, weight });
        taps1D.push_back({ -offset, weight });
      }
    }
    this->Taps.clear();
    for (const auto& y : taps1D)
    {
      for (const auto& x : taps1D)
      {
        this->Taps.insert(this->Taps.end(),
          { static_cast<float>(x.first), static_cast<float>(y.first),
            static_cast<float>(x.second * y.second) });
      }
    }
    // Across a one-pixel line the filtered value is P(d) = g(d): coverage is P's level set at d =
    // width / 2, with the slope there giving one pixel of anti-aliasing.
    const double half = 0.5 * width;
    const double level = std::exp(-half * half / (2.0 * sigma * sigma)) / sum;
    this->CoverageLevel = static_cast<float>(level);
    // No coverage where there is no line at all: 0.5 - level / slope < 0.
    this->CoverageSlope = static_cast<float>(std::min(half / (sigma * sigma), 1.95) * level);
  }
};
}

struct vtkNPREdgePass::Internals
{
  vtkNPRQuadProgram Detect;
  vtkNPRQuadProgram Composite; // lines over the colour, or the mask
  vtkNPRQuadProgram Coverage;  // each type's coverage and depth, for vtkNPRSketchPass
  std::string CompositeSource;
  vtkOpenGLFramebufferObject* Framebuffer = nullptr;
  vtkTextureObject* LineTexture = nullptr;
  // What the line image was computed from: the G-buffer's content and the detection settings
  // (colours, width, anti-aliasing and CoverageOnly only change the composite).
  unsigned long LineImageVersion = 0;
  std::string LineImageSettings;
  bool LineImageValid = false;
  bool WarnedAboutEncoding = false;
  LineFilter Filter;
  // The last composite, for frames in which nothing changed (KeepUnchangedComposite).
  vtkNPRKeptImage Kept;
  std::string CompositeKey; // what the last composite was drawn from; empty: not reusable
  int FramesSinceUnchanged = KeepAfterUnchanged + 1;
  // Keep a changed frame's composite while one of this many previous frames was unchanged.
  static constexpr int KeepAfterUnchanged = 8;
};

vtkStandardNewMacro(vtkNPREdgePass);
vtkCxxSetObjectMacro(vtkNPREdgePass, GBufferPass, vtkNPRGBufferPass);

vtkNPREdgePass::vtkNPREdgePass()
  : Internal(new Internals)
{
}

vtkNPREdgePass::~vtkNPREdgePass()
{
  this->SetGBufferPass(nullptr);
  if (this->Internal->LineTexture)
  {
    this->Internal->LineTexture->Delete();
  }
  if (this->Internal->Framebuffer)
  {
    this->Internal->Framebuffer->Delete();
  }
}

const char* vtkNPREdgePass::GetEncodingName(int encoding)
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

int vtkNPREdgePass::GetEncodingFromName(const char* name)
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

double vtkNPREdgePass::GetEffectiveLineWidth(vtkRenderer* renderer) const
{
  return vtkNPREffectiveLineWidth(renderer, this->LineWidth);
}

void vtkNPREdgePass::Render(const vtkRenderState* state)
{
  this->Draw(state, this->CoverageOnly ? OutputMask : OutputComposite);
}

void vtkNPREdgePass::RenderLineCoverage(const vtkRenderState* state)
{
  this->Draw(state, OutputLineCoverage);
}

void vtkNPREdgePass::Draw(const vtkRenderState* state, int output)
{
  vtkOpenGLClearErrorMacro();
  this->NumberOfRenderedProps = 0;
  vtkNPRGBufferPass* gbuffer = this->GBufferPass;
  if (!gbuffer || gbuffer->GetLastRenderWasSelection() || !gbuffer->GetHasContent())
  {
    return; // a picking render, or nothing was drawn
  }
  vtkRenderer* renderer = state->GetRenderer();
  auto* window = static_cast<vtkOpenGLRenderWindow*>(renderer->GetRenderWindow());
  vtkOpenGLState* glState = window->GetState();
  Internals& internal = *this->Internal;
  vtkTextureObject* geometry = gbuffer->GetGeometryTexture();
  const int width = geometry->GetWidth();
  const int height = geometry->GetHeight();
  const bool lines = this->GetDrawsLines();

  // ---- Step 1: the one-pixel line image, recomputed only when its inputs changed ----
  const int encoding = gbuffer->GetWrittenEncoding();
  if (encoding != this->Encoding && !internal.WarnedAboutEncoding)
  {
    vtkWarningMacro("the G-buffer holds the "
      << GetEncodingName(encoding) << " encoding, not the edge pass's "
      << GetEncodingName(this->Encoding) << ": set its GeometryEncoding to match");
    internal.WarnedAboutEncoding = true;
  }
  const bool packed = encoding == PACKED8 || encoding == PACKED16;
  // n.v at each tap, for the smooth silhouettes and the suggestive contours.
  const bool facing = !packed && gbuffer->GetWritesNormals() &&
    ((this->Silhouettes && this->SmoothSilhouettes) || this->SuggestiveContours);
  std::ostringstream detectDefines;
  detectDefines << "#define NPR_ENCODING " << encoding << "\n#define NPR_PACKED_BLUR "
                << (packed && this->PackedBlur ? 1 : 0) << "\n#define NPR_PERSPECTIVE "
                << (gbuffer->GetPerspective() ? 1 : 0) << "\n#define NPR_SILHOUETTES "
                << (this->Silhouettes ? 1 : 0) << "\n#define NPR_CREASES "
                << (this->Creases && gbuffer->GetWritesNormals() ? 1 : 0) << "\n#define NPR_FACING "
                << (facing ? 1 : 0) << "\n#define NPR_SMOOTH_SILHOUETTES "
                << (facing && this->Silhouettes && this->SmoothSilhouettes ? 1 : 0)
                << "\n#define NPR_SUGGESTIVE " << (facing && this->SuggestiveContours ? 1 : 0)
                << "\n#define NPR_CONTOURS " << (this->Contours ? 1 : 0)
                << "\n#define NPR_HAVE_OBJECT_IDS " << (gbuffer->GetWritesObjectIds() ? 1 : 0)
                << "\n#define NPR_HAVE_FACE_NORMALS "
                << (this->FaceCreases && gbuffer->GetWritesFaceNormals() ? 1 : 0)
                << "\n#define NPR_CONTOUR_SIDE " << this->ContourSide << "\n";
  std::ostringstream detectSettings;
  detectSettings << detectDefines.str() << this->SilhouetteThreshold << " " << this->CreaseAngle
                 << " " << this->PackedThreshold << " " << this->SuggestiveContourThreshold;
  if (lines &&
    (!internal.LineImageValid || internal.LineImageVersion != gbuffer->GetContentVersion() ||
      internal.LineImageSettings != detectSettings.str()))
  {
    if (!internal.LineTexture)
    {
      internal.LineTexture =
        vtkNPRNewTexture(window, vtkTextureObject::Linear, vtkTextureObject::ClampToEdge);
      internal.LineTexture->Allocate2D(width, height, 4, VTK_UNSIGNED_CHAR);
      internal.Framebuffer = vtkOpenGLFramebufferObject::New();
      internal.Framebuffer->SetContext(window);
    }
    internal.LineTexture->Resize(width, height);

    vtkShaderProgram* program =
      internal.Detect.Ready(window, vtkNPREdgeDetectFS, detectDefines.str());
    if (!program)
    {
      vtkErrorMacro("the line detection shader did not compile");
      return;
    }
    geometry->Activate();
    program->SetUniformi("geometryTexture", geometry->GetTextureUnit());
    if (!packed)
    {
      program->SetUniformf("silhouetteThreshold", static_cast<float>(this->SilhouetteThreshold));
      const double radians = vtkMath::RadiansFromDegrees(this->CreaseAngle);
      program->SetUniformf("creaseAngle", static_cast<float>(radians));
      program->SetUniformf("creaseRamp", static_cast<float>(std::min(0.0175, 0.25 * radians)));
      program->SetUniformf(
        "suggestiveThreshold", static_cast<float>(this->SuggestiveContourThreshold));
      float rayOrigin[3], rayPerPixelX[3], rayPerPixelY[3];
      gbuffer->GetViewRay(rayOrigin, rayPerPixelX, rayPerPixelY);
      program->SetUniform3f("viewRayOrigin", rayOrigin);
      program->SetUniform3f("viewRayPerPixelX", rayPerPixelX);
      program->SetUniform3f("viewRayPerPixelY", rayPerPixelY);
    }
    else
    {
      // A texel's normalised value in units of one component's range (0..63 or 0..16383).
      const double unit = encoding == PACKED8 ? 255.0 / 63.0 : 65535.0 / 16383.0;
      program->SetUniformf("packedUnit", static_cast<float>(unit));
      program->SetUniformf("packedThreshold", static_cast<float>(this->PackedThreshold));
    }

    vtkOpenGLState::ScopedglViewport viewportSaver(glState);
    vtkOpenGLState::ScopedglEnableDisable depthTestSaver(glState, GL_DEPTH_TEST);
    vtkOpenGLState::ScopedglEnableDisable blendSaver(glState, GL_BLEND);
    vtkOpenGLState::ScopedglEnableDisable scissorTestSaver(glState, GL_SCISSOR_TEST);
    glState->PushFramebufferBindings();
    internal.Framebuffer->Bind();
    internal.Framebuffer->AddColorAttachment(0, internal.LineTexture);
    internal.Framebuffer->ActivateDrawBuffers(1);
    internal.Framebuffer->StartNonOrtho(width, height);
    glState->vtkglViewport(0, 0, width, height);
    glState->vtkglDisable(GL_DEPTH_TEST);
    glState->vtkglDisable(GL_BLEND);
    // Only where the props can be: the rest of the line image stays clear.
    const int* rect = gbuffer->GetContentRectangle();
    vtkOpenGLState::ScopedglClearColor clearColorSaver(glState);
    vtkOpenGLState::ScopedglScissor scissorSaver(glState);
    glState->vtkglDisable(GL_SCISSOR_TEST);
    glState->vtkglClearColor(0.0, 0.0, 0.0, 0.0);
    glState->vtkglClear(GL_COLOR_BUFFER_BIT);
    glState->vtkglEnable(GL_SCISSOR_TEST);
    glState->vtkglScissor(rect[0], rect[1], rect[2] - rect[0] + 1, rect[3] - rect[1] + 1);
    internal.Detect.Render();
    internal.Framebuffer->RemoveColorAttachments(1);
    glState->PopFramebufferBindings();
    geometry->Deactivate();

    internal.LineImageValid = true;
    internal.LineImageVersion = gbuffer->GetContentVersion();
    internal.LineImageSettings = detectSettings.str();
    ++this->NumberOfLineImageUpdates;
  }

  // ---- Step 2: composite colour, lines and depth into the current framebuffer ----
  const double lineWidth = this->GetEffectiveLineWidth(renderer);
  internal.Filter.Compute(lineWidth);
  const int taps = static_cast<int>(internal.Filter.Taps.size() / 3);
  std::ostringstream defines;
  defines << "#define NPR_LINES " << (lines ? 1 : 0) << "\n#define NPR_TAPS " << taps
          << "\n#define NPR_RADIUS " << internal.Filter.Radius + 1 << "\n#define NPR_ANTIALIAS "
          << (this->AntiAliasing ? 1 : 0) << "\n#define NPR_OUTPUT " << output
          << "\n#define NPR_REMAPPED_DEPTH " << (gbuffer->GetDepthRemapped() ? 1 : 0) << "\n";
  int origin[2] = { 0, 0 };
  if (output != OutputLineCoverage)
  {
    vtkNPRViewportOrigin(state, origin);
  }
  // Outside the props' projected bounds there is only background: nothing to write there.
  const int* rect = gbuffer->GetContentRectangle();
  const int windowRect[4] = { origin[0] + rect[0], origin[1] + rect[1], origin[0] + rect[2],
    origin[1] + rect[3] };
  // An unchanged frame: the kept composite copied back, before any of the composite's setup.
  const std::string compositeKey = output == OutputComposite
    ? this->CompositeKey(renderer, defines.str(), windowRect)
    : std::string();
  const bool unchanged = !compositeKey.empty() && compositeKey == internal.CompositeKey;
  internal.CompositeKey = compositeKey;
  internal.FramesSinceUnchanged = unchanged ? 0 : internal.FramesSinceUnchanged + 1;
  if (unchanged && internal.Kept.Restore(window))
  {
    ++this->NumberOfKeptCompositeRestores;
    this->NumberOfRenderedProps = gbuffer->GetNumberOfRenderedProps();
    vtkOpenGLCheckErrorMacro("failed after vtkNPREdgePass::Render (kept composite)");
    return;
  }

  if (internal.CompositeSource.empty())
  {
    internal.CompositeSource = vtkNPREdgeCompositeFS;
    vtkShaderProgram::Substitute(internal.CompositeSource, "//NPR::LineColor", vtkNPRLineColor);
    vtkShaderProgram::Substitute(internal.CompositeSource, "//NPR::WindowDepth", vtkNPRWindowDepth);
    vtkShaderProgram::Substitute(
      internal.CompositeSource, "//NPR::NearestDepth", vtkNPRNearestDepth);
  }
  vtkNPRQuadProgram& composite =
    output == OutputLineCoverage ? internal.Coverage : internal.Composite;
  vtkShaderProgram* program = composite.Ready(window, internal.CompositeSource, defines.str());
  if (!program)
  {
    vtkErrorMacro("the line composite shader did not compile");
    return;
  }
  vtkTextureObject* color = gbuffer->GetColorTexture();
  vtkTextureObject* depth = gbuffer->GetDepthTexture();
  color->Activate();
  depth->Activate();
  program->SetUniformi("colorTexture", color->GetTextureUnit());
  program->SetUniformi("depthTexture", depth->GetTextureUnit());
  if (lines)
  {
    internal.LineTexture->Activate();
    program->SetUniformi("lineTexture", internal.LineTexture->GetTextureUnit());
    program->SetUniform3fv(
      "taps", taps, reinterpret_cast<const float(*)[3]>(internal.Filter.Taps.data()));
    const float texelSize[2] = { 1.0f / width, 1.0f / height };
    program->SetUniform2f("texelSize", texelSize);
    program->SetUniformf("coverageLevel", internal.Filter.CoverageLevel);
    program->SetUniformf("coverageSlope", internal.Filter.CoverageSlope);
    program->SetUniform3f("silhouetteColor", this->SilhouetteColor);
    program->SetUniform3f("creaseColor", this->CreaseColor);
    program->SetUniform3f("contourColor", this->ContourColor);
    program->SetUniform3f("suggestiveColor", this->SuggestiveContourColor);
  }
  program->SetUniform2i("viewportOrigin", origin);
  if (gbuffer->GetDepthRemapped())
  {
    program->SetUniform2f("nprDepthRemap", gbuffer->GetDepthRemap());
  }

  vtkNPRCompositeState compositeState(glState);
  compositeState.Apply(origin, width, height);
  if (output == OutputMask)
  {
    glState->vtkglDisable(GL_SCISSOR_TEST); // a mask is black everywhere else
  }
  else
  {
    glState->vtkglEnable(GL_SCISSOR_TEST);
    glState->vtkglScissor(
      windowRect[0], windowRect[1], rect[2] - rect[0] + 1, rect[3] - rect[1] + 1);
  }
  if (output == OutputLineCoverage)
  {
    // Plain values into the caller's target, which has no depth buffer.
    glState->vtkglDisable(GL_DEPTH_TEST);
    glState->vtkglDepthMask(GL_FALSE);
    glState->vtkglDisable(GL_BLEND);
  }
  composite.Render();
  if (internal.CompositeKey.empty() ||
    internal.FramesSinceUnchanged > Internals::KeepAfterUnchanged ||
    !internal.Kept.Capture(window, windowRect))
  {
    internal.Kept.Invalidate();
  }

  color->Deactivate();
  depth->Deactivate();
  if (lines)
  {
    internal.LineTexture->Deactivate();
  }
  this->NumberOfRenderedProps = gbuffer->GetNumberOfRenderedProps();
  vtkOpenGLCheckErrorMacro("failed after vtkNPREdgePass::Render");
}

std::string vtkNPREdgePass::CompositeKey(
  vtkRenderer* renderer, const std::string& defines, const int windowRect[4])
{
  // Only where what lies under the composite is this renderer's own clear, which these settings
  // describe: another layer below, a preserved colour or depth buffer could change on their own.
  if (!this->KeepUnchangedComposite || renderer->Transparent() || !renderer->GetErase() ||
    renderer->GetPreserveDepthBuffer())
  {
    return std::string();
  }
  auto* window = static_cast<vtkOpenGLRenderWindow*>(renderer->GetRenderWindow());
  unsigned int binding = 0, drawBuffer = 0;
  window->GetState()->GetCurrentDrawFramebufferState(binding, drawBuffer);
  std::ostringstream key;
  key.precision(17);
  key << defines << this->GBufferPass->GetContentVersion() << " " << this->NumberOfLineImageUpdates
      << " " << this->Internal->LineImageSettings << " " << this->GetEffectiveLineWidth(renderer)
      << " " << binding << " " << drawBuffer << " " << window->GetSize()[0] << " "
      << window->GetSize()[1];
  for (int i = 0; i < 4; ++i)
  {
    key << " " << windowRect[i];
  }
  for (const double* colorValue :
    { this->SilhouetteColor, this->CreaseColor, this->ContourColor, this->SuggestiveContourColor })
  {
    key << " " << colorValue[0] << " " << colorValue[1] << " " << colorValue[2];
  }
  // The renderer's clear (vtkOpenGLRenderer::Clear); not its MTime, which capturing the window
  // changes (vtkWindowToImageFilter).
  for (const double* colorValue : { renderer->GetBackground(), renderer->GetBackground2() })
  {
    key << " " << colorValue[0] << " " << colorValue[1] << " " << colorValue[2];
  }
  vtkTexture* background = renderer->GetBackgroundTexture();
  key << " " << renderer->GetBackgroundAlpha() << " " << renderer->GetGradientBackground() << " "
      << renderer->GetTexturedBackground() << " " << background << " "
      << (background ? background->GetMTime() : 0);
#if VTK_MAJOR_VERSION > 9 || (VTK_MAJOR_VERSION == 9 && VTK_MINOR_VERSION >= 3)
  key << " " << static_cast<int>(renderer->GetGradientMode());
#endif
  return key.str();
}

void vtkNPREdgePass::ReleaseGraphicsResources(vtkWindow* window)
{
  Internals& internal = *this->Internal;
  internal.Detect.Release(window);
  internal.Composite.Release(window);
  internal.Coverage.Release(window);
  if (internal.LineTexture)
  {
    internal.LineTexture->ReleaseGraphicsResources(window);
    internal.LineTexture->Delete();
    internal.LineTexture = nullptr;
  }
  if (internal.Framebuffer)
  {
    internal.Framebuffer->ReleaseGraphicsResources(window);
    internal.Framebuffer->Delete();
    internal.Framebuffer = nullptr;
  }
  internal.LineImageValid = false;
  internal.Kept.ReleaseGraphicsResources(window);
  internal.CompositeKey.clear();
}

void vtkNPREdgePass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "GBufferPass: " << this->GBufferPass << "\n";
  os << indent << "Silhouettes: " << this->Silhouettes << " threshold " << this->SilhouetteThreshold
     << " color " << this->SilhouetteColor[0] << " " << this->SilhouetteColor[1] << " "
     << this->SilhouetteColor[2] << "\n";
  os << indent << "SmoothSilhouettes: " << this->SmoothSilhouettes << "\n";
  os << indent << "SuggestiveContours: " << this->SuggestiveContours << " threshold "
     << this->SuggestiveContourThreshold << " color " << this->SuggestiveContourColor[0] << " "
     << this->SuggestiveContourColor[1] << " " << this->SuggestiveContourColor[2] << "\n";
  os << indent << "Creases: " << this->Creases << " angle " << this->CreaseAngle << " color "
     << this->CreaseColor[0] << " " << this->CreaseColor[1] << " " << this->CreaseColor[2] << "\n";
  os << indent << "FaceCreases: " << this->FaceCreases << "\n";
  os << indent << "Contours: " << this->Contours << " side " << this->ContourSide << " color "
     << this->ContourColor[0] << " " << this->ContourColor[1] << " " << this->ContourColor[2]
     << "\n";
  os << indent << "LineWidth: " << this->LineWidth << "\n";
  os << indent << "Encoding: " << GetEncodingName(this->Encoding) << " packed threshold "
     << this->PackedThreshold << " blur " << this->PackedBlur << "\n";
  os << indent << "AntiAliasing: " << this->AntiAliasing << "\n";
  os << indent << "CoverageOnly: " << this->CoverageOnly << "\n";
  os << indent << "NumberOfLineImageUpdates: " << this->NumberOfLineImageUpdates << "\n";
  os << indent << "KeepUnchangedComposite: " << this->KeepUnchangedComposite << "\n";
  os << indent << "NumberOfKeptCompositeRestores: " << this->NumberOfKeptCompositeRestores << "\n";
}
