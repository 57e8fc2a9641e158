// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// The strokes of a technical drawing (vtkNPRDrawingLines): a cube's visible and hidden edges
// against their analytic projections, in perspective and parallel; one object hiding another's
// lines, split where the front object's outline crosses them. The program's other cases:
// TestDrawingLinesScenes.cxx.
//
// usage: TestDrawingLines CASE [DATA_DIR]   (CASE: the NPR_TEST_CASE names below)
#include "nprFeatureLineTesting.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkCylinderSource.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkImageData.h"
#include "vtkIntArray.h"
#include "vtkNPRDrawingLines.h"
#include "vtkNPRModelReader.h"
#include "vtkNew.h"
#include "vtkOutputWindow.h"
#include "vtkParametricFunctionSource.h"
#include "vtkParametricTorus.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <functional>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace
{
using namespace nprFeatureLineTesting;

double Distance(const Image2& a, const Image2& b)
{
  return std::hypot(a[0] - b[0], a[1] - b[1]);
}

// ---- A unit cube from a corner: 9 visible edges, 3 hidden, against the analytic projection ----
// The analytic edges of the corner cube as pairs of corner indices, visible (a face towards the
// viewer) or hidden.
void CubeEdgesByVisibility(
  bool parallel, std::set<std::pair<int, int>>& visible, std::set<std::pair<int, int>>& hidden)
{
  const double* eye = nprCornerEye;
  double toward[3];
  for (int i = 0; i < 3; ++i)
  {
    toward[i] = -eye[i];
  }
  for (const BoxEdge& edge : BoxEdges())
  {
    int ends[2];
    for (int c = 0; c < 8; ++c)
    {
      if (Corner(c) == edge.Ends.first)
      {
        ends[0] = c;
      }
      if (Corner(c) == edge.Ends.second)
      {
        ends[1] = c;
      }
    }
    const bool seen =
      BoxFaceFront(edge.Faces[0][0], edge.Faces[0][1], parallel, parallel ? toward : eye) ||
      BoxFaceFront(edge.Faces[1][0], edge.Faces[1][1], parallel, parallel ? toward : eye);
    (seen ? visible : hidden).insert({ std::min(ends[0], ends[1]), std::max(ends[0], ends[1]) });
  }
}

int DrawingCube(bool parallel)
{
  DrawingScene scene(400, 300);
  nprAddCornerCube(scene.Renderer, parallel);
  scene.Lines->HiddenLinesOn();
  const std::vector<Stroke> strokes = scene.Strokes();

  std::vector<Image2> corners;
  for (int c = 0; c < 8; ++c)
  {
    corners.push_back(scene.Project(Corner(c)));
  }
  std::set<std::pair<int, int>> visible, hidden;
  CubeEdgesByVisibility(parallel, visible, hidden);
  NPR_CHECK(visible.size() == 9 && hidden.size() == 3, "a cube seen from a corner shows 9 edges");

  // Every stroke point is a corner's projection (within 0.5 px; in fact to rounding), and the
  // strokes' segments are exactly the analytic edges of their visibility.
  std::set<std::pair<int, int>> gotVisible, gotHidden;
  double worst = 0.0;
  int closedSilhouettes = 0;
  for (const Stroke& stroke : strokes)
  {
    std::vector<int> at;
    for (const Image2& p : stroke.Points)
    {
      int best = 0;
      for (int c = 1; c < 8; ++c)
      {
        best = Distance(p, corners[c]) < Distance(p, corners[best]) ? c : best;
      }
      worst = std::max(worst, Distance(p, corners[best]));
      at.push_back(best);
    }
    for (size_t i = 0; i + 1 < at.size(); ++i)
    {
      const std::pair<int, int> edge{ std::min(at[i], at[i + 1]), std::max(at[i], at[i + 1]) };
      NPR_CHECK((stroke.Hidden ? gotHidden : gotVisible).insert(edge).second,
        "edge " << edge.first << "-" << edge.second << " drawn twice");
    }
    closedSilhouettes +=
      stroke.Closed() && !stroke.Hidden && stroke.Type == vtkNPRFeatureLines::SILHOUETTE ? 1 : 0;
  }
  std::cout << (parallel ? "parallel" : "perspective") << ": " << strokes.size()
            << " strokes, farthest point " << worst << " px from its corner, "
            << scene.Lines->GetNumberOfRayCasts() << " rays\n";
  NPR_CHECK(worst <= 0.5, "a stroke point lies " << worst << " px from the corner's projection");
  NPR_CHECK(worst <= 1e-6, "stroke points are not the corners' projections: " << worst << " px");
  NPR_CHECK(gotVisible == visible, "the visible strokes are not the 9 visible edges");
  NPR_CHECK(gotHidden == hidden, "the hidden strokes are not the 3 hidden edges");
  // The outline is one closed stroke; the 3 creases and 3 hidden edges meet at a corner each.
  NPR_CHECK(closedSilhouettes == 1, closedSilhouettes << " closed outlines");
  NPR_CHECK(strokes.size() == 7, strokes.size() << " strokes, expected 7 (outline, 3 + 3)");

  // Without hidden lines: the same visible strokes, no hidden ones.
  scene.Lines->HiddenLinesOff();
  const std::vector<Stroke> visibleOnly = scene.Strokes();
  NPR_CHECK(visibleOnly.size() == 4 &&
      std::none_of(
        visibleOnly.begin(), visibleOnly.end(), [](const Stroke& s) { return s.Hidden; }),
    "without hidden lines: " << visibleOnly.size() << " strokes");
  vtkDataArray* size = scene.Lines->GetStrokes()->GetFieldData()->GetArray("ImageSize");
  NPR_CHECK(size && size->GetComponent(0, 0) == 400 && size->GetComponent(0, 1) == 300,
    "ImageSize is not 400 x 300");
  return nprTestResult();
}
NPR_TEST_CASE("drawing-cube", [] { return DrawingCube(false); });
NPR_TEST_CASE("drawing-cube-parallel", [] { return DrawingCube(true); });

// Distance from p to the outline (convex polygon edges) of the given points' hull.
double DistanceToHull(const Image2& p, const std::vector<Image2>& points)
{
  const std::vector<Image2> hull = ConvexHull(points);
  double best = 1e300;
  for (size_t i = 0; i < hull.size(); ++i)
  {
    best = std::min(
      best, nprSegmentDistance(p.data(), hull[i].data(), hull[(i + 1) % hull.size()].data()));
  }
  return best;
}

// ---- A small cube in front of a big one: the big cube's lines split at the small one's outline
// ----
int DrawingOcclusion(bool parallel)
{
  DrawingScene scene(500, 400);
  const double origin[3] = { 0, 0, 0 };
  vtkSmartPointer<vtkActor> big = nprAddCube(scene.Renderer, origin, 2.0);
  const double front[3] = { 0.9, 0.6, 2.0 };
  vtkSmartPointer<vtkActor> small = nprAddCube(scene.Renderer, front, 0.8);
  const double eye[3] = { 2.0, 1.5, 8.0 };
  vtkCamera* camera = scene.Camera();
  nprLookAtOrigin(camera, eye, 20.0);
  camera->SetParallelProjection(parallel);
  camera->SetParallelScale(2.0);
  scene.Lines->HiddenLinesOn();
  const std::vector<Stroke> strokes = scene.Strokes();

  std::vector<Image2> bigCorners, smallCorners;
  for (int c = 0; c < 8; ++c)
  {
    Point p = Corner(c, 1.0);
    bigCorners.push_back(scene.Project(p));
    Point q = Corner(c, 0.4);
    for (int i = 0; i < 3; ++i)
    {
      q[i] += front[i];
    }
    smallCorners.push_back(scene.Project(q));
  }
  auto nearestCorner = [](const Image2& p, const std::vector<Image2>& corners)
  {
    double best = 1e300;
    for (const Image2& c : corners)
    {
      best = std::min(best, Distance(p, c));
    }
    return best;
  };
  // Stroke ends that are no corner of either cube are where a line passes behind the small one:
  // on its outline.
  int splits = 0;
  double worst = 0.0;
  for (const Stroke& stroke : strokes)
  {
    for (const Image2& p : { stroke.Points.front(), stroke.Points.back() })
    {
      // (vtkCubeSource's points are floats: its corners are ours to 1e-7.)
      if (nearestCorner(p, bigCorners) < 1e-3 || nearestCorner(p, smallCorners) < 1e-3)
      {
        continue;
      }
      ++splits;
      worst = std::max(worst, DistanceToHull(p, smallCorners));
    }
  }
  // Nothing hides the front cube: its visible strokes are its 9 edges seen from the camera.
  long long smallVisible = 0;
  for (const Stroke& stroke : strokes)
  {
    if (!stroke.Hidden &&
      std::all_of(stroke.Points.begin(), stroke.Points.end(),
        [&](const Image2& p) { return nearestCorner(p, smallCorners) < 1e-3; }))
    {
      smallVisible += static_cast<long long>(stroke.Points.size()) - 1;
    }
  }
  std::cout << (parallel ? "parallel" : "perspective") << ": " << strokes.size() << " strokes, "
            << splits << " split ends, farthest " << worst << " px from the front cube's outline\n";
  NPR_CHECK(splits >= 4, "the big cube's lines were split at " << splits << " points");
  NPR_CHECK(worst <= 0.01, "a split lies " << worst << " px from the front cube's outline");
  NPR_CHECK(smallVisible == 9, "the front cube shows " << smallVisible << " edges, not 9");
  return nprTestResult();
}
NPR_TEST_CASE("drawing-occlusion", [] { return DrawingOcclusion(false); });
NPR_TEST_CASE("drawing-occlusion-parallel", [] { return DrawingOcclusion(true); });
}
