// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// vtkNPRShadingNormals: usable normals are kept; a triangle soup is merged and shaded smoothly;
// zero-length and NaN normals are recomputed with one warning; no faces, no normals.
//
// usage: TestShadingNormals CASE   (CASE: see the table at the end of this file)
#include "nprTesting.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkNPRShadingNormals.h"
#include "vtkNew.h"
#include "vtkOutputWindow.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSphereSource.h"
#include "vtkTriangleFilter.h"

#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <string>

namespace
{
// The sphere's triangles, each with its own three points (a soup).
vtkSmartPointer<vtkPolyData> SphereSoup(vtkPolyData* sphere)
{
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> triangles;
  auto iterator = vtk::TakeSmartPointer(sphere->GetPolys()->NewIterator());
  for (iterator->GoToFirstCell(); !iterator->IsDoneWithTraversal(); iterator->GoToNextCell())
  {
    vtkIdType size;
    const vtkIdType* ids;
    iterator->GetCurrentCell(size, ids);
    triangles->InsertNextCell(size);
    for (vtkIdType k = 0; k < size; ++k)
    {
      triangles->InsertCellPoint(points->InsertNextPoint(sphere->GetPoint(ids[k])));
    }
  }
  auto soup = vtkSmartPointer<vtkPolyData>::New();
  soup->SetPoints(points);
  soup->SetPolys(triangles);
  return soup;
}

vtkSmartPointer<vtkPolyData> Sphere()
{
  vtkNew<vtkSphereSource> source;
  source->SetThetaResolution(24);
  source->SetPhiResolution(12);
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(source->GetOutputPort());
  triangles->Update();
  auto sphere = vtkSmartPointer<vtkPolyData>::New();
  sphere->ShallowCopy(triangles->GetOutput());
  return sphere;
}

// The largest angle (degrees) between a point's normal and its radial direction on the unit
// sphere: smooth shading gives a few degrees, facets tens.
double LargestDeviation(vtkPolyData* mesh)
{
  vtkDataArray* normals = mesh->GetPointData()->GetNormals();
  double largest = 0.0;
  for (vtkIdType i = 0; normals && i < mesh->GetNumberOfPoints(); ++i)
  {
    double p[3], n[3];
    mesh->GetPoint(i, p);
    normals->GetTuple(i, n);
    const double lp = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    const double ln = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    const double c = (p[0] * n[0] + p[1] * n[1] + p[2] * n[2]) / (lp * ln);
    largest =
      std::max(largest, std::acos(std::min(1.0, std::max(-1.0, c))) * 180.0 / 3.14159265358979);
  }
  return normals ? largest : 180.0;
}

int KeepsUsable()
{
  vtkSmartPointer<vtkPolyData> sphere = Sphere();
  vtkNew<vtkNPRShadingNormals> filter;
  filter->SetInputData(sphere);
  filter->Update();
  NPR_CHECK(!filter->GetComputedNormals(), "usable normals are kept");
  NPR_CHECK(
    filter->GetOutput()->GetPointData()->GetNormals() == sphere->GetPointData()->GetNormals(),
    "the same array passes through");
  return nprTestResult();
}

int Soup()
{
  vtkSmartPointer<vtkPolyData> sphere = Sphere();
  vtkSmartPointer<vtkPolyData> soup = SphereSoup(sphere);
  vtkNew<vtkNPRShadingNormals> filter;
  filter->SetInputData(soup);
  filter->Update();
  vtkPolyData* output = filter->GetOutput();
  std::cout << soup->GetNumberOfPoints() << " soup points -> " << output->GetNumberOfPoints()
            << " points, largest normal deviation " << LargestDeviation(output) << " degrees\n";
  NPR_CHECK(filter->GetComputedNormals(), "normals computed");
  NPR_CHECK(output->GetNumberOfPoints() == sphere->GetNumberOfPoints(),
    "coincident points merged: " << output->GetNumberOfPoints() << " of "
                                 << sphere->GetNumberOfPoints());
  NPR_CHECK(output->GetNumberOfPolys() == sphere->GetNumberOfPolys(), "every triangle kept");
  NPR_CHECK(LargestDeviation(output) < 3.0, "smooth normals");
  return nprTestResult();
}

int Invalid()
{
  vtkSmartPointer<vtkPolyData> sphere = Sphere();
  vtkNew<vtkPolyData> broken;
  broken->DeepCopy(sphere);
  vtkDataArray* normals = broken->GetPointData()->GetNormals();
  normals->SetTuple3(3, 0.0, 0.0, 0.0);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  normals->SetTuple3(7, nan, 0.0, 1.0);
  vtkNew<nprCountingOutputWindow> messages;
  vtkOutputWindow* previous = vtkOutputWindow::GetInstance();
  previous->Register(nullptr);
  vtkOutputWindow::SetInstance(messages);
  vtkNew<vtkNPRShadingNormals> filter;
  filter->SetInputData(broken);
  filter->Update();
  vtkOutputWindow::SetInstance(previous);
  previous->UnRegister(nullptr);
  NPR_CHECK(messages->Warnings == 1 && messages->Errors == 0,
    messages->Warnings << " warnings, " << messages->Errors << " errors");
  NPR_CHECK(filter->GetComputedNormals() && filter->GetNumberOfInvalidNormals() == 2,
    filter->GetNumberOfInvalidNormals() << " invalid normals");
  NPR_CHECK(LargestDeviation(filter->GetOutput()) < 3.0, "recomputed normals are smooth");
  // The input is untouched.
  double n[3];
  broken->GetPointData()->GetNormals()->GetTuple(3, n);
  NPR_CHECK(n[0] == 0.0 && n[1] == 0.0 && n[2] == 0.0, "the input keeps its normals");

  vtkNew<vtkPolyData> empty;
  filter->SetInputData(empty);
  filter->Update();
  NPR_CHECK(filter->GetOutput()->GetNumberOfPoints() == 0 &&
      !filter->GetOutput()->GetPointData()->GetNormals(),
    "empty input, empty output");
  return nprTestResult();
}
}

int main(int argc, char* argv[])
{
  const std::map<std::string, std::function<int()>> cases = {
    { "keeps-usable", KeepsUsable },
    { "soup", Soup },
    { "invalid", Invalid },
  };
  return nprRunTestCase(argc, argv, cases);
}
