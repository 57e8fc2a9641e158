// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// Smooth contours (vtkNPRFeatureLines::SmoothContours), part of the TestFeatureLines program: a
// torus's against its analytic contour generator; a mesh without normals, and one with zero or
// NaN normals.
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

// The torus of the test (ring R, tube r) and the eye it is seen from.
struct TorusView
{
  double R, r;
  double Eye[3];
};

// The largest analytic facing cosine at the torus points nearest the contour's points, which
// are also returned.
double WorstFacing(vtkNPRFeatureLines* filter, const Contour& contour, const TorusView& torus,
  std::vector<std::array<double, 3>>& points)
{
  const double R = torus.R, r = torus.r;
  const double* eye = torus.Eye;
  auto facing = [&](const double x[3], double surface[3])
  {
    const double u = std::atan2(x[1], x[0]);
    const double v = std::atan2(x[2], std::hypot(x[0], x[1]) - R);
    const double n[3] = { std::cos(v) * std::cos(u), std::cos(v) * std::sin(u), std::sin(v) };
    const double c = R + r * std::cos(v);
    const double s[3] = { c * std::cos(u), c * std::sin(u), r * std::sin(v) };
    std::copy_n(s, 3, surface);
    const double toEye[3] = { s[0] - eye[0], s[1] - eye[1], s[2] - eye[2] };
    return vtkMath::Dot(n, toEye) / vtkMath::Norm(toEye);
  };
  double worst = 0.0;
  for (const auto& use : contour.Uses)
  {
    double x[3], s[3];
    filter->GetOutput()->GetPoint(use.first, x);
    worst = std::max(worst, std::abs(facing(x, s)));
    points.push_back({ x[0], x[1], x[2] });
  }
  return worst;
}

// Coverage: the analytic generator, found along v for 360 values of u; its number of points and
// the farthest of them from the contour's points.
std::pair<int, double> AnalyticCoverage(
  const TorusView& torus, const std::vector<std::array<double, 3>>& contourPoints)
{
  const double pi = vtkMath::Pi();
  const double R = torus.R, r = torus.r;
  const double* eye = torus.Eye;
  double farthestMiss = 0.0;
  int roots = 0;
  for (int i = 0; i < 360; ++i)
  {
    const double u = 2 * pi * i / 360;
    auto h = [&](double v)
    {
      const double c = R + r * std::cos(v);
      const double x[3] = { c * std::cos(u), c * std::sin(u), r * std::sin(v) };
      const double n[3] = { std::cos(v) * std::cos(u), std::cos(v) * std::sin(u), std::sin(v) };
      const double toEye[3] = { x[0] - eye[0], x[1] - eye[1], x[2] - eye[2] };
      return vtkMath::Dot(n, toEye);
    };
    for (int j = 0; j < 720; ++j)
    {
      double a = 2 * pi * j / 720, b = 2 * pi * (j + 1) / 720;
      if ((h(a) >= 0.0) == (h(b) >= 0.0))
      {
        continue;
      }
      for (int step = 0; step < 60; ++step)
      {
        const double m = 0.5 * (a + b);
        ((h(m) >= 0.0) == (h(a) >= 0.0) ? a : b) = m;
      }
      const double c = R + r * std::cos(a);
      const double x[3] = { c * std::cos(u), c * std::sin(u), r * std::sin(a) };
      double best = 1e300;
      for (const auto& p : contourPoints)
      {
        best = std::min(best, std::sqrt(vtkMath::Distance2BetweenPoints(x, p.data())));
      }
      farthestMiss = std::max(farthestMiss, best);
      ++roots;
    }
  }
  return { roots, farthestMiss };
}

// Each loop of the contour's reach from the torus axis, largest first.
std::vector<double> LoopReach(vtkNPRFeatureLines* filter, const Contour& contour)
{
  std::vector<double> reach;
  std::map<vtkIdType, std::vector<vtkIdType>> next;
  for (const auto& s : contour.Segments)
  {
    next[s[0]].push_back(s[1]);
    next[s[1]].push_back(s[0]);
  }
  std::set<vtkIdType> seen;
  for (const auto& start : next)
  {
    if (seen.count(start.first))
    {
      continue;
    }
    double most = 0.0;
    std::vector<vtkIdType> stack = { start.first };
    while (!stack.empty())
    {
      const vtkIdType p = stack.back();
      stack.pop_back();
      if (!seen.insert(p).second)
      {
        continue;
      }
      double x[3];
      filter->GetOutput()->GetPoint(p, x);
      most = std::max(most, std::hypot(x[0], x[1]));
      for (vtkIdType q : next[p])
      {
        stack.push_back(q);
      }
    }
    reach.push_back(most);
  }
  std::sort(reach.rbegin(), reach.rend());
  return reach;
}

// A torus (ring R, tube r) with analytic normals, seen obliquely in perspective: an outer loop
// and interior contours, every point near the analytic contour generator and that generator
// covered.
int SmoothTorus()
{
  const double pi = vtkMath::Pi();
  const TorusView view{ 1.0, 0.35, { 0.3, -3.0, 1.6 } };
  const double R = view.R, r = view.r;
  const int nu = 96, nv = 48;
  vtkSmartPointer<vtkPolyData> torus = nprMakeTorus(R, r, nu, nv);
  auto filter = MakeFilter(AllTypes);
  filter->SmoothContoursOn();
  filter->SetEyePosition(view.Eye);
  filter->SetInputData(torus);
  filter->Update();
  const Contour contour = SmoothContour(filter);

  // Linear interpolation of g along an edge of length l errs by l^2/8 max|g''|, with
  // |g''| <= k^2 |p - eye| + 3k on a surface of largest curvature k = 1/r; the nearest
  // surface point is within the sag l^2 k / 8, which moves g by about that (|n| = 1) and the
  // cosine by that over the distance.
  const double longest = std::hypot(2 * pi * (R + r) / nu, 2 * pi * r / nv);
  const double k = 1.0 / r;
  const double farthest = vtkMath::Norm(view.Eye) + R + r;
  const double nearest = vtkMath::Norm(view.Eye) - R - r;
  const double tolerance = (longest * longest / 8.0) * (k * k * farthest + 3.0 * k + k) / nearest;
  std::vector<std::array<double, 3>> contourPoints;
  const double worst = WorstFacing(filter, contour, view, contourPoints);
  const std::pair<int, double> coverage = AnalyticCoverage(view, contourPoints);
  const int roots = coverage.first;
  const double farthestMiss = coverage.second;
  // The loops' sizes: the outer one reaches beyond the ring, the others stay inside R + r.
  const std::vector<double> reach = LoopReach(filter, contour);
  std::cout << "torus " << nu << "x" << nv << ": " << contour.Segments.size() << " segments, "
            << contour.Loops << " loops, closed " << contour.Closed << "; loop reach";
  for (double x : reach)
  {
    std::cout << " " << x;
  }
  std::cout << "; facing cosine <= " << worst << " (bound " << tolerance << "); " << roots
            << " analytic points, farthest " << farthestMiss << " from the contour (edge "
            << longest << ")\n";
  NPR_CHECK(contour.Closed, "the torus contour is not closed");
  NPR_CHECK(
    contour.Loops >= 2 && reach.size() >= 2 && reach[0] > R + 0.9 * r && reach[1] < R + 0.5 * r,
    contour.Loops << " loops: no outer loop and interior contour");
  NPR_CHECK(worst <= tolerance, "a contour point's facing cosine is " << worst);
  NPR_CHECK(roots >= 720 && farthestMiss <= longest,
    "the analytic contour is " << farthestMiss << " from the smooth contour");
  NPR_CHECK(WorstZeroPoint(filter, torus, contour) <= 1e-12, "zero points off their edges");
  return nprTestResult();
}
NPR_TEST_CASE("smooth-torus", SmoothTorus);

// Without point normals the option changes nothing.
int SmoothNoNormals()
{
  vtkSmartPointer<vtkPolyData> sphere = nprSphere(1.0, 32, 32);
  sphere->GetPointData()->SetNormals(nullptr);
  auto off = MakeFilter(AllTypes);
  auto on = MakeFilter(AllTypes);
  on->SmoothContoursOn();
  for (auto* filter : { off.Get(), on.Get() })
  {
    filter->SetEyePosition(0.4, -0.3, 4.0);
    filter->SetInputData(sphere);
    filter->Update();
  }
  vtkPolyData* a = off->GetOutput();
  vtkPolyData* b = on->GetOutput();
  bool same = a->GetNumberOfPoints() == b->GetNumberOfPoints() &&
    a->GetNumberOfCells() == b->GetNumberOfCells() &&
    b->GetCellData()->GetNumberOfArrays() == a->GetCellData()->GetNumberOfArrays() &&
    !b->GetCellData()->GetArray("ContourTriangle");
  for (vtkIdType i = 0; same && i < a->GetNumberOfPoints(); ++i)
  {
    double p[3], q[3];
    a->GetPoint(i, p);
    b->GetPoint(i, q);
    same = p[0] == q[0] && p[1] == q[1] && p[2] == q[2];
  }
  for (const char* name : { "FeatureType", "InputPointIds" })
  {
    vtkDataArray* x = a->GetCellData()->GetArray(name);
    vtkDataArray* y = b->GetCellData()->GetArray(name);
    for (vtkIdType i = 0; same && x && y && i < x->GetNumberOfValues(); ++i)
    {
      same = x->GetVariantValue(i) == y->GetVariantValue(i);
    }
  }
  for (vtkIdType i = 0; same && i < a->GetNumberOfCells(); ++i)
  {
    vtkIdType n, m;
    const vtkIdType *p, *q;
    a->GetLines()->GetCellAtId(i, n, p);
    b->GetLines()->GetCellAtId(i, m, q);
    same = n == 2 && m == 2 && p[0] == q[0] && p[1] == q[1];
  }
  std::cout << "no normals: " << b->GetNumberOfCells() << " lines, "
            << CountCells(on, vtkNPRFeatureLines::SILHOUETTE) << " mesh silhouettes, "
            << (same ? "identical" : "different") << " with smooth contours on\n";
  NPR_CHECK(same, "without normals, SmoothContours changed the output");
  NPR_CHECK(CountCells(on, vtkNPRFeatureLines::SILHOUETTE) > 32, "no mesh silhouettes");
  return nprTestResult();
}
NPR_TEST_CASE("smooth-no-normals", SmoothNoNormals);

// Zero and NaN normals: those points' triangles are skipped and counted, the rest unchanged.
int SmoothBadNormals()
{
  vtkSmartPointer<vtkPolyData> good = nprSphere(1.0, 48, 48);
  // On two arcs of the contour of the view below (the circle x = 0 for a view along +x).
  std::vector<vtkIdType> brokenIds;
  for (vtkIdType i = 0; i < good->GetNumberOfPoints(); ++i)
  {
    double p[3];
    good->GetPoint(i, p);
    if (std::abs(p[0]) < 0.07 && (p[1] > 0.5 || p[1] < -0.9))
    {
      brokenIds.push_back(i);
    }
  }
  vtkSmartPointer<vtkPolyData> bad = nprBreakNormals(good, brokenIds);
  const std::set<vtkIdType> broken(brokenIds.begin(), brokenIds.end());
  vtkCellArray* polys = bad->GetPolys();
  long long touching = 0;
  for (vtkIdType c = 0; c < polys->GetNumberOfCells(); ++c)
  {
    vtkIdType size;
    const vtkIdType* ids;
    polys->GetCellAtId(c, size, ids);
    bool hit = false;
    for (vtkIdType k = 0; k < size; ++k)
    {
      hit = hit || broken.count(ids[k]) > 0;
    }
    touching += hit ? size - 2 : 0;
  }
  std::set<std::vector<double>> expected, got;
  long long skipped = -1;
  for (vtkPolyData* mesh : { good.Get(), bad.Get() })
  {
    auto filter = MakeFilter(AllTypes);
    filter->SmoothContoursOn();
    filter->ParallelProjectionOn();
    filter->SetDirectionOfProjection(1, 0, 0);
    filter->SetInputData(mesh);
    filter->Update();
    const Contour contour = SmoothContour(filter);
    for (size_t s = 0; s < contour.Segments.size(); ++s)
    {
      const auto& t = contour.Triangles[s];
      if (mesh == good.Get() && (broken.count(t[0]) || broken.count(t[1]) || broken.count(t[2])))
      {
        continue;
      }
      double a[3], b[3];
      filter->GetOutput()->GetPoint(contour.Segments[s][0], a);
      filter->GetOutput()->GetPoint(contour.Segments[s][1], b);
      (mesh == good.Get() ? expected : got)
        .insert({ a[0], a[1], a[2], b[0], b[1], b[2], double(t[0]), double(t[1]), double(t[2]) });
    }
    if (mesh == bad.Get())
    {
      skipped = filter->GetNumberOfSkippedContourTriangles();
      NPR_CHECK(!contour.Closed && contour.Loops == 2,
        "the contour broken twice: " << contour.Loops << " pieces, closed " << contour.Closed);
    }
  }
  std::cout << broken.size() << " points with zero, NaN or infinite normals, " << touching
            << " triangles use them, " << skipped << " skipped; " << got.size() << " segments, "
            << expected.size() << " of the intact mesh's away from them\n";
  NPR_CHECK(
    broken.size() >= 6 && skipped == touching, skipped << " skipped, " << touching << " expected");
  NPR_CHECK(got == expected && !got.empty(), "the segments away from the broken normals changed");
  return nprTestResult();
}
NPR_TEST_CASE("smooth-bad-normals", SmoothBadNormals);
}
