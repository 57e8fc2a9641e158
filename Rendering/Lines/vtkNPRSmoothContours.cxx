// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNPRSmoothContours.h"

#include "vtkDataArray.h"
#include "vtkNPRMeshAdjacencyInternals.h"
#include "vtkNPRMeshFaces.h"
#include "vtkNPRVectors.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace
{
using vtkNPRMeshAdjacencyInternals::BlockSize;
}

vtkDataArray* vtkNPRSmoothContours::PointNormals(vtkPolyData* input)
{
  vtkDataArray* normals = input->GetPointData()->GetNormals();
  const vtkIdType points = input->GetPoints() ? input->GetPoints()->GetNumberOfPoints() : 0;
  return normals && normals->GetNumberOfComponents() == 3 &&
      normals->GetNumberOfTuples() == points && points > 0 &&
      points <= static_cast<vtkIdType>(std::numeric_limits<std::uint32_t>::max())
    ? normals
    : nullptr;
}

void vtkNPRSmoothContours::Reset()
{
  std::vector<std::uint32_t>().swap(this->Triangles);
  std::vector<double>().swap(this->UnitNormals);
  std::vector<double>().swap(this->Facing);
  std::vector<std::vector<Segment>>().swap(this->Segments);
  this->TrianglesValid = false;
  this->NormalsArray = nullptr;
}

size_t vtkNPRSmoothContours::GetMemorySize() const
{
  size_t bytes = this->Triangles.capacity() * sizeof(std::uint32_t) +
    (this->UnitNormals.capacity() + this->Facing.capacity()) * sizeof(double);
  for (const auto& block : this->Segments)
  {
    bytes += block.capacity() * sizeof(Segment);
  }
  return bytes;
}

void vtkNPRSmoothContours::Compute(
  const vtkNPRMeshFaces& mesh, vtkDataArray* normals, bool parallel, const double view[3])
{
  this->MakeTables(mesh, normals);
  this->ComputeFacing(mesh, parallel, view);
  this->FindSegments();
}

void vtkNPRSmoothContours::MakeTables(const vtkNPRMeshFaces& mesh, vtkDataArray* normals)
{
  if (!this->TrianglesValid)
  {
    this->MakeTriangles(mesh);
  }
  const vtkIdType pointCount = mesh.GetNumberOfPoints();
  if (this->NormalsArray != normals || this->NormalsTime != normals->GetMTime())
  {
    this->UnitNormals.resize(3 * pointCount);
    double* unit = this->UnitNormals.data();
    vtkSMPTools::For(0, pointCount,
      [=](vtkIdType first, vtkIdType last)
      {
        for (vtkIdType i = first; i < last; ++i)
        {
          double n[3];
          normals->GetTuple(i, n);
          const double length = glm::length(vtkNPRVector(n));
          const bool usable = length > 0.0 && std::isfinite(length);
          vtkNPRStore(usable ? vtkNPRVector(n) / length
                             : glm::dvec3(std::numeric_limits<double>::quiet_NaN()),
            unit + 3 * i);
        }
      });
    this->NormalsArray = normals;
    this->NormalsTime = normals->GetMTime();
  }
}

void vtkNPRSmoothContours::MakeTriangles(const vtkNPRMeshFaces& mesh)
{
  const vtkIdType pointCount = mesh.GetNumberOfPoints();
  this->Triangles.clear();
  for (vtkIdType t = 0; t < mesh.GetNumberOfTriangles(); ++t)
  {
    vtkIdType ids[3];
    mesh.GetTriangle(t, ids);
    // A repeated point (strips repeat points to turn): no area, and a zero-length segment.
    const bool inRange =
      std::all_of(ids, ids + 3, [&](vtkIdType id) { return id >= 0 && id < pointCount; });
    if (inRange && ids[0] != ids[1] && ids[1] != ids[2] && ids[2] != ids[0])
    {
      this->Triangles.insert(this->Triangles.end(),
        { static_cast<std::uint32_t>(ids[0]), static_cast<std::uint32_t>(ids[1]),
          static_cast<std::uint32_t>(ids[2]) });
    }
  }
  this->TrianglesValid = true;
}

void vtkNPRSmoothContours::ComputeFacing(
  const vtkNPRMeshFaces& mesh, bool parallel, const double view[3])
{
  // g per point: not finite where the normal or the point is unusable.
  const vtkIdType pointCount = mesh.GetNumberOfPoints();
  this->Facing.resize(pointCount);
  const double* unit = this->UnitNormals.data();
  double* facing = this->Facing.data();
  vtkSMPTools::For(0, pointCount,
    [=, &mesh](vtkIdType first, vtkIdType last)
    {
      for (vtkIdType i = first; i < last; ++i)
      {
        double p[3];
        mesh.GetPoint(i, p);
        const glm::dvec3 sight =
          parallel ? vtkNPRVector(view) : vtkNPRVector(p) - vtkNPRVector(view);
        facing[i] = glm::dot(vtkNPRVector(unit + 3 * i), sight);
      }
    });
}

void vtkNPRSmoothContours::FindSegments()
{
  const double* facing = this->Facing.data();
  // The triangles where g changes sign, in blocks that list them in order.
  const vtkIdType triangleCount = static_cast<vtkIdType>(this->Triangles.size() / 3);
  const vtkIdType blockCount = (triangleCount + BlockSize - 1) / BlockSize;
  this->Segments.resize(static_cast<size_t>(blockCount));
  const std::uint32_t* triangles = this->Triangles.data();
  vtkSMPThreadLocal<vtkIdType> skipped(0);
  vtkSMPTools::For(0, blockCount,
    [&](vtkIdType firstBlock, vtkIdType lastBlock)
    {
      vtkIdType skippedHere = 0;
      for (vtkIdType block = firstBlock; block < lastBlock; ++block)
      {
        auto& listed = this->Segments[block];
        listed.clear();
        const vtkIdType last = std::min(triangleCount, (block + 1) * BlockSize);
        for (vtkIdType t = block * BlockSize; t < last; ++t)
        {
          const std::uint32_t* ids = triangles + 3 * t;
          const double g[3] = { facing[ids[0]], facing[ids[1]], facing[ids[2]] };
          if (!(std::isfinite(g[0]) && std::isfinite(g[1]) && std::isfinite(g[2])))
          {
            ++skippedHere;
            continue;
          }
          // g == 0 counts as positive, so that each edge is decided one way for all its faces.
          const bool positive[3] = { g[0] >= 0.0, g[1] >= 0.0, g[2] >= 0.0 };
          if (positive[0] == positive[1] && positive[1] == positive[2])
          {
            continue;
          }
          Segment segment{ static_cast<std::uint32_t>(t), 0, 0 };
          for (unsigned char k = 0; k < 3; ++k)
          {
            const bool next = positive[(k + 1) % 3];
            if (positive[k] != next)
            {
              (next ? segment.Rise : segment.Fall) = k;
            }
          }
          listed.push_back(segment);
        }
      }
      skipped.Local() += skippedHere;
    });
  this->SkippedTriangles = 0;
  for (vtkIdType count : skipped)
  {
    this->SkippedTriangles += count;
  }
}
