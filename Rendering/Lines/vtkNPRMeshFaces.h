// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// A mesh's points and faces read where the vtkPolyData stores them, without copying them: the
// numbering of faces, edge uses and triangles that vtkNPRMeshAdjacency and vtkNPROccluders index
// by, so that a 20M-triangle mesh costs them no second copy of its points or cells. Valid while
// the mesh's points and cells are unchanged. Private to NPR::Lines.
#ifndef vtkNPRMeshFaces_h
#define vtkNPRMeshFaces_h

#include "vtkType.h" // for vtkIdType, vtkTypeInt32, vtkTypeInt64

#include <algorithm>   // for std::upper_bound
#include <cstddef>     // for size_t
#include <type_traits> // for std::is_same
#include <vector>      // for the prefix tables

class vtkCellArray;
class vtkPolyData;

class vtkNPRMeshFaces
{
public:
  vtkNPRMeshFaces() = default;
  // Not copied: the points may be held here (CopiedPoints) and pointed to.
  vtkNPRMeshFaces(const vtkNPRMeshFaces&) = delete;
  vtkNPRMeshFaces& operator=(const vtkNPRMeshFaces&) = delete;
  vtkNPRMeshFaces(vtkNPRMeshFaces&&) = default;
  vtkNPRMeshFaces& operator=(vtkNPRMeshFaces&&) = default;

  // Reads `mesh` as it is now (nullptr: an empty mesh).
  void Set(vtkPolyData* mesh);

  vtkIdType GetNumberOfPoints() const { return this->NumberOfPoints; }
  // Point `id` in double precision (float coordinates convert exactly).
  void GetPoint(vtkIdType id, double x[3]) const
  {
    if (this->FloatPoints)
    {
      const float* p = this->FloatPoints + 3 * id;
      x[0] = p[0];
      x[1] = p[1];
      x[2] = p[2];
      return;
    }
    const double* p = this->DoublePoints + 3 * id;
    x[0] = p[0];
    x[1] = p[1];
    x[2] = p[2];
  }

  // Faces: the polygons, then the triangles of the strips (triangle k of a strip is its points
  // k, k+1, k+2, every other one reversed to keep the winding).
  vtkIdType GetNumberOfFaces() const { return this->Polys.Count + this->StripTriangles; }
  vtkIdType GetFaceSize(vtkIdType face) const
  {
    return face < this->Polys.Count ? this->Polys.Offset(face + 1) - this->Polys.Offset(face) : 3;
  }
  // Calls visit(size, ids) with the face's point ids in its winding order.
  template <typename Visit>
  void VisitFace(vtkIdType face, Visit&& visit) const;

  // The uses of the faces' edges: use GetFirstUse(f) + i is face f's edge from its point i to
  // point i + 1 (the last to the first). Uses increase with the face, then with i.
  vtkIdType GetNumberOfUses() const { return this->Polys.Size() + 3 * this->StripTriangles; }
  vtkIdType GetFirstUse(vtkIdType face) const
  {
    return face < this->Polys.Count ? this->Polys.Offset(face)
                                    : this->Polys.Size() + 3 * (face - this->Polys.Count);
  }
  vtkIdType GetFaceOfUse(vtkIdType use) const;

  // Triangles: the polygons as fans (points 0, k, k + 1), then the strips' triangles.
  vtkIdType GetNumberOfTriangles() const { return this->PolyTriangles + this->StripTriangles; }
  void GetTriangle(vtkIdType triangle, vtkIdType ids[3]) const;
  // The cell a triangle is part of, counted over the polygons, then the strips (add the mesh's
  // vertices and lines for its vtkPolyData cell id).
  vtkIdType GetCellOfTriangle(vtkIdType triangle) const;

  // Bytes of the tables made by Set() (none for a mesh of triangles with float or double points).
  size_t GetMemorySize() const;

private:
  // A cell array's offsets and connectivity, in 32- or 64-bit storage.
  struct Cells
  {
    const vtkTypeInt32* Offsets32 = nullptr;
    const vtkTypeInt32* Connectivity32 = nullptr;
    const vtkTypeInt64* Offsets64 = nullptr;
    const vtkTypeInt64* Connectivity64 = nullptr;
    vtkIdType Count = 0;
    void Set(vtkCellArray* cells);
    vtkIdType Offset(vtkIdType i) const
    {
      return this->Offsets64 ? this->Offsets64[i] : this->Offsets32[i];
    }
    vtkIdType Id(vtkIdType i) const
    {
      return this->Connectivity64 ? this->Connectivity64[i] : this->Connectivity32[i];
    }
    vtkIdType Size() const { return this->Count > 0 ? this->Offset(this->Count) : 0; }
  };
  // The strip and the triangle of it that is strip triangle `r` (counted over all strips).
  void GetStripTriangle(vtkIdType r, vtkIdType ids[3]) const;

  vtkIdType NumberOfPoints = 0;
  const float* FloatPoints = nullptr;
  const double* DoublePoints = nullptr;
  std::vector<double> CopiedPoints; // points of another type, converted
  Cells Polys, Strips;
  bool PolysAreTriangles = true;           // every polygon has three points
  vtkIdType PolyTriangles = 0;             // triangles of the polygons' fans
  vtkIdType StripTriangles = 0;            // triangles of the strips
  std::vector<vtkIdType> FanFirstTriangle; // per polygon and one more, unless all are triangles
  std::vector<vtkIdType> StripFirstFace;   // per strip and one more: its first strip triangle
};

template <typename Visit>
void vtkNPRMeshFaces::VisitFace(vtkIdType face, Visit&& visit) const
{
  if (face >= this->Polys.Count)
  {
    vtkIdType ids[3];
    this->GetStripTriangle(face - this->Polys.Count, ids);
    visit(static_cast<vtkIdType>(3), static_cast<const vtkIdType*>(ids));
    return;
  }
  const vtkIdType first = this->Polys.Offset(face);
  const vtkIdType size = this->Polys.Offset(face + 1) - first;
  if (this->Polys.Connectivity64 && std::is_same<vtkTypeInt64, vtkIdType>::value)
  {
    visit(size, reinterpret_cast<const vtkIdType*>(this->Polys.Connectivity64 + first));
    return;
  }
  vtkIdType small[16];
  std::vector<vtkIdType> large(size > 16 ? size : 0);
  vtkIdType* ids = size > 16 ? large.data() : small;
  for (vtkIdType i = 0; i < size; ++i)
  {
    ids[i] = this->Polys.Id(first + i);
  }
  visit(size, static_cast<const vtkIdType*>(ids));
}

#endif
// VTK-HeaderTest-Exclude: vtkNPRMeshFaces.h
