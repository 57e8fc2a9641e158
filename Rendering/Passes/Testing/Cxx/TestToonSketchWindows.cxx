// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// The toon, toon+edges and sketch styles (vtkNPRPass) in several windows of one process, through
// a resize and ReleaseGraphicsResources: the object, and its lines where the style has them,
// drawn every time.
//
// usage: TestToonSketchWindows CASE [DATA_DIR]   (CASE: the NPR_TEST_CASE names below)
#include "nprTesting.h"

#include "vtkImageData.h"
#include "vtkRenderWindow.h"

#include <algorithm>
#include <functional>
#include <map>
#include <string>

namespace
{
using Scene = nprPassScene;

// ---- Several windows, a resize and a release: every style draws each time ----
int Windows()
{
  const double color[3] = { 0.9, 0.6, 0.3 };
  auto check = [&](Scene& scene, const std::string& what)
  {
    auto image = scene.Render();
    long long object = 0, dark = 0;
    for (int y = 0; y < scene.Height; ++y)
    {
      for (int x = 0; x < scene.Width; ++x)
      {
        const int r = nprPixel(image, x, y, 0), g = nprPixel(image, x, y, 1);
        object += (r != 255 || g != 255) ? 1 : 0;
        dark += std::max(r, g) < 60 ? 1 : 0;
      }
    }
    const bool lines = scene.Pass->GetStyle() != vtkNPRPass::TOON;
    NPR_CHECK(object > 2000, what << ": only " << object << " object pixels");
    NPR_CHECK(!lines || dark > 100, what << ": only " << dark << " line pixels");
  };
  for (int style : { vtkNPRPass::TOON, vtkNPRPass::TOON_EDGES, vtkNPRPass::SKETCH })
  {
    const std::string name = vtkNPRPass::GetStyleName(style);
    for (int round = 0; round < 2; ++round)
    {
      Scene first(200, 150), second(160, 120);
      for (Scene* scene : { &first, &second })
      {
        const double origin[3] = { 0, 0, 0 };
        nprAddSphere(scene->Renderer, origin, 1.0, color, 32);
        scene->LookAtOrigin(4.5);
        scene->Pass->SetStyle(style);
      }
      check(first, name + " first window");
      check(second, name + " second window");
      first.Window->SetSize(260, 180);
      first.Width = 260;
      first.Height = 180;
      check(first, name + " resized");
      first.Pass->ReleaseGraphicsResources(first.Window);
      check(first, name + " after ReleaseGraphicsResources");
    }
  }
  return nprTestResult();
}
NPR_TEST_CASE("windows", Windows);
}
