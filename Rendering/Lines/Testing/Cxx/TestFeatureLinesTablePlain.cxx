// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// Part of the TestFeatureLinesTable program: the plain edge table the filter's is held against
// (TestFeatureLinesTable.h), built from the documented rules in double.
#include "TestFeatureLinesTable.h"

#include "vtkCellArray.h"
#include "vtkMath.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <cmath>

namespace nprFeatureLinesTable
{
namespace
{
double Dot3(const double a[3], const double b[3])
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
}

PlainTable::PlainTable(vtkPolyData* mesh, bool merge)
{
  this->ReadPoints(mesh, merge);
  vtkIdType size;
  const vtkIdType* ids;
  vtkCellArray* polys = mesh->GetPolys();
  for (polys->InitTraversal(); polys->GetNextCell(size, ids);)
  {
    this->AddFace(std::vector<vtkIdType>(ids, ids + size));
  }
  vtkCellArray* strips = mesh->GetStrips();
  for (strips->InitTraversal(); strips->GetNextCell(size, ids);)
  {
    for (vtkIdType k = 0; k + 2 < size; ++k)
    {
      this->AddFace({ ids[k + (k & 1)], ids[k + 1 - (k & 1)], ids[k + 2] });
    }
  }
}

std::vector<double> PlainTable::Angles() const
{
  std::vector<double> angles;
  for (const Edge& edge : this->Edges)
  {
    if (edge.Uses.size() == 2)
    {
      angles.push_back(this->Angle(edge));
    }
  }
  return angles;
}

std::vector<Line> PlainTable::Lines(const Viewpoint& viewpoint) const
{
  std::vector<Line> lines;
  for (const Edge& edge : this->Edges)
  {
    const int type = this->Type(edge, viewpoint);
    if (type)
    {
      lines.push_back({ edge.A, edge.B, type });
    }
  }
  return lines;
}

void PlainTable::ReadPoints(vtkPolyData* mesh, bool merge)
{
  std::map<Point, vtkIdType> first;
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    Point p;
    mesh->GetPoint(i, p.data());
    this->Points.push_back(p);
    const bool finite = std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
    const Point key = { p[0] + 0.0, p[1] + 0.0, p[2] + 0.0 }; // -0 as +0
    this->Representatives.push_back(merge && finite ? first.emplace(key, i).first->second : i);
  }
}

// Newell's normal from the first point, unit length; none where the face has no orientation.
bool PlainTable::Normal(const std::vector<vtkIdType>& ids, std::array<double, 3>& unit) const
{
  double normal[3] = { 0.0, 0.0, 0.0 }, size2 = 0.0;
  const Point& o = this->Points[ids[0]];
  for (size_t i = 1; i + 1 < ids.size(); ++i)
  {
    const Point& p = this->Points[ids[i]];
    const Point& q = this->Points[ids[i + 1]];
    const double a[3] = { p[0] - o[0], p[1] - o[1], p[2] - o[2] };
    const double b[3] = { q[0] - o[0], q[1] - o[1], q[2] - o[2] };
    normal[0] += a[1] * b[2] - a[2] * b[1];
    normal[1] += a[2] * b[0] - a[0] * b[2];
    normal[2] += a[0] * b[1] - a[1] * b[0];
    size2 = std::max(size2, std::max(Dot3(a, a), Dot3(b, b)));
  }
  const double length = std::sqrt(Dot3(normal, normal));
  if (!(length > 1e-12 * size2) || !std::isfinite(length))
  {
    return false;
  }
  unit = { normal[0] / length, normal[1] / length, normal[2] / length };
  return true;
}

void PlainTable::AddFace(const std::vector<vtkIdType>& ids)
{
  const size_t size = ids.size();
  bool usable = size >= 3;
  for (vtkIdType id : ids)
  {
    usable = usable && id >= 0 && id < static_cast<vtkIdType>(this->Points.size());
  }
  for (size_t i = 0; usable && i < size; ++i)
  {
    const Point& p = this->Points[ids[i]];
    usable = std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
  }
  std::array<double, 3> normal;
  if (!usable || !this->Normal(ids, normal))
  {
    return;
  }
  this->Normals.push_back(normal);
  for (size_t i = 0; i < size; ++i)
  {
    vtkIdType a = this->Representatives[ids[i]], b = this->Representatives[ids[(i + 1) % size]];
    if (a == b || this->Points[a] == this->Points[b])
    {
      continue;
    }
    const bool forward = a < b;
    const auto key = std::make_pair(std::min(a, b), std::max(a, b));
    auto found = this->Index.emplace(key, this->Edges.size());
    if (found.second)
    {
      this->Edges.push_back({ key.first, key.second, {} });
    }
    this->Edges[found.first->second].Uses.push_back({ this->Normals.size() - 1, forward,
      std::make_pair(
        std::min(ids[i], ids[(i + 1) % size]), std::max(ids[i], ids[(i + 1) % size])) });
  }
}

// The angle between a two-face edge's normals (the second flipped where the windings
// disagree), degrees.
double PlainTable::Angle(const Edge& edge) const
{
  const bool same = edge.Uses[0].Forward == edge.Uses[1].Forward;
  const auto& n0 = this->Normals[edge.Uses[0].Face];
  const auto& n1 = this->Normals[edge.Uses[1].Face];
  double flipped[3], cross[3];
  for (int k = 0; k < 3; ++k)
  {
    flipped[k] = same ? -n1[k] : n1[k];
  }
  vtkMath::Cross(n0.data(), flipped, cross);
  return vtkMath::DegreesFromRadians(std::atan2(vtkMath::Norm(cross), Dot3(n0.data(), flipped)));
}

// The edge's line type for the viewpoint: boundary, non-manifold, crease, silhouette; 0 for none.
int PlainTable::Type(const Edge& edge, const Viewpoint& viewpoint) const
{
  if (edge.Uses.size() != 2)
  {
    return edge.Uses.size() == 1 ? vtkNPRFeatureLines::BOUNDARY : vtkNPRFeatureLines::NON_MANIFOLD;
  }
  const bool same = edge.Uses[0].Forward == edge.Uses[1].Forward;
  const auto& n0 = this->Normals[edge.Uses[0].Face];
  const auto& n1 = this->Normals[edge.Uses[1].Face];
  int type = this->Angle(edge) > viewpoint.Angle ? vtkNPRFeatureLines::CREASE : 0;
  double f0, f1;
  if (viewpoint.Parallel)
  {
    f0 = Dot3(n0.data(), viewpoint.View);
    f1 = Dot3(n1.data(), viewpoint.View);
  }
  else
  {
    const Point& p = this->Points[edge.A];
    const double toPoint[3] = { p[0] - viewpoint.View[0], p[1] - viewpoint.View[1],
      p[2] - viewpoint.View[2] };
    f0 = Dot3(n0.data(), toPoint);
    f1 = Dot3(n1.data(), toPoint);
  }
  // With smooth contours, a mesh edge is a silhouette only where its faces reach it through
  // different points (split normals).
  const bool split = edge.Uses[0].InputIds != edge.Uses[1].InputIds;
  if ((f0 < 0.0) != ((same ? -f1 : f1) < 0.0) && (!viewpoint.Smooth || split))
  {
    type |= vtkNPRFeatureLines::SILHOUETTE;
  }
  return type;
}
}
