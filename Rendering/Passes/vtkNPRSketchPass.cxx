// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNPRSketchPass.h"

#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkNPREdgePass.h"
#include "vtkNPRGBufferPass.h"
#include "vtkNPROpenGL.h"
#include "vtkNPRPassUtilities.h"
#include "vtkNPRQuadProgram.h"
#include "vtkNPRRenderTarget.h"
#include "vtkNPRSketchNoise.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLCamera.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkPointData.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include "vtkNPRAcrossTiles.h"
#include "vtkNPRLineColor.h"
#include "vtkNPRSketchFS.h"
#include "vtkNPRSketchNoiseFS.h"
#include "vtkNPRWindowDepth.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

namespace
{
constexpr int NoiseSize = vtkNPRSketchNoise::ScreenTileSize;
}

struct vtkNPRSketchPass::Internals
{
  vtkNPRQuadProgram Sketch;
  std::string Source;
  vtkNPRRenderTarget Target;
  vtkTextureObject* Noise = nullptr; // this frame's: the screen tile or the surface noise field
  vtkTextureObject* CoverageTexture = nullptr;
  // What the coverage texture was computed from: the G-buffer's content and the edge pass's
  // settings, at a line width and size; unchanged frames reuse it.
  bool CoverageValid = false;
  unsigned long CoverageContentVersion = 0;
  vtkMTimeType CoverageEdgeTime = 0;
  double CoverageLineWidth = 0.0;
  vtkTextureObject* NoiseTexture = nullptr;
  vtkNew<vtkImageData> NoiseImage;
  bool NoiseValid = false;
  unsigned int NoiseImageSeed = 0;
  unsigned int NoiseTextureSeed = 0;
  vtkTextureObject* SurfaceNoiseTexture = nullptr;
  unsigned int SurfaceNoiseTextureSeed = 0;
  // The surface noise of each block of pixels, and what it was computed from.
  vtkNPRQuadProgram NoiseField;
  std::string NoiseFieldSource;
  vtkTextureObject* NoiseFieldTexture = nullptr;
  bool NoiseFieldValid = false;
  unsigned long NoiseFieldContentVersion = 0;
  vtkMTimeType NoiseFieldTime = 0;
  vtkMTimeType NoiseFieldEdgeTime = 0;
  int NoiseFieldBlock = 0;
  // The blocks are those of the renderer's whole image: in a tiled render they start this many
  // pixels before the tile (so that the tiles' noise joins up).
  int NoiseFieldShift[2] = { 0, 0 };
  int NoiseFieldSides[4] = { 0, 0, 0, 0 }; // vtkNPRTilePlacement's
};

vtkStandardNewMacro(vtkNPRSketchPass);

vtkNPRSketchPass::vtkNPRSketchPass()
  : Internal(new Internals)
{
}

vtkNPRSketchPass::~vtkNPRSketchPass()
{
  for (vtkObject* object : { static_cast<vtkObject*>(this->Internal->CoverageTexture),
         static_cast<vtkObject*>(this->Internal->NoiseTexture),
         static_cast<vtkObject*>(this->Internal->SurfaceNoiseTexture),
         static_cast<vtkObject*>(this->Internal->NoiseFieldTexture) })
  {
    if (object)
    {
      object->Delete();
    }
  }
}

const char* vtkNPRSketchPass::GetNoiseSpaceAsString() const
{
  return this->NoiseSpace == SCREEN ? "screen" : "surface";
}

double vtkNPRSketchPass::GetEffectiveUncertainty(vtkRenderer* renderer) const
{
  return this->Uncertainty * vtkNPRWindowScale(renderer);
}

double vtkNPRSketchPass::GetEffectiveNoiseScale(vtkRenderer* renderer) const
{
  return this->NoiseFrequency / 100.0 * vtkNPRSketchNoise::ScreenTexelsPerCell /
    vtkNPRWindowScale(renderer);
}

vtkImageData* vtkNPRSketchPass::GetNoiseImage()
{
  Internals& internal = *this->Internal;
  if (internal.NoiseValid && internal.NoiseImageSeed == this->NoiseSeed)
  {
    return internal.NoiseImage;
  }
  const std::vector<float> tile = vtkNPRSketchNoise::ScreenTile(this->NoiseSeed);
  vtkNew<vtkFloatArray> values;
  values->SetName("noise");
  values->SetNumberOfComponents(2);
  values->SetNumberOfTuples(NoiseSize * NoiseSize);
  std::copy(tile.begin(), tile.end(), values->GetPointer(0));
  internal.NoiseImage->SetDimensions(NoiseSize, NoiseSize, 1);
  internal.NoiseImage->GetPointData()->SetScalars(values);
  internal.NoiseImageSeed = this->NoiseSeed;
  internal.NoiseValid = true;
  return internal.NoiseImage;
}

void vtkNPRSketchPass::GetDisplacement(
  vtkRenderer* renderer, int x, int y, bool surfaces, double displacement[2])
{
  vtkFloatArray* noise =
    vtkFloatArray::SafeDownCast(this->GetNoiseImage()->GetPointData()->GetScalars());
  const double scale = this->GetEffectiveNoiseScale(renderer);
  const double t[2] = { (x + 0.5) * scale - 0.5, (y + 0.5) * scale - 0.5 };
  const double cell[2] = { std::floor(t[0]), std::floor(t[1]) };
  const double f[2] = { t[0] - cell[0], t[1] - cell[1] };
  const int i[2] = { static_cast<int>(cell[0]) & (NoiseSize - 1),
    static_cast<int>(cell[1]) & (NoiseSize - 1) };
  const int j[2] = { (i[0] + 1) & (NoiseSize - 1), (i[1] + 1) & (NoiseSize - 1) };
  double n[2];
  for (int c = 0; c < 2; ++c)
  {
    const double n00 = noise->GetTypedComponent(i[1] * NoiseSize + i[0], c);
    const double n10 = noise->GetTypedComponent(i[1] * NoiseSize + j[0], c);
    const double n01 = noise->GetTypedComponent(j[1] * NoiseSize + i[0], c);
    const double n11 = noise->GetTypedComponent(j[1] * NoiseSize + j[0], c);
    const double bottom = n00 + (n10 - n00) * f[0];
    const double top = n01 + (n11 - n01) * f[0];
    n[c] = bottom + (top - bottom) * f[1];
  }
  double m[4];
  vtkNPRSketchNoise::NormalisedMatrix(surfaces ? this->SurfaceMatrix : this->EdgeMatrix, m);
  const double amplitude = this->GetEffectiveUncertainty(renderer);
  displacement[0] = amplitude * (m[0] * n[0] + m[1] * n[1]);
  displacement[1] = amplitude * (m[2] * n[0] + m[3] * n[1]);
}

bool vtkNPRSketchPass::UpdateImages(const vtkRenderState* state)
{
  vtkRenderer* renderer = state->GetRenderer();
  this->UpdateCoverage(state);
  const double reach =
    this->GetEffectiveUncertainty(renderer) + this->EdgePass->GetEffectiveLineWidth(renderer) + 1.0;
  this->Internal->Noise = this->NoiseSpace == SURFACE
    ? this->RenderSurfaceNoise(state, reach, this->GetSurfaceNoiseBlock(renderer))
    : this->PrepareScreenNoise(static_cast<vtkOpenGLRenderWindow*>(renderer->GetRenderWindow()));
  return this->Internal->Noise != nullptr;
}

void vtkNPRSketchPass::UpdateCoverage(const vtkRenderState* state)
{
  Internals& internal = *this->Internal;
  vtkRenderer* renderer = state->GetRenderer();
  auto* window = static_cast<vtkOpenGLRenderWindow*>(renderer->GetRenderWindow());
  vtkNPRGBufferPass* gbuffer = this->EdgePass->GetGBufferPass();
  const int width = gbuffer->GetDepthTexture()->GetWidth();
  const int height = gbuffer->GetDepthTexture()->GetHeight();
  if (!internal.CoverageTexture)
  {
    internal.CoverageTexture =
      vtkNPRNewTexture(window, vtkTextureObject::Nearest, vtkTextureObject::ClampToEdge);
    internal.CoverageTexture->SetInternalFormat(GL_RGBA32F);
    internal.CoverageTexture->SetFormat(GL_RGBA);
    internal.CoverageTexture->SetDataType(GL_FLOAT);
    internal.CoverageTexture->Allocate2D(width, height, 4, VTK_FLOAT);
  }
  const double lineWidth = this->EdgePass->GetEffectiveLineWidth(renderer);
  if (internal.CoverageValid && internal.CoverageContentVersion == gbuffer->GetContentVersion() &&
    internal.CoverageEdgeTime == this->EdgePass->GetMTime() &&
    internal.CoverageLineWidth == lineWidth &&
    internal.CoverageTexture->GetWidth() == static_cast<unsigned int>(width) &&
    internal.CoverageTexture->GetHeight() == static_cast<unsigned int>(height))
  {
    return;
  }
  // The lines' coverage and depth, unperturbed, at the G-buffer's size, over the content
  // rectangle: the composite takes no line and the far depth outside it, so nothing is cleared.
  internal.CoverageTexture->Resize(width, height);
  {
    vtkNPRRenderTarget::Scope target(
      internal.Target, window, { internal.CoverageTexture }, nullptr, width, height);
    if (!this->EdgePass->RenderLineCoverage(state))
    {
      target.Clear(0.0, 0.0, 0.0, 1.0); // no line, far depth
    }
  }
  internal.CoverageValid = true;
  internal.CoverageContentVersion = gbuffer->GetContentVersion();
  internal.CoverageEdgeTime = this->EdgePass->GetMTime();
  internal.CoverageLineWidth = lineWidth;
}

std::string vtkNPRSketchPass::GetSketchDefines() const
{
  std::ostringstream defines;
  defines << "#define NPR_PAPER " << (this->Paper ? 1 : 0) << "\n#define NPR_REMAPPED_DEPTH "
          << (this->EdgePass->GetGBufferPass()->GetDepthRemapped() ? 1 : 0)
          << "\n#define NPR_SURFACE_NOISE " << (this->NoiseSpace == SURFACE ? 1 : 0) << "\n"
          << this->EdgePass->GetLineColorDefines();
  return defines.str();
}

std::string vtkNPRSketchPass::GetCompositeKey(vtkRenderer* renderer)
{
  // The images follow the G-buffer's content (in the frame's key) and these settings.
  std::ostringstream key;
  key.precision(17);
  key << this->GetSketchDefines() << this->GetMTime() << " " << this->EdgePass->GetMTime() << " "
      << this->GetEffectiveUncertainty(renderer) << " "
      << this->EdgePass->GetEffectiveLineWidth(renderer) << " "
      << this->GetEffectiveNoiseScale(renderer) << " " << this->GetSurfaceNoiseBlock(renderer)
      << " " << this->Internal->Noise;
  return key.str();
}

void vtkNPRSketchPass::GetCompositeRectangle(vtkRenderer* renderer, int rect[4])
{
  vtkNPRGBufferPass* gbuffer = this->EdgePass->GetGBufferPass();
  int whole[4];
  GetWholeRectangle(gbuffer, whole);
  if (this->Paper)
  {
    std::copy_n(whole, 4, rect);
    return;
  }
  // The props' projected bounds, grown by the largest displacement.
  const int* content = gbuffer->GetContentRectangle();
  const int grow = static_cast<int>(std::ceil(this->GetEffectiveUncertainty(renderer))) + 1;
  rect[0] = std::max(0, content[0] - grow);
  rect[1] = std::max(0, content[1] - grow);
  rect[2] = std::max(rect[0] - 1, std::min(whole[2], content[2] + grow));
  rect[3] = std::max(rect[1] - 1, std::min(whole[3], content[3] + grow));
}

bool vtkNPRSketchPass::DrawComposite(const vtkRenderState* state, const int origin[2])
{
  Internals& internal = *this->Internal;
  vtkRenderer* renderer = state->GetRenderer();
  auto* window = static_cast<vtkOpenGLRenderWindow*>(renderer->GetRenderWindow());
  if (internal.Source.empty())
  {
    internal.Source = vtkNPRSketchFS;
    vtkShaderProgram::Substitute(internal.Source, "//NPR::LineColor", vtkNPRLineColor);
    vtkShaderProgram::Substitute(internal.Source, "//NPR::WindowDepth", vtkNPRWindowDepth);
    vtkShaderProgram::Substitute(internal.Source, "//NPR::AcrossTiles", vtkNPRAcrossTiles);
  }
  vtkShaderProgram* program =
    internal.Sketch.Ready(window, internal.Source, this->GetSketchDefines());
  if (!program)
  {
    vtkErrorMacro("the sketch shader did not compile");
    return false;
  }
  vtkNPRGBufferPass* gbuffer = this->EdgePass->GetGBufferPass();
  vtkTextureObject* textures[4] = { gbuffer->GetColorTexture(), gbuffer->GetDepthTexture(),
    internal.CoverageTexture, internal.Noise };
  for (vtkTextureObject* texture : textures)
  {
    texture->Activate();
  }
  this->SetSketchUniforms(program, renderer, origin);
  internal.Sketch.Render();
  for (vtkTextureObject* texture : textures)
  {
    texture->Deactivate();
  }
  return true;
}

void vtkNPRSketchPass::SetSketchUniforms(
  vtkShaderProgram* program, vtkRenderer* renderer, const int origin[2])
{
  Internals& internal = *this->Internal;
  vtkNPRGBufferPass* gbuffer = this->EdgePass->GetGBufferPass();
  program->SetUniformi("colorTexture", gbuffer->GetColorTexture()->GetTextureUnit());
  program->SetUniformi("depthTexture", gbuffer->GetDepthTexture()->GetTextureUnit());
  program->SetUniformi("coverageTexture", internal.CoverageTexture->GetTextureUnit());
  program->SetUniformi("noiseTexture", internal.Noise->GetTextureUnit());
  int tileOffset[2], tileSides[4];
  vtkNPRTilePlacement(renderer, tileOffset, tileSides);
  program->SetUniform1iv("tileSides", 4, tileSides);
  if (this->NoiseSpace == SURFACE)
  {
    program->SetUniformf("noiseBlock", static_cast<float>(this->GetSurfaceNoiseBlock(renderer)));
    const float blockShift[2] = { static_cast<float>(internal.NoiseFieldShift[0]),
      static_cast<float>(internal.NoiseFieldShift[1]) };
    program->SetUniform2f("blockShift", blockShift);
  }
  else
  {
    program->SetUniformf("noiseScale", static_cast<float>(this->GetEffectiveNoiseScale(renderer)));
    program->SetUniform2i("tileOffset", tileOffset);
  }
  const double amplitude = this->GetEffectiveUncertainty(renderer);
  for (int which = 0; which < 2; ++which)
  {
    double m[4];
    vtkNPRSketchNoise::NormalisedMatrix(which == 0 ? this->EdgeMatrix : this->SurfaceMatrix, m);
    float displacement[4];
    for (int i = 0; i < 4; ++i)
    {
      displacement[i] = static_cast<float>(amplitude * m[i]);
    }
    program->SetUniform4f(which == 0 ? "edgeDisplacement" : "surfaceDisplacement", displacement);
  }
  program->SetUniform3f("paperColor", this->PaperColor);
  this->EdgePass->SetLineColorUniforms(program);
  program->SetUniform2i("viewportOrigin", origin);
  const int* written = gbuffer->GetContentRectangle();
  program->SetUniform2i("coverageLow", written);
  program->SetUniform2i("coverageHigh", written + 2);
  if (gbuffer->GetDepthRemapped())
  {
    program->SetUniform2f("nprDepthRemap", gbuffer->GetDepthRemap());
  }
}

vtkTextureObject* vtkNPRSketchPass::PrepareScreenNoise(vtkOpenGLRenderWindow* window)
{
  Internals& internal = *this->Internal;
  vtkImageData* noiseImage = this->GetNoiseImage();
  if (!internal.NoiseTexture || internal.NoiseTextureSeed != this->NoiseSeed)
  {
    if (!internal.NoiseTexture)
    {
      internal.NoiseTexture =
        vtkNPRNewTexture(window, vtkTextureObject::Nearest, vtkTextureObject::Repeat);
    }
    internal.NoiseTexture->SetInternalFormat(GL_RG32F);
    internal.NoiseTexture->SetFormat(GL_RG);
    internal.NoiseTexture->SetDataType(GL_FLOAT);
    internal.NoiseTexture->Create2DFromRaw(NoiseSize, NoiseSize, 2, VTK_FLOAT,
      noiseImage->GetPointData()->GetScalars()->GetVoidPointer(0));
    internal.NoiseTextureSeed = this->NoiseSeed;
  }
  return internal.NoiseTexture;
}

int vtkNPRSketchPass::GetSurfaceNoiseBlock(vtkRenderer* renderer) const
{
  // A noise cell spans at least 8 blocks: the bilinear interpolation between block centres then
  // departs from the noise by under 1 % of its range.
  const double cellPixels = 100.0 / this->NoiseFrequency * vtkNPRWindowScale(renderer);
  return std::max(1, std::min(4, static_cast<int>(cellPixels / 8.0)));
}

vtkTextureObject* vtkNPRSketchPass::RenderSurfaceNoise(
  const vtkRenderState* state, double reach, int block)
{
  Internals& internal = *this->Internal;
  vtkRenderer* renderer = state->GetRenderer();
  auto* window = static_cast<vtkOpenGLRenderWindow*>(renderer->GetRenderWindow());
  vtkNPRGBufferPass* gbuffer = this->EdgePass->GetGBufferPass();
  vtkTextureObject* depth = gbuffer->GetDepthTexture();
  int tileOffset[2], tileSides[4], shift[2];
  vtkNPRTilePlacement(renderer, tileOffset, tileSides);
  shift[0] = tileOffset[0] % block;
  shift[1] = tileOffset[1] % block;
  const int width = (static_cast<int>(depth->GetWidth()) + shift[0] + block - 1) / block;
  const int height = (static_cast<int>(depth->GetHeight()) + shift[1] + block - 1) / block;
  if (!internal.NoiseFieldTexture)
  {
    internal.NoiseFieldTexture =
      vtkNPRNewTexture(window, vtkTextureObject::Nearest, vtkTextureObject::ClampToEdge);
    internal.NoiseFieldTexture->SetInternalFormat(GL_RG32F);
    internal.NoiseFieldTexture->SetFormat(GL_RG);
    internal.NoiseFieldTexture->SetDataType(GL_FLOAT);
    internal.NoiseFieldTexture->Allocate2D(width, height, 2, VTK_FLOAT);
  }
  if (internal.NoiseFieldValid &&
    internal.NoiseFieldContentVersion == gbuffer->GetContentVersion() &&
    internal.NoiseFieldTime == this->GetMTime() &&
    internal.NoiseFieldEdgeTime == this->EdgePass->GetMTime() &&
    internal.NoiseFieldBlock == block && internal.NoiseFieldShift[0] == shift[0] &&
    internal.NoiseFieldShift[1] == shift[1] &&
    internal.NoiseFieldTexture->GetWidth() == static_cast<unsigned int>(width) &&
    internal.NoiseFieldTexture->GetHeight() == static_cast<unsigned int>(height))
  {
    return internal.NoiseFieldTexture;
  }
  vtkShaderProgram* program = this->ReadyNoiseFieldProgram(window, renderer);
  if (!program)
  {
    return nullptr;
  }
  internal.NoiseFieldTexture->Resize(width, height);
  internal.NoiseFieldShift[0] = shift[0];
  internal.NoiseFieldShift[1] = shift[1];
  std::copy(tileSides, tileSides + 4, internal.NoiseFieldSides);
  this->DrawNoiseField(state, program, reach, block);
  internal.NoiseFieldValid = true;
  internal.NoiseFieldContentVersion = gbuffer->GetContentVersion();
  internal.NoiseFieldTime = this->GetMTime();
  internal.NoiseFieldEdgeTime = this->EdgePass->GetMTime();
  internal.NoiseFieldBlock = block;
  return internal.NoiseFieldTexture;
}

vtkShaderProgram* vtkNPRSketchPass::ReadyNoiseFieldProgram(
  vtkOpenGLRenderWindow* window, vtkRenderer* renderer)
{
  Internals& internal = *this->Internal;
  std::ostringstream defines;
  defines << "#define NPR_REMAPPED_DEPTH "
          << (this->EdgePass->GetGBufferPass()->GetDepthRemapped() ? 1 : 0)
          << "\n#define NPR_PERSPECTIVE "
          << (renderer->GetActiveCamera()->GetParallelProjection() ? 0 : 1) << "\n";
  if (internal.NoiseFieldSource.empty())
  {
    internal.NoiseFieldSource = vtkNPRSketchNoiseFS;
    vtkShaderProgram::Substitute(
      internal.NoiseFieldSource, "//NPR::WindowDepth", vtkNPRWindowDepth);
    vtkShaderProgram::Substitute(
      internal.NoiseFieldSource, "//NPR::AcrossTiles", vtkNPRAcrossTiles);
  }
  vtkShaderProgram* program =
    internal.NoiseField.Ready(window, internal.NoiseFieldSource, defines.str());
  if (!program)
  {
    vtkErrorMacro("the sketch's surface noise shader did not compile");
  }
  return program;
}

void vtkNPRSketchPass::DrawNoiseField(
  const vtkRenderState* state, vtkShaderProgram* program, double reach, int block)
{
  Internals& internal = *this->Internal;
  vtkRenderer* renderer = state->GetRenderer();
  auto* window = static_cast<vtkOpenGLRenderWindow*>(renderer->GetRenderWindow());
  vtkNPRGBufferPass* gbuffer = this->EdgePass->GetGBufferPass();
  vtkTextureObject* depth = gbuffer->GetDepthTexture();
  vtkTextureObject* tile = this->PrepareSurfaceNoiseTile(window);
  const int width = internal.NoiseFieldTexture->GetWidth();
  const int height = internal.NoiseFieldTexture->GetHeight();
  vtkNPRRenderTarget::Scope target(
    internal.Target, window, { internal.NoiseFieldTexture }, nullptr, width, height);
  target.Clear(0.0, 0.0, 0.0, 0.0); // no displacement where nothing is near
  // Only the blocks within reach of the props' projected bounds: elsewhere no line or fill can
  // land, and most of this pass's work is the search for a surface from the empty blocks.
  const int* content = gbuffer->GetContentRectangle();
  const int grow = static_cast<int>(std::ceil(reach)) + 2 * block;
  const int* shift = internal.NoiseFieldShift;
  const int blocks[4] = { std::max(0, (content[0] + shift[0] - grow) / block),
    std::max(0, (content[1] + shift[1] - grow) / block),
    std::min(width - 1, (content[2] + shift[0] + grow) / block),
    std::min(height - 1, (content[3] + shift[1] + grow) / block) };
  target.ScissorTo(blocks);
  depth->Activate();
  tile->Activate();
  program->SetUniformi("depthTexture", depth->GetTextureUnit());
  program->SetUniformi("noiseTexture", tile->GetTextureUnit());
  program->SetUniformf("noiseBlock", static_cast<float>(block));
  const float blockShift[2] = { static_cast<float>(shift[0]), static_cast<float>(shift[1]) };
  program->SetUniform2f("blockShift", blockShift);
  program->SetUniform1iv("tileSides", 4, internal.NoiseFieldSides);
  if (gbuffer->GetDepthRemapped())
  {
    program->SetUniform2f("nprDepthRemap", gbuffer->GetDepthRemap());
  }
  this->SetSurfaceNoiseUniforms(program, renderer, depth->GetHeight(), reach);
  internal.NoiseField.Render();
  depth->Deactivate();
  tile->Deactivate();
}

vtkTextureObject* vtkNPRSketchPass::PrepareSurfaceNoiseTile(vtkOpenGLRenderWindow* window)
{
  Internals& internal = *this->Internal;
  if (!internal.SurfaceNoiseTexture || internal.SurfaceNoiseTextureSeed != this->NoiseSeed)
  {
    if (!internal.SurfaceNoiseTexture)
    {
      internal.SurfaceNoiseTexture =
        vtkNPRNewTexture(window, vtkTextureObject::Linear, vtkTextureObject::Repeat);
    }
    auto tile = vtkNPRSketchNoise::SurfaceTile(this->NoiseSeed);
    vtkTextureObject* texture = internal.SurfaceNoiseTexture;
    texture->SetInternalFormat(GL_RGBA8);
    texture->SetFormat(GL_RGBA);
    texture->SetDataType(GL_UNSIGNED_BYTE);
    texture->Create3DFromRaw(vtkNPRSketchNoise::SurfaceTileSize, vtkNPRSketchNoise::SurfaceTileSize,
      vtkNPRSketchNoise::SurfaceTileSize, 4, VTK_UNSIGNED_CHAR,
      const_cast<unsigned char*>(tile->data()));
    internal.SurfaceNoiseTextureSeed = this->NoiseSeed;
  }
  return internal.SurfaceNoiseTexture;
}

void vtkNPRSketchPass::SetSurfaceNoiseUniforms(
  vtkShaderProgram* program, vtkRenderer* renderer, int height, double reach)
{
  vtkCamera* camera = renderer->GetActiveCamera();
  vtkMatrix4x4 *worldToView, *viewToDevice, *worldToDevice;
  vtkMatrix3x3* normalMatrix;
  // The matrices the G-buffer was drawn with, kept by VTK transposed (GLSL's layout).
  static_cast<vtkOpenGLCamera*>(camera)->GetKeyMatrices(
    renderer, worldToView, normalMatrix, viewToDevice, worldToDevice);
  vtkNew<vtkMatrix4x4> deviceToView;
  vtkMatrix4x4::Invert(viewToDevice, deviceToView);
  program->SetUniformMatrix("deviceToView", deviceToView);

  // World positions relative to an anchor near the props, on a grid of the noise period at any
  // octave up to 8 times their size: the noise is the same as without it, with small numbers.
  double bounds[6];
  renderer->ComputeVisiblePropBounds(bounds);
  double anchor[3] = { 0.0, 0.0, 0.0 };
  if (vtkMath::AreBoundsInitialized(bounds))
  {
    const double diagonal = std::sqrt(vtkMath::Distance2BetweenPoints(bounds, bounds + 3));
    if (std::isfinite(diagonal) && diagonal > 0.0)
    {
      const double grid =
        vtkNPRSketchNoise::SurfaceTileCells * std::exp2(std::ceil(std::log2(8.0 * diagonal)));
      for (int i = 0; i < 3; ++i)
      {
        anchor[i] = std::round(0.5 * (bounds[2 * i] + bounds[2 * i + 1]) / grid) * grid;
      }
    }
  }
  vtkNew<vtkMatrix4x4> viewToNoise;
  vtkMatrix4x4::Invert(worldToView, viewToNoise);
  for (int i = 0; i < 3; ++i)
  {
    // Transposed: the translation is the last row.
    viewToNoise->SetElement(3, i, viewToNoise->GetElement(3, i) - anchor[i]);
  }
  program->SetUniformMatrix("viewToNoise", viewToNoise);
  // A pixel's height in view units (at view depth 1 in perspective): 2 / height NDC units over
  // the projection's y scale.
  const double yScale = viewToDevice->GetElement(1, 1);
  program->SetUniformf(
    "pixelFootprint", static_cast<float>(yScale != 0.0 ? 2.0 / height / std::abs(yScale) : 0.0));
  program->SetUniformf(
    "cellPixels", static_cast<float>(100.0 / this->NoiseFrequency * vtkNPRWindowScale(renderer)));
  program->SetUniformf("noiseCells", static_cast<float>(vtkNPRSketchNoise::SurfaceTileCells));
  program->SetUniformf("noiseReach", static_cast<float>(reach));
}

void vtkNPRSketchPass::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Superclass::ReleaseGraphicsResources(window);
  Internals& internal = *this->Internal;
  internal.Noise = nullptr;
  internal.CoverageValid = false;
  internal.NoiseFieldValid = false;
  internal.Sketch.Release(window);
  internal.NoiseField.Release(window);
  for (vtkTextureObject** texture : { &internal.CoverageTexture, &internal.NoiseTexture,
         &internal.SurfaceNoiseTexture, &internal.NoiseFieldTexture })
  {
    if (*texture)
    {
      (*texture)->ReleaseGraphicsResources(window);
      (*texture)->Delete();
      *texture = nullptr;
    }
  }
  internal.Target.ReleaseGraphicsResources(window);
}

void vtkNPRSketchPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Uncertainty: " << this->Uncertainty << "\n";
  os << indent << "NoiseSeed: " << this->NoiseSeed << "\n";
  os << indent << "NoiseFrequency: " << this->NoiseFrequency << "\n";
  os << indent << "NoiseSpace: " << this->GetNoiseSpaceAsString() << "\n";
  os << indent << "EdgeMatrix: " << this->EdgeMatrix[0] << " " << this->EdgeMatrix[1] << " "
     << this->EdgeMatrix[2] << " " << this->EdgeMatrix[3] << "\n";
  os << indent << "SurfaceMatrix: " << this->SurfaceMatrix[0] << " " << this->SurfaceMatrix[1]
     << " " << this->SurfaceMatrix[2] << " " << this->SurfaceMatrix[3] << "\n";
  os << indent << "Paper: " << this->Paper << " color " << this->PaperColor[0] << " "
     << this->PaperColor[1] << " " << this->PaperColor[2] << "\n";
}
