// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// Sketchy drawing (vtkNPRSketchPass), checked with numbers: with no uncertainty it equals the
// edges on flat colours, colour and depth; no line pixel is displaced by more than the
// uncertainty; the z-buffer is the smaller of the two displaced depth lookups; a second layer is
// hidden where the sketch, as drawn, is in front.
//
// usage: TestSketchPass CASE [DATA_DIR]   (CASE: the NPR_TEST_CASE names below)
#include "nprTesting.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkImageData.h"
#include "vtkNPREdgePass.h"
#include "vtkNPRSketchPass.h"
#include "vtkNPRToonPass.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace
{
struct Scene : nprPassScene
{
  using nprPassScene::nprPassScene;
  std::vector<float> Depth()
  {
    std::vector<float> depth(static_cast<size_t>(this->Width) * this->Height);
    this->Window->GetZbufferData(0, 0, this->Width - 1, this->Height - 1, depth.data());
    return depth;
  }
};

// A scene with creases, silhouettes and contours at several depths, seen from above one side.
void ShowParts(Scene& scene, const double color[3])
{
  const double cubeCenter[3] = { -0.35, -0.1, 0.0 };
  nprAddCube(scene.Renderer, cubeCenter, 0.9, color);
  const double sphereCenter[3] = { 0.45, 0.2, -0.6 };
  nprAddSphere(scene.Renderer, sphereCenter, 0.55, color, 48);
  scene.LookAtOrigin(4.0);
  scene.Camera()->Azimuth(25);
  scene.Camera()->Elevation(20);
  scene.Camera()->OrthogonalizeViewUp();
  scene.Camera()->SetClippingRange(1, 10);
}

// The parts (ShowParts) sketched with lines of the given width, uncertainty 0 to start from.
void SketchParts(Scene& scene, const double color[3], double lineWidth)
{
  ShowParts(scene, color);
  scene.Pass->SetStyleToSketch();
  scene.Edges()->SetLineWidth(lineWidth);
  scene.Sketch()->SetUncertainty(0.0);
}

// ---- Uncertainty 0 reproduces the edges on flat colours exactly, colour and depth ----
int SketchIdentity()
{
  Scene scene(400, 300);
  const double color[3] = { 0.8, 0.75, 0.6 };
  ShowParts(scene, color);
  scene.Edges()->SetCreaseColor(0.1, 0.2, 0.7);
  scene.Edges()->SetContourColor(0.7, 0.1, 0.1);
  scene.Pass->SetStyleToToonEdges();
  scene.Toon()->SetNumberOfBands(1);
  scene.Toon()->SetSpecular(false);
  auto edges = scene.Render();
  const std::vector<float> edgesDepth = scene.Depth();
  scene.Pass->SetStyleToSketch();
  scene.Sketch()->SetUncertainty(0.0);
  auto sketch = scene.Render();
  const std::vector<float> sketchDepth = scene.Depth();
  long long differing = 0, depthDiffering = 0, lines = 0;
  for (int y = 0; y < 300; ++y)
  {
    for (int x = 0; x < 400; ++x)
    {
      bool same = true;
      for (int c = 0; c < 3; ++c)
      {
        same = same && nprPixel(edges, x, y, c) == nprPixel(sketch, x, y, c);
      }
      differing += same ? 0 : 1;
      lines += nprPixel(edges, x, y, 0) < 100 ? 1 : 0;
    }
  }
  // The edges copy the G-buffer's depth unchanged where no line is (vtkNPRGBufferPass::
  // CopySurfacesBack); the sketch reads it through a float on the way to gl_FragDepth.
  depthDiffering = nprCountDepthsApart(edgesDepth, sketchDepth, nprDepthReadRounding);
  const long long depthRounded = nprCountDepthsApart(edgesDepth, sketchDepth, 0.0) - depthDiffering;
  std::cout << differing << " pixels and " << depthDiffering << " depths differ (" << depthRounded
            << " more by a float's rounding); " << lines << " line pixels\n";
  NPR_CHECK(lines > 500, "the scene has too few lines to compare: " << lines);
  NPR_CHECK(differing == 0, differing << " pixels differ from the edges on flat colours");
  NPR_CHECK(depthDiffering == 0, depthDiffering << " depths differ from the edges' depth sprite");

  // With an uncertainty the image changes.
  scene.Sketch()->SetUncertainty(3.0);
  auto wobbly = scene.Render();
  long long moved = 0;
  for (int y = 0; y < 300; ++y)
  {
    for (int x = 0; x < 400; ++x)
    {
      moved += nprPixel(wobbly, x, y, 0) != nprPixel(edges, x, y, 0) ? 1 : 0;
    }
  }
  NPR_CHECK(moved > 500, "an uncertainty of 3 pixels changed only " << moved << " pixels");
  return nprTestResult();
}
NPR_TEST_CASE("sketch-identity", SketchIdentity);

// The pixels darker than half: the lines of a white scene on white.
std::vector<char> DarkPixels(vtkImageData* image, int width, int height)
{
  std::vector<char> dark(static_cast<size_t>(width) * height, 0);
  for (int y = 0; y < height; ++y)
  {
    for (int x = 0; x < width; ++x)
    {
      dark[y * width + x] = nprPixel(image, x, y, 0) < 128 ? 1 : 0;
    }
  }
  return dark;
}

// ---- No line pixel is farther from the unperturbed lines than the uncertainty ----
int SketchDisplacement()
{
  const int width = 400, height = 300;
  Scene scene(width, height);
  const double white[3] = { 1, 1, 1 };
  SketchParts(scene, white, 1.5);
  const std::vector<char> exact = DarkPixels(scene.Render(), width, height);
  for (int space : { vtkNPRSketchPass::SCREEN, vtkNPRSketchPass::SURFACE })
  {
    for (double uncertainty : { 2.0, 5.0 })
    {
      for (unsigned int seed : { 1u, 2u })
      {
        scene.Sketch()->SetNoiseSpace(space);
        scene.Sketch()->SetUncertainty(uncertainty);
        scene.Sketch()->SetNoiseSeed(seed);
        const std::vector<char> moved = DarkPixels(scene.Render(), width, height);
        // Each line pixel's distance to the nearest unperturbed line pixel.
        const int reach = static_cast<int>(uncertainty) + 4;
        double largest = 0.0;
        long long count = 0;
        for (int y = 0; y < height; ++y)
        {
          for (int x = 0; x < width; ++x)
          {
            if (!moved[y * width + x])
            {
              continue;
            }
            ++count;
            double nearest = 1e9;
            for (int dy = -reach; dy <= reach; ++dy)
            {
              for (int dx = -reach; dx <= reach; ++dx)
              {
                const int u = x + dx, v = y + dy;
                if (u >= 0 && v >= 0 && u < width && v < height && exact[v * width + u])
                {
                  nearest = std::min(nearest, std::hypot(dx, dy));
                }
              }
            }
            largest = std::max(largest, nearest);
          }
        }
        // The largest displacement the pass computes over the whole image (GetDisplacement() is
        // the screen noise's; the surface noise is bounded the same way in the shader).
        double largestDisplacement = space == vtkNPRSketchPass::SCREEN ? 0.0 : uncertainty;
        for (int y = 0; space == vtkNPRSketchPass::SCREEN && y < height; ++y)
        {
          for (int x = 0; x < width; ++x)
          {
            double d[2];
            scene.Sketch()->GetDisplacement(scene.Renderer, x, y, false, d);
            largestDisplacement = std::max(largestDisplacement, std::hypot(d[0], d[1]));
          }
        }
        std::cout << scene.Sketch()->GetNoiseSpaceAsString() << " noise, uncertainty "
                  << uncertainty << ", seed " << seed << ": " << count << " line pixels, farthest "
                  << largest << " px from the exact lines; largest "
                  << "displacement " << largestDisplacement << " px\n";
        // One pixel of tolerance: a line pixel is one whose coverage, mixed from the four texels
        // around the displaced position, exceeds one half.
        NPR_CHECK(largest <= uncertainty + 1.0,
          "a line pixel lies " << largest << " px from the exact lines (uncertainty " << uncertainty
                               << ")");
        NPR_CHECK(largestDisplacement <= uncertainty * (1.0 + 1e-9),
          "the displacement reaches " << largestDisplacement << " px");
        NPR_CHECK(largest >= 0.5 * uncertainty,
          "the lines hardly moved (" << largest << " px for an uncertainty of " << uncertainty
                                     << ")");
        NPR_CHECK(largestDisplacement >= 0.7 * uncertainty,
          "the noise hardly reaches the uncertainty (" << largestDisplacement << ")");
      }
    }
  }
  return nprTestResult();
}
NPR_TEST_CASE("sketch-displacement", SketchDisplacement);

// ---- The z-buffer after the sketch is the smaller of the two displaced depth lookups ----
int SketchDepth()
{
  const int width = 400, height = 300;
  Scene scene(width, height);
  const double color[3] = { 0.8, 0.75, 0.6 };
  SketchParts(scene, color, 3.0); // lines reaching onto the background have their own depth
  scene.Edges()->SetSilhouettes(false);
  scene.Edges()->SetCreases(false);
  scene.Edges()->SetContours(false);
  scene.Render();
  const std::vector<float> surfaceDepth = scene.Depth(); // the G-buffer's depth
  scene.Edges()->SetSilhouettes(true);
  scene.Edges()->SetCreases(true);
  scene.Edges()->SetContours(true);
  scene.Render();
  const std::vector<float> lineDepth = scene.Depth(); // the depth the lines are drawn at
  scene.Sketch()->SetUncertainty(5.0);
  scene.Sketch()->SetNoiseSeed(3);
  scene.Sketch()->SetNoiseSpaceToScreen(); // the noise GetDisplacement() computes
  scene.Render();
  const std::vector<float> depth = scene.Depth();

  auto lookup = [&](const std::vector<float>& image, double x, double y, bool& ambiguous)
  {
    // Too close to a texel border for float and double to agree on the texel: not checked.
    ambiguous =
      ambiguous || std::abs(x - std::round(x)) < 1e-3 || std::abs(y - std::round(y)) < 1e-3;
    const int u = static_cast<int>(std::floor(x)), v = static_cast<int>(std::floor(y));
    return (u < 0 || v < 0 || u >= width || v >= height) ? 1.0f : image[v * width + u];
  };
  long long checked = 0, wrong = 0, changed = 0;
  for (int y = 0; y < height; ++y)
  {
    for (int x = 0; x < width; ++x)
    {
      double surface[2], lines[2];
      scene.Sketch()->GetDisplacement(scene.Renderer, x, y, true, surface);
      scene.Sketch()->GetDisplacement(scene.Renderer, x, y, false, lines);
      bool ambiguous = false;
      const float expected =
        std::min(lookup(surfaceDepth, x + 0.5 + surface[0], y + 0.5 + surface[1], ambiguous),
          lookup(lineDepth, x + 0.5 + lines[0], y + 0.5 + lines[1], ambiguous));
      if (ambiguous)
      {
        continue;
      }
      ++checked;
      wrong += depth[y * width + x] == expected ? 0 : 1;
      changed += depth[y * width + x] != lineDepth[y * width + x] ? 1 : 0;
    }
  }
  std::cout << checked << " pixels checked, " << wrong << " differ from the smaller displaced "
            << "depth; the displacement changed " << changed << " depths\n";
  NPR_CHECK(checked > 0.98 * width * height, "only " << checked << " pixels could be checked");
  NPR_CHECK(wrong == 0, wrong << " depths are not the smaller of the two displaced lookups");
  NPR_CHECK(changed > 1000, "the displacement changed only " << changed << " depths");
  return nprTestResult();
}
NPR_TEST_CASE("sketch-depth", SketchDepth);

// ---- A second layer is hidden where the sketched surface, as drawn, is in front ----
int SketchLayer()
{
  const int width = 400, height = 300;
  Scene scene(width, height);
  scene.ShowCube(5.0, nprGrey);
  scene.Pass->SetStyleToSketch();
  scene.Sketch()->SetUncertainty(6.0);

  vtkSmartPointer<vtkActor> ball = scene.AddSphereBehind();
  ball->VisibilityOff();
  scene.Sketch()->SetUncertainty(0.0);
  scene.Render();
  const std::vector<float> exact = scene.Depth();
  scene.Sketch()->SetUncertainty(6.0);
  scene.Render();
  const std::vector<float> sketched = scene.Depth();
  ball->VisibilityOn();
  auto image = scene.Render();

  long long redOverSketch = 0, redElsewhere = 0, displacedOnly = 0;
  for (int y = 0; y < height; ++y)
  {
    for (int x = 0; x < width; ++x)
    {
      const size_t i = static_cast<size_t>(y) * width + x;
      const bool isRed = nprIsRed(image, x, y);
      if (sketched[i] < 1.0f)
      {
        redOverSketch += isRed ? 1 : 0;
        displacedOnly += exact[i] == 1.0f ? 1 : 0;
      }
      else
      {
        redElsewhere += isRed ? 1 : 0;
      }
    }
  }
  std::cout << "layer-1 sphere: " << redOverSketch << " red pixels over the sketch, "
            << redElsewhere << " beside it; " << displacedOnly
            << " pixels covered only by the displaced sketch\n";
  NPR_CHECK(redOverSketch == 0, "the sphere behind the sketch shows through it");
  NPR_CHECK(redElsewhere > 100, "the part of the sphere beside the cube should be drawn");
  NPR_CHECK(displacedOnly > 50, "the displacement should reach past the exact outline");
  return nprTestResult();
}
NPR_TEST_CASE("sketch-layer", SketchLayer);
}
