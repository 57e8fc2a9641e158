// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// What vtkNPRModelReader keeps of what VTK's reader read: the points with finite coordinates,
// the cells whose points all exist and are finite, and whether what is left spans an area. Each
// step on every core where it walks the points. Private to the module.
#ifndef vtkNPRDrawableSurface_h
#define vtkNPRDrawableSurface_h

#include "vtkType.h"

#include <vector>

class vtkPoints;
class vtkPolyData;

namespace vtkNPRDrawableSurface
{
enum class CellStatus
{
  Drawable,
  NonFinite,  // uses a point with a NaN or infinite coordinate
  OutOfRange, // names a point that does not exist
};

// The number of cells of each status.
struct CellCounts
{
  vtkIdType NonFinite = 0;
  vtkIdType OutOfRange = 0;

  void Add(CellStatus status)
  {
    this->NonFinite += status == CellStatus::NonFinite;
    this->OutOfRange += status == CellStatus::OutOfRange;
  }
};

// The diagonals of the bounds that VTK's float rendering frames: measured with npr-render
// (llvmpipe, a cube at the default camera): 1.7e-20 and 3.5e37 drawn, 1.7e-22 and 8.7e37 blank
// (the camera's distance and clipping range leave float's range).
constexpr double SmallestDrawableDiagonal = 1e-20;
constexpr double LargestDrawableDiagonal = 1e37;

// For every point, its number among the drawable ones (-1: a NaN or infinite coordinate, or
// one beyond float's range, which is infinite once the points reach the GPU); beyondFloat
// counts the finite points dropped for their range.
std::vector<vtkIdType> NumberFinitePoints(
  vtkPoints* points, vtkIdType& finitePoints, vtkIdType& beyondFloat);

// The cells of every kind that use a non-finite point, and those that name a missing one.
CellCounts CountUndrawableCells(vtkPolyData* surface, const std::vector<vtkIdType>& newPointIds);

// The surface without its non-finite points and the cells that use them or name a point that
// does not exist, its point and cell data following.
void CopyDrawable(vtkPolyData* surface, const std::vector<vtkIdType>& newPointIds,
  vtkIdType finitePoints, vtkPolyData* output);

// How many of the three axes the points the cells use span no length along (2: on one line,
// 3: at one spot); diagonal is the length of their bounds' diagonal.
int CountFlatAxes(vtkPolyData* mesh, double& diagonal);

// True when the mesh has only polygons and every one of them has no area (its vertices on one
// line, to 1e-12 of the square of its bounds' diagonal): nothing of it can cover a pixel. Stops at
// the first polygon with an area, so a sound mesh costs one polygon.
bool HasOnlyZeroAreaPolygons(vtkPolyData* mesh);
}

#endif
