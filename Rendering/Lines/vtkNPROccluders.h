// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// The triangles of a scene in double precision, and whether a segment passes through one of them:
// the visibility test of vtkNPRReferenceMask. Private to NPR::FiltersNPR.
#ifndef vtkNPROccluders_h
#define vtkNPROccluders_h

#include "vtkCellArray.h"         // for vtkNPRForEachTriangle
#include "vtkCellArrayIterator.h" // for vtkNPRForEachTriangle
#include "vtkPolyData.h"          // for vtkNPRForEachTriangle
#include "vtkSmartPointer.h"      // for the groups
#include "vtkType.h"              // for vtkIdType, vtkMTimeType

#include <array>  // for the matrices
#include <vector> // for the groups

class vtkActor;
class vtkIdList;
class vtkIdTypeArray;
class vtkPolyData;
class vtkStaticCellLocator;

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

// Calls add(a, b, c) with the point ids of each triangle of the mesh: its polygons as fans (as
// the OpenGL mapper draws convex polygons), its strips' triangles in the strip's winding. The ids
// are the cells' as they are: the caller checks their range.
template <typename Add>
void vtkNPRForEachTriangle(vtkPolyData* mesh, Add&& add)
{
  auto iterator = vtk::TakeSmartPointer(mesh->GetPolys()->NewIterator());
  for (iterator->GoToFirstCell(); !iterator->IsDoneWithTraversal(); iterator->GoToNextCell())
  {
    vtkIdType size;
    const vtkIdType* ids;
    iterator->GetCurrentCell(size, ids);
    for (vtkIdType k = 1; k + 1 < size; ++k)
    {
      add(ids[0], ids[k], ids[k + 1]);
    }
  }
  iterator = vtk::TakeSmartPointer(mesh->GetStrips()->NewIterator());
  for (iterator->GoToFirstCell(); !iterator->IsDoneWithTraversal(); iterator->GoToNextCell())
  {
    vtkIdType size;
    const vtkIdType* ids;
    iterator->GetCurrentCell(size, ids);
    for (vtkIdType k = 0; k + 2 < size; ++k)
    {
      add(ids[k + (k & 1)], ids[k + 1 - (k & 1)], ids[k + 2]);
    }
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
  // Every triangle of the meshes, in world coordinates normalised to the scene (so that the
  // tests keep their precision far from the origin and at any scale), in Morton-ordered groups
  // of `trianglesPerLocator` triangles with a locator each.
  void Build(const std::vector<vtkNPRMeshInstance>& actors, int trianglesPerLocator);

  // Whether a triangle crosses the segment between two world points, ends and edges included.
  // `candidates` is scratch space, reused between calls. The triangles with a corner at the
  // coordinates of one of the `ignoredCount` scene points `ignored` do not count (a smooth
  // contour's own triangle and its neighbours); a scene point's id is its mesh's id plus the
  // points of the meshes before it in Build's list.
  bool Hidden(const double from[3], const double to[3], vtkIdList* candidates,
    const vtkIdType* ignored = nullptr, int ignoredCount = 0) const;

  // Where two triangles that share no corner (by coordinates) cross each other: the segment
  // in world coordinates and the angle between their planes (degrees, 0 to 90). Computed on the
  // first call after Build(), then kept.
  struct Crossing
  {
    double A[3], B[3];
    double Angle;
  };
  const std::vector<Crossing>& GetCrossings();

private:
  std::vector<Crossing> Crossings;
  bool CrossingsValid = false;
  double FrameCenter[3] = { 0.0, 0.0, 0.0 }; // the locators' frame: (world - centre) x scale
  double FrameScale = 1.0;
  std::vector<double> Points; // every scene point in that frame, for the ignored points
  // vtkStaticCellLocator, not vtkCellLocator: VTK 9.1's vtkCellLocator::IntersectWithLine
  // misses some triangles (rays through a cube's faces at 2 of 297 points in a test). The
  // static locator clears a flag per cell on every ray (O(cells) per ray), hence the groups.
  // Only its candidates along a ray are used (FindCellsAlongLine), not its IntersectWithLine:
  // since VTK 9.2 that keeps a hit only within the given tolerance of the bin being walked, and
  // with none it loses hits on faces that lie on a bin's side (a cube's) rounded just outside.
  struct Group
  {
    vtkSmartPointer<vtkPolyData> Triangles;
    vtkSmartPointer<vtkStaticCellLocator> Locator;
    vtkSmartPointer<vtkIdTypeArray> Corners; // the triangles' point ids, 3 each
    const double* Coordinates;               // Triangles' points, x y z each
    double Bounds[6];
  };
  std::vector<Group> Groups;
};

#endif
// VTK-HeaderTest-Exclude: vtkNPROccluders.h
