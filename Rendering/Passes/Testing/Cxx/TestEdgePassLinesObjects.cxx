// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// The lines of the edge pass (vtkNPREdgePass over vtkNPRGBufferPass), part of the
// TestEdgePassLines program: the id contour between touching objects, and its sides;
// anti-aliasing, line width and DPI along a slanted silhouette.
//
// usage: TestEdgePassLines CASE [DATA_DIR]   (CASE: the NPR_TEST_CASE names below)
#include "nprTesting.h"

#include "vtkAppendPolyData.h"
#include "vtkCamera.h"
#include "vtkCleanPolyData.h"
#include "vtkCubeSource.h"
#include "vtkImageData.h"
#include "vtkNPREdgePass.h"
#include "vtkNPRGBufferPass.h"
#include "vtkNew.h"
#include "vtkPlaneSource.h"
#include "vtkTransform.h"
#include "vtkTransformPolyDataFilter.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace
{
using Scene = nprPassScene;

// ---- Two cubes touching face to face, seen straight on: only the id contour separates them ----
int TouchingObjects()
{
  Scene scene(400, 300);
  const double left[3] = { -0.5, 0, 0 }, right[3] = { 0.5, 0, 0 };
  nprAddCube(scene.Renderer, left, 1.0, nprGrey);
  nprAddCube(scene.Renderer, right, 1.0, nprGrey);
  scene.LookAtOrigin(5);
  const double top[3] = { 0, 0.5, 0.5 }, bottom[3] = { 0, -0.5, 0.5 };
  double t[2], b[2];
  scene.Project(top, t);
  scene.Project(bottom, b);
  auto countOnSeam = [&](vtkImageData* mask)
  {
    long long count = 0, rows = 0;
    for (int y = static_cast<int>(b[1]) + 4; y < static_cast<int>(t[1]) - 4; ++y)
    {
      bool row = false;
      for (int x = static_cast<int>(t[0]) - 2; x <= static_cast<int>(t[0]) + 2; ++x)
      {
        count += nprPixel(mask, x, y) > 127 ? 1 : 0;
        row = row || nprPixel(mask, x, y) > 127;
      }
      rows += row ? 1 : 0;
    }
    return std::make_pair(count, rows);
  };
  const int seamRows = static_cast<int>(t[1]) - static_cast<int>(b[1]) - 8;

  auto with = countOnSeam(scene.Mask());
  NPR_CHECK(scene.GBuffer()->GetWritesObjectIds(), "two props and contours: ids expected");
  scene.Edges()->ContoursOff();
  auto without = countOnSeam(scene.Mask());
  std::cout << "seam: contour on " << with.second << "/" << seamRows << " rows, off "
            << without.first << " pixels\n";
  NPR_CHECK(with.second >= seamRows, "the contour misses rows of the seam");
  NPR_CHECK(without.first == 0, "silhouettes or creases fired on a flat seam");

  // Both sides: a line twice as wide as inside or outside alone.
  scene.Edges()->ContoursOn();
  scene.Edges()->SetLineWidth(1.0);
  scene.Edges()->AntiAliasingOff();
  scene.Edges()->SetContourSideToInside();
  const long long inside = countOnSeam(scene.Mask()).first;
  scene.Edges()->SetContourSideToBoth();
  const long long both = countOnSeam(scene.Mask()).first;
  std::cout << "contour pixels on the seam: inside " << inside << ", both " << both << "\n";
  NPR_CHECK(both >= 2 * inside - 4 && inside > 0, "both sides should double the seam's line");
  return nprTestResult();
}
NPR_TEST_CASE("touching-objects", TouchingObjects);

// ---- Anti-aliasing: intermediate coverage along slanted lines, and less staircase ----
// A 2 x 1 box turned by 12 degrees about the view axis, 5 units away, and the window positions
// of its top edge's ends, from (-1, 0.5) to (1, 0.5) turned.
struct SlantedEdge
{
  double From[2], To[2];

  // The edge's row at the centre of column x.
  double RowAt(int x) const
  {
    return From[1] + (x + 0.5 - From[0]) * (To[1] - From[1]) / (To[0] - From[0]);
  }
};

SlantedEdge AddSlantedBox(Scene& scene)
{
  vtkNew<vtkCubeSource> cube;
  cube->SetXLength(2);
  cube->SetYLength(1);
  vtkNew<vtkTransform> tilt;
  tilt->RotateZ(12);
  vtkNew<vtkTransformPolyDataFilter> tilted;
  tilted->SetTransform(tilt);
  tilted->SetInputConnection(cube->GetOutputPort());
  nprAddActor(scene.Renderer, tilted->GetOutputPort());
  scene.LookAtOrigin(5);
  const double ends[2][3] = { { -1, 0.5, 0.5 }, { 1, 0.5, 0.5 } };
  double rotated[2][3];
  for (int i = 0; i < 2; ++i)
  {
    tilt->TransformPoint(ends[i], rotated[i]);
  }
  SlantedEdge edge;
  scene.Project(rotated[0], edge.From);
  scene.Project(rotated[1], edge.To);
  return edge;
}

// In the middle columns, the line's pixels, those partly covered, and the residual of the
// coverage-weighted row of the line from its least-squares straight line: the staircase.
double Staircase(
  vtkImageData* mask, const SlantedEdge& edge, long long& intermediate, long long& lit)
{
  intermediate = lit = 0;
  std::vector<double> xs, ys;
  for (int x = static_cast<int>(edge.From[0]) + 20; x < static_cast<int>(edge.To[0]) - 20; ++x)
  {
    const double yEdge = edge.RowAt(x);
    double sum = 0, weighted = 0;
    for (int y = static_cast<int>(yEdge) - 4; y <= static_cast<int>(yEdge) + 4; ++y)
    {
      const int v = nprPixel(mask, x, y);
      lit += v > 0 ? 1 : 0;
      intermediate += v > 25 && v < 230 ? 1 : 0;
      sum += v;
      weighted += v * (y + 0.5);
    }
    if (sum > 0)
    {
      xs.push_back(x + 0.5);
      ys.push_back(weighted / sum);
    }
  }
  const double n = static_cast<double>(xs.size());
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (size_t i = 0; i < xs.size(); ++i)
  {
    sx += xs[i];
    sy += ys[i];
    sxx += xs[i] * xs[i];
    sxy += xs[i] * ys[i];
  }
  const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  const double offset = (sy - slope * sx) / n;
  double residual = 0;
  for (size_t i = 0; i < xs.size(); ++i)
  {
    const double r = ys[i] - (slope * xs[i] + offset);
    residual += r * r;
  }
  return std::sqrt(residual / std::max(1.0, n));
}

// The coverage within 8 px of the edge, summed over the middle columns.
double CoverageAcross(vtkImageData* mask, const SlantedEdge& edge)
{
  double sum = 0;
  for (int x = static_cast<int>(edge.From[0]) + 20; x < static_cast<int>(edge.To[0]) - 20; ++x)
  {
    for (int y = 0; y < 300; ++y)
    {
      sum += std::abs(y + 0.5 - edge.RowAt(x)) < 8 ? nprPixel(mask, x, y) / 255.0 : 0.0;
    }
  }
  return sum;
}

int AntiAliasing()
{
  Scene scene(400, 300);
  const SlantedEdge edge = AddSlantedBox(scene);
  scene.Edges()->SetLineWidth(1.5);
  long long intermediateOn, litOn, intermediateOff, litOff;
  const double staircaseOn = Staircase(scene.Mask(), edge, intermediateOn, litOn);
  scene.Edges()->AntiAliasingOff();
  const double staircaseOff = Staircase(scene.Mask(), edge, intermediateOff, litOff);
  std::cout << "anti-aliasing on: " << intermediateOn << " of " << litOn
            << " line pixels partly covered, centre wobble " << staircaseOn
            << " px; off: " << intermediateOff << " of " << litOff << ", wobble " << staircaseOff
            << " px\n";
  NPR_CHECK(intermediateOn > litOn / 3, "too few partly covered pixels with anti-aliasing");
  NPR_CHECK(intermediateOff == 0, "partly covered pixels without anti-aliasing");
  // The G-buffer has one sample per pixel: the long steps of a shallow line are smoothed, not
  // removed (see Documentation/edges.md).
  NPR_CHECK(staircaseOn < 0.85 * staircaseOff, "anti-aliasing should straighten the staircase");

  // The width is honoured: a width-6 line is about 4 times as heavy as a width-1.5 line.
  scene.Edges()->AntiAliasingOn();
  const double thin = CoverageAcross(scene.Mask(), edge);
  scene.Edges()->SetLineWidth(6.0);
  const double thick = CoverageAcross(scene.Mask(), edge);
  std::cout << "coverage across the edge: width 1.5 -> " << thin << ", width 6 -> " << thick
            << "\n";
  NPR_CHECK(thick > 3.0 * thin && thick < 5.0 * thin, "line width not honoured");
  // Widths are at 72 DPI: a window at 144 DPI draws them twice as wide.
  scene.Edges()->SetLineWidth(1.5);
  scene.Window->SetDPI(144);
  const double doubled = CoverageAcross(scene.Mask(), edge);
  scene.Window->SetDPI(72);
  std::cout << "width 1.5 at 144 DPI -> " << doubled << "\n";
  NPR_CHECK(doubled > 1.6 * thin && doubled < 2.4 * thin, "the DPI scale is not applied");
  return nprTestResult();
}
NPR_TEST_CASE("antialiasing", AntiAliasing);
}
