// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNPRDrawingPass.h"

#include "vtkNPRDrawingFS.h"
#include "vtkNPRDrawingLines.h"
#include "vtkNPREdgePass.h"
#include "vtkNPRFrameSignature.h"
#include "vtkNPRGBufferPass.h"
#include "vtkNPRNearestDepth.h"
#include "vtkNPROpenGL.h"
#include "vtkNPRPassUtilities.h"
#include "vtkNPRQuadProgram.h"
#include "vtkNPRStrokePainter.h"
#include "vtkNPRWindowDepth.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkPolyData.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

struct vtkNPRDrawingPass::Internals
{
  vtkNew<vtkNPRDrawingLines> Lines;
  vtkTextureObject* StrokeTexture = nullptr;
  vtkNPRQuadProgram Composite;
  std::string CompositeSource;
  // What the strokes in the texture were made from.
  bool StrokesValid = false;
  vtkNPRFrameSignature Signature;
  vtkIdType StrokeUpdates = 0;
  std::vector<unsigned char> Pixels;
};

vtkStandardNewMacro(vtkNPRDrawingPass);

vtkNPRDrawingPass::vtkNPRDrawingPass()
  : Internal(new Internals)
{
}

vtkNPRDrawingPass::~vtkNPRDrawingPass()
{
  if (this->Internal->StrokeTexture)
  {
    this->Internal->StrokeTexture->Delete();
  }
}

vtkNPRDrawingLines* vtkNPRDrawingPass::GetDrawingLines()
{
  return this->Internal->Lines;
}

vtkPolyData* vtkNPRDrawingPass::GetStrokes()
{
  return this->Internal->Lines->GetStrokes();
}

vtkIdType vtkNPRDrawingPass::GetNumberOfStrokeUpdates() const
{
  return this->Internal->StrokeUpdates;
}

bool vtkNPRDrawingPass::UpdateImages(const vtkRenderState* state)
{
  Internals& internal = *this->Internal;
  vtkTextureObject* depth = this->EdgePass->GetGBufferPass()->GetDepthTexture();
  const int width = depth->GetWidth();
  const int height = depth->GetHeight();
  // The strokes, computed and rasterised again only when the frame changed.
  const vtkMTimeType settingsTime = std::max(this->GetMTime(), this->EdgePass->GetMTime());
  vtkNPRFrameSignature signature =
    vtkNPRTakeFrameSignature(state, width, height, false, false, settingsTime);
  if (internal.StrokesValid && signature == internal.Signature && internal.StrokeTexture)
  {
    return true;
  }
  if (!this->UpdateStrokes(state->GetRenderer(), width, height))
  {
    return false;
  }
  auto* window = static_cast<vtkOpenGLRenderWindow*>(state->GetRenderer()->GetRenderWindow());
  if (!internal.StrokeTexture)
  {
    internal.StrokeTexture =
      vtkNPRNewTexture(window, vtkTextureObject::Nearest, vtkTextureObject::ClampToEdge);
  }
  internal.StrokeTexture->Create2DFromRaw(
    width, height, 4, VTK_UNSIGNED_CHAR, internal.Pixels.data());
  internal.Signature = signature;
  internal.StrokesValid = true;
  ++internal.StrokeUpdates;
  return true;
}

bool vtkNPRDrawingPass::UpdateStrokes(vtkRenderer* renderer, int width, int height)
{
  Internals& internal = *this->Internal;
  vtkNPRDrawingLines* lines = internal.Lines;
  lines->SetRenderer(renderer);
  lines->SetSize(width, height);
  const vtkNPRStrokeStyle style = vtkNPRMakeStrokeStyle(this, this->EdgePass, renderer);
  vtkNPRSelectStrokeLines(lines, style, this->EdgePass);
  const bool updated = lines->Update();
  // Not kept: the renderer holds this pass, so a reference back would be a cycle (a leak).
  lines->SetRenderer(nullptr);
  if (!updated)
  {
    return false;
  }
  std::string error;
  if (!vtkNPRRasterizeStrokes(lines->GetStrokes(), style, width, height, internal.Pixels, error))
  {
    vtkErrorMacro("the strokes could not be rasterised: " << error);
    return false;
  }
  return true;
}

std::string vtkNPRDrawingPass::GetDrawingDefines(vtkRenderer* renderer) const
{
  const double reach = std::ceil(0.5 * this->EdgePass->GetEffectiveLineWidth(renderer)) + 1.0;
  std::ostringstream defines;
  defines << "#define NPR_RADIUS " << static_cast<int>(reach) << "\n#define NPR_REMAPPED_DEPTH "
          << (this->EdgePass->GetGBufferPass()->GetDepthRemapped() ? 1 : 0) << "\n";
  return defines.str();
}

std::string vtkNPRDrawingPass::GetCompositeKey(vtkRenderer* renderer)
{
  // The strokes follow the frame's signature; their texture's version is the update count.
  std::ostringstream key;
  key.precision(17);
  key << this->GetDrawingDefines(renderer) << this->Internal->StrokeUpdates << " "
      << this->FaceColor[0] << " " << this->FaceColor[1] << " " << this->FaceColor[2];
  return key.str();
}

void vtkNPRDrawingPass::GetCompositeRectangle(vtkRenderer*, int rect[4])
{
  GetWholeRectangle(this->EdgePass->GetGBufferPass(), rect);
}

bool vtkNPRDrawingPass::DrawComposite(const vtkRenderState* state, const int origin[2])
{
  Internals& internal = *this->Internal;
  vtkRenderer* renderer = state->GetRenderer();
  auto* window = static_cast<vtkOpenGLRenderWindow*>(renderer->GetRenderWindow());
  if (internal.CompositeSource.empty())
  {
    internal.CompositeSource = vtkNPRDrawingFS;
    vtkShaderProgram::Substitute(internal.CompositeSource, "//NPR::WindowDepth", vtkNPRWindowDepth);
    vtkShaderProgram::Substitute(
      internal.CompositeSource, "//NPR::NearestDepth", vtkNPRNearestDepth);
  }
  vtkShaderProgram* program =
    internal.Composite.Ready(window, internal.CompositeSource, this->GetDrawingDefines(renderer));
  if (!program)
  {
    vtkErrorMacro("the drawing composite shader did not compile");
    return false;
  }
  vtkNPRGBufferPass* gbuffer = this->EdgePass->GetGBufferPass();
  vtkTextureObject* depth = gbuffer->GetDepthTexture();
  internal.StrokeTexture->Activate();
  depth->Activate();
  program->SetUniformi("strokeTexture", internal.StrokeTexture->GetTextureUnit());
  program->SetUniformi("depthTexture", depth->GetTextureUnit());
  program->SetUniform3f("faceColor", this->FaceColor);
  program->SetUniform2i("viewportOrigin", origin);
  if (gbuffer->GetDepthRemapped())
  {
    program->SetUniform2f("nprDepthRemap", gbuffer->GetDepthRemap());
  }
  internal.Composite.Render();
  internal.StrokeTexture->Deactivate();
  depth->Deactivate();
  return true;
}

void vtkNPRDrawingPass::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Superclass::ReleaseGraphicsResources(window);
  Internals& internal = *this->Internal;
  internal.Composite.Release(window);
  if (internal.StrokeTexture)
  {
    internal.StrokeTexture->ReleaseGraphicsResources(window);
    internal.StrokeTexture->Delete();
    internal.StrokeTexture = nullptr;
  }
  internal.StrokesValid = false;
}

void vtkNPRDrawingPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "HiddenLines: " << this->HiddenLines << "\n";
  os << indent << "FaceColor: " << this->FaceColor[0] << " " << this->FaceColor[1] << " "
     << this->FaceColor[2] << "\n";
  os << indent << "HiddenLineColor: " << this->HiddenLineColor[0] << " " << this->HiddenLineColor[1]
     << " " << this->HiddenLineColor[2] << "\n";
  os << indent << "HiddenLineWidth: " << this->HiddenLineWidth << "\n";
  os << indent << "DashLength: " << this->DashLength << " GapLength: " << this->GapLength << "\n";
  os << indent << "TaperLength: " << this->TaperLength << "\n";
  os << indent << "CurvatureWidth: " << this->CurvatureWidth << "\n";
  os << indent << "NumberOfStrokeUpdates: " << this->Internal->StrokeUpdates << "\n";
}
