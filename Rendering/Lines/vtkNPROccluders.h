// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// The triangles of a scene in double precision, and whether a segment passes through one of them:
// the visibility test of vtkNPRReferenceMask. Private to NPR::Lines.
#ifndef vtkNPROccluders_h
#define vtkNPROccluders_h

#include "vtkNPRMeshFaces.h" // for the meshes' triangles
#include "vtkType.h"         // for vtkIdType, vtkMTimeType

#include <array>   // for the matrices
#include <cstddef> // for size_t
#include <cstdint> // for the hierarchy
#include <vector>  // for the hierarchy

class vtkActor;
class vtkPolyData;

// x' = M x for a point (w = 1), divided by the result's w.
inline void vtkNPRTransformPoint(const double m[16], const double x[3], double out[3])
{
  double h[4];
  for (int r = 0; r < 4; ++r)
  {
    h[r] = m[4 * r] * x[0] + m[4 * r + 1] * x[1] + m[4 * r + 2] * x[2] + m[4 * r + 3];
  }
  for (int r = 0; r < 3; ++r)
  {
    out[r] = h[r] / h[3];
  }
}

// What an actor contributes: its mesh and matrix, as drawn now.
struct vtkNPRMeshInstance
{
  vtkActor* Actor;
  vtkPolyData* Mesh;
  vtkMTimeType MeshTime;
  std::array<double, 16> Matrix;
  bool operator==(const vtkNPRMeshInstance& other) const
  {
    return this->Actor == other.Actor && this->Mesh == other.Mesh &&
      this->MeshTime == other.MeshTime && this->Matrix == other.Matrix;
  }
};

class vtkNPROccluders
{
public:
  // Every triangle of the meshes (polygons as fans, strips' triangles), in world coordinates
  // normalised to the scene (so that the tests keep their precision far from the origin and at
  // any scale), in a bounding volume hierarchy over the triangles in Morton order of their
  // centroids, split first at every `trianglesPerGroup` triangles (speed only). The meshes'
  // points and cells are read where they are: keep them unchanged until the next Build(). At
  // most 2^32 - 1 triangles and points in all (32-bit indices).
  void Build(const std::vector<vtkNPRMeshInstance>& actors, int trianglesPerGroup);

  // Whether a triangle crosses the segment between two world points, ends and edges included.
  // With the `ignoredCount` scene points `ignored` (a smooth contour's triangle), the triangles
  // with a corner at the coordinates of one of them, or closer to `to` than the longest edge
  // between them, do not count (the contour's own surface about it); a scene point's id is its
  // mesh's id plus the points of the meshes before it in Build's list. Safe to call from
  // several threads.
  bool Hidden(const double from[3], const double to[3], const vtkIdType* ignored = nullptr,
    int ignoredCount = 0) const;

  // Where two triangles that share no corner (by coordinates) cross each other: the segment
  // in world coordinates and the angle between their planes (degrees, 0 to 90). Computed on the
  // first call after Build(), then kept.
  struct Crossing
  {
    double A[3], B[3];
    double Angle;
  };
  const std::vector<Crossing>& GetCrossings();

  // Bytes held: the hierarchy, the triangles' corners and the points in the frame (about 32 a
  // triangle), and the meshes' tables (none for triangles with float or double points).
  size_t GetMemorySize() const;

private:
  // A node of the hierarchy, in depth-first order (an inner node's first child follows it): its
  // box in the frame, rounded outwards to float, and either its second child (Count 0) or its
  // Count triangles from Index in the leaf order.
  struct Node
  {
    float Low[3], High[3];
    std::uint32_t Index;
    std::uint32_t Count;
  };
  struct Mesh
  {
    vtkNPRMeshFaces Faces;
    std::array<double, 16> Matrix;
    vtkIdType FirstTriangle, FirstPoint; // in the scene's numbering
  };
  // Build steps.
  void SetMeshes(const std::vector<vtkNPRMeshInstance>& actors);
  std::vector<double> WorldPoints() const;
  size_t SortTriangles(std::vector<double>& points);
  void FindFrame(std::vector<double>& points, std::vector<std::uint64_t>& keys);
  void GatherPoints(std::vector<double>& points);
  std::uint32_t AddNodes(std::uint32_t first, std::uint32_t last, std::uint32_t group);
  void BoundNodes();
  // A mesh's point in the frame (as the build makes it); a scene triangle's corners as scene
  // point ids, false where one names no point.
  void FramePoint(const Mesh& mesh, vtkIdType id, double x[3]) const;
  bool SceneTriangle(vtkIdType triangle, vtkIdType ids[3]) const;
  std::uint64_t MortonCode(const double x[3]) const; // in the frame's box, 10 bits an axis
  // The corners of the triangle at `position` in the leaf order.
  void Corners(std::uint32_t position, const double* corners[3]) const
  {
    for (int k = 0; k < 3; ++k)
    {
      corners[k] = this->Points.data() + 3 * static_cast<size_t>(this->Triangles[3 * position + k]);
    }
  }
  bool SegmentHitsNode(const Node& node, const double from[3], const double to[3]) const;
  void CrossingsOf(std::uint32_t position, std::vector<Crossing>& found) const;

  std::vector<Mesh> Meshes;
  std::vector<vtkIdType> MeshFirstTriangles; // each mesh's first scene triangle
  std::vector<Node> Nodes;
  // The triangles in the leaf order, three indices into Points each; Points, the frame
  // coordinates of the scene's finite points in their Morton order (so that a leaf's corners
  // lie together in memory), as the frame's arithmetic makes them from the meshes.
  std::vector<std::uint32_t> Triangles;
  std::vector<double> Points;
  std::vector<Crossing> Crossings;
  bool CrossingsValid = false;
  double FrameCenter[3] = { 0.0, 0.0, 0.0 }; // the frame: (world - centre) x scale
  double FrameScale = 1.0;
  double FrameLow[3] = { 0.0, 0.0, 0.0 }; // the kept triangles' box, in the frame
  double FrameHigh[3] = { 0.0, 0.0, 0.0 };
};

#endif
// VTK-HeaderTest-Exclude: vtkNPROccluders.h
