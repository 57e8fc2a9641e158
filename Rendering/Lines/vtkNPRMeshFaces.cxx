// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNPRMeshFaces.h"

#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"

#include <atomic>

void vtkNPRMeshFaces::Cells::Set(vtkCellArray* cells)
{
  *this = Cells();
  if (!cells)
  {
    return;
  }
  this->Count = cells->GetNumberOfCells();
  if (cells->IsStorage64Bit())
  {
    this->Offsets64 = cells->GetOffsetsArray64()->GetPointer(0);
    this->Connectivity64 = cells->GetConnectivityArray64()->GetPointer(0);
  }
  else
  {
    this->Offsets32 = cells->GetOffsetsArray32()->GetPointer(0);
    this->Connectivity32 = cells->GetConnectivityArray32()->GetPointer(0);
  }
}

void vtkNPRMeshFaces::Set(vtkPolyData* mesh)
{
  *this = vtkNPRMeshFaces();
  vtkPoints* points = mesh ? mesh->GetPoints() : nullptr;
  this->NumberOfPoints = points ? points->GetNumberOfPoints() : 0;
  if (auto* floats = vtkFloatArray::FastDownCast(points ? points->GetData() : nullptr))
  {
    this->FloatPoints = floats->GetPointer(0);
  }
  else if (auto* doubles = vtkDoubleArray::FastDownCast(points ? points->GetData() : nullptr))
  {
    this->DoublePoints = doubles->GetPointer(0);
  }
  else if (this->NumberOfPoints > 0)
  {
    this->CopiedPoints.resize(3 * static_cast<size_t>(this->NumberOfPoints));
    for (vtkIdType i = 0; i < this->NumberOfPoints; ++i)
    {
      points->GetPoint(i, &this->CopiedPoints[3 * i]);
    }
    this->DoublePoints = this->CopiedPoints.data();
  }
  this->Polys.Set(mesh ? mesh->GetPolys() : nullptr);
  this->Strips.Set(mesh ? mesh->GetStrips() : nullptr);

  // Polygons: all triangles (the common case) needs no table; else each one's first fan triangle.
  std::atomic<bool> triangles(true);
  const Cells& polys = this->Polys;
  vtkSMPTools::For(0, polys.Count,
    [&](vtkIdType first, vtkIdType last)
    {
      bool all = true;
      for (vtkIdType c = first; c < last && all; ++c)
      {
        all = polys.Offset(c) == 3 * c;
      }
      if (!all)
      {
        triangles = false;
      }
    });
  this->PolysAreTriangles = triangles && polys.Size() == 3 * polys.Count;
  if (this->PolysAreTriangles)
  {
    this->PolyTriangles = polys.Count;
  }
  else
  {
    this->FanFirstTriangle.resize(polys.Count + 1);
    for (vtkIdType c = 0; c < polys.Count; ++c)
    {
      const vtkIdType size = polys.Offset(c + 1) - polys.Offset(c);
      this->FanFirstTriangle[c + 1] = this->FanFirstTriangle[c] + std::max<vtkIdType>(0, size - 2);
    }
    this->PolyTriangles = this->FanFirstTriangle.back();
  }
  this->StripFirstFace.resize(this->Strips.Count + 1);
  for (vtkIdType s = 0; s < this->Strips.Count; ++s)
  {
    const vtkIdType size = this->Strips.Offset(s + 1) - this->Strips.Offset(s);
    this->StripFirstFace[s + 1] = this->StripFirstFace[s] + std::max<vtkIdType>(0, size - 2);
  }
  this->StripTriangles = this->StripFirstFace.back();
}

void vtkNPRMeshFaces::GetStripTriangle(vtkIdType r, vtkIdType ids[3]) const
{
  // The last strip that starts at or before r (strips of fewer than three points start where
  // the next one does, and are passed over).
  const auto found =
    std::upper_bound(this->StripFirstFace.begin(), this->StripFirstFace.end(), r) - 1;
  const vtkIdType k = r - *found;
  const vtkIdType base = this->Strips.Offset(found - this->StripFirstFace.begin()) + k;
  ids[0] = this->Strips.Id(base + (k & 1));
  ids[1] = this->Strips.Id(base + 1 - (k & 1));
  ids[2] = this->Strips.Id(base + 2);
}

vtkIdType vtkNPRMeshFaces::GetFaceOfUse(vtkIdType use) const
{
  const vtkIdType polyUses = this->Polys.Size();
  if (use >= polyUses)
  {
    return this->Polys.Count + (use - polyUses) / 3;
  }
  if (this->PolysAreTriangles)
  {
    return use / 3;
  }
  // The last polygon that starts at or before the use (empty ones start where the next does).
  vtkIdType low = 0, high = this->Polys.Count; // Offset(low) <= use < Offset(high)
  while (high - low > 1)
  {
    const vtkIdType middle = low + (high - low) / 2;
    (this->Polys.Offset(middle) <= use ? low : high) = middle;
  }
  return low;
}

void vtkNPRMeshFaces::GetTriangle(vtkIdType triangle, vtkIdType ids[3]) const
{
  if (triangle >= this->PolyTriangles)
  {
    this->GetStripTriangle(triangle - this->PolyTriangles, ids);
    return;
  }
  vtkIdType polygon = triangle, k = 1;
  if (!this->PolysAreTriangles)
  {
    const auto found =
      std::upper_bound(this->FanFirstTriangle.begin(), this->FanFirstTriangle.end(), triangle) - 1;
    polygon = found - this->FanFirstTriangle.begin();
    k = triangle - *found + 1;
  }
  const vtkIdType first = this->Polys.Offset(polygon);
  ids[0] = this->Polys.Id(first);
  ids[1] = this->Polys.Id(first + k);
  ids[2] = this->Polys.Id(first + k + 1);
}

vtkIdType vtkNPRMeshFaces::GetCellOfTriangle(vtkIdType triangle) const
{
  if (triangle >= this->PolyTriangles)
  {
    const vtkIdType r = triangle - this->PolyTriangles;
    return this->Polys.Count +
      (std::upper_bound(this->StripFirstFace.begin(), this->StripFirstFace.end(), r) - 1 -
        this->StripFirstFace.begin());
  }
  if (this->PolysAreTriangles)
  {
    return triangle;
  }
  return std::upper_bound(this->FanFirstTriangle.begin(), this->FanFirstTriangle.end(), triangle) -
    1 - this->FanFirstTriangle.begin();
}

size_t vtkNPRMeshFaces::GetMemorySize() const
{
  return sizeof(double) * this->CopiedPoints.capacity() +
    sizeof(vtkIdType) * (this->FanFirstTriangle.capacity() + this->StripFirstFace.capacity());
}
