// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// What the G-buffer pass (vtkNPRGBufferPass) draws and keeps for the edge pass: an unchanged
// frame reuses the G-buffer and the line image, every kind of change redraws once, a line setting
// recomputes the lines only; only the channels the lines need are written, and nothing for an
// empty renderer or the shaded style; an unchanged frame copies back the kept composite, bit for
// bit, and only where that is safe, in every style that composites (edges, sketch, drawing); the
// composite drawn over the blocks near lines alone is the full one, bit for bit, and so is the
// sketch's line coverage.
//
// usage: TestEdgePassGBuffer CASE [DATA_DIR]   (CASE: the NPR_TEST_CASE names below)
#include "nprTesting.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkLightCollection.h"
#include "vtkNPRDrawingPass.h"
#include "vtkNPREdgePass.h"
#include "vtkNPRGBufferPass.h"
#include "vtkNPRImageEffectPass.h"
#include "vtkNPRModelReader.h"
#include "vtkNPRPass.h"
#include "vtkNPRSketchPass.h"
#include "vtkNew.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkSphereSource.h"
#include "vtkTextureObject.h"

#include <cmath>
#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace
{
using Scene = nprPassScene;

// The sphere the cases draw (kept by the caller, which may change it).
vtkSmartPointer<vtkSphereSource> NewSphere()
{
  return nprSphereSource(0.5, 32, 16);
}

// ---- Unchanged frames reuse the G-buffer and line image; every kind of change redraws ----
int Reuse()
{
  Scene scene(300, 200);
  vtkSmartPointer<vtkSphereSource> sphere = NewSphere();
  vtkSmartPointer<vtkActor> actor = nprAddActor(scene.Renderer, sphere->GetOutputPort(), nprGrey);
  vtkNPRGBufferPass* gbuffer = scene.GBuffer();
  auto first = scene.Render();
  NPR_CHECK(gbuffer->GetNumberOfGeometryDraws() == 1, "first frame: one draw");
  auto second = scene.Render();
  NPR_CHECK(gbuffer->GetNumberOfGeometryDraws() == 1,
    "nothing changed: no redraw, got " << gbuffer->GetNumberOfGeometryDraws());
  NPR_CHECK(scene.Edges()->GetNumberOfLineImageUpdates() == 1, "line image recomputed");
  const nprImageDifference same = nprCompareImages(second, first, { 0, 0.0 });
  NPR_CHECK(same.DifferingPixels == 0, "a reused frame differs from the drawn one");

  int expected = 1;
  const std::pair<const char*, std::function<void()>> changes[] = {
    { "camera", [&] { scene.Camera()->Azimuth(10); } },
    { "actor colour", [&] { actor->GetProperty()->SetColor(0.5, 0.6, 0.7); } },
    { "actor position", [&] { actor->SetPosition(0.1, 0, 0); } },
    { "source", [&] { sphere->SetRadius(0.4); } },
    { "visibility of a new actor",
      [&]
      { nprAddActor(scene.Renderer, sphere->GetOutputPort(), nprGrey)->SetPosition(1, 0, 0); } },
    { "light", [&] { scene.Renderer->GetLights()->GetItemAsObject(0)->Modified(); } },
    { "size", [&] { scene.Window->SetSize(320, 200); } },
    { "line types", [&] { scene.Edges()->CreasesOff(); } },
  };
  for (const auto& change : changes)
  {
    change.second();
    scene.Render();
    ++expected;
    NPR_CHECK(gbuffer->GetNumberOfGeometryDraws() == expected,
      "a change of " << change.first << " did not redraw");
    scene.Render();
    NPR_CHECK(gbuffer->GetNumberOfGeometryDraws() == expected,
      "after a change of " << change.first << ", the next unchanged frame redrew");
  }
  // A line setting only recomputes the lines.
  const int updates = scene.Edges()->GetNumberOfLineImageUpdates();
  scene.Edges()->SetSilhouetteThreshold(0.01);
  scene.Render();
  NPR_CHECK(gbuffer->GetNumberOfGeometryDraws() == expected, "a line setting redrew geometry");
  NPR_CHECK(scene.Edges()->GetNumberOfLineImageUpdates() == updates + 1, "line image not updated");
  // And the cache can be turned off.
  gbuffer->ReuseUnchangedFramesOff();
  scene.Render();
  NPR_CHECK(gbuffer->GetNumberOfGeometryDraws() == expected + 1, "ReuseUnchangedFramesOff ignored");
  return nprTestResult();
}
NPR_TEST_CASE("reuse", Reuse);

// ---- Only the channels the lines need; nothing for an empty renderer ----
int Channels()
{
  Scene scene(200, 150);
  vtkNPRGBufferPass* gbuffer = scene.GBuffer();
  // Empty renderer.
  auto empty = scene.Render();
  NPR_CHECK(gbuffer->GetNumberOfGeometryDraws() == 0, "an empty renderer drew a G-buffer");
  NPR_CHECK(
    !gbuffer->GetHasContent() && !gbuffer->GetGeometryTexture() && !gbuffer->GetColorTexture(),
    "an empty renderer allocated G-buffer textures");
  NPR_CHECK(nprPixel(empty, 100, 75, 0) == 255, "the empty renderer's background is not white");

  const double origin[3] = { 0, 0, 0 }, beside[3] = { 1.5, 0, 0 };
  nprAddCube(scene.Renderer, origin, 1.0, nprGrey);
  scene.Renderer->ResetCamera();
  struct Case
  {
    bool Creases, Contours, Smooth, TwoProps;
    bool Normals, FaceNormals, Ids;
    int Components;
  };
  const Case cases[] = {
    { true, true, true, false, true, true, false, 4 },     // one prop: coverage replaces ids
    { true, true, true, false, true, false, false, 2 },    // creases from shading normals
    { false, true, true, false, true, false, false, 2 },   // smooth silhouettes: n.v
    { false, true, false, false, false, false, false, 1 }, // depth only
    { false, false, false, false, false, false, false, 1 },
    { true, false, true, true, true, true, false, 4 },   // contours off: no ids
    { false, true, false, true, false, false, true, 4 }, // ids, no normals
    { true, true, true, true, true, true, true, 4 },
  };
  vtkSmartPointer<vtkActor> second;
  for (const Case& c : cases)
  {
    if (c.TwoProps && !second)
    {
      second = nprAddCube(scene.Renderer, beside, 1.0, nprGrey);
      scene.Renderer->ResetCamera();
    }
    scene.Edges()->SetCreases(c.Creases);
    scene.Edges()->SetContours(c.Contours);
    scene.Edges()->SetSmoothSilhouettes(c.Smooth);
    scene.Edges()->SetFaceCreases(c.FaceNormals);
    scene.Render();
    vtkTextureObject* geometry = gbuffer->GetGeometryTexture();
    NPR_CHECK(gbuffer->GetWritesNormals() == c.Normals,
      "creases " << c.Creases << ", smooth silhouettes " << c.Smooth << ": normals written "
                 << gbuffer->GetWritesNormals());
    NPR_CHECK(gbuffer->GetWritesFaceNormals() == c.FaceNormals,
      "creases " << c.Creases << ": face normals written " << gbuffer->GetWritesFaceNormals());
    NPR_CHECK(gbuffer->GetWritesObjectIds() == c.Ids,
      "contours " << c.Contours << ", two props " << c.TwoProps << ": ids written "
                  << gbuffer->GetWritesObjectIds());
    NPR_CHECK(geometry && geometry->GetComponents() == c.Components,
      "geometry attachment has " << (geometry ? geometry->GetComponents() : 0)
                                 << " components, expected " << c.Components);
  }
  scene.Edges()->SetSmoothSilhouettes(false);
  scene.Edges()->SetFaceCreases(false);
  // The shaded style makes no G-buffer at all.
  const int draws = gbuffer->GetNumberOfGeometryDraws();
  scene.Pass->SetStyleToShaded();
  scene.Camera()->Azimuth(5);
  scene.Render();
  NPR_CHECK(gbuffer->GetNumberOfGeometryDraws() == draws, "the shaded style drew a G-buffer");
  return nprTestResult();
}
NPR_TEST_CASE("channels", Channels);

// ---- An unchanged frame copies back the kept composite (KeepUnchangedComposite) ----
std::vector<float> WindowDepths(Scene& scene)
{
  vtkNew<vtkFloatArray> depths;
  scene.Window->GetZbufferData(0, 0, scene.Width - 1, scene.Height - 1, depths);
  return std::vector<float>(
    depths->GetPointer(0), depths->GetPointer(0) + scene.Width * scene.Height);
}

// A style's effect pass and the settings whose change must composite again.
struct KeptStyle
{
  int Style;
  std::function<vtkNPRImageEffectPass*(Scene&)> Effect;
  std::vector<std::pair<const char*, std::function<void(Scene&)>>> Settings;
};

// Every frame in which nothing changed is copied back bit for bit (colour and depth); a change
// of the camera, the background or a setting composites again, as if nothing had been kept.
int KeptCompositeOf(const KeptStyle& style)
{
  Scene scene(300, 200);
  scene.Pass->SetStyle(style.Style);
  vtkSmartPointer<vtkSphereSource> sphere = NewSphere();
  nprAddActor(scene.Renderer, sphere->GetOutputPort(), nprGrey);
  scene.Renderer->ResetCamera();
  vtkNPRImageEffectPass* effect = style.Effect(scene);
  const nprImageTolerance exact = { 0, 0.0 };

  auto first = scene.Render();
  auto second = scene.Render(); // unchanged: composited again, and kept
  const std::vector<float> composited = WindowDepths(scene);
  NPR_CHECK(effect->GetNumberOfKeptCompositeRestores() == 0,
    "the first unchanged frame had nothing kept to restore, yet restored");
  auto third = scene.Render(); // copied back
  NPR_CHECK(effect->GetNumberOfKeptCompositeRestores() == 1,
    "the second unchanged frame was not copied back: " << effect->GetNumberOfKeptCompositeRestores()
                                                       << " restores");
  NPR_CHECK(nprCompareImages(third, first, exact).DifferingPixels == 0,
    "the copied-back frame differs from the composited one");
  const std::vector<float> restored = WindowDepths(scene);
  long long onSurface = 0, differing = 0;
  for (size_t i = 0; i < restored.size(); ++i)
  {
    onSurface += composited[i] < 1.0f ? 1 : 0;
    differing += restored[i] != composited[i] ? 1 : 0;
  }
  NPR_CHECK(onSurface > 1000, "the sphere left no depth: " << onSurface << " pixels");
  NPR_CHECK(differing == 0, differing << " depths differ after the copy back");

  // A moving camera composites every frame; while frames are being reused it keeps each one.
  scene.Camera()->Azimuth(20);
  scene.Camera()->Elevation(10);
  auto moved = scene.Render();
  NPR_CHECK(effect->GetNumberOfKeptCompositeRestores() == 1, "a changed frame was copied back");
  NPR_CHECK(nprCompareImages(moved, first, exact).DifferingPixels > 100, "the camera did not move");
  auto movedAgain = scene.Render();
  NPR_CHECK(effect->GetNumberOfKeptCompositeRestores() == 2,
    "the frame after a change was not copied back from the changed frame's copy");
  NPR_CHECK(nprCompareImages(movedAgain, moved, exact).DifferingPixels == 0,
    "the copy of a changed frame differs from it");

  // What the composite draws over, or with, changed: composited again, as if nothing were kept.
  std::vector<std::pair<const char*, std::function<void(Scene&)>>> changes = {
    { "background colour", [](Scene& s) { s.Renderer->SetBackground(0.2, 0.3, 0.4); } },
    { "gradient background",
      [](Scene& s)
      {
        s.Renderer->SetBackground2(0.9, 0.5, 0.1);
        s.Renderer->GradientBackgroundOn();
      } },
  };
  changes.insert(changes.end(), style.Settings.begin(), style.Settings.end());
  for (const auto& change : changes)
  {
    scene.Render(); // kept
    const int restores = effect->GetNumberOfKeptCompositeRestores();
    change.second(scene);
    auto changed = scene.Render();
    NPR_CHECK(effect->GetNumberOfKeptCompositeRestores() == restores,
      "a change of " << change.first << " was copied back from the frame before");
    effect->KeepUnchangedCompositeOff();
    auto reference = scene.Render();
    effect->KeepUnchangedCompositeOn();
    NPR_CHECK(nprCompareImages(changed, reference, exact).DifferingPixels == 0,
      "after a change of " << change.first << " the frame differs from one drawn in full");
  }
  effect->KeepUnchangedCompositeOff();
  const int restores = effect->GetNumberOfKeptCompositeRestores();
  scene.Render();
  scene.Render();
  NPR_CHECK(effect->GetNumberOfKeptCompositeRestores() == restores,
    "KeepUnchangedCompositeOff still copied back");
  return nprTestResult();
}

int KeptComposite()
{
  return KeptCompositeOf({ vtkNPRPass::EDGES, [](Scene& s) { return s.Edges(); },
    { { "silhouette colour", [](Scene& s) { s.Edges()->SetSilhouetteColor(1.0, 0.0, 0.0); } },
      { "line width", [](Scene& s) { s.Edges()->SetLineWidth(3.0); } } } });
}
NPR_TEST_CASE("kept-composite", KeptComposite);

int KeptCompositeSketch()
{
  return KeptCompositeOf({ vtkNPRPass::SKETCH, [](Scene& s) { return s.Sketch(); },
    { { "silhouette colour", [](Scene& s) { s.Edges()->SetSilhouetteColor(1.0, 0.0, 0.0); } },
      { "uncertainty", [](Scene& s) { s.Sketch()->SetUncertainty(5.0); } },
      { "noise seed", [](Scene& s) { s.Sketch()->SetNoiseSeed(7); } },
      { "paper", [](Scene& s) { s.Sketch()->PaperOn(); } } } });
}
NPR_TEST_CASE("kept-composite-sketch", KeptCompositeSketch);

int KeptCompositeDrawing()
{
  return KeptCompositeOf({ vtkNPRPass::DRAWING, [](Scene& s) { return s.Pass->GetDrawingPass(); },
    { { "face colour", [](Scene& s) { s.Pass->GetDrawingPass()->SetFaceColor(0.9, 0.8, 0.7); } },
      { "line width", [](Scene& s) { s.Edges()->SetLineWidth(3.0); } },
      { "hidden lines", [](Scene& s) { s.Pass->GetDrawingPass()->HiddenLinesOn(); } } } });
}
NPR_TEST_CASE("kept-composite-drawing", KeptCompositeDrawing);

// ---- The composite over the blocks near lines alone (SkipLineFreeBlocks) ----
// A frame drawn with the full-screen composite (the G-buffer drawn each time), and the count of
// composites over blocks before it.
struct FullFrame
{
  vtkSmartPointer<vtkImageData> Image;
  std::vector<float> Depths;
  int BlockComposites;
};

// Renders the scene with the full composite, then over blocks: the same colour bit for bit and
// depths within nprDepthReadRounding (the surfaces copied back whole write the G-buffer's own
// depth, the shaders round it through a float), the window's image held or not as expected.
// Returns the full frame and the frame over blocks.
std::pair<FullFrame, vtkSmartPointer<vtkImageData>> CheckOverBlocks(
  Scene& scene, const std::string& label, bool holdsWindowImage)
{
  vtkNPREdgePass* edges = scene.Edges();
  vtkNPRGBufferPass* gbuffer = scene.GBuffer();
  gbuffer->ReuseUnchangedFramesOff();
  edges->KeepUnchangedCompositeOff();
  edges->SkipLineFreeBlocksOff();
  FullFrame full{ nullptr, {}, edges->GetNumberOfBlockComposites() };
  full.Image = scene.Render();
  full.Depths = WindowDepths(scene);
  NPR_CHECK(edges->GetNumberOfBlockComposites() == full.BlockComposites,
    label << ": SkipLineFreeBlocksOff still drew over blocks");
  edges->SkipLineFreeBlocksOn();
  const int surfaceCopies = edges->GetNumberOfSurfaceCopies();
  auto blocks = scene.Render();
  const std::vector<float> blockDepths = WindowDepths(scene);
  NPR_CHECK(edges->GetNumberOfBlockComposites() == full.BlockComposites + 1,
    label << ": the composite was not drawn over blocks");
  NPR_CHECK(gbuffer->GetHoldsWindowImage() == holdsWindowImage,
    label << ": the G-buffer holds the window's image: " << gbuffer->GetHoldsWindowImage());
  NPR_CHECK(edges->GetNumberOfSurfaceCopies() == surfaceCopies + (holdsWindowImage ? 1 : 0),
    label << ": " << edges->GetNumberOfSurfaceCopies() - surfaceCopies
          << " frames copied the surfaces back whole");
  const nprImageDifference difference = nprCompareImages(blocks, full.Image, { 0, 0.0 });
  NPR_CHECK(difference.DifferingPixels == 0,
    label << ": " << difference.DifferingPixels << " pixels differ from the full composite");
  const long long beyond = nprCountDepthsApart(blockDepths, full.Depths, nprDepthReadRounding);
  NPR_CHECK(
    beyond == 0, label << ": " << beyond << " depths differ by more than a float's rounding");
  return { full, blocks };
}

// The frame over blocks with the copy shader over the line-free blocks (the G-buffer kept from
// the frame before): the full frame bit for bit, colour and depth.
void CheckShaderCopy(Scene& scene, const std::string& label, const FullFrame& full)
{
  vtkNPRGBufferPass* gbuffer = scene.GBuffer();
  gbuffer->ReuseUnchangedFramesOn();
  scene.Render(); // drawn once more: the reuse setting itself is a change
  const int draws = gbuffer->GetNumberOfGeometryDraws();
  const int surfaceCopies = scene.Edges()->GetNumberOfSurfaceCopies();
  auto shaderCopy = scene.Render();
  NPR_CHECK(gbuffer->GetNumberOfGeometryDraws() == draws && !gbuffer->GetHoldsWindowImage() &&
      scene.Edges()->GetNumberOfSurfaceCopies() == surfaceCopies,
    label << ": the G-buffer was drawn again or the surfaces copied");
  const nprImageDifference difference = nprCompareImages(shaderCopy, full.Image, { 0, 0.0 });
  NPR_CHECK(difference.DifferingPixels == 0,
    label << ", shader copy: " << difference.DifferingPixels
          << " pixels differ from the full composite");
  NPR_CHECK(WindowDepths(scene) == full.Depths, label << ", shader copy: the depths differ");
}

// The frame compared over blocks has lines (dark pixels) in it: there is something to compare.
void CheckHasLines(Scene& scene, vtkImageData* frame, const std::string& label)
{
  long long dark = 0;
  for (int y = 0; y < scene.Height; ++y)
  {
    for (int x = 0; x < scene.Width; ++x)
    {
      dark += nprPixel(frame, x, y, 0) < 60 ? 1 : 0;
    }
  }
  std::cout << label << ": " << dark << " line pixels, the same over blocks\n";
  NPR_CHECK(dark > 300, label << ": only " << dark << " line pixels");
}

// The bunny in a renderer whose viewport starts inside the window, so that its size is no
// multiple of the blocks' (16 pixels) and its origin is not the window's.
vtkSmartPointer<vtkNPRModelReader> AddBunnyInOffsetViewport(Scene& scene)
{
  scene.Renderer->SetViewport(0.07, 0.11, 0.96, 1.0);
  auto reader = vtkSmartPointer<vtkNPRModelReader>::New();
  reader->SetFileName((nprTestDataDir() + "/bunny.ply").c_str());
  nprAddActor(scene.Renderer, reader->GetOutputPort(), nprGrey);
  return reader;
}

// Every setting that changes where or how wide lines are drawn, on a real mesh and a cube in a
// renderer whose viewport starts inside the window and whose size is no multiple of the blocks':
// the frame drawn over the blocks is the full-screen composite's, with the surfaces copied back
// whole and with the copy shader.
void SetUpBlockScene(Scene& scene)
{
  AddBunnyInOffsetViewport(scene);
  const double corner[3] = { 0.06, 0.02, -0.05 };
  nprAddCube(scene.Renderer, corner, 0.05, nprGrey);
  scene.Renderer->ResetCamera();
  scene.Camera()->Azimuth(30);
  scene.Camera()->Elevation(15);
  scene.Renderer->ResetCameraClippingRange();
}

int LineFreeBlocks()
{
  Scene scene(333, 217);
  SetUpBlockScene(scene);
  vtkNPREdgePass* edges = scene.Edges();
  const std::vector<std::pair<const char*, std::function<void()>>> settings = {
    { "the defaults", [] {} },
    { "16 px silhouettes, 3 px creases",
      [edges]
      {
        edges->SetSilhouetteLineWidth(16.0);
        edges->SetCreaseLineWidth(3.0);
      } },
    { "depth falloff", [edges] { edges->DepthFalloffOn(); } },
    { "surface line shade", [edges] { edges->SetSurfaceLineShade(0.5); } },
    { "width limit", [edges] { edges->SetMaximumLineFraction(0.2); } },
    { "suggestive contours, smooth silhouettes",
      [edges]
      {
        edges->SuggestiveContoursOn();
        edges->SmoothSilhouettesOn();
      } },
    { "no anti-aliasing", [edges] { edges->AntiAliasingOff(); } },
    { "parallel projection", [&scene] { scene.Camera()->ParallelProjectionOn(); } },
  };
  for (const auto& setting : settings)
  {
    setting.second(); // on top of the ones before
    const auto frames = CheckOverBlocks(scene, setting.first, true);
    CheckShaderCopy(scene, setting.first, frames.first);
    CheckHasLines(scene, frames.second, setting.first);
  }
  return nprTestResult();
}
NPR_TEST_CASE("line-free-blocks", LineFreeBlocks);

// ---- The sketch's line coverage over the blocks near lines alone ----
// The frame with the output drawn over blocks is the full-screen one's, colour and depth bit for
// bit, and it was drawn over blocks.
void CheckCoverageOverBlocks(Scene& scene, const std::string& label)
{
  vtkNPREdgePass* edges = scene.Edges();
  edges->SkipLineFreeBlocksOff();
  const int blockComposites = edges->GetNumberOfBlockComposites();
  auto full = scene.Render();
  const std::vector<float> fullDepths = WindowDepths(scene);
  edges->SkipLineFreeBlocksOn();
  auto blocks = scene.Render();
  NPR_CHECK(edges->GetNumberOfBlockComposites() == blockComposites + 1,
    label << ": " << edges->GetNumberOfBlockComposites() - blockComposites
          << " frames drawn over blocks, not 1");
  const nprImageDifference difference = nprCompareImages(blocks, full, { 0, 0.0 });
  NPR_CHECK(difference.DifferingPixels == 0,
    label << ": " << difference.DifferingPixels << " pixels differ from the full-screen output");
  NPR_CHECK(WindowDepths(scene) == fullDepths, label << ": the depths differ");
  CheckHasLines(scene, blocks, label);
}

// The sketch draws its line coverage over the content rectangle only, without clearing the rest:
// after a frame whose lines filled the window, a smaller rectangle's frame is a fresh window's.
void CheckCoverageOutsideRectangle(const std::function<void(Scene&)>& setUp)
{
  Scene fresh(333, 217);
  setUp(fresh);
  auto expected = fresh.Render();
  const std::vector<float> expectedDepths = WindowDepths(fresh);
  Scene scene(333, 217);
  setUp(scene);
  scene.Camera()->Dolly(4.0); // the bunny's lines all over the viewport
  scene.Renderer->ResetCameraClippingRange();
  scene.Render();
  scene.Camera()->Dolly(0.25);
  scene.Renderer->ResetCameraClippingRange();
  auto after = scene.Render();
  const nprImageDifference difference = nprCompareImages(after, expected, { 0, 0.0 });
  NPR_CHECK(difference.DifferingPixels == 0,
    "after a larger frame: " << difference.DifferingPixels << " pixels differ from a fresh window");
  NPR_CHECK(WindowDepths(scene) == expectedDepths, "after a larger frame: the depths differ");
}

int CoverageOverBlocks()
{
  Scene scene(333, 217);
  SetUpBlockScene(scene);
  scene.GBuffer()->ReuseUnchangedFramesOff();
  scene.Pass->SetStyleToSketch();
  vtkNPREdgePass* edges = scene.Edges();
  vtkNPRSketchPass* sketch = scene.Sketch();
  const std::vector<std::pair<const char*, std::function<void()>>> settings = {
    { "sketch", [] {} },
    { "sketch, 12 px silhouettes, uncertainty 9",
      [edges, sketch]
      {
        edges->SetSilhouetteLineWidth(12.0);
        sketch->SetUncertainty(9.0);
      } },
    { "sketch, screen noise, on paper",
      [sketch]
      {
        sketch->SetNoiseSpace(vtkNPRSketchPass::SCREEN);
        sketch->PaperOn();
      } },
    { "sketch, parallel projection", [&scene] { scene.Camera()->ParallelProjectionOn(); } },
  };
  for (const auto& setting : settings)
  {
    setting.second(); // on top of the ones before
    CheckCoverageOverBlocks(scene, setting.first);
  }
  CheckCoverageOutsideRectangle(
    [](Scene& s)
    {
      SetUpBlockScene(s);
      s.Pass->SetStyleToSketch();
      s.Sketch()->SetUncertainty(9.0);
      s.Sketch()->SetNoiseSpace(vtkNPRSketchPass::SCREEN);
    });
  return nprTestResult();
}
NPR_TEST_CASE("line-free-blocks-coverage", CoverageOverBlocks);

// ---- The surfaces copied back whole over any picture under them, or not at all ----
// No line type on: the composite is the surfaces' copy alone, copied back (the G-buffer drawn)
// or drawn by the copy shader (the G-buffer kept): the same colour, depths within rounding.
void CheckCopyWithoutLines(Scene& scene)
{
  vtkNPREdgePass* edges = scene.Edges();
  edges->SilhouettesOff();
  edges->CreasesOff();
  edges->ContoursOff();
  scene.GBuffer()->ReuseUnchangedFramesOff();
  const int copies = edges->GetNumberOfSurfaceCopies();
  auto copied = scene.Render();
  const std::vector<float> copiedDepths = WindowDepths(scene);
  scene.GBuffer()->ReuseUnchangedFramesOn();
  scene.Render();
  auto drawn = scene.Render();
  NPR_CHECK(edges->GetNumberOfSurfaceCopies() == copies + 2,
    "no line type: " << edges->GetNumberOfSurfaceCopies() - copies << " copies, not 2");
  const nprImageDifference copy = nprCompareImages(copied, drawn, { 0, 0.0 });
  NPR_CHECK(copy.DifferingPixels == 0,
    "no line type: " << copy.DifferingPixels << " pixels of the copy differ from the shader's");
  const long long apart =
    nprCountDepthsApart(copiedDepths, WindowDepths(scene), nprDepthReadRounding);
  NPR_CHECK(apart == 0, "no line type: " << apart << " depths of the copy differ");
}

int WindowImage()
{
  Scene scene(333, 217);
  vtkSmartPointer<vtkNPRModelReader> reader = AddBunnyInOffsetViewport(scene);
  scene.Renderer->ResetCamera();
  scene.Camera()->Azimuth(30);
  scene.Renderer->ResetCameraClippingRange();
  CheckOverBlocks(scene, "a plain background", true);
  scene.GBuffer()->ReuseUnchangedFramesOff();
  auto linesOverWhite = scene.Mask();
  scene.Renderer->SetBackground(0.1, 0.2, 0.5);
  scene.Renderer->SetBackground2(0.0, 0.0, 0.0);
  scene.Renderer->GradientBackgroundOn();
  CheckOverBlocks(scene, "a gradient background", true);
  // The image under the surfaces goes into the colour attachment alone: the lines, found from
  // the geometry attachment, are the same over any background.
  const nprImageDifference lines = nprCompareImages(scene.Mask(), linesOverWhite, { 0, 0.0 });
  NPR_CHECK(lines.DifferingPixels == 0,
    lines.DifferingPixels << " line pixels change with the background under the surfaces");
  scene.Pass->SetStyleToToonEdges();
  CheckOverBlocks(scene, "toon shading with edges", true);

  // A layer over another renderer's picture: what lies under the surfaces is that picture.
  vtkNew<vtkRenderer> below;
  below->SetBackground(0.3, 0.5, 0.3);
  below->SetActiveCamera(scene.Camera());
  const double centre[3] = { -0.03, 0.1, -0.1 };
  const double red[3] = { 0.9, 0.1, 0.1 };
  nprAddSphere(below, centre, 0.05, red, 32);
  scene.Renderer->SetLayer(1);
  scene.Window->SetNumberOfLayers(2);
  scene.Window->AddRenderer(below);
  CheckOverBlocks(scene, "a layer over a renderer with a sphere", true);

  // Where the copy would not be exact: a composite over the line-free blocks instead.
  scene.Renderer->PreserveDepthBufferOn();
  CheckOverBlocks(scene, "the depth buffer preserved", false);
  scene.Renderer->PreserveDepthBufferOff();
  scene.Camera()->SetClippingRange(1e-5, 10.0);
  CheckOverBlocks(scene, "log depth (far / near 1e6)", false);
  NPR_CHECK(scene.GBuffer()->GetDepthRemapped(), "far / near 1e6: depth not remapped");
  scene.Renderer->ResetCameraClippingRange();
  scene.Pass->SetStyleToSketch();
  scene.Render();
  NPR_CHECK(
    !scene.GBuffer()->GetHoldsWindowImage(), "the sketch's G-buffer holds the window's image");
  scene.Pass->SetStyleToEdges();
  CheckOverBlocks(scene, "edges again", true);

  CheckCopyWithoutLines(scene);

  // A multisampled window: no copy (a blit cannot write one from the single-sampled G-buffer).
  Scene multisampled(240, 160);
  multisampled.Window->SetMultiSamples(4);
  nprAddActor(multisampled.Renderer, reader->GetOutputPort(), nprGrey);
  multisampled.Renderer->ResetCamera();
  CheckOverBlocks(multisampled, "a 4x multisampled window", false);
  return nprTestResult();
}
NPR_TEST_CASE("window-image", WindowImage);

// Where what lies under the composite is not the renderer's own clear, nothing is kept: a
// renderer on a layer above another, and a multisampled window (blits resolve, never restore).
int KeptCompositeUnsafe()
{
  {
    Scene scene(240, 160);
    vtkSmartPointer<vtkSphereSource> sphere = NewSphere();
    nprAddActor(scene.Renderer, sphere->GetOutputPort(), nprGrey);
    scene.Renderer->ResetCamera();
    vtkNew<vtkRenderer> below;
    below->SetBackground(0.0, 0.0, 0.0);
    scene.Window->SetNumberOfLayers(2);
    scene.Window->AddRenderer(below);
    scene.Renderer->SetLayer(1);
    scene.Render();
    below->SetBackground(0.0, 0.5, 0.0); // changes under the pass's renderer only
    auto image = scene.Render();
    scene.Render();
    NPR_CHECK(scene.Edges()->GetNumberOfKeptCompositeRestores() == 0,
      "a renderer on layer 1 copied back its kept composite");
    NPR_CHECK(nprPixel(image, 2, 2, 1) > 100, "the layer below is not drawn");
  }
  {
    Scene scene(240, 160);
    scene.Window->SetMultiSamples(4);
    vtkSmartPointer<vtkSphereSource> sphere = NewSphere();
    nprAddActor(scene.Renderer, sphere->GetOutputPort(), nprGrey);
    scene.Renderer->ResetCamera();
    auto first = scene.Render();
    scene.Render();
    auto third = scene.Render();
    NPR_CHECK(scene.Edges()->GetNumberOfKeptCompositeRestores() == 0,
      "a multisampled window copied back its kept composite");
    NPR_CHECK(nprCompareImages(third, first, { 0, 0.0 }).DifferingPixels == 0,
      "an unchanged multisampled frame differs");
  }
  return nprTestResult();
}
NPR_TEST_CASE("kept-composite-unsafe", KeptCompositeUnsafe);
}
