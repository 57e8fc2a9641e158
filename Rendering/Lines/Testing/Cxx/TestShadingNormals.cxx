// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// vtkNPRShadingNormals: usable normals are kept; a triangle soup is merged and shaded smoothly;
// zero-length and NaN normals are recomputed with one warning; no faces, no normals. The
// program's other cases: TestShadingNormalsClean.cxx.
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
  vtkSmartPointer<vtkPolyData> sphere = nprSphere(0.5, 24, 12);
  vtkNew<vtkNPRShadingNormals> filter;
  filter->SetInputData(sphere);
  filter->Update();
  NPR_CHECK(!filter->GetComputedNormals(), "usable normals are kept");
  NPR_CHECK(
    filter->GetOutput()->GetPointData()->GetNormals() == sphere->GetPointData()->GetNormals(),
    "the same array passes through");
  return nprTestResult();
}
NPR_TEST_CASE("keeps-usable", KeepsUsable);

int Soup()
{
  vtkSmartPointer<vtkPolyData> sphere = nprSphere(0.5, 24, 12);
  vtkSmartPointer<vtkPolyData> soup = nprPolygonSoup(sphere);
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
NPR_TEST_CASE("soup", Soup);

int Invalid()
{
  // Point 3's normal zero, point 7's NaN.
  vtkSmartPointer<vtkPolyData> broken = nprBreakNormals(nprSphere(0.5, 24, 12), { 3, 7 });
  vtkNew<nprCountingOutputWindow> messages;
  vtkNew<vtkNPRShadingNormals> filter;
  filter->SetInputData(broken);
  nprUpdateCounting(filter, messages);
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
NPR_TEST_CASE("invalid", Invalid);
}
