// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNPRSketchPass.h"

#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkNPREdgePass.h"
#include "vtkNPRGBufferPass.h"
#include "vtkNPROpenGL.h"
#include "vtkNPRPassUtilities.h"
#include "vtkNPRQuadProgram.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkPointData.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include "vtkNPRLineColor.h"
#include "vtkNPRSketchFS.h"
#include "vtkNPRWindowDepth.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <sstream>
#include <vector>

namespace
{
constexpr int NoiseSize = 256; // texels of the tile on each side
constexpr int NoiseCells = 8;  // lattice cells of the tile on each side
constexpr int TexelsPerCell = NoiseSize / NoiseCells;

// Periodic 2D Perlin gradient noise over a NoiseCells x NoiseCells lattice.
struct GradientNoise
{
  double Gradients[NoiseCells][NoiseCells][2];

  explicit GradientNoise(std::mt19937& random)
  {
    for (auto& row : this->Gradients)
    {
      for (auto& gradient : row)
      {
        // The raw 32-bit output, so that a seed gives the same angles on every platform.
        const double angle = random() * (2.0 * vtkMath::Pi() / 4294967296.0);
        gradient[0] = std::cos(angle);
        gradient[1] = std::sin(angle);
      }
    }
  }

  static double Fade(double t) { return t * t * t * (t * (t * 6.0 - 15.0) + 10.0); }

  double Corner(int i, int j, double dx, double dy) const
  {
    const double* g = this->Gradients[i % NoiseCells][j % NoiseCells];
    return g[0] * dx + g[1] * dy;
  }

  // x, y in lattice cells, in [0, NoiseCells).
  double operator()(double x, double y) const
  {
    const int i = static_cast<int>(std::floor(x));
    const int j = static_cast<int>(std::floor(y));
    const double fx = x - i, fy = y - j;
    const double u = Fade(fx), v = Fade(fy);
    const double n00 = this->Corner(i, j, fx, fy);
    const double n10 = this->Corner(i + 1, j, fx - 1.0, fy);
    const double n01 = this->Corner(i, j + 1, fx, fy - 1.0);
    const double n11 = this->Corner(i + 1, j + 1, fx - 1.0, fy - 1.0);
    return (n00 + u * (n10 - n00)) + v * ((n01 + u * (n11 - n01)) - (n00 + u * (n10 - n00)));
  }
};

// The matrix scaled down to operator norm 1 when its norm is larger.
void NormalisedMatrix(const double m[4], double out[4])
{
  const double t = m[0] * m[0] + m[1] * m[1] + m[2] * m[2] + m[3] * m[3];
  const double d = m[0] * m[3] - m[1] * m[2];
  const double norm = std::sqrt(0.5 * (t + std::sqrt(std::max(0.0, t * t - 4.0 * d * d))));
  const double scale = norm > 1.0 ? 1.0 / norm : 1.0;
  for (int i = 0; i < 4; ++i)
  {
    out[i] = std::isfinite(m[i]) ? m[i] * scale : 0.0;
  }
}
}

struct vtkNPRSketchPass::Internals
{
  vtkNPRQuadProgram Sketch;
  std::string Source;
  vtkOpenGLFramebufferObject* Framebuffer = nullptr;
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
};

vtkStandardNewMacro(vtkNPRSketchPass);
vtkCxxSetObjectMacro(vtkNPRSketchPass, EdgePass, vtkNPREdgePass);

vtkNPRSketchPass::vtkNPRSketchPass()
  : Internal(new Internals)
{
}

vtkNPRSketchPass::~vtkNPRSketchPass()
{
  this->SetEdgePass(nullptr);
  for (vtkObject* object : { static_cast<vtkObject*>(this->Internal->CoverageTexture),
         static_cast<vtkObject*>(this->Internal->NoiseTexture),
         static_cast<vtkObject*>(this->Internal->Framebuffer) })
  {
    if (object)
    {
      object->Delete();
    }
  }
}

double vtkNPRSketchPass::GetEffectiveUncertainty(vtkRenderer* renderer) const
{
  return this->Uncertainty * vtkNPRWindowScale(renderer);
}

double vtkNPRSketchPass::GetEffectiveNoiseScale(vtkRenderer* renderer) const
{
  return this->NoiseFrequency / 100.0 * TexelsPerCell / vtkNPRWindowScale(renderer);
}

vtkImageData* vtkNPRSketchPass::GetNoiseImage()
{
  Internals& internal = *this->Internal;
  if (internal.NoiseValid && internal.NoiseImageSeed == this->NoiseSeed)
  {
    return internal.NoiseImage;
  }
  std::mt19937 random(this->NoiseSeed);
  const GradientNoise noiseX(random);
  const GradientNoise noiseY(random);
  vtkNew<vtkFloatArray> values;
  values->SetName("noise");
  values->SetNumberOfComponents(2);
  values->SetNumberOfTuples(NoiseSize * NoiseSize);
  std::vector<double> vectors(2 * NoiseSize * NoiseSize);
  double largest = 0.0;
  for (int y = 0; y < NoiseSize; ++y)
  {
    for (int x = 0; x < NoiseSize; ++x)
    {
      const double u = static_cast<double>(x) / TexelsPerCell;
      const double v = static_cast<double>(y) / TexelsPerCell;
      double* n = &vectors[2 * (y * NoiseSize + x)];
      n[0] = noiseX(u, v);
      n[1] = noiseY(u, v);
      largest = std::max(largest, std::hypot(n[0], n[1]));
    }
  }
  // Vectors of length up to 1: bilinear mixes of them stay within 1.
  const double scale = largest > 0.0 ? 1.0 / largest : 0.0;
  for (vtkIdType i = 0; i < NoiseSize * NoiseSize; ++i)
  {
    // Rounded towards zero so that float storage cannot push a length above 1.
    for (int c = 0; c < 2; ++c)
    {
      const double value = vectors[2 * i + c] * scale * (1.0 - 1e-6);
      values->SetTypedComponent(i, c, static_cast<float>(value));
    }
  }
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
  NormalisedMatrix(surfaces ? this->SurfaceMatrix : this->EdgeMatrix, m);
  const double amplitude = this->GetEffectiveUncertainty(renderer);
  displacement[0] = amplitude * (m[0] * n[0] + m[1] * n[1]);
  displacement[1] = amplitude * (m[2] * n[0] + m[3] * n[1]);
}

void vtkNPRSketchPass::Render(const vtkRenderState* state)
{
  vtkOpenGLClearErrorMacro();
  this->NumberOfRenderedProps = 0;
  vtkNPRGBufferPass* gbuffer = this->EdgePass ? this->EdgePass->GetGBufferPass() : nullptr;
  if (!gbuffer)
  {
    vtkWarningMacro("no edge pass with a G-buffer: nothing drawn");
    return;
  }
  if (gbuffer->GetLastRenderWasSelection() || !gbuffer->GetHasContent())
  {
    return; // a picking render, or nothing was drawn
  }
  vtkRenderer* renderer = state->GetRenderer();
  auto* window = static_cast<vtkOpenGLRenderWindow*>(renderer->GetRenderWindow());
  vtkOpenGLState* glState = window->GetState();
  Internals& internal = *this->Internal;
  vtkTextureObject* color = gbuffer->GetColorTexture();
  vtkTextureObject* depth = gbuffer->GetDepthTexture();
  const int width = depth->GetWidth();
  const int height = depth->GetHeight();

  // ---- The lines' coverage and depth, unperturbed, into a texture of the G-buffer's size,
  // recomputed only when the G-buffer or the line settings changed ----
  if (!internal.CoverageTexture)
  {
    internal.CoverageTexture = vtkTextureObject::New();
    internal.CoverageTexture->SetContext(window);
    internal.CoverageTexture->SetMinificationFilter(vtkTextureObject::Nearest);
    internal.CoverageTexture->SetMagnificationFilter(vtkTextureObject::Nearest);
    internal.CoverageTexture->SetWrapS(vtkTextureObject::ClampToEdge);
    internal.CoverageTexture->SetWrapT(vtkTextureObject::ClampToEdge);
    internal.CoverageTexture->SetInternalFormat(GL_RGBA32F);
    internal.CoverageTexture->SetFormat(GL_RGBA);
    internal.CoverageTexture->SetDataType(GL_FLOAT);
    internal.CoverageTexture->Allocate2D(width, height, 4, VTK_FLOAT);
    internal.Framebuffer = vtkOpenGLFramebufferObject::New();
    internal.Framebuffer->SetContext(window);
  }
  const double lineWidth = this->EdgePass->GetEffectiveLineWidth(renderer);
  const bool coverageCurrent = internal.CoverageValid &&
    internal.CoverageContentVersion == gbuffer->GetContentVersion() &&
    internal.CoverageEdgeTime == this->EdgePass->GetMTime() &&
    internal.CoverageLineWidth == lineWidth &&
    internal.CoverageTexture->GetWidth() == static_cast<unsigned int>(width) &&
    internal.CoverageTexture->GetHeight() == static_cast<unsigned int>(height);
  if (!coverageCurrent)
  {
    internal.CoverageTexture->Resize(width, height);
    vtkOpenGLState::ScopedglViewport viewportSaver(glState);
    vtkOpenGLState::ScopedglClearColor clearColorSaver(glState);
    vtkOpenGLState::ScopedglEnableDisable scissorTestSaver(glState, GL_SCISSOR_TEST);
    glState->PushFramebufferBindings();
    internal.Framebuffer->Bind();
    internal.Framebuffer->AddColorAttachment(0, internal.CoverageTexture);
    internal.Framebuffer->ActivateDrawBuffers(1);
    internal.Framebuffer->StartNonOrtho(width, height);
    glState->vtkglViewport(0, 0, width, height);
    glState->vtkglDisable(GL_SCISSOR_TEST);
    glState->vtkglClearColor(0.0, 0.0, 0.0, 1.0); // no line, far depth
    glState->vtkglClear(GL_COLOR_BUFFER_BIT);
    this->EdgePass->RenderLineCoverage(state);
    internal.Framebuffer->RemoveColorAttachments(1);
    glState->PopFramebufferBindings();
    internal.CoverageValid = true;
    internal.CoverageContentVersion = gbuffer->GetContentVersion();
    internal.CoverageEdgeTime = this->EdgePass->GetMTime();
    internal.CoverageLineWidth = lineWidth;
  }

  // ---- The noise tile ----
  vtkImageData* noiseImage = this->GetNoiseImage();
  if (!internal.NoiseTexture || internal.NoiseTextureSeed != this->NoiseSeed)
  {
    if (!internal.NoiseTexture)
    {
      internal.NoiseTexture = vtkTextureObject::New();
    }
    internal.NoiseTexture->SetContext(window);
    internal.NoiseTexture->SetMinificationFilter(vtkTextureObject::Nearest);
    internal.NoiseTexture->SetMagnificationFilter(vtkTextureObject::Nearest);
    internal.NoiseTexture->SetWrapS(vtkTextureObject::Repeat);
    internal.NoiseTexture->SetWrapT(vtkTextureObject::Repeat);
    internal.NoiseTexture->SetInternalFormat(GL_RG32F);
    internal.NoiseTexture->SetFormat(GL_RG);
    internal.NoiseTexture->SetDataType(GL_FLOAT);
    internal.NoiseTexture->Create2DFromRaw(NoiseSize, NoiseSize, 2, VTK_FLOAT,
      noiseImage->GetPointData()->GetScalars()->GetVoidPointer(0));
    internal.NoiseTextureSeed = this->NoiseSeed;
  }

  // ---- The sketch into the current framebuffer ----
  std::ostringstream defines;
  defines << "#define NPR_PAPER " << (this->Paper ? 1 : 0) << "\n#define NPR_REMAPPED_DEPTH "
          << (gbuffer->GetDepthRemapped() ? 1 : 0) << "\n";
  if (internal.Source.empty())
  {
    internal.Source = vtkNPRSketchFS;
    vtkShaderProgram::Substitute(internal.Source, "//NPR::LineColor", vtkNPRLineColor);
    vtkShaderProgram::Substitute(internal.Source, "//NPR::WindowDepth", vtkNPRWindowDepth);
  }
  vtkShaderProgram* program = internal.Sketch.Ready(window, internal.Source, defines.str());
  if (!program)
  {
    vtkErrorMacro("the sketch shader did not compile");
    return;
  }
  color->Activate();
  depth->Activate();
  internal.CoverageTexture->Activate();
  internal.NoiseTexture->Activate();
  program->SetUniformi("colorTexture", color->GetTextureUnit());
  program->SetUniformi("depthTexture", depth->GetTextureUnit());
  program->SetUniformi("coverageTexture", internal.CoverageTexture->GetTextureUnit());
  program->SetUniformi("noiseTexture", internal.NoiseTexture->GetTextureUnit());
  program->SetUniformf("noiseScale", static_cast<float>(this->GetEffectiveNoiseScale(renderer)));
  const double amplitude = this->GetEffectiveUncertainty(renderer);
  for (int which = 0; which < 2; ++which)
  {
    double m[4];
    NormalisedMatrix(which == 0 ? this->EdgeMatrix : this->SurfaceMatrix, m);
    float displacement[4];
    for (int i = 0; i < 4; ++i)
    {
      displacement[i] = static_cast<float>(amplitude * m[i]);
    }
    program->SetUniform4f(which == 0 ? "edgeDisplacement" : "surfaceDisplacement", displacement);
  }
  program->SetUniform3f("paperColor", this->PaperColor);
  program->SetUniform3f("silhouetteColor", this->EdgePass->GetSilhouetteColor());
  program->SetUniform3f("creaseColor", this->EdgePass->GetCreaseColor());
  program->SetUniform3f("contourColor", this->EdgePass->GetContourColor());
  int origin[2];
  vtkNPRViewportOrigin(state, origin);
  program->SetUniform2i("viewportOrigin", origin);
  if (gbuffer->GetDepthRemapped())
  {
    program->SetUniform2f("nprDepthRemap", gbuffer->GetDepthRemap());
  }

  vtkNPRCompositeState compositeState(glState);
  compositeState.Apply(origin, width, height);
  if (this->Paper)
  {
    glState->vtkglScissor(origin[0], origin[1], width, height);
  }
  else
  {
    // The props' projected bounds, grown by the largest displacement.
    const int* rect = gbuffer->GetContentRectangle();
    const int grow = static_cast<int>(std::ceil(amplitude)) + 1;
    const int x0 = std::max(0, rect[0] - grow), y0 = std::max(0, rect[1] - grow);
    const int x1 = std::min(width - 1, rect[2] + grow), y1 = std::min(height - 1, rect[3] + grow);
    glState->vtkglScissor(
      origin[0] + x0, origin[1] + y0, std::max(0, x1 - x0 + 1), std::max(0, y1 - y0 + 1));
  }
  internal.Sketch.Render();

  color->Deactivate();
  depth->Deactivate();
  internal.CoverageTexture->Deactivate();
  internal.NoiseTexture->Deactivate();
  this->NumberOfRenderedProps = gbuffer->GetNumberOfRenderedProps();
  vtkOpenGLCheckErrorMacro("failed after vtkNPRSketchPass::Render");
}

void vtkNPRSketchPass::ReleaseGraphicsResources(vtkWindow* window)
{
  Internals& internal = *this->Internal;
  internal.CoverageValid = false;
  internal.Sketch.Release(window);
  for (vtkTextureObject** texture : { &internal.CoverageTexture, &internal.NoiseTexture })
  {
    if (*texture)
    {
      (*texture)->ReleaseGraphicsResources(window);
      (*texture)->Delete();
      *texture = nullptr;
    }
  }
  if (internal.Framebuffer)
  {
    internal.Framebuffer->ReleaseGraphicsResources(window);
    internal.Framebuffer->Delete();
    internal.Framebuffer = nullptr;
  }
}

void vtkNPRSketchPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "EdgePass: " << this->EdgePass << "\n";
  os << indent << "Uncertainty: " << this->Uncertainty << "\n";
  os << indent << "NoiseSeed: " << this->NoiseSeed << "\n";
  os << indent << "NoiseFrequency: " << this->NoiseFrequency << "\n";
  os << indent << "EdgeMatrix: " << this->EdgeMatrix[0] << " " << this->EdgeMatrix[1] << " "
     << this->EdgeMatrix[2] << " " << this->EdgeMatrix[3] << "\n";
  os << indent << "SurfaceMatrix: " << this->SurfaceMatrix[0] << " " << this->SurfaceMatrix[1]
     << " " << this->SurfaceMatrix[2] << " " << this->SurfaceMatrix[3] << "\n";
  os << indent << "Paper: " << this->Paper << " color " << this->PaperColor[0] << " "
     << this->PaperColor[1] << " " << this->PaperColor[2] << "\n";
}
