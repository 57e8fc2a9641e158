// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// The edge table of vtkNPRFeatureLines against a plain one built from the documented rules
// (TestFeatureLinesTablePlain.cxx: a map from each edge's two points to the faces that use it, all
// in double): the same lines, types, input ids and order, edge for edge, on meshes with creases
// (some exactly at the crease angle), boundaries, a non-manifold fin, faces wound the other way,
// points split along creases, faces in a random order, quads and a pentagon, strips, degenerate
// faces and a NaN point; with the cells in 64- and 32-bit storage and float and double points.
// The memory the tables hold is TestFeatureLinesTableMemory.cxx's case.
//
// usage: TestFeatureLinesTable CASE [DATA_DIR]   (CASE: table-reference, table-memory)
#include "TestFeatureLinesTable.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkCylinderSource.h"
#include "vtkIdTypeArray.h"
#include "vtkMath.h"
#include "vtkNPRModelReader.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataNormals.h"
#include "vtkSphereSource.h"
#include "vtkStripper.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <string>
#include <vector>

namespace
{
using namespace nprFeatureLineTesting;
using nprFeatureLinesTable::Line;
using nprFeatureLinesTable::PlainTable;
using nprFeatureLinesTable::Viewpoint;

// ---- The meshes ----
// Creases, a non-manifold fin, a face wound the other way, a quad and a pentagon, a point
// coincident with another, strips (with a repeated point and a two-point strip), zero-area and
// two-point faces, an out-of-range id and a NaN point.
vtkSmartPointer<vtkPolyData> MixedMesh()
{
  const double p[][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 }, { 0.5, 0.5, 1 },
    { 0.5, 0.5, -1 }, { 0.5, 1.5, 0.3 }, { 1, 0, 0 }, { 2, 0, 0 }, { 2, 1, 0.2 }, { 1.5, 1.8, 0.1 },
    { std::nan(""), 0, 0 }, { 3, 0, 0 }, { 3, 1, 0 }, { 4, 0, 0.5 }, { 4, 1, 0 },
    { 0.25, 0.25, 0 } };
  vtkNew<vtkPoints> points;
  for (const auto& x : p)
  {
    points->InsertNextPoint(x);
  }
  vtkNew<vtkCellArray> polys;
  const std::vector<std::vector<vtkIdType>> faces = { { 0, 1, 4 }, { 1, 2, 4 }, { 2, 3, 4 },
    { 3, 0, 4 }, { 0, 5, 1 }, { 1, 5, 2 }, { 2, 5, 3 }, { 0, 3, 5 }, { 3, 2, 6 }, { 2, 3, 6 },
    { 0, 1, 16 }, { 0, 0, 1 }, { 0, 16, 16 }, { 11, 1, 2 }, { 1, 2, 99 }, { 7, 8, 9, 2 },
    { 8, 12, 13, 10, 9 }, { 0, 1 } };
  for (const auto& face : faces)
  {
    polys->InsertNextCell(static_cast<vtkIdType>(face.size()), face.data());
  }
  vtkNew<vtkCellArray> strips;
  const std::vector<std::vector<vtkIdType>> stripCells = { { 12, 14, 13, 15, 15, 14, 12 },
    { 12, 14 }, { 8, 12, 9, 13 } };
  for (const auto& strip : stripCells)
  {
    strips->InsertNextCell(static_cast<vtkIdType>(strip.size()), strip.data());
  }
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->SetPoints(points);
  mesh->SetPolys(polys);
  mesh->SetStrips(strips);
  return mesh;
}

std::vector<std::pair<std::string, vtkSmartPointer<vtkPolyData>>> Meshes()
{
  std::vector<std::pair<std::string, vtkSmartPointer<vtkPolyData>>> meshes;
  meshes.emplace_back("mixed", MixedMesh());
  // The bunny with its points split along creases (its normals' feature edges).
  vtkNew<vtkNPRModelReader> reader;
  reader->SetFileName((nprTestDataDir() + "/bunny.ply").c_str());
  vtkNew<vtkPolyDataNormals> split;
  split->SetInputConnection(reader->GetOutputPort());
  split->SetFeatureAngle(20.0);
  split->Update();
  meshes.emplace_back("bunny, split", split->GetOutput());
  // The bunny with its faces in a random order (the table numbers them in space instead).
  vtkPolyData* bunny = split->GetOutput();
  std::vector<vtkIdType> order(bunny->GetNumberOfPolys());
  std::iota(order.begin(), order.end(), 0);
  std::shuffle(order.begin(), order.end(), std::mt19937(5));
  vtkNew<vtkCellArray> shuffled;
  for (vtkIdType cell : order)
  {
    vtkIdType size;
    const vtkIdType* ids;
    bunny->GetPolys()->GetCellAtId(cell, size, ids);
    shuffled->InsertNextCell(size, ids);
  }
  auto shuffledBunny = vtkSmartPointer<vtkPolyData>::New();
  shuffledBunny->SetPoints(bunny->GetPoints());
  shuffledBunny->SetPolys(shuffled);
  meshes.emplace_back("bunny, shuffled", shuffledBunny);
  // A 12-sided cylinder: its sides meet at exactly 30 degrees, the default crease angle; one of
  // 300 sides, whose caps are polygons of 300 points.
  for (int sides : { 12, 300 })
  {
    vtkNew<vtkCylinderSource> cylinder;
    cylinder->SetResolution(sides);
    cylinder->Update();
    meshes.emplace_back("cylinder of " + std::to_string(sides), cylinder->GetOutput());
  }
  auto sphere = nprSphereSource(0.5, 24, 13);
  vtkNew<vtkStripper> strips;
  strips->SetInputConnection(sphere->GetOutputPort());
  strips->Update();
  meshes.emplace_back("sphere strips", strips->GetOutput());
  return meshes;
}

// The same mesh with its cells in 32-bit storage and its points in double.
vtkSmartPointer<vtkPolyData> OtherStorage(vtkPolyData* mesh)
{
  auto copy = vtkSmartPointer<vtkPolyData>::New();
  copy->DeepCopy(mesh);
  copy->GetPolys()->ConvertTo32BitStorage();
  copy->GetStrips()->ConvertTo32BitStorage();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->DeepCopy(mesh->GetPoints());
  copy->SetPoints(points);
  return copy;
}

// Views from all sides; some with the crease angle at an edge's exact angle, or the double just
// below it, which only the exact angle decides.
std::vector<Viewpoint> Viewpoints(vtkPolyData* mesh, const std::vector<double>& angles)
{
  double bounds[6];
  mesh->GetPoints()->GetBounds(bounds);
  const double centre[3] = { 0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]),
    0.5 * (bounds[4] + bounds[5]) };
  std::mt19937 random(11);
  std::normal_distribution<double> gaussian;
  std::vector<Viewpoint> views;
  for (int v = 0; v < 16; ++v)
  {
    const bool smooth = v % 7 == 3 && mesh->GetPointData()->GetNormals();
    Viewpoint view{ v % 3 == 1, {}, v % 4 == 2 ? 10.0 : (v % 4 == 3 ? 89.99 : 30.0), v % 5 != 4,
      smooth };
    double d[3] = { gaussian(random), gaussian(random), gaussian(random) };
    vtkMath::Normalize(d);
    for (int k = 0; k < 3; ++k)
    {
      view.View[k] = view.Parallel ? d[k] : centre[k] + 4.0 * d[k];
    }
    if (v % 6 == 5) // the eye at a mesh point: its faces seen edge-on
    {
      mesh->GetPoint(v % mesh->GetNumberOfPoints(), view.View);
      view.Parallel = false;
    }
    if (v % 4 == 1 && !angles.empty())
    {
      const double angle = angles[random() % angles.size()];
      view.Angle = v % 8 == 1 ? angle : std::nextafter(angle, 0.0);
    }
    views.push_back(view);
  }
  return views;
}

// ---- The filter's table against the plain one ----
// The output's mesh edges: its cells before the smooth contours.
vtkIdType MeshEdges(vtkPolyData* output)
{
  auto* types = vtkUnsignedCharArray::SafeDownCast(output->GetCellData()->GetArray("FeatureType"));
  vtkIdType count = 0;
  while (types && count < types->GetNumberOfValues() &&
    !(types->GetValue(count) & vtkNPRFeatureLines::SMOOTH_CONTOUR))
  {
    ++count;
  }
  return count;
}

// Whether the output's first lines are the expected ones: input ids, type and coordinates.
bool SameLines(vtkPolyData* output, vtkPolyData* mesh, const std::vector<Line>& expected)
{
  auto* ids = vtkIdTypeArray::SafeDownCast(output->GetCellData()->GetArray("InputPointIds"));
  auto* types = vtkUnsignedCharArray::SafeDownCast(output->GetCellData()->GetArray("FeatureType"));
  auto cells = vtk::TakeSmartPointer(output->GetLines()->NewIterator());
  cells->GoToFirstCell();
  bool same = ids && types;
  for (size_t i = 0; same && i < expected.size(); ++i, cells->GoToNextCell())
  {
    vtkIdType size;
    const vtkIdType* ends;
    cells->GetCurrentCell(size, ends);
    Point got, wanted;
    output->GetPoint(ends[0], got.data());
    mesh->GetPoint(expected[i].A, wanted.data());
    same = ids->GetValue(2 * i) == expected[i].A && ids->GetValue(2 * i + 1) == expected[i].B &&
      types->GetValue(i) == expected[i].Type && got == wanted;
  }
  return same;
}

int TableReference()
{
  vtkObject::GlobalWarningDisplayOff(); // the NaN point's warning
  long long compared = 0;
  for (const auto& named : Meshes())
  {
    for (const bool other : { false, true })
    {
      vtkSmartPointer<vtkPolyData> mesh = other ? OtherStorage(named.second) : named.second;
      const std::string name = named.first + (other ? " (32-bit cells, double points)" : "");
      auto filter = MakeFilter(AllTypes);
      filter->SetInputData(mesh);
      const PlainTable merged(mesh, true), separate(mesh, false);
      for (const Viewpoint& view : Viewpoints(mesh, merged.Angles()))
      {
        filter->SetParallelProjection(view.Parallel);
        if (view.Parallel)
        {
          filter->SetDirectionOfProjection(view.View);
        }
        else
        {
          filter->SetEyePosition(view.View);
        }
        filter->SetFeatureAngle(view.Angle);
        filter->SetMergeCoincidentPoints(view.Merge);
        filter->SetSmoothContours(view.Smooth);
        filter->Update();
        const std::vector<Line> expected = (view.Merge ? merged : separate).Lines(view);
        const vtkIdType got = MeshEdges(filter->GetOutput());
        NPR_CHECK(got == static_cast<vtkIdType>(expected.size()) &&
            SameLines(filter->GetOutput(), mesh, expected),
          name << ": " << got << " mesh edges, the plain table has " << expected.size()
               << " (or they differ)");
        compared += static_cast<long long>(expected.size());
      }
    }
  }
  vtkObject::GlobalWarningDisplayOn();
  std::cout << compared << " lines identical to the plain table, in order\n";
  NPR_CHECK(compared > 10000, "too few lines compared: " << compared);
  return nprTestResult();
}
NPR_TEST_CASE("table-reference", TableReference);
}
