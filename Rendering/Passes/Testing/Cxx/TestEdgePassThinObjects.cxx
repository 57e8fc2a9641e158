// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// Lines that keep thin objects' colours visible (issue 37): vtkNPREdgePass's MaximumLineFraction
// and SurfaceLineShade on a green ring 6 pixels thick in front of a large orange sphere.
// - width: with the limit at 0.1 the ring keeps far more of its colour (its near-black pixels fall
//   to under half: measured 1271 to 484), and the sphere alone is drawn exactly as without it;
// - shade: at 0.5 the lines over the sphere's bright part (brighter than 128) are a darker orange,
//   none near-black, over at least 70 % as many pixels as black lines (measured: as many, 540,
//   of which the black lines turn 78 near-black);
// - settings: both clamp to [0, 1]; the limit recomputes the line image (not the G-buffer), the
//   shade only the composite; ReleaseGraphicsResources and the packed encoding (where the limit
//   does not apply) leave the image as it was.
//
// usage: TestEdgePassThinObjects width|shade|settings
#include "nprTestImages.h"
#include "nprTestMeshes.h"
#include "nprTesting.h"

#include "vtkActor.h"
#include "vtkActorCollection.h"
#include "vtkImageData.h"
#include "vtkNPREdgePass.h"
#include "vtkNPRGBufferPass.h"
#include "vtkNPRPass.h"
#include "vtkPolyData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include <algorithm>
#include <sstream>

namespace
{
constexpr double Green[3] = { 0.2, 0.7, 0.3 }, Orange[3] = { 0.9, 0.5, 0.2 };

// The ring in front of the sphere, seen from +z (the sphere's centre 1.5 behind the ring's).
struct ThinScene : nprPassScene
{
  ThinScene()
    : nprPassScene(400, 300)
  {
    const double behind[3] = { 0.0, 0.0, -1.5 };
    nprAddSphere(this->Renderer, behind, 0.9, Orange, 64);
    nprAddMesh(this->Renderer, nprMakeTorus(0.8, 0.02, 256, 12), Green)->RotateX(60.0);
    this->LookAtOrigin(4.0);
  }
};

// Pixels of each object in the shaded image (green: the ring; orange: the sphere) that are
// near-black in image (every channel under 64) but not in shaded.
struct DarkPixels
{
  long long Ring = 0, RingDark = 0, Sphere = 0, SphereDark = 0;
};

bool NearBlack(vtkImageData* image, int x, int y)
{
  return std::max(
           { nprPixel(image, x, y, 0), nprPixel(image, x, y, 1), nprPixel(image, x, y, 2) }) < 64;
}

DarkPixels CountDark(vtkImageData* shaded, vtkImageData* image)
{
  DarkPixels count;
  int dims[3];
  shaded->GetDimensions(dims);
  for (int y = 0; y < dims[1]; ++y)
  {
    for (int x = 0; x < dims[0]; ++x)
    {
      const int r = nprPixel(shaded, x, y, 0), g = nprPixel(shaded, x, y, 1);
      const bool newlyDark = NearBlack(image, x, y) && !NearBlack(shaded, x, y);
      if (g > r + 20)
      {
        ++count.Ring;
        count.RingDark += newlyDark ? 1 : 0;
      }
      else if (r > g + 20)
      {
        ++count.Sphere;
        count.SphereDark += newlyDark ? 1 : 0;
      }
    }
  }
  return count;
}

vtkSmartPointer<vtkImageData> RenderStyle(ThinScene& scene, int style)
{
  scene.Pass->SetStyle(style);
  return scene.Render();
}

int Width()
{
  ThinScene scene;
  const auto shaded = RenderStyle(scene, vtkNPRPass::SHADED);
  const DarkPixels full = CountDark(shaded, RenderStyle(scene, vtkNPRPass::EDGES));
  scene.Edges()->SetMaximumLineFraction(0.1);
  const DarkPixels limited = CountDark(shaded, RenderStyle(scene, vtkNPRPass::EDGES));
  std::cout << "ring: " << full.Ring << " pixels, near-black under the lines " << full.RingDark
            << " without the limit, " << limited.RingDark << " with it\n";
  NPR_CHECK(full.Ring > 1500 && full.Sphere > 20000, "the scene was not drawn");
  NPR_CHECK(full.RingDark > full.Ring / 4, "the ring's lines do not cover it: no test");
  NPR_CHECK(2 * limited.RingDark < full.RingDark,
    "the limit kept " << limited.RingDark << " of " << full.RingDark << " near-black ring pixels");
  NPR_CHECK(limited.RingDark > 0, "the ring lost its outline");

  // The sphere alone (200 pixels across) keeps its lines.
  scene.Renderer->RemoveActor(scene.Renderer->GetActors()->GetLastActor());
  const auto sphereLimited = scene.Render();
  scene.Edges()->SetMaximumLineFraction(0.0);
  const auto sphere = scene.Render();
  const nprImageDifference difference = nprCompareImages(sphereLimited, sphere, { 0, 0.0 });
  std::cout << "the sphere alone: " << difference.DifferingPixels << " pixels differ\n";
  NPR_CHECK(difference.DifferingPixels == 0, "the limit changed a wide object's lines");
  return nprTestResult();
}
NPR_TEST_CASE("width", Width);

int Shade()
{
  ThinScene scene;
  const auto shaded = RenderStyle(scene, vtkNPRPass::SHADED);
  const auto black = RenderStyle(scene, vtkNPRPass::EDGES);
  scene.Edges()->SetSurfaceLineShade(0.5);
  const auto shade = RenderStyle(scene, vtkNPRPass::EDGES);
  // The sphere's pixels brighter than 128 in the shaded image: those the lines change (by more
  // than 16), those they turn near-black, and those that stay orange.
  long long blackChanged = 0, blackNearBlack = 0, shadeChanged = 0, shadeNearBlack = 0, orange = 0;
  int dims[3];
  shaded->GetDimensions(dims);
  for (int y = 0; y < dims[1]; ++y)
  {
    for (int x = 0; x < dims[0]; ++x)
    {
      const int r = nprPixel(shaded, x, y, 0), g = nprPixel(shaded, x, y, 1);
      if (r <= g + 20 || r < 128)
      {
        continue; // not the sphere's bright part
      }
      const bool blackChange = r - nprPixel(black, x, y, 0) > 16;
      const bool shadeChange = r - nprPixel(shade, x, y, 0) > 16;
      blackChanged += blackChange ? 1 : 0;
      blackNearBlack += blackChange && NearBlack(black, x, y) ? 1 : 0;
      shadeChanged += shadeChange ? 1 : 0;
      shadeNearBlack += shadeChange && NearBlack(shade, x, y) ? 1 : 0;
      orange += shadeChange && nprPixel(shade, x, y, 0) > nprPixel(shade, x, y, 1) + 10 ? 1 : 0;
    }
  }
  std::cout << "bright sphere pixels under lines: black lines " << blackChanged << " ("
            << blackNearBlack << " near-black), shaded lines " << shadeChanged << " ("
            << shadeNearBlack << " near-black, " << orange << " orange)\n";
  NPR_CHECK(blackNearBlack > 50, "no black lines on the sphere: no test");
  NPR_CHECK(shadeChanged * 10 >= blackChanged * 7,
    "the shaded lines cover " << shadeChanged << " pixels, the black ones " << blackChanged);
  NPR_CHECK(shadeNearBlack == 0, shadeNearBlack << " bright sphere pixels turned near-black");
  NPR_CHECK(orange * 100 >= shadeChanged * 95, "the shaded lines lost the sphere's hue");
  return nprTestResult();
}
NPR_TEST_CASE("shade", Shade);

int Settings()
{
  ThinScene scene;
  vtkNPREdgePass* edges = scene.Edges();
  edges->SetMaximumLineFraction(-1.0);
  NPR_CHECK(edges->GetMaximumLineFraction() == 0.0, "the fraction was not clamped to 0");
  edges->SetMaximumLineFraction(5.0);
  NPR_CHECK(edges->GetMaximumLineFraction() == 1.0, "the fraction was not clamped to 1");
  edges->SetSurfaceLineShade(-2.0);
  NPR_CHECK(edges->GetSurfaceLineShade() == 0.0, "the shade was not clamped to 0");
  edges->SetSurfaceLineShade(2.0);
  NPR_CHECK(edges->GetSurfaceLineShade() == 1.0, "the shade was not clamped to 1");
  std::ostringstream printed;
  edges->Print(printed);
  NPR_CHECK(printed.str().find("MaximumLineFraction: 1") != std::string::npos &&
      printed.str().find("SurfaceLineShade: 1") != std::string::npos,
    "PrintSelf leaves the settings out");

  edges->SetMaximumLineFraction(0.0);
  edges->SetSurfaceLineShade(0.0);
  const auto plain = scene.Render();
  const int draws = scene.GBuffer()->GetNumberOfGeometryDraws();
  const int updates = edges->GetNumberOfLineImageUpdates();
  edges->SetMaximumLineFraction(0.1);
  const auto limited = scene.Render();
  NPR_CHECK(edges->GetNumberOfLineImageUpdates() == updates + 1, "the limit kept the old lines");
  NPR_CHECK(scene.GBuffer()->GetNumberOfGeometryDraws() == draws, "the limit redrew the G-buffer");
  NPR_CHECK(nprCompareImages(limited, plain, { 0, 0.0 }).DifferingPixels > 100,
    "the limit changed nothing");
  edges->SetSurfaceLineShade(0.5);
  const auto shaded = scene.Render();
  NPR_CHECK(edges->GetNumberOfLineImageUpdates() == updates + 1, "the shade recomputed the lines");
  NPR_CHECK(nprCompareImages(shaded, limited, { 0, 0.0 }).DifferingPixels > 100,
    "the shade changed nothing");

  // Released resources come back as they were.
  scene.Pass->ReleaseGraphicsResources(scene.Window);
  const auto again = scene.Render();
  NPR_CHECK(nprCompareImages(again, shaded, { 0, 0.0 }).DifferingPixels == 0,
    "the frame after ReleaseGraphicsResources differs");

  // The packed encodings have no object widths: the limit does not apply.
  edges->SetSurfaceLineShade(0.0);
  scene.GBuffer()->SetGeometryEncoding(vtkNPRGBufferPass::PACKED16);
  edges->SetEncoding(vtkNPREdgePass::PACKED16);
  const auto packedLimited = scene.Render();
  edges->SetMaximumLineFraction(0.0);
  const auto packed = scene.Render();
  NPR_CHECK(nprCompareImages(packedLimited, packed, { 0, 0.0 }).DifferingPixels == 0,
    "the limit changed the packed encoding's lines");
  return nprTestResult();
}
NPR_TEST_CASE("settings", Settings);
}
