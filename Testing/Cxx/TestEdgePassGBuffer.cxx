// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// What the G-buffer pass (vtkNPRGBufferPass) draws and keeps for the edge pass: an unchanged
// frame reuses the G-buffer and the line image, every kind of change redraws once, a line setting
// recomputes the lines only; only the channels the lines need are written, and nothing for an
// empty renderer or the shaded style.
//
// usage: TestEdgePassGBuffer CASE [DATA_DIR]   (CASE: see the table at the end of this file)
#include "nprTesting.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkImageData.h"
#include "vtkLightCollection.h"
#include "vtkNPREdgePass.h"
#include "vtkNPRGBufferPass.h"
#include "vtkNew.h"
#include "vtkProperty.h"
#include "vtkSphereSource.h"
#include "vtkTextureObject.h"

#include <functional>
#include <map>
#include <string>
#include <utility>

namespace
{
using Scene = nprPassScene;

// ---- Unchanged frames reuse the G-buffer and line image; every kind of change redraws ----
int Reuse()
{
  Scene scene(300, 200);
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(32);
  sphere->SetPhiResolution(16);
  const double grey[3] = { 0.8, 0.8, 0.8 };
  vtkSmartPointer<vtkActor> actor = nprAddActor(scene.Renderer, sphere->GetOutputPort(), grey);
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
      [&] { nprAddActor(scene.Renderer, sphere->GetOutputPort(), grey)->SetPosition(1, 0, 0); } },
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
  const double grey[3] = { 0.8, 0.8, 0.8 };
  nprAddCube(scene.Renderer, origin, 1.0, grey);
  scene.Renderer->ResetCamera();
  struct Case
  {
    bool Creases, Contours, TwoProps;
    bool Normals, Ids;
    int Components;
  };
  const Case cases[] = {
    { true, true, false, true, false, 2 },   // one prop: coverage replaces ids
    { false, true, false, false, false, 1 }, // depth only
    { false, false, false, false, false, 1 },
    { true, false, true, true, false, 2 }, // contours off: no ids
    { false, true, true, false, true, 4 }, // ids, no normals
    { true, true, true, true, true, 4 },
  };
  vtkSmartPointer<vtkActor> second;
  for (const Case& c : cases)
  {
    if (c.TwoProps && !second)
    {
      second = nprAddCube(scene.Renderer, beside, 1.0, grey);
      scene.Renderer->ResetCamera();
    }
    scene.Edges()->SetCreases(c.Creases);
    scene.Edges()->SetContours(c.Contours);
    scene.Render();
    vtkTextureObject* geometry = gbuffer->GetGeometryTexture();
    NPR_CHECK(gbuffer->GetWritesNormals() == c.Normals,
      "creases " << c.Creases << ": normals written " << gbuffer->GetWritesNormals());
    NPR_CHECK(gbuffer->GetWritesObjectIds() == c.Ids,
      "contours " << c.Contours << ", two props " << c.TwoProps << ": ids written "
                  << gbuffer->GetWritesObjectIds());
    NPR_CHECK(geometry && geometry->GetComponents() == c.Components,
      "geometry attachment has " << (geometry ? geometry->GetComponents() : 0)
                                 << " components, expected " << c.Components);
  }
  // The shaded style makes no G-buffer at all.
  const int draws = gbuffer->GetNumberOfGeometryDraws();
  scene.Pass->SetStyleToShaded();
  scene.Camera()->Azimuth(5);
  scene.Render();
  NPR_CHECK(gbuffer->GetNumberOfGeometryDraws() == draws, "the shaded style drew a G-buffer");
  return nprTestResult();
}
}

int main(int argc, char* argv[])
{
  const std::map<std::string, std::function<int()>> cases = {
    { "reuse", Reuse },
    { "channels", Channels },
  };
  return nprRunTestCase(argc, argv, cases);
}
