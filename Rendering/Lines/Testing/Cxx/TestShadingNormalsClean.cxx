// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// vtkNPRShadingNormals, part of the TestShadingNormals program: the output is, value for value,
// what vtkCleanPolyData (tolerance 0) and vtkPolyDataNormals give; a point id past the end.
//
// usage: TestShadingNormals CASE   (CASE: the NPR_TEST_CASE names below)
#include "nprTesting.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkCleanPolyData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkIdList.h"
#include "vtkIntArray.h"
#include "vtkNPRModelReader.h"
#include "vtkNPRShadingNormals.h"
#include "vtkNew.h"
#include "vtkOutputWindow.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataNormals.h"
#include "vtkSOADataArrayTemplate.h"
#include "vtkSphereSource.h"
#include "vtkStripper.h"
#include "vtkTriangleFilter.h"
#include "vtkVersionMacros.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <string>

namespace
{
// What vtkNPRShadingNormals computed before it merged points itself.
vtkSmartPointer<vtkPolyData> CleanAndNormals(vtkPolyData* mesh)
{
  vtkNew<vtkCleanPolyData> merge;
  merge->SetInputData(mesh);
  merge->ToleranceIsAbsoluteOn();
  merge->SetAbsoluteTolerance(0.0);
  merge->ConvertPolysToLinesOff();
  merge->ConvertLinesToPointsOff();
  merge->ConvertStripsToPolysOff();
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputConnection(merge->GetOutputPort());
  normals->SetFeatureAngle(30.0);
  normals->SplittingOn();
  normals->ConsistencyOff();
  normals->Update();
  return normals->GetOutput();
}

// Values equal, or within tolerance of each other.
bool SameArray(vtkDataArray* a, vtkDataArray* b, double tolerance = 0.0)
{
  if (!a || !b)
  {
    return a == b;
  }
  if (a->GetNumberOfTuples() != b->GetNumberOfTuples() ||
    a->GetNumberOfComponents() != b->GetNumberOfComponents() ||
    a->GetDataType() != b->GetDataType())
  {
    return false;
  }
  for (vtkIdType i = 0; i < a->GetNumberOfValues(); ++i)
  {
    const double x =
      a->GetComponent(i / a->GetNumberOfComponents(), i % a->GetNumberOfComponents());
    const double y =
      b->GetComponent(i / b->GetNumberOfComponents(), i % b->GetNumberOfComponents());
    if (!(std::abs(x - y) <= tolerance) && !(std::isnan(x) && std::isnan(y)))
    {
      return false;
    }
  }
  return true;
}

// How far the normals may be from vtkPolyDataNormals': VTK 9.1 and 9.2 sum each point's face
// normals in face order, as vtkNPRShadingNormals does, so bit for bit; from 9.3 on its threads
// add them under locks in whatever order they run, and normalise by a product with the inverse,
// which moves the last bits (the point and cell numbering is the same).
#if VTK_VERSION_NUMBER < VTK_VERSION_CHECK(9, 3, 0)
const double NormalTolerance = 0.0;
#else
const double NormalTolerance = 1e-6;
#endif

// The arrays of a and b alike, but for the one named except; normals within NormalTolerance.
bool SameAttributes(vtkDataSetAttributes* a, vtkDataSetAttributes* b, const char* except = "")
{
  bool same = a->GetNumberOfArrays() == b->GetNumberOfArrays();
  for (int i = 0; same && i < a->GetNumberOfArrays(); ++i)
  {
    const std::string name = a->GetArrayName(i) ? a->GetArrayName(i) : "";
    same = name == except ||
      SameArray(a->GetArray(i), b->GetArray(name.c_str()),
        a->GetArray(i) == a->GetNormals() ? NormalTolerance : 0.0);
    if (!same)
    {
      std::cout << "array '" << name << "' differs\n";
    }
  }
  return same;
}

void CheckMatchesClean(const std::string& name, vtkPolyData* mesh)
{
  vtkSmartPointer<vtkPolyData> expected = CleanAndNormals(mesh);
  vtkNew<vtkNPRShadingNormals> filter;
  filter->SetInputData(mesh);
  filter->Update();
  vtkPolyData* output = filter->GetOutput();
  std::cout << name << ": " << mesh->GetNumberOfPoints() << " points -> "
            << output->GetNumberOfPoints()
            << " (vtkCleanPolyData + normals: " << expected->GetNumberOfPoints() << ")\n";
  NPR_CHECK(SameArray(output->GetPoints()->GetData(), expected->GetPoints()->GetData()),
    name << ": the same points in the same order");
  NPR_CHECK(nprSameCells(output->GetVerts(), expected->GetVerts()) &&
      nprSameCells(output->GetLines(), expected->GetLines()) &&
      nprSameCells(output->GetPolys(), expected->GetPolys()) &&
      nprSameCells(output->GetStrips(), expected->GetStrips()),
    name << ": the same cells");
  // Where coincident points carry different values, VTK releases differ in which one
  // vtkCleanPolyData keeps; the merge keeps the first use's (EveryMergeRule checks it).
  NPR_CHECK(SameAttributes(output->GetPointData(), expected->GetPointData(), "corner"),
    name << ": the same point data, normals included");
  NPR_CHECK(
    SameAttributes(output->GetCellData(), expected->GetCellData()), name << ": the same cell data");
}

// Every rule of the merge at once: a soup with a value per corner (the last use's is kept),
// cell data, vertices, lines (one reduced to a point), a triangle with two corners merged, a
// polygon closing on its first point, a strip, a point no cell uses, -0 beside 0, and a face
// whose points all coincide.
vtkSmartPointer<vtkPolyData> EveryMergeRule()
{
  vtkSmartPointer<vtkPolyData> soup = nprPolygonSoup(nprSphere(0.5, 24, 12));
  vtkPoints* points = soup->GetPoints();
  auto add = [&](double x, double y, double z) { return points->InsertNextPoint(x, y, z); };
  const vtkIdType a = add(0, 0, 2), b = add(0.0, -0.0, 2.0), c = add(1, 0, 2), d = add(1, 1, 2);
  const vtkIdType e = add(1, 0, 2), f = add(0, 1, 2), unused = add(5, 5, 5);
  (void)unused;
  vtkNew<vtkCellArray> verts, lines, strips;
  const vtkIdType vert[] = { a, b, a };
  verts->InsertNextCell(3, vert);
  const vtkIdType line[] = { a, b, c, e, d }, point[] = { a, b }, single[] = { c };
  lines->InsertNextCell(5, line);
  lines->InsertNextCell(2, point);
  lines->InsertNextCell(1, single);
  const vtkIdType twice[] = { a, c, e }, closing[] = { a, c, d, f, b }, collapsed[] = { c, e, c };
  soup->GetPolys()->InsertNextCell(3, twice);
  soup->GetPolys()->InsertNextCell(5, closing);
  soup->GetPolys()->InsertNextCell(3, collapsed);
  const vtkIdType strip[] = { a, c, f, d, f };
  strips->InsertNextCell(5, strip);
  soup->SetVerts(verts);
  soup->SetLines(lines);
  soup->SetStrips(strips);
  vtkNew<vtkFloatArray> corner;
  corner->SetName("corner");
  vtkNew<vtkIntArray> face;
  face->SetName("face");
  for (vtkIdType i = 0; i < soup->GetNumberOfPoints(); ++i)
  {
    corner->InsertNextValue(static_cast<float>(i));
  }
  for (vtkIdType i = 0; i < soup->GetNumberOfCells(); ++i)
  {
    face->InsertNextValue(static_cast<int>(7 * i));
  }
  soup->GetPointData()->AddArray(corner);
  soup->GetCellData()->AddArray(face);
  return soup;
}

// Each merged point keeps the point data of its first use: in EveryMergeRule's mesh, the
// lowest-numbered of the points it merged, whose number the "corner" array holds.
void CheckFirstUseData(vtkPolyData* mesh)
{
  vtkNew<vtkNPRShadingNormals> filter;
  filter->SetInputData(mesh);
  filter->Update();
  vtkPolyData* output = filter->GetOutput();
  vtkDataArray* corner = output->GetPointData()->GetArray("corner");
  vtkIdType wrong = corner ? 0 : 1;
  for (vtkIdType i = 0; corner && i < output->GetNumberOfPoints(); ++i)
  {
    double p[3], q[3];
    output->GetPoint(i, p);
    vtkIdType lowest = 0;
    for (; lowest < mesh->GetNumberOfPoints(); ++lowest)
    {
      mesh->GetPoint(lowest, q);
      if (p[0] == q[0] && p[1] == q[1] && p[2] == q[2])
      {
        break;
      }
    }
    wrong += corner->GetComponent(i, 0) != static_cast<double>(lowest);
  }
  NPR_CHECK(wrong == 0, wrong << " merged points without their first use's point data");
}

// A fan of 600 triangles around one point, each creased against the next (rim points alternately
// above and below): 600 regions at the apex, more than vtkNPRSplitNormals keeps, so
// vtkPolyDataNormals computes them.
vtkSmartPointer<vtkPolyData> CreasedFan()
{
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0, 0, 0);
  const int rim = 600;
  for (int i = 0; i < rim; ++i)
  {
    const double angle = 2.0 * 3.14159265358979 * i / rim;
    points->InsertNextPoint(std::cos(angle), std::sin(angle), i % 2 ? 0.5 : -0.5);
  }
  vtkNew<vtkCellArray> triangles;
  for (vtkIdType i = 0; i < rim; ++i)
  {
    const vtkIdType ids[] = { 0, 1 + i, 1 + (i + 1) % rim };
    triangles->InsertNextCell(3, ids);
  }
  auto fan = vtkSmartPointer<vtkPolyData>::New();
  fan->SetPoints(points);
  fan->SetPolys(triangles);
  return fan;
}

// The mesh with its coordinates in another array: double, or float in a struct-of-arrays layout,
// which the merge and the normals read through vtkDataArray rather than directly.
vtkSmartPointer<vtkPolyData> WithCoordinates(vtkPolyData* mesh, vtkDataArray* array)
{
  array->SetNumberOfComponents(3);
  array->SetNumberOfTuples(mesh->GetNumberOfPoints());
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    array->SetTuple(i, mesh->GetPoint(i));
  }
  vtkNew<vtkPoints> points;
  points->SetData(array);
  auto copy = vtkSmartPointer<vtkPolyData>::New();
  copy->ShallowCopy(mesh);
  copy->SetPoints(points);
  return copy;
}

int MatchesClean()
{
  CheckMatchesClean("a fan of 600 regions", CreasedFan());
  CheckMatchesClean("every merge rule", EveryMergeRule());
  CheckMatchesClean("every merge rule, double coordinates",
    WithCoordinates(EveryMergeRule(), vtkNew<vtkDoubleArray>()));
  CheckMatchesClean("every merge rule, struct-of-arrays coordinates",
    WithCoordinates(EveryMergeRule(), vtkNew<vtkSOADataArrayTemplate<float>>()));
  CheckFirstUseData(EveryMergeRule());
  vtkNew<vtkStripper> strips; // strips: vtkPolyDataNormals' path
  strips->SetInputData(nprSphere(0.5, 24, 12));
  strips->Update();
  strips->GetOutput()->GetPointData()->SetNormals(nullptr);
  CheckMatchesClean("sphere as strips", strips->GetOutput());
  for (const char* model : { "bunny.ply", "rotor.ply", "cad_part.vtp" })
  {
    vtkSmartPointer<vtkNPRModelReader> reader = nprReadTestModel(model);
    if (*reader->GetErrorMessage())
    {
      continue; // reported by nprReadTestModel
    }
    vtkNew<vtkPolyData> mesh;
    mesh->ShallowCopy(reader->GetOutput());
    mesh->GetPointData()->SetNormals(nullptr);
    CheckMatchesClean(model, mesh);
  }
  return nprTestResult();
}
NPR_TEST_CASE("matches-clean", MatchesClean);

// A cell naming a point past the end: an error, no output, no crash.
int PointPastTheEnd()
{
  vtkSmartPointer<vtkPolyData> mesh = nprPolygonSoup(nprSphere(0.5, 24, 12));
  const vtkIdType ids[] = { 0, 1, mesh->GetNumberOfPoints() + 5 };
  mesh->GetPolys()->InsertNextCell(3, ids);
  vtkNew<nprCountingOutputWindow> messages;
  vtkNew<vtkNPRShadingNormals> filter;
  filter->SetInputData(mesh);
  nprUpdateCounting(filter, messages);
  NPR_CHECK(messages->Errors >= 1, messages->Errors << " errors");
  NPR_CHECK(filter->GetOutput()->GetNumberOfCells() == 0, "no output");
  return nprTestResult();
}
NPR_TEST_CASE("point-past-the-end", PointPastTheEnd);
}
