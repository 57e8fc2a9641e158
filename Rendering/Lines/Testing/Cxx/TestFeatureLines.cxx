// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// Object-space feature lines (vtkNPRFeatureLines) checked against what can be stated
// analytically: a box's creases; its silhouettes from chosen viewpoints, also through an actor
// matrix; the boundaries of an open box and a non-manifold fin. The program's other cases:
// TestFeatureLinesSides.cxx (adjacency reuse, exact sides), TestFeatureLinesSmooth.cxx and
// TestFeatureLinesSmoothMeshes.cxx (smooth contours), TestFeatureLinesSettings.cxx (the line
// settings the filter, the reference mask and the drawing lines share).
//
// usage: TestFeatureLines CASE [DATA_DIR]   (CASE: the NPR_TEST_CASE names below)
#include "nprFeatureLineTesting.h"

#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCubeSource.h"
#include "vtkDoubleArray.h"
#include "vtkIdTypeArray.h"
#include "vtkMath.h"
#include "vtkNPRModelReader.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSphereSource.h"
#include "vtkTransform.h"
#include "vtkTransformPolyDataFilter.h"
#include "vtkTriangleFilter.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <random>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace
{
using namespace nprFeatureLineTesting;

// ---- Creases of a box: exactly its 12 edges, with and without triangulation ----
int CubeCreases()
{
  const std::set<Edge> twelve = AllBoxEdges();
  for (bool triangulate : { false, true })
  {
    vtkSmartPointer<vtkPolyData> cube = CubeSource();
    if (triangulate)
    {
      cube = Triangulated(cube);
    }
    const std::string name = triangulate ? "triangulated cube" : "cube";
    auto filter = MakeFilter(vtkNPRFeatureLines::CREASE);
    filter->SetInputData(cube);
    filter->Update();
    const auto lines = Lines(filter);
    CheckEdges(EdgesOf(lines, AllTypes), twelve, name + " creases");
    for (const auto& line : lines)
    {
      NPR_CHECK(line.second == vtkNPRFeatureLines::CREASE, name << ": type " << line.second);
    }
    vtkPolyData* output = filter->GetOutput();
    NPR_CHECK(output->GetPoints()->GetDataType() == VTK_DOUBLE, "output points are not double");
    NPR_CHECK(output->GetNumberOfPoints() == 8,
      name << ": " << output->GetNumberOfPoints() << " output points, only the 8 used expected");
    auto* ids = vtkIdTypeArray::SafeDownCast(output->GetCellData()->GetArray("InputPointIds"));
    NPR_CHECK(ids && ids->GetNumberOfComponents() == 2 && ids->GetNumberOfTuples() == 12,
      "InputPointIds missing");
    for (vtkIdType i = 0; ids && i < 12; ++i)
    {
      double in[3], out[3];
      cube->GetPoint(ids->GetTypedComponent(i, 0), in);
      vtkIdType size;
      const vtkIdType* pts;
      output->GetLines()->GetCellAtId(i, size, pts);
      output->GetPoint(pts[0], out);
      NPR_CHECK(in[0] == out[0] && in[1] == out[1] && in[2] == out[2],
        "InputPointIds does not name the line's first point");
    }
    // A right angle is a crease below 90 degrees only; flat diagonals never are.
    filter->SetFeatureAngle(89.9);
    filter->Update();
    NPR_CHECK(filter->GetOutput()->GetNumberOfCells() == 12, name << ": creases at 89.9 degrees");
    filter->SetFeatureAngle(90.1);
    filter->Update();
    NPR_CHECK(filter->GetOutput()->GetNumberOfCells() == 0, name << ": creases at 90.1 degrees");
    filter->SetFeatureAngle(0.0);
    filter->Update();
    NPR_CHECK(filter->GetOutput()->GetNumberOfCells() == 12, name << ": diagonals are flat");

    // Without merging, vtkCubeSource's faces share no point: 24 boundary edges, no crease.
    auto separate = MakeFilter(AllTypes);
    separate->MergeCoincidentPointsOff();
    separate->SetInputData(cube);
    separate->Update();
    const long long boundaries = CountCells(separate, vtkNPRFeatureLines::BOUNDARY);
    NPR_CHECK(separate->GetOutput()->GetNumberOfCells() == 24 && boundaries == 24,
      name << " unmerged: " << separate->GetOutput()->GetNumberOfCells() << " lines, " << boundaries
           << " boundaries; 24 expected (each face's own)");
  }
  return nprTestResult();
}
NPR_TEST_CASE("cube-creases", CubeCreases);

// ---- Silhouettes of a box from viewpoints where they can be stated ----
struct View
{
  const char* Name;
  bool Parallel;
  double Vector[3]; // eye, or direction of projection
  size_t Count;     // silhouette edges expected
};
const View Views[] = {
  { "corner, perspective", false, { 2.2, 1.7, 2.9 }, 6 },
  { "corner, parallel", true, { -1.0, -0.8, -1.3 }, 6 },
  { "along -z, parallel", true, { 0.0, 0.0, -1.0 }, 4 },
  { "along -z, perspective", false, { 0.0, 0.0, 5.0 }, 4 },
  { "off axis, perspective", false, { 0.2, -0.3, 5.0 }, 4 },
  { "two faces, perspective", false, { 0.7, 0.0, 5.0 }, 6 },
  { "inside", false, { 0.1, 0.2, 0.3 }, 0 },
};

void SetView(vtkNPRFeatureLines* filter, const View& view)
{
  filter->SetParallelProjection(view.Parallel);
  const double* v = view.Vector;
  if (view.Parallel)
  {
    filter->SetDirectionOfProjection(v[0], v[1], v[2]);
  }
  else
  {
    filter->SetEyePosition(v[0], v[1], v[2]);
  }
}

// Every view's silhouettes of the cube, as quads and as triangles, are the analytic outline.
void CheckViews()
{
  for (bool triangulate : { false, true })
  {
    vtkSmartPointer<vtkPolyData> cube = CubeSource();
    if (triangulate)
    {
      cube = Triangulated(cube);
    }
    auto filter = MakeFilter(vtkNPRFeatureLines::SILHOUETTE);
    filter->SetInputData(cube);
    for (const View& view : Views)
    {
      SetView(filter, view);
      filter->Update();
      const std::set<Edge> expected = BoxSilhouettes(view.Parallel, view.Vector);
      NPR_CHECK(expected.size() == view.Count,
        view.Name << ": the analytic outline has " << expected.size() << " edges");
      const auto lines = Lines(filter);
      CheckEdges(EdgesOf(lines, AllTypes), expected,
        std::string(view.Name) + (triangulate ? " (triangles)" : ""));
    }
  }
}

// Both types: the union, with both bits on the outline.
void CheckUnion()
{
  auto both = MakeFilter(vtkNPRFeatureLines::SILHOUETTE | vtkNPRFeatureLines::CREASE);
  both->SetInputData(CubeSource());
  SetView(both, Views[0]);
  both->Update();
  const auto lines = Lines(both);
  CheckEdges(EdgesOf(lines, AllTypes), AllBoxEdges(), "silhouettes and creases");
  CheckEdges(EdgesOf(lines, vtkNPRFeatureLines::SILHOUETTE), BoxSilhouettes(false, Views[0].Vector),
    "silhouette bits of the union");
  CheckEdges(EdgesOf(lines, vtkNPRFeatureLines::CREASE), AllBoxEdges(), "crease bits of the union");
}

// SetCamera with an actor matrix (rotation, non-uniform scale, translation): the silhouettes
// are those of the transformed mesh seen from the camera directly.
void CheckCameraMatrix()
{
  vtkNew<vtkTransform> transform;
  transform->Translate(3.0, -1.0, 2.0);
  transform->RotateWXYZ(35.0, 1.0, 2.0, 0.5);
  transform->Scale(2.0, 0.5, 1.3);
  vtkNew<vtkTransformPolyDataFilter> moved;
  moved->SetInputData(Triangulated(CubeSource()));
  moved->SetTransform(transform);
  moved->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  moved->Update();
  for (bool parallel : { false, true })
  {
    vtkNew<vtkCamera> camera;
    camera->SetPosition(7.0, 4.0, 9.0);
    camera->SetFocalPoint(3.0, -1.0, 2.0);
    camera->SetParallelProjection(parallel);
    auto model = MakeFilter(vtkNPRFeatureLines::SILHOUETTE);
    model->SetInputData(Triangulated(CubeSource()));
    model->SetCamera(camera, transform->GetMatrix());
    model->Update();
    auto world = MakeFilter(vtkNPRFeatureLines::SILHOUETTE);
    world->SetInputData(moved->GetOutput());
    world->SetCamera(camera);
    world->Update();
    auto ids = [](vtkNPRFeatureLines* filter)
    {
      std::set<std::pair<vtkIdType, vtkIdType>> pairs;
      auto* array =
        vtkIdTypeArray::SafeDownCast(filter->GetOutput()->GetCellData()->GetArray("InputPointIds"));
      for (vtkIdType i = 0; array && i < array->GetNumberOfTuples(); ++i)
      {
        pairs.insert({ array->GetTypedComponent(i, 0), array->GetTypedComponent(i, 1) });
      }
      return pairs;
    };
    const auto inModel = ids(model), inWorld = ids(world);
    std::cout << (parallel ? "parallel" : "perspective")
              << " camera through a matrix: " << inModel.size()
              << " silhouette edges in model coordinates, " << inWorld.size()
              << " in world coordinates\n";
    NPR_CHECK(inModel.size() == 6 && inModel == inWorld,
      "SetCamera with a matrix finds other silhouettes than the transformed mesh");
  }
}

int CubeSilhouettes()
{
  CheckViews();
  CheckUnion();
  CheckCameraMatrix();
  return nprTestResult();
}
NPR_TEST_CASE("cube-silhouettes", CubeSilhouettes);

// ---- Boundaries of an open box; a non-manifold fin ----
int BoundaryAndNonManifold()
{
  const int top = 2 * 2 + 1; // face +z
  auto filter = MakeFilter(vtkNPRFeatureLines::BOUNDARY);
  filter->SetInputData(MakeBox(top));
  filter->Update();
  std::set<Edge> rim;
  for (const BoxEdge& edge : BoxEdges())
  {
    if (edge.Ends.first[2] > 0 && edge.Ends.second[2] > 0)
    {
      rim.insert(edge.Ends);
    }
  }
  CheckEdges(EdgesOf(Lines(filter), AllTypes), rim, "open box boundary");

  auto all = MakeFilter(AllTypes);
  all->SetInputData(MakeBox(top));
  all->SetEyePosition(2.2, 1.7, 2.9);
  all->Update();
  const auto lines = Lines(all);
  CheckEdges(EdgesOf(lines, vtkNPRFeatureLines::BOUNDARY), rim, "open box boundary, all types");
  NPR_CHECK(EdgesOf(lines, vtkNPRFeatureLines::CREASE).size() == 8,
    "open box: the 8 edges between its walls are creases");

  // Three triangles on one edge: one non-manifold edge, six boundary edges.
  vtkNew<vtkPolyData> fin;
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0, 0, 0);
  points->InsertNextPoint(1, 0, 0);
  points->InsertNextPoint(0.5, 1, 0);
  points->InsertNextPoint(0.5, -1, 0.3);
  points->InsertNextPoint(0.5, 0, 1);
  vtkNew<vtkCellArray> triangles;
  const vtkIdType t0[3] = { 0, 1, 2 }, t1[3] = { 1, 0, 3 }, t2[3] = { 0, 1, 4 };
  triangles->InsertNextCell(3, t0);
  triangles->InsertNextCell(3, t1);
  triangles->InsertNextCell(3, t2);
  fin->SetPoints(points);
  fin->SetPolys(triangles);
  auto nonManifold = MakeFilter(vtkNPRFeatureLines::NON_MANIFOLD);
  nonManifold->SetInputData(fin);
  nonManifold->Update();
  const Edge spine = MakeEdge({ 0, 0, 0 }, { 1, 0, 0 });
  CheckEdges(EdgesOf(Lines(nonManifold), AllTypes), { spine }, "non-manifold fin");
  auto finAll = MakeFilter(AllTypes);
  finAll->SetInputData(fin);
  finAll->SetEyePosition(0.3, 3, 2);
  finAll->Update();
  const auto finLines = Lines(finAll);
  NPR_CHECK(finLines.size() == 7 && finLines.count(spine) &&
      finLines.at(spine) == vtkNPRFeatureLines::NON_MANIFOLD &&
      EdgesOf(finLines, vtkNPRFeatureLines::BOUNDARY).size() == 6,
    "fin: the spine only non-manifold, six boundary edges (" << finLines.size() << " lines)");
  return nprTestResult();
}
NPR_TEST_CASE("boundary-non-manifold", BoundaryAndNonManifold);
}
