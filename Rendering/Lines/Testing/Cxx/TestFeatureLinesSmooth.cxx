// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// Smooth contours (vtkNPRFeatureLines::SmoothContours), part of the TestFeatureLines program: a
// sphere's, in parallel and in perspective, against its analytic contour.
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

// ---- Smooth contours: the zero set of the interpolated facing function ----

// A sphere seen along -z in parallel: g = -z, the contour is the equator, one closed loop.
int SmoothSphereParallel()
{
  const double pi = vtkMath::Pi();
  // vtkSphereSource's phi resolution counts the rings, poles included: 63 puts a ring on the
  // equator (also with exact zeros there: ties count as positive), 64 puts the equator
  // between two rings, so the contour crosses their edges.
  for (int variant = 0; variant < 3; ++variant)
  {
    const int phi = variant == 0 ? 64 : 63;
    vtkSmartPointer<vtkPolyData> sphere = nprSphere(1.0, 64, phi);
    std::string name = "sphere 64x" + std::to_string(phi);
    if (variant == 1)
    {
      name += ", exact zeros on the equator";
      vtkNew<vtkPoints> points;
      points->SetDataTypeToDouble();
      points->DeepCopy(sphere->GetPoints());
      vtkDataArray* normals = sphere->GetPointData()->GetNormals();
      int zeros = 0;
      for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
      {
        double p[3], n[3];
        points->GetPoint(i, p);
        normals->GetTuple(i, n);
        if (std::abs(p[2]) < 1e-6)
        {
          p[2] = n[2] = 0.0;
          points->SetPoint(i, p);
          normals->SetTuple(i, n);
          ++zeros;
        }
      }
      sphere->SetPoints(points);
      NPR_CHECK(zeros == 64, zeros << " equator points");
    }
    auto filter = MakeFilter(AllTypes);
    filter->SmoothContoursOn();
    filter->ParallelProjectionOn();
    filter->SetDirectionOfProjection(0, 0, -1);
    filter->SetInputData(sphere);
    filter->Update();
    const Contour contour = SmoothContour(filter);
    // The chord bound: an edge's points lie at least cos(half its angle) from the centre.
    const double chord = std::cos(pi / 64) * (phi % 2 ? 1.0 : std::cos(pi / (2 * (phi - 1))));
    double worstZ = 0.0, lowest = 1.0, highest = 0.0;
    for (const auto& use : contour.Uses)
    {
      double x[3];
      filter->GetOutput()->GetPoint(use.first, x);
      worstZ = std::max(worstZ, std::abs(x[2]));
      const double r = std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
      lowest = std::min(lowest, r);
      highest = std::max(highest, r);
    }
    const double zero = WorstZeroPoint(filter, sphere, contour);
    std::cout << name << ": " << contour.Segments.size() << " segments, " << contour.Uses.size()
              << " points, " << contour.Loops << " loop(s), closed " << contour.Closed
              << "; |z| <= " << worstZ << ", radius " << lowest << " to " << highest
              << " (chord bound " << chord << "), zero points within " << zero << "\n";
    NPR_CHECK(
      contour.Segments.size() >= 64, name << ": " << contour.Segments.size() << " segments");
    NPR_CHECK(contour.Closed && contour.Loops == 1,
      name << ": " << contour.Loops << " pieces, closed " << contour.Closed);
    NPR_CHECK(worstZ <= 1e-9, name << ": a contour point at z = " << worstZ);
    NPR_CHECK(lowest >= chord - 1e-6 && highest <= 1.0 + 1e-6,
      name << ": radius from " << lowest << " to " << highest);
    NPR_CHECK(zero <= 1e-12, name << ": a zero point " << zero << " from its edge's");
    NPR_CHECK(filter->GetNumberOfSkippedContourTriangles() == 0, "skipped triangles");
    NPR_CHECK(CountCells(filter, vtkNPRFeatureLines::SILHOUETTE) == 0,
      name << ": mesh edges still silhouettes");
  }
  return nprTestResult();
}
NPR_TEST_CASE("smooth-sphere-parallel", SmoothSphereParallel);

// In perspective from (0, 0, D): on the unit sphere g = 1 - D z is linear along every edge,
// so the contour lies on the plane z = 1/D, inside the analytic circle by the chord sag.
int SmoothSpherePerspective()
{
  const double pi = vtkMath::Pi();
  const double D = 5.0;
  vtkSmartPointer<vtkPolyData> sphere = nprSphere(1.0, 64, 64);
  auto filter = MakeFilter(vtkNPRFeatureLines::SILHOUETTE);
  filter->SmoothContoursOn();
  filter->SetEyePosition(0, 0, D);
  filter->SetInputData(sphere);
  filter->Update();
  const Contour contour = SmoothContour(filter);
  const double circle = std::sqrt(1.0 - 1.0 / (D * D));
  // Sag of the longest edges (the quads' diagonals), for points on a chord of the sphere.
  const double sag = 1.0 - std::cos(0.5 * std::hypot(2 * pi / 64, pi / 64));
  double worstPlane = 0.0, worstIn = 0.0, worstOut = 0.0;
  for (const auto& use : contour.Uses)
  {
    double x[3];
    filter->GetOutput()->GetPoint(use.first, x);
    worstPlane = std::max(worstPlane, std::abs(x[2] - 1.0 / D));
    const double rho = std::hypot(x[0], x[1]);
    worstIn = std::max(worstIn, circle - rho);
    worstOut = std::max(worstOut, rho - circle);
  }
  const double zero = WorstZeroPoint(filter, sphere, contour);
  std::cout << "perspective: " << contour.Segments.size() << " segments, " << contour.Loops
            << " loop(s), closed " << contour.Closed << "; |z - 1/D| <= " << worstPlane
            << " (float normals and points), inside the circle by <= " << worstIn << ", outside by "
            << worstOut << " (sag " << sag << "), zero points within " << zero << "\n";
  NPR_CHECK(contour.Closed && contour.Loops == 1, contour.Loops << " pieces");
  NPR_CHECK(worstPlane <= 1e-6, "off the plane z = 1/D by " << worstPlane);
  NPR_CHECK(worstIn <= sag && worstOut <= 1e-6,
    "from the analytic circle: inside " << worstIn << ", outside " << worstOut);
  NPR_CHECK(zero <= 1e-12, "a zero point " << zero << " from its edge's");

  // Normals of other lengths (1/4 to 4, per point) are made unit: the same contour.
  vtkNew<vtkPolyData> scaled;
  scaled->DeepCopy(sphere);
  vtkDataArray* normals = scaled->GetPointData()->GetNormals();
  std::mt19937 random(11);
  std::uniform_real_distribution<double> power(-2.0, 2.0);
  for (vtkIdType i = 0; i < normals->GetNumberOfTuples(); ++i)
  {
    const double factor = std::pow(2.0, power(random));
    double n[3];
    normals->GetTuple(i, n);
    normals->SetTuple3(i, factor * n[0], factor * n[1], factor * n[2]);
  }
  filter->SetInputData(scaled);
  filter->Update();
  const Contour other = SmoothContour(filter);
  double moved = other.Segments.size() == contour.Segments.size() ? 0.0 : 1e300;
  for (const auto& use : other.Uses)
  {
    double x[3];
    filter->GetOutput()->GetPoint(use.first, x);
    moved = std::max(moved, std::abs(x[2] - 1.0 / D));
  }
  std::cout << "normals scaled by 1/4 to 4: " << other.Segments.size()
            << " segments, |z - 1/D| <= " << moved << "\n";
  NPR_CHECK(moved <= 1e-6, "normals not made unit: the contour moved by " << moved);
  return nprTestResult();
}
NPR_TEST_CASE("smooth-sphere-perspective", SmoothSpherePerspective);
}
