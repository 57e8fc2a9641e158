// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// The lines of the edge pass (vtkNPREdgePass over vtkNPRGBufferPass) where their place can be
// stated: a cube's visible edges projected analytically, in perspective and parallel; no false
// line on a plane seen at a grazing angle, nor on a shallow fold seen nearly edge-on (while a step
// of that size is drawn); creases from the crease angle on, never below; the id contour between
// touching objects, and its sides; anti-aliasing, line width and DPI along a slanted silhouette.
//
// usage: TestEdgePassLines CASE [DATA_DIR]   (CASE: see the table at the end of this file)
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

const double Grey[3] = { 0.8, 0.8, 0.8 };

// ---- A unit cube from a known camera: line pixels on its visible edges and nowhere else ----
int CubeEdges(bool parallel)
{
  Scene scene(400, 400);
  const double origin[3] = { 0, 0, 0 };
  nprAddCube(scene.Renderer, origin, 1.0, Grey);
  const double eye[3] = { 2.2, 1.7, 2.9 };
  nprViewFromCorner(scene.Camera(), eye, parallel);
  scene.Edges()->SetLineWidth(1.0);
  scene.Edges()->AntiAliasingOff();
  auto mask = scene.Mask();

  // Visible edges of a convex box: those with at least one face turned towards the eye.
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
  std::vector<std::pair<std::array<double, 2>, std::array<double, 2>>> visible;
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
  NPR_CHECK(visible.size() == 9, "a cube seen from a corner shows 9 edges, got " << visible.size());

  double worst = 0.0;
  long long linePixels = 0, falsePixels = 0;
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
        ++linePixels;
        worst = std::max(worst, nearest);
      }
      if (nearest > 2.0 && nprPixel(mask, x, y) > 0)
      {
        ++falsePixels;
      }
    }
  }
  // Recall: every visible edge is drawn along its length.
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
  const double recall = samples ? static_cast<double>(found) / samples : 0.0;
  std::cout << (parallel ? "parallel" : "perspective") << ": " << linePixels
            << " line pixels, farthest " << worst << " px from an edge, " << falsePixels
            << " pixels lit inside faces, recall " << recall << "\n";
  NPR_CHECK(linePixels > 500, "too few line pixels: " << linePixels);
  NPR_CHECK(worst <= 1.0, "a line pixel lies " << worst << " px from every visible edge");
  NPR_CHECK(falsePixels == 0, falsePixels << " line pixels inside the faces");
  NPR_CHECK(recall >= 0.98, "visible edges drawn along only " << recall << " of their length");
  return nprTestResult();
}

// The camera of the fold scenes: straight down the z axis at the fold along x (y = 0), and the
// fold's ends (x = -0.8 and 0.8) in pixels.
void LookAtFold(Scene& scene, bool parallel)
{
  vtkCamera* camera = scene.Camera();
  camera->SetPosition(0, 0, 10);
  camera->SetFocalPoint(0, 0, 0);
  camera->SetViewUp(0, 1, 0);
  camera->SetViewAngle(14);
  camera->SetParallelProjection(parallel);
  camera->SetParallelScale(1.2);
  camera->SetClippingRange(5, 15);
}

void ProjectFold(Scene& scene, double left[2], double right[2])
{
  const double foldLeft[3] = { -0.8, 0, 0 };
  const double foldRight[3] = { 0.8, 0, 0 };
  scene.Project(foldLeft, left);
  scene.Project(foldRight, right);
}

// ---- A plane at a grazing angle: its far border is a silhouette, its inside has no line ----
int GrazingPlane()
{
  Scene scene(400, 300);
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-50, 0, -50);
  plane->SetPoint1(50, 0, -50);
  plane->SetPoint2(-50, 0, 50);
  plane->SetResolution(20, 20);
  const double grey[3] = { 0.7, 0.7, 0.7 };
  nprAddActor(scene.Renderer, plane->GetOutputPort(), grey);
  vtkCamera* camera = scene.Camera();
  camera->SetPosition(0, 0.3, 30);
  camera->SetFocalPoint(0, -0.5, -50);
  camera->SetViewUp(0, 1, 0);
  camera->SetViewAngle(30);
  camera->SetClippingRange(0.1, 200);
  auto mask = scene.Mask();
  const double farEdge[3] = { 0, 0, -50 };
  double horizon[2];
  scene.Project(farEdge, horizon);
  long long far = 0, inside = 0;
  for (int y = 0; y < 300; ++y)
  {
    for (int x = 0; x < 400; ++x)
    {
      if (nprPixel(mask, x, y) > 0)
      {
        (std::abs(y + 0.5 - horizon[1]) <= 3.0 ? far : inside)++;
      }
    }
  }
  std::cout << "far border row " << horizon[1] << ": " << far << " line pixels there, " << inside
            << " elsewhere\n";
  NPR_CHECK(far > 300, "the far border should be a silhouette line: " << far << " pixels");
  NPR_CHECK(inside == 0, inside << " false line pixels on the grazing plane");
  return nprTestResult();
}

// ---- A 15-degree fold seen nearly edge-on bends the depth as much as a step: no line ----
// Seen from the eye, face A (n.v 0.31) runs down the screen to the fold, face B (n.v 0.05) on
// from it, receding eight times as steeply. The depth's second difference at the fold is 2.5
// times the silhouette threshold, but the surface is continuous and front-facing: the mesh has
// no silhouette and no crease there. With a gap (B moved back by a relative depth step of 3 %)
// the same place is a step, which must be drawn. (A step smaller than B's own depth change over
// a pixel, 1.5 %, fits a fold between the pixels as well: the pass takes it for one.)
int GrazingFold(bool parallel, bool gap)
{
  Scene scene(400, 300);
  const double pi = std::acos(-1.0);
  const double angleA = 18.0 * pi / 180.0; // between each face and the view direction
  const double angleB = 3.0 * pi / 180.0;
  const double back = gap ? 0.3 : 0.0;
  vtkNew<vtkPlaneSource> faceA;
  faceA->SetOrigin(-1, 0, 0);
  faceA->SetPoint1(1, 0, 0);
  faceA->SetPoint2(-1, 2 * std::sin(angleA), 2 * std::cos(angleA));
  vtkNew<vtkPlaneSource> faceB;
  faceB->SetOrigin(-1, 0, -back); // wound as faceA: both normals towards the eye
  faceB->SetPoint1(-1, -2 * std::sin(angleB), -back - 2 * std::cos(angleB));
  faceB->SetPoint2(1, 0, -back);
  vtkNew<vtkAppendPolyData> both;
  both->AddInputConnection(faceA->GetOutputPort());
  both->AddInputConnection(faceB->GetOutputPort());
  vtkNew<vtkCleanPolyData> merged; // one surface along the fold: the faces share its points
  merged->SetInputConnection(both->GetOutputPort());
  nprAddActor(scene.Renderer, merged->GetOutputPort(), Grey);
  LookAtFold(scene, parallel);
  auto mask = scene.Mask();
  double left[2], right[2];
  ProjectFold(scene, left, right);
  long long near = 0;
  for (int y = 0; y < 300; ++y)
  {
    for (int x = static_cast<int>(left[0]); x <= static_cast<int>(right[0]); ++x)
    {
      near += std::abs(y + 0.5 - left[1]) <= 3.0 && nprPixel(mask, x, y) > 0 ? 1 : 0;
    }
  }
  const double length = right[0] - left[0];
  std::cout << (gap ? "step" : "fold") << " at row " << left[1] << ", " << length
            << " px long: " << near << " line pixels within 3 px\n";
  if (gap)
  {
    NPR_CHECK(near >= 0.9 * length, "the step is drawn along only " << near << " pixels");
  }
  else
  {
    NPR_CHECK(near == 0, near << " line pixels on the fold");
  }
  return nprTestResult();
}

// ---- A roof seen from the front: a crease where its faces turn by more than the crease angle ----
// The faces turn by `turn` degrees at the fold (flat normals, one object, no depth step); the
// crease is drawn from the crease angle less its ramp (a quarter of the angle, at most 1 degree)
// and in full past it, never below. Angles inside the ramp check that no pixel on a crease is
// skipped as plain surface before its test.
int CreaseThreshold(double creaseAngle, double turn)
{
  Scene scene(400, 300);
  const double pi = std::acos(-1.0);
  const double half = 0.5 * turn * pi / 180.0;
  vtkNew<vtkPlaneSource> faceA; // upwards from the fold, receding; its normal towards the eye
  faceA->SetOrigin(-1, 0, 0);
  faceA->SetPoint1(1, 0, 0);
  faceA->SetPoint2(-1, std::cos(half), -std::sin(half));
  vtkNew<vtkPlaneSource> faceB; // downwards
  faceB->SetOrigin(-1, 0, 0);
  faceB->SetPoint1(-1, -std::cos(half), -std::sin(half));
  faceB->SetPoint2(1, 0, 0);
  // Not merged: each face keeps its own normals along the fold, as a mesh split at its creases.
  vtkNew<vtkAppendPolyData> both;
  both->AddInputConnection(faceA->GetOutputPort());
  both->AddInputConnection(faceB->GetOutputPort());
  nprAddActor(scene.Renderer, both->GetOutputPort(), Grey);
  LookAtFold(scene, false);
  scene.Edges()->SetCreaseAngle(creaseAngle);
  scene.Edges()->SetLineWidth(1.0);
  scene.Edges()->AntiAliasingOff();
  auto mask = scene.Mask();
  double left[2], right[2];
  ProjectFold(scene, left, right);
  long long near = 0, elsewhere = 0;
  for (int y = 0; y < 300; ++y)
  {
    for (int x = static_cast<int>(left[0]); x <= static_cast<int>(right[0]); ++x)
    {
      const bool onFold = std::abs(y + 0.5 - left[1]) <= 3.0;
      const bool lit = nprPixel(mask, x, y) > 127;
      near += onFold && lit ? 1 : 0;
      // The faces' far borders are silhouettes: only the rows between them and the fold count.
      elsewhere += !onFold && std::abs(y + 0.5 - left[1]) < 40.0 && lit ? 1 : 0;
    }
  }
  const double ramp = std::min(1.0, 0.25 * creaseAngle) * 1.0027; // 0.0175 rad
  const double length = right[0] - left[0];
  std::cout << "crease angle " << creaseAngle << ", faces turning by " << turn << ": " << near
            << " line pixels on the " << length << " px fold, " << elsewhere << " beside it\n";
  NPR_CHECK(elsewhere == 0, elsewhere << " line pixels on the faces beside the fold");
  if (turn < creaseAngle - ramp)
  {
    NPR_CHECK(near == 0, near << " line pixels on a fold below the crease angle");
  }
  else
  {
    NPR_CHECK(near >= 0.95 * length, "the crease is drawn along only " << near << " pixels");
  }
  return nprTestResult();
}

// ---- Two cubes touching face to face, seen straight on: only the id contour separates them ----
int TouchingObjects()
{
  Scene scene(400, 300);
  const double left[3] = { -0.5, 0, 0 }, right[3] = { 0.5, 0, 0 };
  nprAddCube(scene.Renderer, left, 1.0, Grey);
  nprAddCube(scene.Renderer, right, 1.0, Grey);
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

// ---- Anti-aliasing: intermediate coverage along slanted lines, and less staircase ----
int AntiAliasing()
{
  Scene scene(400, 300);
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
  scene.Edges()->SetLineWidth(1.5);

  // The top edge runs from (-1, 0.5) to (1, 0.5) turned by 12 degrees; in the middle columns
  // the coverage-weighted row of the line should follow a straight line.
  const double ends[2][3] = { { -1, 0.5, 0.5 }, { 1, 0.5, 0.5 } };
  double e0[2], e1[2], rotated[2][3];
  for (int i = 0; i < 2; ++i)
  {
    tilt->TransformPoint(ends[i], rotated[i]);
  }
  scene.Project(rotated[0], e0);
  scene.Project(rotated[1], e1);
  auto measure = [&](vtkImageData* mask, long long& intermediate, long long& lit)
  {
    intermediate = lit = 0;
    std::vector<double> xs, ys;
    for (int x = static_cast<int>(e0[0]) + 20; x < static_cast<int>(e1[0]) - 20; ++x)
    {
      const double yEdge = e0[1] + (x + 0.5 - e0[0]) * (e1[1] - e0[1]) / (e1[0] - e0[0]);
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
    // Residual of the line's centre from its least-squares straight line: the staircase.
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
  };
  long long intermediateOn, litOn, intermediateOff, litOff;
  const double staircaseOn = measure(scene.Mask(), intermediateOn, litOn);
  scene.Edges()->AntiAliasingOff();
  const double staircaseOff = measure(scene.Mask(), intermediateOff, litOff);
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
  auto coverageSum = [&](vtkImageData* mask)
  {
    double sum = 0;
    for (int x = static_cast<int>(e0[0]) + 20; x < static_cast<int>(e1[0]) - 20; ++x)
    {
      for (int y = 0; y < 300; ++y)
      {
        const double yEdge = e0[1] + (x + 0.5 - e0[0]) * (e1[1] - e0[1]) / (e1[0] - e0[0]);
        sum += std::abs(y + 0.5 - yEdge) < 8 ? nprPixel(mask, x, y) / 255.0 : 0.0;
      }
    }
    return sum;
  };
  const double thin = coverageSum(scene.Mask());
  scene.Edges()->SetLineWidth(6.0);
  const double thick = coverageSum(scene.Mask());
  std::cout << "coverage across the edge: width 1.5 -> " << thin << ", width 6 -> " << thick
            << "\n";
  NPR_CHECK(thick > 3.0 * thin && thick < 5.0 * thin, "line width not honoured");
  // Widths are at 72 DPI: a window at 144 DPI draws them twice as wide.
  scene.Edges()->SetLineWidth(1.5);
  scene.Window->SetDPI(144);
  const double doubled = coverageSum(scene.Mask());
  scene.Window->SetDPI(72);
  std::cout << "width 1.5 at 144 DPI -> " << doubled << "\n";
  NPR_CHECK(doubled > 1.6 * thin && doubled < 2.4 * thin, "the DPI scale is not applied");
  return nprTestResult();
}
}

int main(int argc, char* argv[])
{
  const std::map<std::string, std::function<int()>> cases = {
    { "cube", [] { return CubeEdges(false); } },
    { "cube-parallel", [] { return CubeEdges(true); } },
    { "grazing-plane", GrazingPlane },
    { "grazing-fold", [] { return GrazingFold(false, false); } },
    { "grazing-fold-parallel", [] { return GrazingFold(true, false); } },
    { "grazing-step", [] { return GrazingFold(false, true); } },
    { "grazing-step-parallel", [] { return GrazingFold(true, true); } },
    { "touching-objects", TouchingObjects },
    // Below the ramp, inside it (0.7 of the way up) and past it, at three crease angles.
    { "crease-threshold",
      []
      {
        int failed = 0;
        for (double angle : { 30.0, 10.0, 2.0 })
        {
          const double ramp = std::min(1.0, 0.25 * angle) * 1.0027;
          for (double turn : { angle - ramp - 0.5, angle + 0.7 * ramp, angle + ramp + 1.0 })
          {
            failed |= CreaseThreshold(angle, turn);
          }
        }
        return failed;
      } },
    { "antialiasing", AntiAliasing },
  };
  return nprRunTestCase(argc, argv, cases);
}
