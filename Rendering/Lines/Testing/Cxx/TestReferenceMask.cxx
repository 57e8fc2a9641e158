// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// The ground-truth mask of the visible feature lines (vtkNPRReferenceMask): a cube's mask against
// an independent projection of its visible edges, in perspective and parallel; occlusion by
// another object; what is rebuilt between updates. The program's other cases:
// TestReferenceMaskStability.cxx, TestReferenceMaskSmooth.cxx, TestReferenceMaskIntersections.cxx.
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

// A unit cube from a known camera: the mask against the analytic visible edges.
// The box's edges projected, as x0, y0, x1, y1: visible (at least one face towards the viewer,
// a convex box) and hidden.
struct CubeEdgeSets
{
  std::vector<std::array<double, 4>> Visible, Hidden;
};

CubeEdgeSets ProjectCubeEdges(MaskScene& scene, bool parallel)
{
  const double* eye = nprCornerEye;
  double toward[3];
  for (int i = 0; i < 3; ++i)
  {
    toward[i] = -eye[i]; // direction of projection (focal point at the origin)
  }
  CubeEdgeSets edges;
  for (const BoxEdge& edge : BoxEdges())
  {
    const bool seen =
      BoxFaceFront(edge.Faces[0][0], edge.Faces[0][1], parallel, parallel ? toward : eye) ||
      BoxFaceFront(edge.Faces[1][0], edge.Faces[1][1], parallel, parallel ? toward : eye);
    const auto a = scene.Project(edge.Ends.first), b = scene.Project(edge.Ends.second);
    (seen ? edges.Visible : edges.Hidden).push_back({ a[0], a[1], b[0], b[1] });
  }
  return edges;
}

double Nearest(const std::vector<std::array<double, 4>>& edges, const double p[2])
{
  double best = 1e300;
  for (const auto& e : edges)
  {
    best = std::min(best, nprSegmentDistance(p, &e[0], &e[2]));
  }
  return best;
}

// Precision: every mask pixel 0 or 255, its centre's farthest distance from the visible edges,
// and the mask pixels on hidden edges only.
struct MaskPrecision
{
  double Worst = 0.0;
  long long Pixels = 0;
  long long OnHidden = 0;
};

MaskPrecision MeasureMaskPrecision(
  vtkImageData* mask, const MaskScene& scene, const CubeEdgeSets& edges)
{
  MaskPrecision precision;
  for (int y = 0; y < scene.Height; ++y)
  {
    for (int x = 0; x < scene.Width; ++x)
    {
      const double p[2] = { x + 0.5, y + 0.5 };
      const int value = nprPixel(mask, x, y);
      NPR_CHECK(value == 0 || value == 255, "mask value " << value);
      if (value)
      {
        ++precision.Pixels;
        precision.Worst = std::max(precision.Worst, Nearest(edges.Visible, p));
      }
      if (value && Nearest(edges.Hidden, p) <= 0.5 && Nearest(edges.Visible, p) > 1.5)
      {
        ++precision.OnHidden;
      }
    }
  }
  return precision;
}

// Recall: points every 0.1 px along the visible edges, and those with a mask pixel in the 3x3
// pixels around them.
std::pair<long long, long long> MeasureMaskRecall(
  vtkImageData* mask, const MaskScene& scene, const CubeEdgeSets& edges)
{
  long long samples = 0, found = 0;
  for (const auto& e : edges.Visible)
  {
    const double length = std::hypot(e[2] - e[0], e[3] - e[1]);
    const int steps = static_cast<int>(length / 0.1);
    for (int s = 0; s <= steps; ++s)
    {
      const double px = e[0] + (e[2] - e[0]) * s / steps, py = e[1] + (e[3] - e[1]) * s / steps;
      const int x = static_cast<int>(std::floor(px)), y = static_cast<int>(std::floor(py));
      if (x < 2 || y < 2 || x >= scene.Width - 2 || y >= scene.Height - 2)
      {
        continue;
      }
      const bool hit = nprNearPixel(mask, x, y);
      ++samples;
      found += hit ? 1 : 0;
    }
  }
  return { samples, found };
}

// The visible lines: the same mask with them on, and every visible point in a mask pixel.
void CheckVisibleLines(MaskScene& scene, vtkImageData* mask)
{
  vtkNPRReferenceMask* reference = scene.Reference;
  std::vector<unsigned char> first(static_cast<unsigned char*>(mask->GetScalarPointer()),
    static_cast<unsigned char*>(mask->GetScalarPointer()) + scene.Width * scene.Height);
  reference->GenerateVisibleLinesOn();
  mask = scene.Mask();
  const std::vector<unsigned char> second(static_cast<unsigned char*>(mask->GetScalarPointer()),
    static_cast<unsigned char*>(mask->GetScalarPointer()) + scene.Width * scene.Height);
  NPR_CHECK(first == second, "the mask changed with GenerateVisibleLines");
  vtkPolyData* lines = reference->GetVisibleLines();
  NPR_CHECK(lines->GetNumberOfCells() >= 9 && lines->GetCellData()->GetArray("FeatureType"),
    "visible lines: " << lines->GetNumberOfCells() << " polylines");
  NPR_CHECK(reference->GetNumberOfRayCasts() == reference->GetNumberOfSamples(),
    "with visible lines every sample needs a ray");
  long long outside = 0;
  for (vtkIdType i = 0; i < lines->GetNumberOfPoints(); ++i)
  {
    Point p;
    lines->GetPoint(i, p.data());
    const auto d = scene.Project(p);
    outside +=
      nprPixel(mask, static_cast<int>(std::floor(d[0])), static_cast<int>(std::floor(d[1]))) ? 0
                                                                                             : 1;
  }
  NPR_CHECK(outside <= 2, outside << " visible-line points outside the mask's pixels");
}

int MaskCube(bool parallel)
{
  MaskScene scene(400, 300);
  nprAddCornerCube(scene.Renderer, parallel);
  vtkImageData* mask = scene.Mask();
  NPR_CHECK(mask->GetDimensions()[0] == 400 && mask->GetDimensions()[1] == 300 &&
      mask->GetNumberOfScalarComponents() == 1 && mask->GetScalarType() == VTK_UNSIGNED_CHAR,
    "the mask is not 400x300 unsigned char");
  const CubeEdgeSets edges = ProjectCubeEdges(scene, parallel);
  NPR_CHECK(edges.Visible.size() == 9 && edges.Hidden.size() == 3,
    "a cube seen from a corner shows 9 edges");
  const MaskPrecision precision = MeasureMaskPrecision(mask, scene, edges);
  const auto recall = MeasureMaskRecall(mask, scene, edges);
  const long long samples = recall.first, found = recall.second;
  vtkNPRReferenceMask* reference = scene.Reference;
  std::cout << (parallel ? "parallel" : "perspective") << ": " << precision.Pixels
            << " mask pixels, farthest centre " << precision.Worst << " px from a visible edge, "
            << precision.OnHidden << " on hidden edges, " << found << "/" << samples
            << " edge points found; " << reference->GetNumberOfFeatureEdges() << " edges, "
            << reference->GetNumberOfSamples() << " samples, " << reference->GetNumberOfRayCasts()
            << " rays, " << reference->GetNumberOfVisibleSamples() << " visible\n";
  NPR_CHECK(precision.Pixels > 900, "too few mask pixels: " << precision.Pixels);
  NPR_CHECK(
    precision.Pixels == reference->GetNumberOfLinePixels(), "GetNumberOfLinePixels is wrong");
  NPR_CHECK(precision.Worst <= std::sqrt(0.5) + 1e-6,
    "a mask pixel lies " << precision.Worst << " px from the edges");
  NPR_CHECK(precision.OnHidden == 0, precision.OnHidden << " mask pixels on hidden edges");
  NPR_CHECK(found == samples,
    "visible edges missed at " << samples - found << " of " << samples << " points");
  NPR_CHECK(reference->GetNumberOfFeatureEdges() == 12, "the cube's 12 edges are feature lines");
  CheckVisibleLines(scene, mask);
  return nprTestResult();
}
NPR_TEST_CASE("mask-cube", [] { return MaskCube(false); });
NPR_TEST_CASE("mask-cube-parallel", [] { return MaskCube(true); });

// ---- A small cube behind a big one: hidden entirely, then in part ----
int MaskOcclusion()
{
  MaskScene scene(400, 300);
  const double origin[3] = { 0, 0, 0 };
  vtkSmartPointer<vtkActor> big = nprAddCube(scene.Renderer, origin, 2.0);
  const double eye[3] = { 0.5, 0.4, 8.0 };
  vtkCamera* camera = scene.Camera();
  nprLookAtOrigin(camera, eye, 20.0);
  auto copy = [&](vtkImageData* mask)
  {
    const unsigned char* p = static_cast<unsigned char*>(mask->GetScalarPointer());
    return std::vector<unsigned char>(p, p + scene.Width * scene.Height);
  };
  const std::vector<unsigned char> bigOnly = copy(scene.Mask());

  const double behind[3] = { 0, 0, -3 };
  vtkSmartPointer<vtkActor> small = nprAddCube(scene.Renderer, behind, 0.5);
  const std::vector<unsigned char> both = copy(scene.Mask());
  big->VisibilityOff();
  const std::vector<unsigned char> smallOnly = copy(scene.Mask());
  big->VisibilityOn();
  long long smallPixels = 0;
  for (unsigned char v : smallOnly)
  {
    smallPixels += v ? 1 : 0;
  }
  std::cout << "small cube alone: " << smallPixels
            << " pixels; behind the big one: " << (both == bigOnly ? "hidden" : "visible in part")
            << "\n";
  NPR_CHECK(smallPixels > 100, "the small cube alone has no lines");
  NPR_CHECK(both == bigOnly, "the hidden cube changed the mask");

  // Moved half out from behind: new pixels appear, none inside the big cube's outline.
  small->SetPosition(1.45, 0.0, 0.0);
  const std::vector<unsigned char> partly = copy(scene.Mask());
  std::vector<std::array<double, 2>> corners;
  for (int c = 0; c < 8; ++c)
  {
    corners.push_back(scene.Project(Corner(c, 1.0)));
  }
  const auto hull = ConvexHull(corners);
  long long added = 0, inside = 0;
  for (int y = 0; y < scene.Height; ++y)
  {
    for (int x = 0; x < scene.Width; ++x)
    {
      const size_t i = static_cast<size_t>(y) * scene.Width + x;
      if (!partly[i] || bigOnly[i])
      {
        NPR_CHECK(partly[i] || !bigOnly[i], "the big cube's line pixel lost at " << x << "," << y);
        continue;
      }
      ++added;
      // Inside the hull by more than a pixel: hidden by the big cube.
      double depth = 1e300;
      for (size_t k = 0; k < hull.size(); ++k)
      {
        const auto& a = hull[k];
        const auto& b = hull[(k + 1) % hull.size()];
        const double length = std::hypot(b[0] - a[0], b[1] - a[1]);
        depth = std::min(
          depth, ((b[0] - a[0]) * (y + 0.5 - a[1]) - (b[1] - a[1]) * (x + 0.5 - a[0])) / length);
      }
      inside += depth > 1.0 ? 1 : 0;
    }
  }
  std::cout << "small cube half out: " << added << " new pixels, " << inside
            << " inside the big cube's outline\n";
  NPR_CHECK(added > 50, "the part of the small cube out from behind has no lines");
  NPR_CHECK(inside == 0, inside << " pixels of the hidden part in the mask");
  return nprTestResult();
}
NPR_TEST_CASE("mask-occlusion", MaskOcclusion);

// ---- What the mask reuses between updates ----
int MaskReuse()
{
  MaskScene scene(200, 150);
  vtkNew<vtkCubeSource> cube;
  vtkSmartPointer<vtkActor> actor = nprAddActor(scene.Renderer, cube->GetOutputPort());
  vtkCamera* camera = scene.Camera();
  camera->SetPosition(2.2, 1.7, 2.9);
  camera->SetFocalPoint(0, 0, 0);
  camera->SetClippingRange(1.0, 10.0);
  vtkNPRReferenceMask* reference = scene.Reference;
  const long long first = nprCountAbove(scene.Mask(), 0);
  camera->Azimuth(20);
  const long long turned = nprCountAbove(scene.Mask(), 0);
  NPR_CHECK(
    reference->GetNumberOfAdjacencyBuilds() == 1 && reference->GetNumberOfLocatorBuilds() == 1,
    "a camera move rebuilt: adjacency " << reference->GetNumberOfAdjacencyBuilds() << ", locator "
                                        << reference->GetNumberOfLocatorBuilds());
  NPR_CHECK(first > 100 && turned > 100, "no lines");
  actor->SetPosition(0.2, 0, 0);
  scene.Mask();
  NPR_CHECK(
    reference->GetNumberOfAdjacencyBuilds() == 1 && reference->GetNumberOfLocatorBuilds() == 2,
    "an actor move: adjacency " << reference->GetNumberOfAdjacencyBuilds() << ", locator "
                                << reference->GetNumberOfLocatorBuilds());
  cube->SetXLength(1.5);
  scene.Mask();
  NPR_CHECK(
    reference->GetNumberOfAdjacencyBuilds() == 2 && reference->GetNumberOfLocatorBuilds() == 3,
    "a new mesh: adjacency " << reference->GetNumberOfAdjacencyBuilds() << ", locator "
                             << reference->GetNumberOfLocatorBuilds());
  // Translucent actors neither draw lines nor hide them; the explicit size wins.
  actor->GetProperty()->SetOpacity(0.5);
  NPR_CHECK(nprCountAbove(scene.Mask(), 0) == 0, "a translucent actor has lines");
  actor->GetProperty()->SetOpacity(1.0);
  reference->SetSize(64, 48);
  NPR_CHECK(scene.Mask()->GetDimensions()[0] == 64 && nprCountAbove(reference->GetMask(), 0) > 20,
    "an explicit size");
  reference->CreasesOff();
  reference->SilhouettesOff();
  NPR_CHECK(nprCountAbove(scene.Mask(), 0) == 0, "no line types, still lines");
  return nprTestResult();
}
NPR_TEST_CASE("mask-reuse", MaskReuse);
}
