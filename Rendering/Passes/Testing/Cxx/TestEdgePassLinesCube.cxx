// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// The lines of the edge pass (vtkNPREdgePass over vtkNPRGBufferPass), part of the
// TestEdgePassLines program: a cube's visible edges projected analytically, in perspective and
// parallel.
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

// ---- A unit cube from a known camera: line pixels on its visible edges and nowhere else ----
using Segment = std::pair<std::array<double, 2>, std::array<double, 2>>;

// The visible edges of the unit cube seen from nprCornerEye, projected: those with at least one
// face turned towards the eye (a convex box).
std::vector<Segment> VisibleCubeEdges(Scene& scene, bool parallel)
{
  const double* eye = nprCornerEye;
  const double h = 0.5;
  const int normals[6][3] = { { 1, 0, 0 }, { -1, 0, 0 }, { 0, 1, 0 }, { 0, -1, 0 }, { 0, 0, 1 },
    { 0, 0, -1 } };
  auto facing = [&](int face)
  {
    double toEye[3];
    for (int i = 0; i < 3; ++i)
    {
      // For a parallel camera every point sees the eye along the direction of projection.
      toEye[i] = parallel ? eye[i] : eye[i] - h * normals[face][i];
    }
    return normals[face][0] * toEye[0] + normals[face][1] * toEye[1] + normals[face][2] * toEye[2] >
      0;
  };
  std::vector<Segment> visible;
  for (int a = 0; a < 8; ++a)
  {
    for (int axis = 0; axis < 3; ++axis)
    {
      if (a & (1 << axis))
      {
        continue;
      }
      const int b = a | (1 << axis);
      // The two faces of the edge: the other two axes at the edge's sides.
      bool seen = false;
      for (int other = 0; other < 3; ++other)
      {
        if (other != axis)
        {
          seen = seen || facing(2 * other + ((a >> other) & 1 ? 0 : 1));
        }
      }
      if (!seen)
      {
        continue;
      }
      double pa[3], pb[3];
      for (int i = 0; i < 3; ++i)
      {
        pa[i] = (a >> i) & 1 ? h : -h;
        pb[i] = (b >> i) & 1 ? h : -h;
      }
      std::array<double, 2> da, db;
      scene.Project(pa, da.data());
      scene.Project(pb, db.data());
      visible.push_back({ da, db });
    }
  }
  return visible;
}

// Precision: the line pixels (mask > 127), the farthest of them from every visible edge, and
// the pixels lit at all farther than 2 px from every edge (inside the faces).
struct LinePrecision
{
  long long LinePixels = 0;
  long long FalsePixels = 0;
  double Worst = 0.0;
};

LinePrecision MeasurePrecision(vtkImageData* mask, const std::vector<Segment>& visible)
{
  LinePrecision precision;
  for (int y = 0; y < 400; ++y)
  {
    for (int x = 0; x < 400; ++x)
    {
      const double p[2] = { x + 0.5, y + 0.5 };
      double nearest = 1e9;
      for (const auto& edge : visible)
      {
        nearest = std::min(nearest, nprSegmentDistance(p, edge.first.data(), edge.second.data()));
      }
      if (nprPixel(mask, x, y) > 127)
      {
        ++precision.LinePixels;
        precision.Worst = std::max(precision.Worst, nearest);
      }
      if (nearest > 2.0 && nprPixel(mask, x, y) > 0)
      {
        ++precision.FalsePixels;
      }
    }
  }
  return precision;
}

// Recall: the fraction of points along the visible edges (2 px from their ends) with a line
// pixel's centre within 1 px.
double MeasureRecall(vtkImageData* mask, const std::vector<Segment>& visible)
{
  long long samples = 0, found = 0;
  for (const auto& edge : visible)
  {
    const double dx = edge.second[0] - edge.first[0], dy = edge.second[1] - edge.first[1];
    const int steps = static_cast<int>(std::sqrt(dx * dx + dy * dy));
    for (int s = 2; s < steps - 2; ++s)
    {
      const double px = edge.first[0] + dx * s / steps, py = edge.first[1] + dy * s / steps;
      bool hit = false;
      for (int oy = -2; oy <= 2 && !hit; ++oy)
      {
        for (int ox = -2; ox <= 2 && !hit; ++ox)
        {
          const int x = static_cast<int>(std::floor(px)) + ox,
                    y = static_cast<int>(std::floor(py)) + oy;
          const double c[2] = { x + 0.5, y + 0.5 };
          const double d = std::hypot(c[0] - px, c[1] - py);
          hit = d <= 1.0 && nprPixel(mask, x, y) > 127;
        }
      }
      ++samples;
      found += hit ? 1 : 0;
    }
  }
  return samples ? static_cast<double>(found) / samples : 0.0;
}

int CubeEdges(bool parallel)
{
  Scene scene(400, 400);
  nprAddCornerCube(scene.Renderer, parallel, nprGrey);
  scene.Edges()->SetLineWidth(1.0);
  scene.Edges()->AntiAliasingOff();
  auto mask = scene.Mask();
  const std::vector<Segment> visible = VisibleCubeEdges(scene, parallel);
  NPR_CHECK(visible.size() == 9, "a cube seen from a corner shows 9 edges, got " << visible.size());
  const LinePrecision precision = MeasurePrecision(mask, visible);
  const double recall = MeasureRecall(mask, visible);
  std::cout << (parallel ? "parallel" : "perspective") << ": " << precision.LinePixels
            << " line pixels, farthest " << precision.Worst << " px from an edge, "
            << precision.FalsePixels << " pixels lit inside faces, recall " << recall << "\n";
  NPR_CHECK(precision.LinePixels > 500, "too few line pixels: " << precision.LinePixels);
  NPR_CHECK(precision.Worst <= 1.0,
    "a line pixel lies " << precision.Worst << " px from every visible edge");
  NPR_CHECK(precision.FalsePixels == 0, precision.FalsePixels << " line pixels inside the faces");
  NPR_CHECK(recall >= 0.98, "visible edges drawn along only " << recall << " of their length");
  return nprTestResult();
}
NPR_TEST_CASE("cube", [] { return CubeEdges(false); });
NPR_TEST_CASE("cube-parallel", [] { return CubeEdges(true); });
}
