// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// The strokes of a technical drawing (vtkNPRDrawingLines), part of the TestDrawingLines program:
// smooth silhouettes (SmoothContours) against the analytic outlines of a sphere and a torus,
// without zigzags, and against the visible smooth contours of the scanned bunny; the curves
// where a pin passes through a block (IntersectionCurves), chained and split by visibility.
//
// usage: TestDrawingLines CASE [DATA_DIR]   (CASE: the NPR_TEST_CASE names below)
#include "nprEdgeMetrics.h"
#include "nprFeatureLineTesting.h"

#include "vtkCamera.h"
#include "vtkCubeSource.h"
#include "vtkCylinderSource.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkNPRDrawingLines.h"
#include "vtkNPRFeatureLines.h"
#include "vtkNPRModelReader.h"
#include "vtkNPRShadingNormals.h"
#include "vtkNew.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace
{
using namespace nprFeatureLineTesting;

// The stroke's image resampled every `step` pixels of its length (its ends kept).
std::vector<Image2> Resample(const Stroke& stroke, double step)
{
  std::vector<Image2> points{ stroke.Points.front() };
  double along = 0.0; // length walked since the last point kept
  for (size_t i = 1; i < stroke.Points.size(); ++i)
  {
    const Image2 a = stroke.Points[i - 1], b = stroke.Points[i];
    const double length = std::hypot(b[0] - a[0], b[1] - a[1]);
    double at = step - along; // where the next point falls on this piece
    for (; at <= length; at += step)
    {
      const double t = at / length;
      points.push_back({ a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]) });
    }
    along = length - (at - step);
  }
  if (along > 0.25 * step)
  {
    points.push_back(stroke.Points.back());
  }
  return points;
}

// How strokes turn, measured between consecutive chords one pixel long: the reversals (turns of
// more than 90 degrees: a zigzag's teeth, or a cusp of the contour itself) and the largest other
// turn.
struct Turning
{
  int Reversals = 0;
  double Largest = 0.0; // degrees
};

Turning MeasureTurning(const std::vector<Stroke>& strokes)
{
  Turning turning;
  for (const Stroke& stroke : strokes)
  {
    const std::vector<Image2> points = Resample(stroke, 1.0);
    for (size_t i = 2; i < points.size(); ++i)
    {
      const double a =
        std::atan2(points[i - 1][1] - points[i - 2][1], points[i - 1][0] - points[i - 2][0]);
      const double b = std::atan2(points[i][1] - points[i - 1][1], points[i][0] - points[i - 1][0]);
      const double turn =
        std::abs(vtkMath::DegreesFromRadians(std::remainder(b - a, 2.0 * vtkMath::Pi())));
      if (turn > 90.0)
      {
        ++turning.Reversals;
      }
      else
      {
        turning.Largest = std::max(turning.Largest, turn);
      }
    }
  }
  return turning;
}

// The visible strokes of one type.
std::vector<Stroke> Visible(const std::vector<Stroke>& strokes, int type)
{
  std::vector<Stroke> kept;
  std::copy_if(strokes.begin(), strokes.end(), std::back_inserter(kept),
    [&](const Stroke& stroke) { return !stroke.Hidden && stroke.Type == type; });
  return kept;
}

// The pixels the strokes pass through, sampled every quarter pixel (the reference mask's rule).
std::vector<unsigned char> Rasterize(const std::vector<Stroke>& strokes, int width, int height)
{
  std::vector<unsigned char> pixels(static_cast<size_t>(width) * height, 0);
  for (const Stroke& stroke : strokes)
  {
    for (const Image2& p : Resample(stroke, 0.25))
    {
      const int x = static_cast<int>(std::floor(p[0])), y = static_cast<int>(std::floor(p[1]));
      if (x >= 0 && y >= 0 && x < width && y < height)
      {
        pixels[static_cast<size_t>(y) * width + x] = 255;
      }
    }
  }
  return pixels;
}

// Silhouettes only, with smooth contours or mesh silhouettes, for the drawing and its mask.
void SilhouettesOnly(DrawingScene& scene, bool smooth)
{
  for (vtkNPRRendererLines* lines : { static_cast<vtkNPRRendererLines*>(scene.Lines),
         static_cast<vtkNPRRendererLines*>(scene.Reference) })
  {
    lines->CreasesOff();
    lines->BoundariesOff();
    lines->NonManifoldEdgesOff();
    lines->SetSmoothContours(smooth);
  }
}

// ---- A sphere: its outline one smooth closed stroke within 0.5 px of the analytic circle ----
// Seen obliquely to its poles, so that the outline crosses the latitudes.
int DrawingSmoothSphere()
{
  DrawingScene scene(400, 400);
  nprAddMesh(scene.Renderer, nprSphere(1.0, 96, 48));
  const double eye[3] = { 2.6, 1.8, 2.2 };
  nprLookAtOrigin(scene.Camera(), eye, 10.0);
  scene.Lines->HiddenLinesOn();
  // The analytic outline: the circle where the cone from the eye touches the sphere, seen as a
  // circle about the image of the centre.
  const double distance = std::sqrt(vtkMath::Dot(eye, eye));
  const double toward = 1.0 / distance; // the contour's plane: 1/d of the way to the eye
  double axis[3] = { eye[0], eye[1], eye[2] };
  vtkMath::Normalize(axis);
  double side[3], up[3] = { 0, 1, 0 };
  vtkMath::Cross(axis, up, side);
  vtkMath::Normalize(side);
  const double radius = std::sqrt(1.0 - toward * toward);
  const Image2 centre = scene.Project({ 0, 0, 0 });
  const Image2 rim = scene.Project({ toward * axis[0] + radius * side[0],
    toward * axis[1] + radius * side[1], toward * axis[2] + radius * side[2] });
  const double imageRadius = std::hypot(rim[0] - centre[0], rim[1] - centre[1]);

  for (bool smooth : { true, false })
  {
    SilhouettesOnly(scene, smooth);
    const std::vector<Stroke> strokes = scene.Strokes();
    const std::vector<Stroke> outline = Visible(strokes, vtkNPRFeatureLines::SILHOUETTE);
    double worst = 0.0;
    for (const Stroke& stroke : outline)
    {
      for (const Image2& p : stroke.Points)
      {
        worst =
          std::max(worst, std::abs(std::hypot(p[0] - centre[0], p[1] - centre[1]) - imageRadius));
      }
    }
    const Turning turning = MeasureTurning(outline);
    std::cout << (smooth ? "smooth" : "mesh") << " silhouettes: " << strokes.size() << " strokes, "
              << outline.size() << " visible silhouettes, farthest " << worst
              << " px from the outline (radius " << imageRadius << " px), " << turning.Reversals
              << " reversals, other turns up to " << turning.Largest << " degrees a pixel\n";
    if (smooth)
    {
      NPR_CHECK(strokes.size() == 1 && outline.size() == 1 && outline[0].Closed(),
        "the outline is not one closed visible stroke");
      NPR_CHECK(worst <= 0.5, "a point " << worst << " px from the analytic outline");
      NPR_CHECK(turning.Reversals == 0 && turning.Largest < 5.0, "the outline zigzags");
    }
  }
  return nprTestResult();
}
NPR_TEST_CASE("drawing-smooth-sphere", DrawingSmoothSphere);

// The analytic contour of nprMakeTorus(R, r) seen from eye, in the image: for each of `along`
// angles u, the angles v where the facing term n . (p - eye) = R cos v + r - n . eye is zero.
std::vector<Image2> TorusContour(DrawingScene& scene, double R, double r, const double eye[3])
{
  const double pi = vtkMath::Pi();
  std::vector<Image2> contour;
  const int along = 4096, around = 512;
  for (int i = 0; i < along; ++i)
  {
    const double u = 2.0 * pi * i / along;
    auto facing = [&](double v)
    {
      const double n[3] = { std::cos(u) * std::cos(v), std::sin(u) * std::cos(v), std::sin(v) };
      return R * std::cos(v) + r - vtkMath::Dot(n, eye);
    };
    for (int j = 0; j < around; ++j)
    {
      double low = 2.0 * pi * j / around, high = 2.0 * pi * (j + 1) / around;
      if ((facing(low) < 0.0) == (facing(high) < 0.0))
      {
        continue;
      }
      for (int k = 0; k < 50; ++k)
      {
        const double middle = 0.5 * (low + high);
        ((facing(middle) < 0.0) == (facing(low) < 0.0) ? low : high) = middle;
      }
      const double v = 0.5 * (low + high), c = R + r * std::cos(v);
      contour.push_back(scene.Project({ c * std::cos(u), c * std::sin(u), r * std::sin(v) }));
    }
  }
  return contour;
}

// ---- A torus: smooth silhouettes within 0.5 px of its analytic contour, no zigzag ----
int DrawingSmoothTorus()
{
  DrawingScene scene(480, 360);
  const double R = 1.0, r = 0.4;
  nprAddMesh(scene.Renderer, nprMakeTorus(R, r, 128, 51));
  const double eye[3] = { 3.3, -4.2, 2.4 };
  nprLookAtOrigin(scene.Camera(), eye, 10.0);
  const std::vector<Image2> truth = TorusContour(scene, R, r, eye);
  scene.Lines->HiddenLinesOn();
  for (bool smooth : { true, false })
  {
    SilhouettesOnly(scene, smooth);
    const std::vector<Stroke> outline = scene.Strokes(); // silhouettes, visible and hidden
    double worst = 0.0;
    long long points = 0;
    for (const Stroke& stroke : outline)
    {
      for (const Image2& p : stroke.Points)
      {
        double nearest = 1e30;
        for (const Image2& q : truth)
        {
          nearest = std::min(nearest, std::hypot(p[0] - q[0], p[1] - q[1]));
        }
        worst = std::max(worst, nearest);
        ++points;
      }
    }
    const Turning turning = MeasureTurning(outline);
    std::cout << (smooth ? "smooth" : "mesh") << " silhouettes: " << outline.size()
              << " strokes of " << points << " points, farthest " << worst
              << " px from the analytic contour (" << truth.size() << " points), "
              << turning.Reversals << " reversals, other turns up to " << turning.Largest
              << " degrees a pixel\n";
    if (smooth)
    {
      NPR_CHECK(points > 500 && worst <= 0.5, "a point " << worst << " px from the contour");
      // The contour's own four cusps (the inner rim's ends, seen from above), and no others.
      NPR_CHECK(turning.Reversals <= 4 && turning.Largest < 30.0, "the smooth silhouettes zigzag");
    }
    else
    {
      // What the option mends: the mesh silhouette's teeth across the saddles.
      NPR_CHECK(worst > 1.0 && turning.Reversals > 4, "the mesh silhouette no longer zigzags");
    }
  }
  return nprTestResult();
}
NPR_TEST_CASE("drawing-smooth-torus", DrawingSmoothTorus);

// ---- The scanned bunny: the drawing's silhouettes against the visible smooth contours ----
// Three views; F1@1 of the strokes' pixels against the reference mask of the smooth contours
// (both sampled every quarter pixel) with smooth silhouettes, beside the mesh silhouettes'.
int DrawingSmoothBunny()
{
  DrawingScene scene(640, 480);
  vtkNew<vtkNPRShadingNormals> normals;
  normals->SetInputConnection(nprReadTestModel("bunny.ply")->GetOutputPort());
  nprAddActor(scene.Renderer, normals->GetOutputPort());
  nprTurnBaselineCamera(scene.Renderer);
  double worst[2] = { 1.0, 1.0 }; // smooth, mesh
  for (int view = 0; view < 3; ++view)
  {
    scene.Camera()->Azimuth(view == 0 ? 0.0 : 120.0);
    scene.Camera()->Elevation(view == 2 ? -40.0 : 0.0);
    scene.Camera()->OrthogonalizeViewUp();
    scene.Renderer->ResetCameraClippingRange();
    SilhouettesOnly(scene, true);
    vtkImageData* mask = scene.Mask();
    for (bool smooth : { true, false })
    {
      scene.Lines->SetSmoothContours(smooth);
      const std::vector<unsigned char> drawn = Rasterize(
        Visible(scene.Strokes(), vtkNPRFeatureLines::SILHOUETTE), scene.Width, scene.Height);
      nprEdgeMetrics metrics;
      metrics.Compute(drawn.data(), static_cast<unsigned char*>(mask->GetScalarPointer()),
        scene.Width, scene.Height);
      std::cout << "view " << view << ", " << (smooth ? "smooth" : "mesh") << " silhouettes: F1@1 "
                << metrics.F1(1.0) << " (precision " << metrics.Precision(1.0) << ", recall "
                << metrics.Recall(1.0) << ", " << metrics.GetMethodPixels() << " pixels, mask "
                << metrics.GetReferencePixels() << ")\n";
      double& least = worst[smooth ? 0 : 1];
      least = std::min(least, metrics.F1(1.0));
    }
  }
  NPR_CHECK(worst[0] >= 0.97, "smooth silhouettes: F1@1 " << worst[0] << " in the worst view");
  NPR_CHECK(worst[1] < worst[0], "the mesh silhouettes score as well (" << worst[1] << ")");
  return nprTestResult();
}
NPR_TEST_CASE("drawing-smooth-bunny", DrawingSmoothBunny);

// ---- A pin through a block: the curves where they cross, visible and hidden ----
// A 64-sided pin of radius 0.3 along y through a block 0.8 high: two rings at y = +-0.4, the top
// one seen from above (its far side behind the pin), the bottom one inside the block. With
// IntersectionCurves off, none.
int DrawingIntersections()
{
  DrawingScene scene(480, 360);
  vtkNew<vtkCubeSource> block;
  block->SetXLength(2.0);
  block->SetYLength(0.8);
  block->SetZLength(2.0);
  vtkNew<vtkCylinderSource> pin;
  pin->SetResolution(64);
  pin->SetRadius(0.3);
  pin->SetHeight(2.4);
  nprAddActor(scene.Renderer, block->GetOutputPort());
  nprAddActor(scene.Renderer, pin->GetOutputPort());
  const double eye[3] = { 2.5, 3.5, 4.5 };
  nprLookAtOrigin(scene.Camera(), eye, 20.0);
  scene.Lines->HiddenLinesOn();
  vtkImageData* mask = scene.Mask(); // IntersectionCurves on by default in both
  const std::vector<Stroke> strokes = scene.Strokes();
  int rings[2][2] = { { 0, 0 }, { 0, 0 } }; // [top, bottom][visible, hidden] strokes
  long long points = 0, offRing = 0, visibleOnMask = 0, visiblePoints = 0;
  vtkPolyData* output = scene.Lines->GetStrokes();
  for (const Stroke& stroke : strokes)
  {
    if (stroke.Type != vtkNPRFeatureLines::INTERSECTION)
    {
      continue;
    }
    double first[3];
    output->GetPoint(stroke.Ids.front(), first);
    ++rings[first[1] > 0.0 ? 0 : 1][stroke.Hidden ? 1 : 0];
    for (size_t i = 0; i < stroke.Ids.size(); ++i)
    {
      double p[3];
      output->GetPoint(stroke.Ids[i], p);
      const double fromAxis = std::hypot(p[0], p[2]);
      // On the block's face and on the pin's 64-gon (between its inscribed and outer radius),
      // to the sources' single precision.
      const bool onRing = std::abs(std::abs(p[1]) - 0.4) < 1e-6 &&
        fromAxis >= 0.3 * std::cos(vtkMath::Pi() / 64) - 1e-6 && fromAxis <= 0.3 + 1e-6;
      offRing += onRing ? 0 : 1;
      ++points;
      if (!stroke.Hidden && i > 0 && i + 1 < stroke.Ids.size())
      {
        ++visiblePoints;
        visibleOnMask += nprNearPixel(mask, static_cast<int>(std::floor(stroke.Points[i][0])),
                           static_cast<int>(std::floor(stroke.Points[i][1])))
          ? 1
          : 0;
      }
    }
  }
  std::cout << "top ring: " << rings[0][0] << " visible and " << rings[0][1]
            << " hidden strokes; bottom ring: " << rings[1][0] << " visible and " << rings[1][1]
            << " hidden; " << points << " points, " << offRing << " off the rings; "
            << visibleOnMask << "/" << visiblePoints << " visible points on the mask\n";
  NPR_CHECK(points > 128 && offRing == 0, offRing << " intersection points off the rings");
  NPR_CHECK(
    rings[0][0] == 1 && rings[0][1] == 1, "the top ring is not one visible and one hidden stroke");
  NPR_CHECK(rings[1][0] == 0 && rings[1][1] == 1, "the bottom ring is not one hidden stroke");
  NPR_CHECK(visiblePoints > 30 && visibleOnMask == visiblePoints, "visible points off the mask");

  scene.Lines->IntersectionCurvesOff();
  const std::vector<Stroke> without = scene.Strokes();
  NPR_CHECK(std::none_of(without.begin(), without.end(),
              [](const Stroke& stroke) { return stroke.Type == vtkNPRFeatureLines::INTERSECTION; }),
    "intersection strokes with IntersectionCurves off");
  return nprTestResult();
}
NPR_TEST_CASE("drawing-intersections", DrawingIntersections);
}
