// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// The strokes of a technical drawing (vtkNPRDrawingLines), part of the TestDrawingLines program: a
// rod through a ring, each hiding part of the other's lines; a cylinder's rims as one closed
// stroke each; the bunny's strokes chained and their visible points inside the reference mask;
// bad input; the scene's own line cells, hidden behind a surface.
//
// usage: TestDrawingLines CASE [DATA_DIR]   (CASE: the NPR_TEST_CASE names below)
#include "nprFeatureLineTesting.h"
#include "nprTestMeshes.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkCylinderSource.h"
#include "vtkDataArray.h"
#include "vtkDataSetMapper.h"
#include "vtkFieldData.h"
#include "vtkImageData.h"
#include "vtkIntArray.h"
#include "vtkNPRDrawingLines.h"
#include "vtkNPRFeatureLines.h"
#include "vtkNPRModelReader.h"
#include "vtkNew.h"
#include "vtkOutputWindow.h"
#include "vtkParametricFunctionSource.h"
#include "vtkParametricTorus.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
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
// ---- A rod through a ring: each hides part of the other's lines ----
// Visible line length in pixels on the ring (a torus of radii 1 and 0.25 about z) and on the rod
// (radius 0.15 along x), each stroke segment told by where its world midpoint lies; the curves
// where they cross, on both, are left out.
std::array<double, 2> VisibleLengths(vtkNPRDrawingLines* lines)
{
  vtkPolyData* strokes = lines->GetStrokes();
  vtkDataArray* image = strokes->GetPointData()->GetArray("ImageCoordinates");
  auto* hidden = vtkUnsignedCharArray::SafeDownCast(strokes->GetCellData()->GetArray("Hidden"));
  auto* types = vtkUnsignedCharArray::SafeDownCast(strokes->GetCellData()->GetArray("FeatureType"));
  std::array<double, 2> length = { 0.0, 0.0 };
  nprForEachCell(strokes->GetLines(),
    [&](vtkIdType cell, vtkIdType size, const vtkIdType* ids)
    {
      const bool counted =
        !hidden->GetValue(cell) && types->GetValue(cell) != vtkNPRFeatureLines::INTERSECTION;
      for (vtkIdType i = 0; counted && i + 1 < size; ++i)
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
    });
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
NPR_TEST_CASE("drawing-mutual", DrawingMutual);

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
NPR_TEST_CASE("drawing-cylinder", DrawingCylinder);

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
      const bool hit = nprNearPixel(mask, x, y);
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
NPR_TEST_CASE("drawing-bunny", DrawingBunny);

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
  scene.Renderer->AddActor(nprNaNTriangleActor());
  scene.Renderer->ResetCamera(0, 1, 0, 1, -0.5, 0.5);
  std::cout << "expected: one VTK warning about a face with NaN coordinates\n";
  const std::vector<Stroke> strokes = scene.Strokes();
  NPR_CHECK(!strokes.empty(), "the good triangle's boundary is missing");
  return nprTestResult();
}
NPR_TEST_CASE("drawing-errors", DrawingErrors);

// ---- The scene's own line cells (LinePrimitives) ----
// Two polylines 4 units long across the view, 2 px wide: red behind the cube (z = -1), blue in
// front of it (z = 1).
void AddLinesAcross(vtkRenderer* renderer)
{
  for (const double z : { -1.0, 1.0 })
  {
    vtkNew<vtkPoints> points;
    points->InsertNextPoint(-2.0, 0.0, z);
    points->InsertNextPoint(0.0, 0.0, z);
    points->InsertNextPoint(2.0, 0.0, z);
    vtkNew<vtkCellArray> cells;
    const vtkIdType polyline[3] = { 0, 1, 2 };
    cells->InsertNextCell(3, polyline);
    vtkNew<vtkPolyData> line;
    line->SetPoints(points);
    line->SetLines(cells);
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputData(line);
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    actor->GetProperty()->SetColor(z < 0.0 ? 1.0 : 0.0, 0.0, z < 0.0 ? 0.0 : 1.0);
    actor->GetProperty()->SetLineWidth(2.0);
    renderer->AddActor(actor);
  }
}

// A unit cube at the origin, a red 2 px line behind it along x (z = -1, from x -2 to 2) and a
// blue one before it (z = 1), under a parallel camera on +z: the line behind is hidden where the
// cube covers it, x in [-0.5, 0.5], the one before is whole; each stroke in its actor's colour
// and width; none without LinePrimitives.
int DrawingLinePrimitives()
{
  DrawingScene scene(400, 300);
  vtkNew<vtkPolyDataMapper> cubeMapper;
  cubeMapper->SetInputData(CubeSource());
  vtkNew<vtkActor> cube;
  cube->SetMapper(cubeMapper);
  scene.Renderer->AddActor(cube);
  AddLinesAcross(scene.Renderer);
  nprParallelFromFront(scene.Camera(), 1.5, 5.0, 15.0);
  scene.Lines->HiddenLinesOn();
  const auto countLines = [](const std::vector<Stroke>& strokes)
  {
    return std::count_if(strokes.begin(), strokes.end(),
      [](const Stroke& stroke) { return stroke.Type == vtkNPRFeatureLines::LINE; });
  };
  NPR_CHECK(countLines(scene.Strokes()) == 0, "line strokes without LinePrimitives");
  scene.Lines->LinePrimitivesOn();
  const std::vector<Stroke> strokes = scene.Strokes();
  vtkPolyData* output = scene.Lines->GetStrokes();
  vtkDataArray* colors = output->GetCellData()->GetArray("Colors");
  vtkDataArray* widths = output->GetCellData()->GetArray("LineWidths");
  NPR_CHECK(colors && widths, "no Colors or LineWidths");
  // x of the image: 100 px a unit about pixel 200. Red strokes: visible from the ends to the
  // cube's sides, hidden between; blue: one visible stroke end to end.
  int red = 0, blue = 0, hiddenRed = 0;
  double worst = 0.0;
  vtkIdType cell = 0;
  for (const Stroke& stroke : strokes)
  {
    const vtkIdType at = cell++;
    if (stroke.Type != vtkNPRFeatureLines::LINE || !colors || !widths)
    {
      continue;
    }
    const bool isRed = colors->GetComponent(at, 0) == 255 && colors->GetComponent(at, 2) == 0;
    NPR_CHECK(widths->GetComponent(at, 0) == 2.0, "a line stroke's width is not its actor's");
    double low = 1e300, high = -1e300;
    for (const Image2& p : stroke.Points)
    {
      low = std::min(low, p[0]);
      high = std::max(high, p[0]);
    }
    if (!isRed)
    {
      ++blue;
      worst = std::max({ worst, std::abs(low - 0.0), std::abs(high - 400.0) });
      NPR_CHECK(!stroke.Hidden, "the line before the cube is hidden");
      continue;
    }
    ++red;
    hiddenRed += stroke.Hidden ? 1 : 0;
    const double inner = stroke.Hidden
      ? std::min(std::abs(low - 150.0), std::abs(high - 250.0))
      : (low < 150.0 ? std::abs(high - 150.0) : std::abs(low - 250.0));
    worst = std::max(worst, inner);
  }
  std::cout << countLines(strokes) << " line strokes: " << red << " red (" << hiddenRed
            << " hidden), " << blue << " blue; farthest end " << worst << " px from the truth\n";
  NPR_CHECK(red == 3 && hiddenRed == 1 && blue == 1,
    red << " red strokes (" << hiddenRed << " hidden), " << blue << " blue: expected 3 (1), 1");
  NPR_CHECK(worst < 0.01, "a stroke ends " << worst << " px from where the cube's side is");
  return nprTestResult();
}
NPR_TEST_CASE("drawing-line-primitives", DrawingLinePrimitives);

// A mesh drawn by a vtkDataSetMapper (as PyVista draws its meshes) has the strokes and faces of
// the same mesh drawn by a vtkPolyDataMapper.
int DrawingDataSetMapper()
{
  std::vector<size_t> strokes, faces;
  for (int dataSet = 0; dataSet < 2; ++dataSet)
  {
    DrawingScene scene(300, 200);
    vtkSmartPointer<vtkMapper> mapper;
    if (dataSet)
    {
      mapper = vtkSmartPointer<vtkDataSetMapper>::New();
    }
    else
    {
      mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
    }
    mapper->SetInputDataObject(CubeSource());
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    scene.Renderer->AddActor(actor);
    const double eye[3] = { 2.0, 1.5, 3.0 };
    nprViewFromCorner(scene.Camera(), eye, false);
    strokes.push_back(scene.Strokes().size());
    NPR_CHECK(scene.Lines->UpdateFaces(), "UpdateFaces failed");
    faces.push_back(static_cast<size_t>(scene.Lines->GetFaces()->GetNumberOfCells()));
  }
  std::cout << "vtkPolyDataMapper: " << strokes[0] << " strokes, " << faces[0]
            << " faces; vtkDataSetMapper: " << strokes[1] << ", " << faces[1] << "\n";
  NPR_CHECK(strokes[0] > 0 && faces[0] > 0 && strokes[1] == strokes[0] && faces[1] == faces[0],
    "the vtkDataSetMapper's cube has other strokes or faces");
  return nprTestResult();
}
NPR_TEST_CASE("drawing-dataset-mapper", DrawingDataSetMapper);
}
