// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// Object-space feature lines (vtkNPRFeatureLines) on degenerate input: zero-area and 1- and
// 2-point faces, points split along the sharp edges, faces wound the other way, NaN and infinite
// coordinates, empty input and points without faces.
//
// usage: TestFeatureLinesDegenerate CASE [DATA_DIR]   (CASE: see the table at the end of this
// file)
#include "nprFeatureLineTesting.h"

#include "vtkCellArray.h"
#include "vtkCleanPolyData.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataNormals.h"

#include <functional>
#include <limits>
#include <map>
#include <set>
#include <string>

namespace
{
using namespace nprFeatureLineTesting;

// ---- Degenerate input ----
// The eye and the parallel view's direction of projection the boxes are seen from.
const double eye[3] = { 2.2, 1.7, 2.9 };
const double direction[3] = { -1.0, -0.8, -1.3 };

// Zero-area triangles: repeated points, one point three times, collinear points; a two-point
// and a one-point polygon.
void ZeroAreaFaces()
{
  const std::set<Edge> twelve = AllBoxEdges();
  vtkSmartPointer<vtkPolyData> box = Triangulated(MakeBox());
  vtkNew<vtkPolyData> mesh;
  mesh->DeepCopy(box);
  const vtkIdType middle = mesh->GetPoints()->InsertNextPoint(0.0, -0.5, -0.5); // on edge 0-1
  const vtkIdType degenerate[][3] = { { 0, 0, 1 }, { 0, 1, 0 }, { 2, 2, 2 }, { 0, middle, 1 } };
  for (const auto& triangle : degenerate)
  {
    mesh->GetPolys()->InsertNextCell(3, triangle);
  }
  const vtkIdType two[2] = { 3, 5 }, one[1] = { 6 };
  mesh->GetPolys()->InsertNextCell(2, two);
  mesh->GetPolys()->InsertNextCell(1, one);
  auto filter = MakeFilter(AllTypes);
  filter->SetInputData(mesh);
  filter->SetEyePosition(eye[0], eye[1], eye[2]);
  filter->Update();
  const auto lines = Lines(filter);
  CheckEdges(EdgesOf(lines, vtkNPRFeatureLines::CREASE), twelve, "creases with zero-area faces");
  CheckEdges(EdgesOf(lines, vtkNPRFeatureLines::SILHOUETTE), BoxSilhouettes(false, eye),
    "silhouettes with zero-area faces");
  NPR_CHECK(EdgesOf(lines, vtkNPRFeatureLines::BOUNDARY | vtkNPRFeatureLines::NON_MANIFOLD).empty(),
    "zero-area faces made boundary or non-manifold edges");
  NPR_CHECK(filter->GetNumberOfDegenerateFaces() == 6,
    "degenerate faces counted: " << filter->GetNumberOfDegenerateFaces());
}

// Points split by vtkPolyDataNormals along the sharp edges: still 12 creases, no boundary.
void SplitPoints()
{
  const std::set<Edge> twelve = AllBoxEdges();
  vtkNew<vtkCleanPolyData> clean; // vtkCubeSource's 24 points -> 8
  clean->SetInputData(CubeSource());
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputConnection(clean->GetOutputPort());
  normals->SetFeatureAngle(30.0);
  normals->SplittingOn();
  normals->Update();
  NPR_CHECK(
    clean->GetOutput()->GetNumberOfPoints() == 8 && normals->GetOutput()->GetNumberOfPoints() == 24,
    "the split cube has " << normals->GetOutput()->GetNumberOfPoints() << " points");
  auto filter = MakeFilter(AllTypes);
  filter->SetInputConnection(normals->GetOutputPort());
  filter->SetEyePosition(eye[0], eye[1], eye[2]);
  filter->Update();
  const auto lines = Lines(filter);
  CheckEdges(EdgesOf(lines, AllTypes), twelve, "split cube");
  CheckEdges(EdgesOf(lines, vtkNPRFeatureLines::CREASE), twelve, "split cube creases");
  NPR_CHECK(EdgesOf(lines, vtkNPRFeatureLines::BOUNDARY).empty(), "split cube boundaries");
  // Unmerged, each sharp edge is two boundary edges (one per side's copy of its points).
  filter->MergeCoincidentPointsOff();
  filter->Update();
  NPR_CHECK(CountCells(filter, vtkNPRFeatureLines::BOUNDARY) == 24 &&
      filter->GetOutput()->GetNumberOfCells() == 24,
    "without merging, the split edges should be boundaries");
}

// One face wound the other way: the same creases and silhouettes.
void FlippedFaces()
{
  const std::set<Edge> twelve = AllBoxEdges();
  for (bool parallel : { false, true })
  {
    for (int flip = 0; flip < 6; ++flip)
    {
      for (bool triangulate : { false, true })
      {
        vtkSmartPointer<vtkPolyData> mesh = MakeBox(-1, flip);
        if (triangulate)
        {
          mesh = Triangulated(mesh);
        }
        auto filter = MakeFilter(AllTypes);
        filter->SetInputData(mesh);
        filter->SetParallelProjection(parallel);
        filter->SetEyePosition(eye[0], eye[1], eye[2]);
        filter->SetDirectionOfProjection(direction[0], direction[1], direction[2]);
        filter->Update();
        const auto lines = Lines(filter);
        const std::string name = "face " + std::to_string(flip) + " flipped" +
          (triangulate ? ", triangles" : "") + (parallel ? ", parallel" : "");
        CheckEdges(EdgesOf(lines, vtkNPRFeatureLines::CREASE), twelve, name + ": creases");
        CheckEdges(EdgesOf(lines, vtkNPRFeatureLines::SILHOUETTE),
          BoxSilhouettes(parallel, parallel ? direction : eye), name + ": silhouettes");
        NPR_CHECK(lines.size() == 12, name << ": " << lines.size() << " lines");
      }
    }
  }
}

// NaN and infinite coordinates: their faces are skipped, with one warning per build.
void NonFiniteCoordinates()
{
  const std::set<Edge> twelve = AllBoxEdges();
  vtkNew<vtkPolyData> mesh;
  mesh->DeepCopy(Triangulated(MakeBox()));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const vtkIdType bad = mesh->GetPoints()->InsertNextPoint(nan, 0.0, 0.0);
  const vtkIdType far =
    mesh->GetPoints()->InsertNextPoint(0.0, std::numeric_limits<double>::infinity(), 0.0);
  const vtkIdType onEdge[3] = { 0, 1, bad }, other[3] = { far, 2, 3 };
  mesh->GetPolys()->InsertNextCell(3, onEdge);
  mesh->GetPolys()->InsertNextCell(3, other);
  auto* messages = nprCountingOutputWindow::SafeDownCast(vtkOutputWindow::GetInstance());
  const int warnings = messages ? messages->Warnings : 0;
  std::cout << "expected: one VTK warning about 2 faces with NaN or infinite coordinates\n";
  auto filter = MakeFilter(AllTypes);
  filter->SetInputData(mesh);
  filter->SetEyePosition(eye[0], eye[1], eye[2]);
  filter->Update();
  NPR_CHECK(messages && messages->Warnings == warnings + 1,
    "one warning expected, got " << (messages ? messages->Warnings - warnings : -1));
  NPR_CHECK(filter->GetNumberOfNonFiniteFaces() == 2,
    "non-finite faces counted: " << filter->GetNumberOfNonFiniteFaces());
  const auto lines = Lines(filter);
  CheckEdges(EdgesOf(lines, AllTypes), twelve, "cube with NaN faces");
  CheckEdges(EdgesOf(lines, vtkNPRFeatureLines::CREASE), twelve, "creases with NaN faces");
  filter->SetEyePosition(-2, 1, 3);
  filter->Update();
  NPR_CHECK(messages && messages->Warnings == warnings + 1, "warned again without a rebuild");
}

// Empty input, and points without faces: empty output, no error.
void EmptyInput()
{
  vtkNew<vtkPolyData> empty;
  auto filter = MakeFilter(AllTypes);
  filter->SetInputData(empty);
  filter->Update();
  NPR_CHECK(
    filter->GetOutput()->GetNumberOfCells() == 0 && filter->GetOutput()->GetNumberOfPoints() == 0,
    "empty input gave lines");
  vtkNew<vtkPolyData> cloud;
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0, 0, 0);
  points->InsertNextPoint(1, 0, 0);
  cloud->SetPoints(points);
  filter->SetInputData(cloud);
  filter->Update();
  NPR_CHECK(filter->GetOutput()->GetNumberOfCells() == 0, "points without faces gave lines");
}

int Degenerate()
{
  ZeroAreaFaces();
  SplitPoints();
  FlippedFaces();
  NonFiniteCoordinates();
  EmptyInput();
  return nprTestResult();
}
NPR_TEST_CASE("degenerate", Degenerate);
}
