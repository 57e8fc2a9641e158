// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNPRImageEffectPass.h"

#include "vtkNPRGBufferPass.h"
#include "vtkNPROpenGL.h"
#include "vtkNPRPassUtilities.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkTexture.h"
#include "vtkTextureObject.h"
#include "vtkVersionMacros.h"

#include <sstream>

struct vtkNPRImageEffectPass::Internals
{
  // The last composite, for frames in which nothing changed (KeepUnchangedComposite).
  vtkNPRKeptImage Kept;
  std::string Key; // what the last composite was drawn from; empty: not reusable
  int FramesSinceUnchanged = KeepAfterUnchanged + 1;
  // Keep a changed frame's composite while one of this many previous frames was unchanged.
  static constexpr int KeepAfterUnchanged = 8;
};

vtkNPRImageEffectPass::vtkNPRImageEffectPass()
  : Internal(new Internals)
{
}

vtkNPRImageEffectPass::~vtkNPRImageEffectPass() = default;

void vtkNPRImageEffectPass::Render(const vtkRenderState* state)
{
  vtkOpenGLClearErrorMacro();
  this->NumberOfRenderedProps = 0;
  vtkNPRGBufferPass* gbuffer = this->GetReadyGBuffer(state);
  if (!gbuffer)
  {
    return;
  }
  vtkRenderer* renderer = state->GetRenderer();
  int origin[2];
  vtkNPRViewportOrigin(state, origin);
  int rect[4];
  this->GetCompositeRectangle(renderer, rect);
  const int windowRect[4] = { origin[0] + rect[0], origin[1] + rect[1], origin[0] + rect[2],
    origin[1] + rect[3] };
  if (this->RestoreUnchanged(renderer, windowRect))
  {
    ++this->NumberOfKeptCompositeRestores;
  }
  else
  {
    auto* window = static_cast<vtkOpenGLRenderWindow*>(renderer->GetRenderWindow());
    vtkTextureObject* depth = gbuffer->GetDepthTexture();
    vtkNPRCompositeState compositeState(window->GetState());
    compositeState.Apply(origin, depth->GetWidth(), depth->GetHeight());
    window->GetState()->vtkglScissor(windowRect[0], windowRect[1],
      windowRect[2] - windowRect[0] + 1, windowRect[3] - windowRect[1] + 1);
    if (!this->DrawComposite(state, origin))
    {
      this->Internal->Key.clear();
      return;
    }
    this->KeepComposite(renderer, windowRect);
  }
  this->NumberOfRenderedProps = gbuffer->GetNumberOfRenderedProps();
  vtkOpenGLCheckErrorMacro("failed after the composite");
}

vtkNPRGBufferPass* vtkNPRImageEffectPass::GetReadyGBuffer(const vtkRenderState* state)
{
  vtkNPRGBufferPass* gbuffer = this->GetGBuffer();
  if (!gbuffer || gbuffer->GetLastRenderWasSelection() || !gbuffer->GetHasContent() ||
    !this->UpdateImages(state))
  {
    return nullptr; // no input, a picking render, nothing was drawn, or an error (reported)
  }
  return gbuffer;
}

void vtkNPRImageEffectPass::GetWholeRectangle(vtkNPRGBufferPass* gbuffer, int rect[4])
{
  vtkTextureObject* depth = gbuffer->GetDepthTexture();
  rect[0] = rect[1] = 0;
  rect[2] = static_cast<int>(depth->GetWidth()) - 1;
  rect[3] = static_cast<int>(depth->GetHeight()) - 1;
}

bool vtkNPRImageEffectPass::RestoreUnchanged(vtkRenderer* renderer, const int windowRect[4])
{
  Internals& internal = *this->Internal;
  const std::string key = this->FrameKey(renderer, windowRect);
  const bool unchanged = !key.empty() && key == internal.Key;
  internal.Key = key;
  internal.FramesSinceUnchanged = unchanged ? 0 : internal.FramesSinceUnchanged + 1;
  return unchanged &&
    internal.Kept.Restore(static_cast<vtkOpenGLRenderWindow*>(renderer->GetRenderWindow()));
}

void vtkNPRImageEffectPass::KeepComposite(vtkRenderer* renderer, const int windowRect[4])
{
  Internals& internal = *this->Internal;
  // Only while frames are being reused: a scene in motion pays nothing for the copy.
  if (internal.Key.empty() || internal.FramesSinceUnchanged > Internals::KeepAfterUnchanged ||
    !internal.Kept.Capture(
      static_cast<vtkOpenGLRenderWindow*>(renderer->GetRenderWindow()), windowRect))
  {
    internal.Kept.Invalidate();
  }
}

std::string vtkNPRImageEffectPass::FrameKey(vtkRenderer* renderer, const int windowRect[4])
{
  // Only where what lies under the composite is this renderer's own clear, which the key
  // describes: another layer below, a preserved colour or depth buffer could change on their own.
  if (!this->KeepUnchangedComposite || renderer->Transparent() || !renderer->GetErase() ||
    renderer->GetPreserveDepthBuffer())
  {
    return std::string();
  }
  const std::string effectKey = this->GetCompositeKey(renderer);
  if (effectKey.empty())
  {
    return effectKey;
  }
  auto* window = static_cast<vtkOpenGLRenderWindow*>(renderer->GetRenderWindow());
  unsigned int binding = 0, drawBuffer = 0;
  window->GetState()->GetCurrentDrawFramebufferState(binding, drawBuffer);
  std::ostringstream key;
  key.precision(17);
  key << effectKey << " | " << this->GetGBuffer()->GetContentVersion() << " " << binding << " "
      << drawBuffer << " " << window->GetSize()[0] << " " << window->GetSize()[1];
  for (int i = 0; i < 4; ++i)
  {
    key << " " << windowRect[i];
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

void vtkNPRImageEffectPass::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Internal->Kept.ReleaseGraphicsResources(window);
  this->Internal->Key.clear();
}

void vtkNPRImageEffectPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "KeepUnchangedComposite: " << this->KeepUnchangedComposite << "\n";
  os << indent << "NumberOfKeptCompositeRestores: " << this->NumberOfKeptCompositeRestores << "\n";
}
