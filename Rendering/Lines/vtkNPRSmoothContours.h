// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// The smooth contours of a mesh with point normals, which vtkNPRMeshAdjacency keeps per mesh:
// where the facing term g = n . (p - eye) (n . direction in parallel projection), linear over
// each triangle, changes sign. Made only when asked for. Private to NPR::Lines.
//
// Kept per mesh: the triangles (fans of the polygons, the strips' triangles in their winding,
// none with a repeated or out-of-range point) and the unit point normals (NaN where zero or not
// finite). For the last viewpoint: each point's g, and per block of triangles the segments found.
#ifndef vtkNPRSmoothContours_h
#define vtkNPRSmoothContours_h

#include "vtkType.h" // for vtkIdType, vtkMTimeType

#include <cstddef> // for size_t
#include <cstdint> // for the packed arrays
#include <vector>  // for the packed arrays

class vtkDataArray;
class vtkNPRMeshFaces;
class vtkPolyData;

class vtkNPRSmoothContours
{
public:
  // The point normals a smooth contour can use: 3 components, one per point; else nullptr.
  static vtkDataArray* PointNormals(vtkPolyData* input);

  // Empties the tables (a new mesh), freeing their memory.
  void Reset();
  // Bytes held between updates.
  size_t GetMemorySize() const;

  // Facing, Segments and SkippedTriangles for an eye (perspective) or a direction of projection
  // (parallel), from the mesh's point normals (PointNormals).
  void Compute(
    const vtkNPRMeshFaces& mesh, vtkDataArray* normals, bool parallel, const double view[3]);
  struct Segment
  {
    std::uint32_t Triangle;
    unsigned char Rise, Fall; // its edges (0: points 0-1, 1: 1-2, 2: 2-0) where g changes sign
  };
  // Per block of triangles, the segments found, in the triangles' order.
  const std::vector<std::vector<Segment>>& GetSegments() const { return this->Segments; }
  const std::uint32_t* GetTriangle(std::uint32_t t) const
  {
    return this->Triangles.data() + 3 * static_cast<size_t>(t);
  }
  double GetFacing(std::uint32_t point) const { return this->Facing[point]; }
  // The triangles left out of the last Compute() (a point's g not finite), until cleared.
  vtkIdType GetNumberOfSkippedTriangles() const { return this->SkippedTriangles; }
  void ClearSkippedTriangles() { this->SkippedTriangles = 0; }

private:
  // Compute's steps.
  void MakeTables(const vtkNPRMeshFaces& mesh, vtkDataArray* normals);
  void MakeTriangles(const vtkNPRMeshFaces& mesh);
  void ComputeFacing(const vtkNPRMeshFaces& mesh, bool parallel, const double view[3]);
  void FindSegments();

  std::vector<std::uint32_t> Triangles;
  bool TrianglesValid = false;
  vtkDataArray* NormalsArray = nullptr;
  vtkMTimeType NormalsTime = 0;
  std::vector<double> UnitNormals;
  std::vector<double> Facing;
  std::vector<std::vector<Segment>> Segments;
  vtkIdType SkippedTriangles = 0;
};

#endif
// VTK-HeaderTest-Exclude: vtkNPRSmoothContours.h
