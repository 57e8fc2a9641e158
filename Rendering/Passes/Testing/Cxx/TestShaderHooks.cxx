// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// The shader-template hooks of the passes on the VTK release this build uses. The G-buffer, toon
// and ink passes add their code after tags of VTK's poly-data shaders (//VTK::Light::Impl,
// //VTK::TCoord::Impl, //VTK::Output::Dec), which VTK's releases may move or rename. Each case
// renders one style over a lit sphere and a box and checks that the pass reported no missing hook
// (the harness fails on any VTK error) and that the style's effect is in the image.
//
// usage: TestShaderHooks edges|toon|toon-edges|sketch|inked
#include "nprTesting.h"

#include "vtkCamera.h"
#include "vtkCubeSource.h"
#include "vtkImageData.h"
#include "vtkNPRPass.h"
#include "vtkNPRToonPass.h"
#include "vtkRenderWindow.h"
#include "vtkSphereSource.h"

#include <algorithm>
#include <map>
#include <vector>

namespace
{
// A lit sphere and a box beside it, seen at an angle (silhouettes, creases, smooth shading).
struct HookScene : nprPassScene
{
  explicit HookScene(int style)
    : nprPassScene(240, 180)
  {
    this->Pass->SetStyle(style);
    auto sphere = nprSphereSource(0.5, 48, 24);
    sphere->SetCenter(-0.7, 0, 0);
    const double grey[3] = { 0.8, 0.8, 0.8 };
    nprAddActor(this->Renderer, sphere->GetOutputPort(), grey);
    vtkNew<vtkCubeSource> box;
    box->SetCenter(0.7, 0, 0);
    nprAddActor(this->Renderer, box->GetOutputPort(), grey);
    this->Renderer->ResetCamera();
    this->Camera()->Azimuth(25);
    this->Camera()->Elevation(20);
    this->Renderer->ResetCameraClippingRange();
  }
};

// Pixels darker than 60 in every channel: ink.
long long DarkPixels(vtkImageData* image)
{
  int dims[3];
  image->GetDimensions(dims);
  long long dark = 0;
  for (int y = 0; y < dims[1]; ++y)
  {
    for (int x = 0; x < dims[0]; ++x)
    {
      dark += nprPixel(image, x, y, 0) < 60 && nprPixel(image, x, y, 1) < 60 &&
          nprPixel(image, x, y, 2) < 60
        ? 1
        : 0;
    }
  }
  return dark;
}

// The share of the surface pixels (neither white background nor ink) that have one of the
// `count` most frequent colours.
double ShareOfCommonestColours(vtkImageData* image, size_t count)
{
  int dims[3];
  image->GetDimensions(dims);
  std::map<int, long long> colours;
  long long surface = 0;
  for (int y = 0; y < dims[1]; ++y)
  {
    for (int x = 0; x < dims[0]; ++x)
    {
      const int r = nprPixel(image, x, y, 0), g = nprPixel(image, x, y, 1),
                b = nprPixel(image, x, y, 2);
      if (std::min(r, std::min(g, b)) < 250 && std::max(r, std::max(g, b)) >= 60)
      {
        ++colours[(r << 16) | (g << 8) | b];
        ++surface;
      }
    }
  }
  std::vector<long long> counts;
  for (const auto& colour : colours)
  {
    counts.push_back(colour.second);
  }
  std::sort(counts.rbegin(), counts.rend());
  long long common = 0;
  for (size_t i = 0; i < std::min(count, counts.size()); ++i)
  {
    common += counts[i];
  }
  return surface ? static_cast<double>(common) / surface : 0.0;
}

int TestLines(int style, const char* name)
{
  HookScene scene(style);
  vtkSmartPointer<vtkImageData> image = scene.Render();
  const long long dark = DarkPixels(image);
  std::cout << name << ": " << dark << " ink pixels\n";
  NPR_CHECK(dark > 400, name << ": only " << dark << " ink pixels: no lines were drawn");
  return nprTestResult();
}
NPR_TEST_CASE("edges", [] { return TestLines(vtkNPRPass::EDGES, "edges"); });
NPR_TEST_CASE("sketch", [] { return TestLines(vtkNPRPass::SKETCH, "sketch"); });
NPR_TEST_CASE("inked", [] { return TestLines(vtkNPRPass::INKED, "inked"); });

int TestToon(int style, const char* name)
{
  HookScene scene(style);
  scene.Toon()->SetNumberOfBands(3);
  vtkSmartPointer<vtkImageData> image = scene.Render();
  // With three bands the three commonest colours cover 100 % of the surface in toon and about
  // 88 % in toon+edges (the rest: the lines' anti-aliased rims); unbanded, about 62 %.
  const double share = ShareOfCommonestColours(image, 3);
  std::cout << name << ": the 3 commonest colours cover " << 100 * share << " % of the surface\n";
  NPR_CHECK(share > 0.75, name << ": the lighting is not banded (" << 100 * share << " %)");
  return style == vtkNPRPass::TOON_EDGES ? TestLines(style, name) : nprTestResult();
}
NPR_TEST_CASE("toon", [] { return TestToon(vtkNPRPass::TOON, "toon"); });
NPR_TEST_CASE("toon-edges", [] { return TestToon(vtkNPRPass::TOON_EDGES, "toon+edges"); });
}
