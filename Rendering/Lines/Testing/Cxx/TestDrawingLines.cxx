// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// The strokes of a technical drawing (vtkNPRDrawingLines): a cube's visible and hidden edges
// against their analytic projections, in perspective and parallel; one object hiding another's
// lines, split where the front object's outline crosses them; a rod through a ring, each hiding
// part of the other's lines; a cylinder's rims as one closed stroke each; the bunny's strokes
// chained and their visible points inside the reference mask; bad input.
//
// usage: TestDrawingLines CASE [DATA_DIR]   (CASE: see the table at the end of this file)
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
using Image2 = std::array<double, 2>;

// A stroke as read back: its points in the image, its type and visibility.
struct Stroke
{
  std::vector<Image2> Points;
  std::vector<vtkIdType> Ids;
  int Type;
  bool Hidden;
  bool Closed() const { return this->Ids.size() > 2 && this->Ids.front() == this->Ids.back(); }
};

std::vector<Stroke> ReadStrokes(vtkNPRDrawingLines* lines)
{
  vtkPolyData* strokes = lines->GetStrokes();
  vtkDataArray* image = strokes->GetPointData()->GetArray("ImageCoordinates");
  auto* types = vtkUnsignedCharArray::SafeDownCast(strokes->GetCellData()->GetArray("FeatureType"));
  auto* hidden = vtkUnsignedCharArray::SafeDownCast(strokes->GetCellData()->GetArray("Hidden"));
  std::vector<Stroke> result;
  NPR_CHECK(image && image->GetNumberOfComponents() == 3 && types && hidden,
    "the strokes lack ImageCoordinates, FeatureType or Hidden");
  if (!image || !types || !hidden)
  {
    return result;
  }
  auto iterator = vtk::TakeSmartPointer(strokes->GetLines()->NewIterator());
  vtkIdType cell = 0;
  for (iterator->GoToFirstCell(); !iterator->IsDoneWithTraversal();
       iterator->GoToNextCell(), ++cell)
  {
    vtkIdType size;
    const vtkIdType* ids;
    iterator->GetCurrentCell(size, ids);
    Stroke stroke;
    for (vtkIdType i = 0; i < size; ++i)
    {
      stroke.Ids.push_back(ids[i]);
      stroke.Points.push_back({ image->GetComponent(ids[i], 0), image->GetComponent(ids[i], 1) });
      const double z = image->GetComponent(ids[i], 2);
      NPR_CHECK(z >= 0.0 && z <= 1.0, "a stroke point's depth is " << z);
    }
    stroke.Type = types->GetValue(cell);
    stroke.Hidden = hidden->GetValue(cell) != 0;
    NPR_CHECK(size >= 2, "a stroke of " << size << " points");
    result.push_back(stroke);
  }
  return result;
}

struct DrawingScene : MaskScene
{
  vtkNew<vtkNPRDrawingLines> Lines;
  DrawingScene(int width, int height)
    : MaskScene(width, height)
  {
    this->Lines->SetRenderer(this->Renderer);
  }
  std::vector<Stroke> Strokes()
  {
    NPR_CHECK(this->Lines->Update(), "the drawing lines failed");
    return ReadStrokes(this->Lines);
  }
};

double Distance(const Image2& a, const Image2& b)
{
  return std::hypot(a[0] - b[0], a[1] - b[1]);
}

// ---- A unit cube from a corner: 9 visible edges, 3 hidden, against the analytic projection ----
int DrawingCube(bool parallel)
{
  DrawingScene scene(400, 300);
  const double origin[3] = { 0, 0, 0 };
  nprAddCube(scene.Renderer, origin, 1.0);
  const double eye[3] = { 2.2, 1.7, 2.9 };
  nprViewFromCorner(scene.Camera(), eye, parallel);
  scene.Lines->HiddenLinesOn();
  const std::vector<Stroke> strokes = scene.Strokes();

  double toward[3];
  for (int i = 0; i < 3; ++i)
  {
    toward[i] = -eye[i];
  }
  std::vector<Image2> corners;
  for (int c = 0; c < 8; ++c)
  {
    corners.push_back(scene.Project(Corner(c)));
  }
  // The analytic edges as pairs of corner indices, visible or hidden.
  std::set<std::pair<int, int>> visible, hidden;
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
  vtkCamera* camera = scene.Camera();
  camera->SetPosition(2.0, 1.5, 8.0);
  camera->SetFocalPoint(0, 0, 0);
  camera->SetViewUp(0, 1, 0);
  camera->SetClippingRange(1.0, 20.0);
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

// ---- A rod through a ring: each hides part of the other's lines ----
// Visible line length in pixels on the ring (a torus of radii 1 and 0.25 about z) and on the rod
// (radius 0.15 along x), each stroke segment told by where its world midpoint lies.
std::array<double, 2> VisibleLengths(vtkNPRDrawingLines* lines)
{
  vtkPolyData* strokes = lines->GetStrokes();
  vtkDataArray* image = strokes->GetPointData()->GetArray("ImageCoordinates");
  auto* hidden = vtkUnsignedCharArray::SafeDownCast(strokes->GetCellData()->GetArray("Hidden"));
  std::array<double, 2> length = { 0.0, 0.0 };
  auto iterator = vtk::TakeSmartPointer(strokes->GetLines()->NewIterator());
  vtkIdType cell = 0;
  for (iterator->GoToFirstCell(); !iterator->IsDoneWithTraversal();
       iterator->GoToNextCell(), ++cell)
  {
    vtkIdType size;
    const vtkIdType* ids;
    iterator->GetCurrentCell(size, ids);
    for (vtkIdType i = 0; !hidden->GetValue(cell) && i + 1 < size; ++i)
    {
      double a[3], b[3];
      strokes->GetPoint(ids[i], a);
      strokes->GetPoint(ids[i + 1], b);
      const double m[3] = { 0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1]), 0.5 * (a[2] + b[2]) };
      const double ringResidual = std::abs(std::hypot(std::hypot(m[0], m[1]) - 1.0, m[2]) - 0.25);
      const double pixels =
        std::hypot(image->GetComponent(ids[i + 1], 0) - image->GetComponent(ids[i], 0),
          image->GetComponent(ids[i + 1], 1) - image->GetComponent(ids[i], 1));
      length[ringResidual < 0.02 ? 0 : 1] += pixels;
    }
  }
  return length;
}

int DrawingMutual()
{
  DrawingScene scene(500, 400);
  vtkNew<vtkParametricTorus> torus;
  torus->SetRingRadius(1.0);
  torus->SetCrossSectionRadius(0.25);
  vtkNew<vtkParametricFunctionSource> ring;
  ring->SetParametricFunction(torus);
  ring->SetUResolution(64);
  ring->SetVResolution(16);
  vtkSmartPointer<vtkActor> ringActor = nprAddActor(scene.Renderer, ring->GetOutputPort());
  vtkNew<vtkCylinderSource> cylinder; // along y: turned onto x, through the ring's hole
  cylinder->SetResolution(32);
  cylinder->SetRadius(0.15);
  cylinder->SetHeight(3.0);
  cylinder->SetCenter(0.0, 1.0, 0.0); // its axis crosses the ring's tube at x = 1 once turned
  vtkSmartPointer<vtkActor> rod = nprAddActor(scene.Renderer, cylinder->GetOutputPort());
  rod->SetOrientation(0.0, 0.0, 90.0);
  vtkCamera* camera = scene.Camera();
  camera->SetPosition(1.0, 3.0, 5.0);
  camera->SetFocalPoint(-0.2, 0, 0);
  camera->SetViewUp(0, 1, 0);
  camera->SetClippingRange(1.0, 20.0);
  auto lengths = [&](vtkActor* gone)
  {
    if (gone)
    {
      gone->VisibilityOff();
    }
    NPR_CHECK(scene.Lines->Update(), "the drawing lines failed");
    if (gone)
    {
      gone->VisibilityOn();
    }
    return VisibleLengths(scene.Lines);
  };
  const double ringAlone = lengths(rod)[0];
  const double rodAlone = lengths(ringActor)[1];
  const std::array<double, 2> together = lengths(nullptr);
  std::cout << "visible line length: ring " << ringAlone << " px alone, " << together[0]
            << " px with the rod; rod " << rodAlone << " px alone, " << together[1]
            << " px with the ring\n";
  NPR_CHECK(ringAlone > 500 && rodAlone > 300, "the ring or the rod has too few lines");
  NPR_CHECK(together[0] < ringAlone - 10.0, "the rod hides none of the ring's lines");
  NPR_CHECK(together[1] < rodAlone - 10.0, "the ring hides none of the rod's lines");
  return nprTestResult();
}

// ---- A cylinder seen along its axis: each rim is one closed stroke ----
int DrawingCylinder()
{
  DrawingScene scene(400, 400);
  vtkNew<vtkCylinderSource> cylinder;
  cylinder->SetResolution(64);
  cylinder->SetHeight(1.0);
  cylinder->SetRadius(1.0);
  nprAddActor(scene.Renderer, cylinder->GetOutputPort());
  vtkCamera* camera = scene.Camera();
  camera->SetPosition(0.0, 6.0, 0.0); // on the axis (y), above the top cap
  camera->SetFocalPoint(0, 0, 0);
  camera->SetViewUp(0, 0, -1);
  camera->SetClippingRange(1.0, 10.0);
  scene.Lines->HiddenLinesOn();
  const std::vector<Stroke> strokes = scene.Strokes();
  int visibleRims = 0, hiddenRims = 0;
  for (const Stroke& stroke : strokes)
  {
    std::cout << "stroke: " << stroke.Ids.size() << " points, type " << stroke.Type
              << (stroke.Hidden ? ", hidden" : ", visible") << (stroke.Closed() ? ", closed" : "")
              << "\n";
    if (stroke.Closed() && stroke.Ids.size() == 65)
    {
      (stroke.Hidden ? hiddenRims : visibleRims) += 1;
    }
  }
  NPR_CHECK(strokes.size() == 2 && visibleRims == 1 && hiddenRims == 1,
    "expected the top rim as one closed visible stroke of 64 edges and the bottom rim as one "
    "closed hidden stroke; got "
      << strokes.size() << " strokes");
  NPR_CHECK(scene.Lines->GetNumberOfFeatureEdges() >= 128, "the rims' 128 edges are not lines");
  return nprTestResult();
}

// ---- The bunny: strokes chain many edges; visible points lie on the reference mask ----
int DrawingBunny()
{
  DrawingScene scene(640, 480);
  vtkSmartPointer<vtkNPRModelReader> reader = nprReadTestModel("bunny.ply");
  nprAddActor(scene.Renderer, reader->GetOutputPort());
  nprTurnBaselineCamera(scene.Renderer);
  scene.Lines->HiddenLinesOn();
  auto start = std::chrono::steady_clock::now();
  const std::vector<Stroke> strokes = scene.Strokes();
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  vtkImageData* mask = scene.Mask();
  long long segments = 0, visiblePoints = 0, onMask = 0, hiddenStrokes = 0;
  for (const Stroke& stroke : strokes)
  {
    segments += static_cast<long long>(stroke.Points.size()) - 1;
    hiddenStrokes += stroke.Hidden ? 1 : 0;
    if (stroke.Hidden)
    {
      continue;
    }
    // Interior points of visible strokes (ends may sit exactly on a split).
    for (size_t i = 1; i + 1 < stroke.Points.size(); ++i)
    {
      const int x = static_cast<int>(std::floor(stroke.Points[i][0]));
      const int y = static_cast<int>(std::floor(stroke.Points[i][1]));
      bool hit = false;
      for (int oy = -1; oy <= 1 && !hit; ++oy)
      {
        for (int ox = -1; ox <= 1 && !hit; ++ox)
        {
          hit = nprPixel(mask, x + ox, y + oy) != 0;
        }
      }
      ++visiblePoints;
      onMask += hit ? 1 : 0;
    }
  }
  vtkNPRDrawingLines* lines = scene.Lines;
  std::cout << strokes.size() << " strokes (" << hiddenStrokes << " hidden) of " << segments
            << " pieces from " << lines->GetNumberOfFeatureEdges() << " feature edges; "
            << lines->GetNumberOfRayCasts() << " rays; " << seconds << " s (lines "
            << lines->GetLinesTime() << ", locator " << lines->GetLocatorTime() << ", visibility "
            << lines->GetVisibilityTime() << ", chains " << lines->GetChainTime() << "); " << onMask
            << "/" << visiblePoints << " visible points on the mask\n";
  NPR_CHECK(hiddenStrokes > 0 && hiddenStrokes < static_cast<long long>(strokes.size()),
    "the bunny has both visible and hidden strokes");
  NPR_CHECK(segments >= 3 * static_cast<long long>(strokes.size()),
    "strokes are not chained: " << segments << " pieces in " << strokes.size() << " strokes");
  NPR_CHECK(visiblePoints > 500 && onMask >= visiblePoints * 999 / 1000,
    "visible points off the reference mask: " << visiblePoints - onMask << " of " << visiblePoints);
  // The same camera again: the same strokes, no rebuild of the occluders.
  const std::vector<Stroke> again = scene.Strokes();
  NPR_CHECK(again.size() == strokes.size() && lines->GetNumberOfLocatorBuilds() == 1,
    "a second update differs");
  return nprTestResult();
}

// ---- Bad input: no renderer, no size, an empty scene, a mesh with NaN points ----
int DrawingErrors()
{
  auto* messages = nprCountingOutputWindow::SafeDownCast(vtkOutputWindow::GetInstance());
  // One error expected from `call`: counted, then taken off the harness's count.
  auto expectError = [&](const char* what, const std::function<bool()>& call)
  {
    const int errors = messages ? messages->Errors : 0;
    NPR_CHECK(!call(), what << ": Update() succeeded");
    NPR_CHECK(messages && messages->Errors == errors + 1, what << ": no error reported");
    if (messages)
    {
      messages->Errors = errors;
    }
  };
  vtkNew<vtkNPRDrawingLines> lines;
  expectError("no renderer", [&] { return lines->Update(); });
  vtkNew<vtkRenderer> alone;
  lines->SetRenderer(alone);
  expectError("no size", [&] { return lines->Update(); });

  DrawingScene scene(200, 100);
  NPR_CHECK(scene.Strokes().empty() && scene.Lines->GetStrokes()->GetNumberOfPoints() == 0,
    "an empty scene has strokes");
  vtkNew<vtkPolyData> broken;
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0, 0, 0);
  points->InsertNextPoint(1, 0, 0);
  points->InsertNextPoint(std::nan(""), 1, 0);
  points->InsertNextPoint(0, 1, 0);
  broken->SetPoints(points);
  vtkNew<vtkCellArray> polys;
  const vtkIdType good[3] = { 0, 1, 3 }, bad[3] = { 1, 2, 3 };
  polys->InsertNextCell(3, good);
  polys->InsertNextCell(3, bad);
  broken->SetPolys(polys);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(broken);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  scene.Renderer->AddActor(actor);
  scene.Renderer->ResetCamera(0, 1, 0, 1, -0.5, 0.5);
  std::cout << "expected: one VTK warning about a face with NaN coordinates\n";
  const std::vector<Stroke> strokes = scene.Strokes();
  NPR_CHECK(!strokes.empty(), "the good triangle's boundary is missing");
  return nprTestResult();
}
}

int main(int argc, char* argv[])
{
  const std::map<std::string, std::function<int()>> cases = {
    { "drawing-cube", [] { return DrawingCube(false); } },
    { "drawing-cube-parallel", [] { return DrawingCube(true); } },
    { "drawing-occlusion", [] { return DrawingOcclusion(false); } },
    { "drawing-occlusion-parallel", [] { return DrawingOcclusion(true); } },
    { "drawing-cylinder", DrawingCylinder },
    { "drawing-mutual", DrawingMutual },
    { "drawing-bunny", DrawingBunny },
    { "drawing-errors", DrawingErrors },
  };
  return nprRunTestCase(argc, argv, cases);
}
