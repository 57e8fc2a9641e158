// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// The ground-truth mask of the visible feature lines (vtkNPRReferenceMask), part of the
// TestReferenceMask program: a sphere's smooth contours against its analytic outline, without
// gaps, and still hidden by real occluders.
//
// usage: TestReferenceMask CASE [DATA_DIR]   (CASE: the NPR_TEST_CASE names below)
#include "nprFeatureLineTesting.h"

#include "vtkActor.h"
#include "vtkActorCollection.h"
#include "vtkCamera.h"
#include "vtkCellData.h"
#include "vtkCubeSource.h"
#include "vtkIdTypeArray.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkNPRModelReader.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkSphereSource.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <numeric>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace
{
using namespace nprFeatureLineTesting;
// ---- Smooth contours: a sphere's mask against its analytic outline ----
// The outline of a sphere (centre c, radius r) seen from eye: the circle where the tangent cone
// touches it, projected through the renderer, as a closed polyline in window coordinates.
std::vector<std::array<double, 2>> SphereOutline(
  MaskScene& scene, const double c[3], double r, const double eye[3])
{
  double e[3] = { eye[0] - c[0], eye[1] - c[1], eye[2] - c[2] };
  const double distance = vtkMath::Norm(e);
  vtkMath::Normalize(e);
  double u[3], v[3];
  vtkMath::Perpendiculars(e, u, v, 0.0);
  const double offset = r * r / distance,
               radius = r * std::sqrt(1.0 - (r / distance) * (r / distance));
  std::vector<std::array<double, 2>> outline;
  for (int i = 0; i < 7200; ++i)
  {
    const double a = 2.0 * vtkMath::Pi() * i / 7200;
    Point p;
    for (int k = 0; k < 3; ++k)
    {
      p[k] = c[k] + offset * e[k] + radius * (std::cos(a) * u[k] + std::sin(a) * v[k]);
    }
    outline.push_back(scene.Project(p));
  }
  return outline;
}

double OutlineDistance(const std::vector<std::array<double, 2>>& outline, const double p[2])
{
  double best = 1e300;
  for (size_t i = 0; i < outline.size(); ++i)
  {
    best = std::min(
      best, nprSegmentDistance(p, outline[i].data(), outline[(i + 1) % outline.size()].data()));
  }
  return best;
}

// Precision (every mask pixel's centre within 1 px of the outline) and no gap (at every pixel
// column's centre line, each crossing of the outline has a mask pixel within 1 px): the
// worst distance, and the crossings without a pixel.
void OutlineMatch(vtkImageData* mask, int width, int height,
  const std::vector<std::array<double, 2>>& outline, double& worst, long long& pixels,
  long long& crossings, long long& gaps, const std::function<bool(double, double)>& counted)
{
  worst = 0.0;
  pixels = crossings = gaps = 0;
  for (int y = 0; y < height; ++y)
  {
    for (int x = 0; x < width; ++x)
    {
      const double p[2] = { x + 0.5, y + 0.5 };
      if (nprPixel(mask, x, y) && counted(p[0], p[1]))
      {
        ++pixels;
        worst = std::max(worst, OutlineDistance(outline, p));
      }
    }
  }
  for (size_t i = 0; i < outline.size(); ++i)
  {
    const auto& a = outline[i];
    const auto& b = outline[(i + 1) % outline.size()];
    for (int x = static_cast<int>(std::ceil(std::min(a[0], b[0]) - 0.5));
         x + 0.5 < std::max(a[0], b[0]); ++x)
    {
      const double cx = x + 0.5;
      if (cx < std::min(a[0], b[0]) || a[0] == b[0])
      {
        continue;
      }
      const double cy = a[1] + (b[1] - a[1]) * (cx - a[0]) / (b[0] - a[0]);
      if (!counted(cx, cy))
      {
        continue;
      }
      ++crossings;
      bool hit = false;
      for (int oy = -1; oy <= 1 && !hit; ++oy)
      {
        for (int ox = -1; ox <= 1 && !hit; ++ox)
        {
          const int px = x + ox, py = static_cast<int>(std::floor(cy)) + oy;
          const double q[2] = { px + 0.5, py + 0.5 };
          hit = px >= 0 && py >= 0 && px < width && py < height && nprPixel(mask, px, py) &&
            std::hypot(q[0] - cx, q[1] - cy) <= 1.0 + std::sqrt(0.5);
        }
      }
      gaps += hit ? 0 : 1;
    }
  }
}

vtkSmartPointer<vtkActor> AddSphere(MaskScene& scene, const double c[3], double r, int resolution)
{
  return nprAddActor(
    scene.Renderer, nprSphereSource(r, resolution, resolution, c)->GetOutputPort());
}

// A sphere with normals at 400x400: with and without smooth contours, the mask within 1 px of
// the analytic outline and without gaps along it (the faces next to the contour's triangle
// would hide most of the smooth contour under the mesh-silhouette ray test).
int MaskSmoothSphere()
{
  const int resolution = 64;
  MaskScene scene(400, 400);
  const double centre[3] = { 0, 0, 0 };
  AddSphere(scene, centre, 1.0, resolution);
  const double eye[3] = { 2.6, 1.5, 3.1 };
  nprViewFromCorner(scene.Camera(), eye, false);
  const auto outline = SphereOutline(scene, centre, 1.0, eye);
  vtkNPRReferenceMask* reference = scene.Reference;
  reference->GenerateVisibleLinesOn();
  for (bool smooth : { false, true })
  {
    reference->SetSmoothContours(smooth);
    vtkImageData* mask = scene.Mask();
    double worst;
    long long pixels, crossings, gaps;
    OutlineMatch(mask, scene.Width, scene.Height, outline, worst, pixels, crossings, gaps,
      [](double, double) { return true; });
    long long smoothLines = 0;
    auto* types = vtkUnsignedCharArray::SafeDownCast(
      reference->GetVisibleLines()->GetCellData()->GetArray("FeatureType"));
    for (vtkIdType i = 0; types && i < types->GetNumberOfValues(); ++i)
    {
      smoothLines += (types->GetValue(i) & vtkNPRFeatureLines::SMOOTH_CONTOUR) ? 1 : 0;
    }
    const std::string name = "sphere " + std::to_string(resolution) +
      (smooth ? ", smooth contours" : ", mesh silhouettes");
    std::cout << name << ": " << pixels << " pixels, farthest " << worst
              << " px from the analytic outline, " << gaps << " of " << crossings
              << " column crossings without a pixel within 1 px; "
              << reference->GetNumberOfFeatureEdges() << " lines, "
              << reference->GetNumberOfVisibleSamples() << " of "
              << reference->GetNumberOfRayCasts() << " samples visible, " << smoothLines
              << " visible smooth polylines\n";
    NPR_CHECK(pixels > 600 && worst <= 1.0, name << ": a pixel " << worst << " px off");
    NPR_CHECK(gaps == 0, name << ": " << gaps << " gaps along the outline");
    NPR_CHECK((smoothLines > 0) == smooth, name << ": " << smoothLines << " smooth polylines");
  }
  return nprTestResult();
}
NPR_TEST_CASE("mask-smooth-sphere", MaskSmoothSphere);

// Real occluders still hide a smooth contour: a small sphere in front of the big one's outline
// (another actor), and the big sphere hiding the small one's outline behind it.
int MaskSmoothOcclusion()
{
  MaskScene scene(400, 400);
  const double big[3] = { 0, 0, 0 }, small[3] = { 0.75, 0.75, 1.2 };
  AddSphere(scene, big, 1.0, 48);
  AddSphere(scene, small, 0.3, 32);
  const double eye[3] = { 0, 0, 6 };
  nprViewFromCorner(scene.Camera(), eye, false);
  scene.Camera()->SetClippingRange(0.5, 20);
  scene.Reference->SmoothContoursOn();
  vtkImageData* mask = scene.Mask();
  const auto bigOutline = SphereOutline(scene, big, 1.0, eye);
  const auto smallOutline = SphereOutline(scene, small, 0.3, eye);
  auto inside = [](const std::vector<std::array<double, 2>>& outline, double x, double y)
  {
    bool in = false;
    for (size_t i = 0, j = outline.size() - 1; i < outline.size(); j = i++)
    {
      const auto& a = outline[i];
      const auto& b = outline[j];
      if ((a[1] > y) != (b[1] > y) && x < (b[0] - a[0]) * (y - a[1]) / (b[1] - a[1]) + a[0])
      {
        in = !in;
      }
    }
    return in;
  };
  // The big outline: no pixel deep inside the small disk, none missing outside it.
  double worst;
  long long pixels, crossings, gaps;
  OutlineMatch(mask, scene.Width, scene.Height, bigOutline, worst, pixels, crossings, gaps,
    [&](double x, double y)
    {
      const double p[2] = { x, y };
      return !inside(smallOutline, x, y) && OutlineDistance(smallOutline, p) > 1.5;
    });
  long long hidden = 0, covered = 0;
  for (int y = 0; y < scene.Height; ++y)
  {
    for (int x = 0; x < scene.Width; ++x)
    {
      const double p[2] = { x + 0.5, y + 0.5 };
      if (inside(smallOutline, p[0], p[1]) && OutlineDistance(smallOutline, p) > 1.5 &&
        OutlineDistance(bigOutline, p) <= 3.0)
      {
        ++covered;
        hidden += nprPixel(mask, x, y) ? 1 : 0;
      }
    }
  }
  // The small sphere's outline is whole (it is in front).
  double smallWorst;
  long long smallPixels, smallCrossings, smallGaps;
  OutlineMatch(mask, scene.Width, scene.Height, smallOutline, smallWorst, smallPixels,
    smallCrossings, smallGaps, [](double, double) { return true; });
  std::cout << "big outline outside the small sphere: " << gaps << " gaps of " << crossings << "; "
            << hidden << " mask pixels of " << covered
            << " on the big outline behind the small sphere; small outline: " << smallGaps
            << " gaps of " << smallCrossings << "\n";
  NPR_CHECK(covered > 20 && hidden == 0, hidden << " pixels of the hidden outline in the mask");
  NPR_CHECK(crossings > 200 && gaps == 0, gaps << " gaps in the visible outline");
  NPR_CHECK(smallCrossings > 50 && smallGaps == 0, smallGaps << " gaps in the small outline");

  // Behind: the small sphere moved behind the big one is hidden entirely.
  vtkActor* second = vtkActor::SafeDownCast(scene.Renderer->GetActors()->GetItemAsObject(1));
  const long long before = nprCountAbove(scene.Mask(), 0);
  second->SetPosition(-0.75, -0.75, -2.6);
  const long long behind = nprCountAbove(scene.Mask(), 0);
  second->VisibilityOff();
  const long long alone = nprCountAbove(scene.Mask(), 0);
  std::cout << "mask pixels: " << before << " with the small sphere in front, " << behind
            << " with it behind, " << alone << " without it\n";
  NPR_CHECK(behind == alone, "the sphere behind shows " << behind - alone << " pixels");
  return nprTestResult();
}
NPR_TEST_CASE("mask-smooth-occlusion", MaskSmoothOcclusion);
}
