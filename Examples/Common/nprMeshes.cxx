// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nprMeshes.h"

#include "vtkCellArray.h"
#include "vtkIdList.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <cmath>

vtkSmartPointer<vtkPolyData> nprMesh(vtkPoints* points, vtkCellArray* polygons)
{
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->SetPoints(points);
  mesh->SetPolys(polygons);
  return mesh;
}

void nprForEachCell(vtkCellArray* cells,
  const std::function<void(vtkIdType cell, vtkIdType size, const vtkIdType* ids)>& visit)
{
  vtkNew<vtkIdList> ids; // a copy of each cell's ids, whatever the array's storage
  for (vtkIdType cell = 0; cell < cells->GetNumberOfCells(); ++cell)
  {
    cells->GetCellAtId(cell, ids);
    visit(cell, ids->GetNumberOfIds(), ids->begin());
  }
}

vtkSmartPointer<vtkPolyData> nprPolygonSoup(vtkPolyData* mesh)
{
  vtkNew<vtkPoints> points;
  points->SetDataType(mesh->GetPoints()->GetDataType());
  vtkNew<vtkCellArray> polygons;
  nprForEachCell(mesh->GetPolys(),
    [&](vtkIdType, vtkIdType size, const vtkIdType* ids)
    {
      polygons->InsertNextCell(size);
      for (vtkIdType k = 0; k < size; ++k)
      {
        polygons->InsertCellPoint(points->InsertNextPoint(mesh->GetPoint(ids[k])));
      }
    });
  return nprMesh(points, polygons);
}

vtkSmartPointer<vtkCellArray> nprTubeTriangles(int along, int around)
{
  auto triangles = vtkSmartPointer<vtkCellArray>::New();
  auto id = [&](int i, int j) { return static_cast<vtkIdType>((i % along) * around + j % around); };
  for (int i = 0; i < along; ++i)
  {
    for (int j = 0; j < around; ++j)
    {
      const vtkIdType first[3] = { id(i, j), id(i + 1, j), id(i + 1, j + 1) };
      const vtkIdType second[3] = { id(i, j), id(i + 1, j + 1), id(i, j + 1) };
      triangles->InsertNextCell(3, first);
      triangles->InsertNextCell(3, second);
    }
  }
  return triangles;
}

vtkSmartPointer<vtkPolyData> nprRevolvedProfile(
  const std::vector<std::array<double, 2>>& profile, int around)
{
  const double step = 2.0 * vtkMath::Pi() / around;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  std::vector<vtkIdType> firstId; // of each profile point: its ring, or its one point on the axis
  for (const auto& rz : profile)
  {
    firstId.push_back(points->GetNumberOfPoints());
    const int count = rz[0] > 0.0 ? around : 1;
    for (int j = 0; j < count; ++j)
    {
      points->InsertNextPoint(rz[0] * std::cos(j * step), rz[0] * std::sin(j * step), rz[1]);
    }
  }
  auto id = [&](size_t i, int j)
  { return profile[i][0] > 0.0 ? firstId[i] + j % around : firstId[i]; };
  vtkNew<vtkCellArray> triangles;
  for (size_t i = 0; i + 1 < profile.size(); ++i)
  {
    for (int j = 0; j < around; ++j)
    {
      // The quad (i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1) as two triangles, outwards; a
      // side on the axis has collapsed to a point, and its triangle with it.
      const vtkIdType a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      if (b != c)
      {
        const vtkIdType first[3] = { a, c, b };
        triangles->InsertNextCell(3, first);
      }
      if (a != d)
      {
        const vtkIdType second[3] = { a, d, c };
        triangles->InsertNextCell(3, second);
      }
    }
  }
  return nprMesh(points, triangles);
}

vtkSmartPointer<vtkPolyData> nprConeOnFlange(double coneAngle, int around)
{
  const double foot = 0.85, top = 0.1, flange = 0.25;
  const double height = flange + (foot - top) * std::tan(vtkMath::RadiansFromDegrees(coneAngle));
  return nprRevolvedProfile({ { 0.0, 0.0 }, { 1.0, 0.0 }, { 1.0, flange }, { foot, flange },
                              { top, height }, { 0.0, height } },
    around);
}

namespace
{
// A quarter circle of six facets about centre, from angle `from` (degrees) on, turning by 90
// degrees in the direction of `turn` (+1 counter-clockwise), appended to profile.
void AppendQuarterRound(std::vector<std::array<double, 2>>& profile,
  const std::array<double, 2>& centre, double radius, double from, int turn)
{
  for (int k = 0; k <= 6; ++k)
  {
    const double angle = vtkMath::RadiansFromDegrees(from + turn * 15.0 * k);
    profile.push_back(
      { centre[0] + radius * std::cos(angle), centre[1] + radius * std::sin(angle) });
  }
}
}

vtkSmartPointer<vtkPolyData> nprFilletedCylinder(int around)
{
  std::vector<std::array<double, 2>> profile = { { 0.0, 0.0 }, { 0.8, 0.0 }, { 1.0, 0.2 } };
  AppendQuarterRound(profile, { 0.75, 1.15 }, 0.25, 0.0, 1);    // convex: the top's outer edge
  AppendQuarterRound(profile, { 0.55, 1.65 }, 0.25, -90.0, -1); // concave: the boss's foot
  profile.push_back({ 0.3, 2.0 });
  profile.push_back({ 0.0, 2.0 });
  return nprRevolvedProfile(profile, around);
}

vtkSmartPointer<vtkPolyData> nprBossAndPocket(int around)
{
  return nprRevolvedProfile({ { 0.0, 0.0 }, { 1.0, 0.0 }, { 1.0, 0.3 }, { 0.55, 0.3 },
                              { 0.55, 0.9 }, { 0.3, 0.9 }, { 0.3, 0.6 }, { 0.0, 0.6 } },
    around);
}

vtkSmartPointer<vtkPolyData> nprBumpyTorus(int along, int around)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (int i = 0; i < along; ++i)
  {
    const double u = 2.0 * vtkMath::Pi() * i / along;
    for (int j = 0; j < around; ++j)
    {
      const double v = 2.0 * vtkMath::Pi() * j / around;
      // Bumps of three sizes, their phases mixed so that no two line up: lumpy, not
      // periodic-looking.
      const double bumps = 0.10 * std::sin(3.0 * u + 1.3) * std::sin(2.0 * v + 0.4) +
        0.05 * std::sin(7.0 * u + 2.0 * v + 0.7) + 0.025 * std::sin(13.0 * u - 5.0 * v + 2.1);
      const double r = 0.4 * (1.0 + bumps);
      const double ring = 1.0 + r * std::cos(v);
      points->InsertNextPoint(ring * std::cos(u), ring * std::sin(u), r * std::sin(v));
    }
  }
  return nprMesh(points, nprTubeTriangles(along, around));
}
