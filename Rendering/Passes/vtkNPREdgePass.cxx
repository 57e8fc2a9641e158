// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNPREdgePass.h"

#include "vtkCamera.h"
#include "vtkMath.h"
#include "vtkNPRGBufferPass.h"
#include "vtkNPRLineBlocks.h"
#include "vtkNPRLineFilter.h"
#include "vtkNPROpenGL.h"
#include "vtkNPRPassUtilities.h"
#include "vtkNPRQuadProgram.h"
#include "vtkNPRRenderTarget.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include "vtkNPREdgeCompositeFS.h"
#include "vtkNPREdgeDetectFS.h"
#include "vtkNPREdgeLimitFS.h"
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
// A line image of the G-buffer's size, allocated once and resized with it.
void ReadyLineTexture(
  vtkTextureObject*& texture, vtkOpenGLRenderWindow* window, vtkTextureObject* geometry)
{
  const unsigned int width = geometry->GetWidth();
  const unsigned int height = geometry->GetHeight();
  if (!texture)
  {
    texture = vtkNPRNewTexture(window, vtkTextureObject::Linear, vtkTextureObject::ClampToEdge);
    texture->Allocate2D(width, height, 4, VTK_UNSIGNED_CHAR);
  }
  texture->Resize(width, height);
}

void ReleaseLineTexture(vtkTextureObject*& texture, vtkWindow* window)
{
  if (texture)
  {
    if (window)
    {
      texture->ReleaseGraphicsResources(window);
    }
    texture->Delete();
    texture = nullptr;
  }
}
}

struct vtkNPREdgePass::Internals
{
  vtkNPRQuadProgram Detect;
  vtkNPRQuadProgram Composite; // lines over the colour, or the mask
  vtkNPRQuadProgram Coverage;  // each type's coverage and depth, for vtkNPRSketchPass
  std::string CompositeSource;
  vtkNPRRenderTarget Target;
  vtkNPRLineBlocks Blocks; // SkipLineFreeBlocks
  vtkNPRQuadProgram Limit; // MaximumLineFraction
  vtkTextureObject* LineTexture = nullptr;
  vtkTextureObject* LimitedLineTexture = nullptr; // the line image the limit drew
  bool LinesLimited = false;

  // The line image the composite draws.
  vtkTextureObject* DrawnLines() const
  {
    return this->LinesLimited ? this->LimitedLineTexture : this->LineTexture;
  }
  // What the line image was computed from: the G-buffer's content and the detection settings
  // (colours, width, anti-aliasing and CoverageOnly only change the composite).
  unsigned long LineImageVersion = 0;
  std::string LineImageSettings;
  bool LineImageValid = false;
  bool WarnedAboutEncoding = false;
  vtkNPRLineFilter Filter;

  // The composite's shader with its shared snippets in place.
  const std::string& GetCompositeSource()
  {
    if (this->CompositeSource.empty())
    {
      this->CompositeSource = vtkNPREdgeCompositeFS;
      vtkShaderProgram::Substitute(this->CompositeSource, "//NPR::LineColor", vtkNPRLineColor);
      vtkShaderProgram::Substitute(this->CompositeSource, "//NPR::WindowDepth", vtkNPRWindowDepth);
      vtkShaderProgram::Substitute(
        this->CompositeSource, "//NPR::NearestDepth", vtkNPRNearestDepth);
    }
    return this->CompositeSource;
  }
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
  ReleaseLineTexture(this->Internal->LineTexture, nullptr);
  ReleaseLineTexture(this->Internal->LimitedLineTexture, nullptr);
}

const char* vtkNPREdgePass::GetEncodingName(int encoding)
{
  return vtkNPRGBufferPass::GetEncodingName(encoding);
}

int vtkNPREdgePass::GetEncodingFromName(const char* name)
{
  return vtkNPRGBufferPass::GetEncodingFromName(name);
}

void vtkNPREdgePass::GetDrawnLineWidths(vtkRenderer* renderer, double widths[4]) const
{
  this->GetEffectiveLineWidths(renderer, widths);
  const double widest = this->GetWidestDrawn(renderer, widths);
  for (int kind = 0; kind < 4; ++kind)
  {
    widths[kind] = std::min(widths[kind], widest); // a kind not drawn widens nothing
  }
}

void vtkNPREdgePass::GetEffectiveLineWidths(vtkRenderer* renderer, double widths[4]) const
{
  const double kinds[4] = { this->SilhouetteLineWidth, this->CreaseLineWidth,
    this->ContourLineWidth, this->SuggestiveContourLineWidth };
  for (int kind = 0; kind < 4; ++kind)
  {
    widths[kind] =
      vtkNPREffectiveLineWidth(renderer, kinds[kind] > 0.0 ? kinds[kind] : this->LineWidth);
  }
}

double vtkNPREdgePass::GetEffectiveLineWidth(vtkRenderer* renderer) const
{
  double widths[4];
  this->GetEffectiveLineWidths(renderer, widths);
  return this->GetWidestDrawn(renderer, widths);
}

double vtkNPREdgePass::GetWidestDrawn(vtkRenderer* renderer, const double widths[4]) const
{
  // The kinds drawn (the packed encodings draw every line as a silhouette); with none, LineWidth.
  const bool drawn[4] = { this->Silhouettes, this->Creases, this->Contours,
    this->SuggestiveContours };
  double widest = 0.0;
  for (int kind = 0; kind < 4; ++kind)
  {
    widest = drawn[kind] ? std::max(widest, widths[kind]) : widest;
  }
  return widest > 0.0 ? widest : vtkNPREffectiveLineWidth(renderer, this->LineWidth);
}

vtkNPRGBufferPass* vtkNPREdgePass::GetGBuffer()
{
  return this->GBufferPass;
}

bool vtkNPREdgePass::UpdateImages(const vtkRenderState* state)
{
  return !this->GetDrawsLines() || this->UpdateLineImage(state);
}

bool vtkNPREdgePass::RenderLineCoverage(const vtkRenderState* state)
{
  this->NumberOfRenderedProps = 0;
  vtkNPRGBufferPass* gbuffer = this->GetReadyGBuffer(state);
  if (!gbuffer)
  {
    return false;
  }
  // Plain values into the caller's target, from its origin; it has no depth buffer. Only the
  // content rectangle: the rest is the caller's.
  vtkOpenGLState* glState =
    static_cast<vtkOpenGLRenderWindow*>(state->GetRenderer()->GetRenderWindow())->GetState();
  const int origin[2] = { 0, 0 };
  const int* rect = gbuffer->GetContentRectangle();
  vtkNPRCompositeState compositeState(glState);
  compositeState.Apply(
    origin, gbuffer->GetDepthTexture()->GetWidth(), gbuffer->GetDepthTexture()->GetHeight());
  glState->vtkglScissor(rect[0], rect[1], rect[2] - rect[0] + 1, rect[3] - rect[1] + 1);
  glState->vtkglDisable(GL_DEPTH_TEST);
  glState->vtkglDepthMask(GL_FALSE);
  glState->vtkglDisable(GL_BLEND);
  if (!this->DrawLines(state, origin, OutputLineCoverage))
  {
    return false;
  }
  this->NumberOfRenderedProps = gbuffer->GetNumberOfRenderedProps();
  return true;
}

std::string vtkNPREdgePass::GetDetectDefines(int encoding) const
{
  vtkNPRGBufferPass* gbuffer = this->GBufferPass;
  const bool packed = encoding == PACKED8 || encoding == PACKED16;
  // n.v at each tap, for the smooth silhouettes and the suggestive contours.
  const bool facing = !packed && gbuffer->GetWritesNormals() &&
    ((this->Silhouettes && this->SmoothSilhouettes) || this->SuggestiveContours);
  std::ostringstream defines;
  defines << "#define NPR_ENCODING " << encoding << "\n#define NPR_PACKED_BLUR "
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
  return defines.str();
}

bool vtkNPREdgePass::UpdateLineImage(const vtkRenderState* state)
{
  vtkNPRGBufferPass* gbuffer = this->GBufferPass;
  Internals& internal = *this->Internal;
  const int encoding = gbuffer->GetWrittenEncoding();
  if (encoding != this->Encoding && !internal.WarnedAboutEncoding)
  {
    vtkWarningMacro("the G-buffer holds the "
      << GetEncodingName(encoding) << " encoding, not the edge pass's "
      << GetEncodingName(this->Encoding) << ": set its GeometryEncoding to match");
    internal.WarnedAboutEncoding = true;
  }
  const std::string defines = this->GetDetectDefines(encoding);
  const bool limited =
    this->MaximumLineFraction > 0.0 && encoding != PACKED8 && encoding != PACKED16;
  std::ostringstream settings;
  settings.precision(17);
  settings << defines << this->SilhouetteThreshold << " " << this->CreaseAngle << " "
           << this->PackedThreshold << " " << this->SuggestiveContourThreshold;
  if (limited)
  {
    // The width limit sets the line image's values by the widths the composite draws.
    double widths[4];
    this->GetDrawnLineWidths(state->GetRenderer(), widths);
    settings << " " << this->MaximumLineFraction << " " << widths[0] << " " << widths[1] << " "
             << widths[2] << " " << widths[3];
  }
  if (internal.LineImageValid && internal.LineImageVersion == gbuffer->GetContentVersion() &&
    internal.LineImageSettings == settings.str())
  {
    return true;
  }
  auto* window = static_cast<vtkOpenGLRenderWindow*>(state->GetRenderer()->GetRenderWindow());
  if (!this->DetectLines(window, encoding, defines) ||
    (limited && !this->LimitLineWidths(window, encoding, state->GetRenderer())))
  {
    return false;
  }
  internal.LinesLimited = limited;
  internal.LineImageValid = true;
  internal.LineImageVersion = gbuffer->GetContentVersion();
  internal.LineImageSettings = settings.str();
  ++this->NumberOfLineImageUpdates;
  return true;
}

bool vtkNPREdgePass::DetectLines(
  vtkOpenGLRenderWindow* window, int encoding, const std::string& defines)
{
  Internals& internal = *this->Internal;
  vtkShaderProgram* program = internal.Detect.Ready(window, vtkNPREdgeDetectFS, defines);
  if (!program)
  {
    vtkErrorMacro("the line detection shader did not compile");
    return false;
  }
  vtkTextureObject* geometry = this->GBufferPass->GetGeometryTexture();
  ReadyLineTexture(internal.LineTexture, window, geometry);
  geometry->Activate();
  this->SetDetectUniforms(program, encoding);
  this->DrawLineImage(window, internal.LineTexture, internal.Detect);
  geometry->Deactivate();
  return true;
}

bool vtkNPREdgePass::LimitLineWidths(
  vtkOpenGLRenderWindow* window, int encoding, vtkRenderer* renderer)
{
  Internals& internal = *this->Internal;
  vtkNPRGBufferPass* gbuffer = this->GBufferPass;
  std::ostringstream defines;
  defines << "#define NPR_HAVE_OBJECT_IDS " << (gbuffer->GetWritesObjectIds() ? 1 : 0)
          << "\n#define NPR_ID_CHANNEL " << (encoding == HALF ? 3 : 2) << "\n";
  vtkShaderProgram* program = internal.Limit.Ready(window, vtkNPREdgeLimitFS, defines.str());
  if (!program)
  {
    vtkErrorMacro("the line width limit's shader did not compile");
    return false;
  }
  vtkTextureObject* geometry = gbuffer->GetGeometryTexture();
  ReadyLineTexture(internal.LimitedLineTexture, window, geometry);
  geometry->Activate();
  internal.LineTexture->Activate();
  program->SetUniformi("geometryTexture", geometry->GetTextureUnit());
  program->SetUniformi("lineTexture", internal.LineTexture->GetTextureUnit());
  double widths[4];
  this->GetDrawnLineWidths(renderer, widths);
  vtkNPRSetWidthLimitUniforms(program, widths, this->MaximumLineFraction);
  this->DrawLineImage(window, internal.LimitedLineTexture, internal.Limit);
  internal.LineTexture->Deactivate();
  geometry->Deactivate();
  return true;
}

void vtkNPREdgePass::DrawLineImage(
  vtkOpenGLRenderWindow* window, vtkTextureObject* image, vtkNPRQuadProgram& program)
{
  vtkNPRRenderTarget::Scope target(this->Internal->Target, window, { image }, nullptr,
    static_cast<int>(image->GetWidth()), static_cast<int>(image->GetHeight()));
  target.Clear(0.0, 0.0, 0.0, 0.0);
  // Only where the props can be: the rest of the line image stays clear.
  target.ScissorTo(this->GBufferPass->GetContentRectangle());
  program.Render();
}

void vtkNPREdgePass::SetDetectUniforms(vtkShaderProgram* program, int encoding)
{
  vtkNPRGBufferPass* gbuffer = this->GBufferPass;
  program->SetUniformi("geometryTexture", gbuffer->GetGeometryTexture()->GetTextureUnit());
  if (encoding == PACKED8 || encoding == PACKED16)
  {
    // A texel's normalised value in units of one component's range (0..63 or 0..16383).
    const double unit = encoding == PACKED8 ? 255.0 / 63.0 : 65535.0 / 16383.0;
    program->SetUniformf("packedUnit", static_cast<float>(unit));
    program->SetUniformf("packedThreshold", static_cast<float>(this->PackedThreshold));
    return;
  }
  program->SetUniformf("silhouetteThreshold", static_cast<float>(this->SilhouetteThreshold));
  const double radians = vtkMath::RadiansFromDegrees(this->CreaseAngle);
  program->SetUniformf("creaseAngle", static_cast<float>(radians));
  program->SetUniformf("creaseRamp", static_cast<float>(std::min(0.0175, 0.25 * radians)));
  program->SetUniformf("suggestiveThreshold", static_cast<float>(this->SuggestiveContourThreshold));
  float rayOrigin[3], rayPerPixelX[3], rayPerPixelY[3];
  gbuffer->GetViewRay(rayOrigin, rayPerPixelX, rayPerPixelY);
  program->SetUniform3f("viewRayOrigin", rayOrigin);
  program->SetUniform3f("viewRayPerPixelX", rayPerPixelX);
  program->SetUniform3f("viewRayPerPixelY", rayPerPixelY);
  if (!gbuffer->GetPerspective())
  {
    float pixelStepX[3], pixelStepY[3];
    gbuffer->GetViewPixelStep(pixelStepX, pixelStepY);
    program->SetUniform3f("viewPixelStepX", pixelStepX);
    program->SetUniform3f("viewPixelStepY", pixelStepY);
  }
}

std::string vtkNPREdgePass::GetCompositeDefines(vtkRenderer* renderer, int output, bool lines)
{
  Internals& internal = *this->Internal;
  double widths[4];
  this->GetDrawnLineWidths(renderer, widths);
  if (this->DepthFalloff)
  {
    internal.Filter.Compute(widths, this->NearLineScale, this->FarLineScale);
  }
  else
  {
    internal.Filter.Compute(widths);
  }
  std::ostringstream defines;
  defines << "#define NPR_LINES " << (lines ? 1 : 0) << "\n#define NPR_TAPS "
          << internal.Filter.Taps.size() / 3 << "\n#define NPR_RADIUS "
          << internal.Filter.Radius + 1 << "\n#define NPR_ANTIALIAS "
          << (this->AntiAliasing ? 1 : 0) << "\n#define NPR_OUTPUT " << output
          << "\n#define NPR_REMAPPED_DEPTH " << (this->GBufferPass->GetDepthRemapped() ? 1 : 0)
          << "\n#define NPR_DEPTH_FALLOFF " << (internal.Filter.HasFalloff() ? 1 : 0)
          << "\n#define NPR_FALLOFF_STEPS " << vtkNPRLineFilter::FalloffSteps << "\n"
          << this->GetLineColorDefines();
  return defines.str();
}

void vtkNPREdgePass::GetCompositeRectangle(vtkRenderer*, int rect[4])
{
  if (this->CoverageOnly)
  {
    GetWholeRectangle(this->GBufferPass, rect); // a mask is black everywhere else
    return;
  }
  // Outside the props' projected bounds there is only background: nothing to write there.
  std::copy_n(this->GBufferPass->GetContentRectangle(), 4, rect);
}

std::string vtkNPREdgePass::GetCompositeKey(vtkRenderer* renderer)
{
  if (this->CoverageOnly)
  {
    return std::string(); // a measurement: always drawn
  }
  std::ostringstream key;
  key.precision(17);
  // The line image's settings and content change its update count.
  key << this->GetCompositeDefines(renderer, OutputComposite, this->GetDrawsLines())
      << this->NumberOfLineImageUpdates << " " << this->SkipLineFreeBlocks;
  for (const double width : this->Internal->Filter.Widths) // as GetCompositeDefines computed them
  {
    key << " " << width;
  }
  for (const double* colorValue :
    { this->SilhouetteColor, this->CreaseColor, this->ContourColor, this->SuggestiveContourColor })
  {
    key << " " << colorValue[0] << " " << colorValue[1] << " " << colorValue[2];
  }
  key << " " << this->SurfaceLineShade << " " << this->Internal->Filter.Scales[0] << " "
      << this->Internal->Filter.Scales[1];
  return key.str();
}

bool vtkNPREdgePass::DrawComposite(const vtkRenderState* state, const int origin[2])
{
  return this->DrawLines(state, origin, this->CoverageOnly ? OutputMask : OutputComposite);
}

bool vtkNPREdgePass::DrawLines(const vtkRenderState* state, const int origin[2], int output)
{
  Internals& internal = *this->Internal;
  vtkRenderer* renderer = state->GetRenderer();
  auto* window = static_cast<vtkOpenGLRenderWindow*>(renderer->GetRenderWindow());
  const std::string defines = this->GetCompositeDefines(renderer, output, this->GetDrawsLines());
  vtkNPRGBufferPass* gbuffer = this->GBufferPass;
  vtkTextureObject* color = gbuffer->GetColorTexture();
  vtkTextureObject* depth = gbuffer->GetDepthTexture();
  const bool lines = this->GetDrawsLines();
  // No line type on: the composite is the surfaces' copy, copied back whole where it can be.
  if (output == OutputComposite && !lines && this->CopySurfacesBack &&
    gbuffer->CopySurfacesBack(window, origin))
  {
    ++this->NumberOfSurfaceCopies;
    return true;
  }
  // The blocks first: marking them binds and releases the line image. Not for the mask, black
  // over the whole view where the blocks cover the content rectangle only.
  const bool overBlocks =
    output != OutputMask && this->SkipsLineFreeBlocks() && this->UpdateLineBlocks(window);
  color->Activate();
  depth->Activate();
  if (lines)
  {
    internal.DrawnLines()->Activate();
  }
  bool drawn = false;
  if (overBlocks)
  {
    drawn = this->DrawOverBlocks(window, renderer, origin, output, defines);
  }
  else
  {
    vtkNPRQuadProgram& composite =
      output == OutputLineCoverage ? internal.Coverage : internal.Composite;
    vtkShaderProgram* program = composite.Ready(window, internal.GetCompositeSource(), defines);
    if (program)
    {
      this->SetCompositeUniforms(program, origin, renderer);
      composite.Render();
      drawn = true;
    }
  }
  color->Deactivate();
  depth->Deactivate();
  if (lines)
  {
    internal.DrawnLines()->Deactivate();
  }
  if (!drawn)
  {
    vtkErrorMacro("the line composite shader did not compile");
  }
  return drawn;
}

bool vtkNPREdgePass::SkipsLineFreeBlocks() const
{
  // Only where a pixel that no line value reaches comes out as the surfaces' copy: its coverage,
  // clamp(0.5 - level / slope), is zero (a margin for the shader's single precision).
  const vtkNPRLineFilter& filter = this->Internal->Filter;
  auto zeroWithoutLine = [](const float level[4], const float slope[4])
  {
    for (int kind = 0; kind < 4; ++kind)
    {
      if (!(level[kind] > 0.0f && slope[kind] > 0.0f && level[kind] / slope[kind] > 0.5001f))
      {
        return false;
      }
    }
    return true;
  };
  bool zero = zeroWithoutLine(filter.CoverageLevel, filter.CoverageSlope);
  for (int step = 0; zero && filter.HasFalloff() && step < vtkNPRLineFilter::FalloffSteps; ++step)
  {
    zero = zeroWithoutLine(filter.FalloffLevels[step], filter.FalloffSlopes[step]);
  }
  return this->SkipLineFreeBlocks && this->GetDrawsLines() && (zero || !this->AntiAliasing);
}

bool vtkNPREdgePass::UpdateLineBlocks(vtkOpenGLRenderWindow* window)
{
  Internals& internal = *this->Internal;
  // A filtered line value needs a texel within the farthest tap's bilinear reach.
  float farthest = 0.0f;
  for (size_t i = 0; i < internal.Filter.Taps.size(); i += 3)
  {
    farthest = std::max(
      { farthest, std::abs(internal.Filter.Taps[i]), std::abs(internal.Filter.Taps[i + 1]) });
  }
  const int reach = static_cast<int>(std::ceil(farthest)) + 1;
  return internal.Blocks.Update(window, internal.DrawnLines(), this->NumberOfLineImageUpdates,
    reach, this->GBufferPass->GetContentRectangle());
}

bool vtkNPREdgePass::DrawOverBlocks(vtkOpenGLRenderWindow* window, vtkRenderer* renderer,
  const int origin[2], int output, const std::string& lineDefines)
{
  Internals& internal = *this->Internal;
  // The lines' output near them; elsewhere the output without lines (the surfaces' copy, or no
  // coverage at the surfaces' depth). The composite's surfaces are copied back whole first where
  // the G-buffer holds the window's image under them.
  const bool copiedBack = output == OutputComposite && this->CopySurfacesBack &&
    this->GBufferPass->CopySurfacesBack(window, origin);
  if (copiedBack)
  {
    // The depth under the lines is now the surfaces' own, not the cleared far plane: the lines'
    // depth sprite replaces it, as it passed over the cleared depth (read through a float, it
    // can come out a unit above the copied value).
    window->GetState()->vtkglDepthFunc(GL_ALWAYS);
    ++this->NumberOfSurfaceCopies;
  }
  const std::string& source = internal.GetCompositeSource();
  const std::string copyDefines = this->GetCompositeDefines(renderer, output, false);
  for (const bool near : { true, false })
  {
    if (!near && copiedBack)
    {
      break;
    }
    vtkShaderProgram* program =
      internal.Blocks.Ready(window, near, source, near ? lineDefines : copyDefines);
    if (!program)
    {
      return false;
    }
    this->SetCompositeUniforms(program, origin, renderer);
    internal.Blocks.Draw(program, near);
  }
  ++this->NumberOfBlockComposites;
  return true;
}

void vtkNPREdgePass::SetCompositeUniforms(
  vtkShaderProgram* program, const int origin[2], vtkRenderer* renderer)
{
  Internals& internal = *this->Internal;
  vtkNPRGBufferPass* gbuffer = this->GBufferPass;
  program->SetUniformi("colorTexture", gbuffer->GetColorTexture()->GetTextureUnit());
  program->SetUniformi("depthTexture", gbuffer->GetDepthTexture()->GetTextureUnit());
  program->SetUniform2i("viewportOrigin", origin);
  if (gbuffer->GetDepthRemapped())
  {
    program->SetUniform2f("nprDepthRemap", gbuffer->GetDepthRemap());
  }
  if (!this->GetDrawsLines())
  {
    return;
  }
  const vtkNPRLineFilter& filter = internal.Filter;
  program->SetUniformi("lineTexture", internal.DrawnLines()->GetTextureUnit());
  program->SetUniform3fv("taps", static_cast<int>(filter.Taps.size() / 3),
    reinterpret_cast<const float(*)[3]>(filter.Taps.data()));
  const float texelSize[2] = { 1.0f / internal.DrawnLines()->GetWidth(),
    1.0f / internal.DrawnLines()->GetHeight() };
  program->SetUniform2f("texelSize", texelSize);
  program->SetUniform4f("coverageLevel", filter.CoverageLevel);
  program->SetUniform4f("coverageSlope", filter.CoverageSlope);
  if (filter.HasFalloff())
  {
    // Each kind's mapping at the falloff's steps, and the camera that gives a depth its step.
    program->SetUniform4fv("falloffLevels", vtkNPRLineFilter::FalloffSteps, filter.FalloffLevels);
    program->SetUniform4fv("falloffSlopes", vtkNPRLineFilter::FalloffSteps, filter.FalloffSlopes);
    vtkCamera* camera = renderer->GetActiveCamera();
    const double* range = camera->GetClippingRange();
    const float falloffCamera[3] = { static_cast<float>(range[0]), static_cast<float>(range[1]),
      camera->GetParallelProjection() ? 1.0f : 0.0f };
    program->SetUniform3f("falloffCamera", falloffCamera);
  }
  this->SetLineColorUniforms(program);
}

std::string vtkNPREdgePass::GetLineColorDefines() const
{
  return std::string("#define NPR_SURFACE_SHADE ") + (this->SurfaceLineShade > 0.0 ? "1" : "0") +
    "\n";
}

void vtkNPREdgePass::SetLineColorUniforms(vtkShaderProgram* program) const
{
  program->SetUniform3f("silhouetteColor", this->SilhouetteColor);
  program->SetUniform3f("creaseColor", this->CreaseColor);
  program->SetUniform3f("contourColor", this->ContourColor);
  program->SetUniform3f("suggestiveColor", this->SuggestiveContourColor);
  if (this->SurfaceLineShade > 0.0)
  {
    program->SetUniformf("surfaceLineShade", static_cast<float>(this->SurfaceLineShade));
  }
}

void vtkNPREdgePass::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Superclass::ReleaseGraphicsResources(window);
  Internals& internal = *this->Internal;
  internal.Detect.Release(window);
  internal.Composite.Release(window);
  internal.Coverage.Release(window);
  internal.Limit.Release(window);
  ReleaseLineTexture(internal.LineTexture, window);
  ReleaseLineTexture(internal.LimitedLineTexture, window);
  internal.Target.ReleaseGraphicsResources(window);
  internal.Blocks.ReleaseGraphicsResources(window);
  internal.LineImageValid = false;
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
  os << indent << "LineWidth: " << this->LineWidth << " (silhouettes " << this->SilhouetteLineWidth
     << ", creases " << this->CreaseLineWidth << ", contours " << this->ContourLineWidth
     << ", suggestive contours " << this->SuggestiveContourLineWidth << ": 0 is LineWidth)\n";
  os << indent << "DepthFalloff: " << this->DepthFalloff << " (near x" << this->NearLineScale
     << ", far x" << this->FarLineScale << ")\n";
  os << indent << "MaximumLineFraction: " << this->MaximumLineFraction << "\n";
  os << indent << "SurfaceLineShade: " << this->SurfaceLineShade << "\n";
  os << indent << "Encoding: " << GetEncodingName(this->Encoding) << " packed threshold "
     << this->PackedThreshold << " blur " << this->PackedBlur << "\n";
  os << indent << "AntiAliasing: " << this->AntiAliasing << "\n";
  os << indent << "CoverageOnly: " << this->CoverageOnly << "\n";
  os << indent << "SkipLineFreeBlocks: " << this->SkipLineFreeBlocks << "\n";
  os << indent << "NumberOfLineImageUpdates: " << this->NumberOfLineImageUpdates << "\n";
  os << indent << "NumberOfBlockComposites: " << this->NumberOfBlockComposites << "\n";
  os << indent << "CopySurfacesBack: " << this->CopySurfacesBack << "\n";
  os << indent << "NumberOfSurfaceCopies: " << this->NumberOfSurfaceCopies << "\n";
}
