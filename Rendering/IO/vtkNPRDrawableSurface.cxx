// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNPRDrawableSurface.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkNPRPointCoordinates.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace
{
using vtkNPRDrawableSurface::CellStatus;

// Whether a cell's points all exist and are finite, given each point's number among the finite
// ones (-1: not finite).
CellStatus Classify(vtkIdType size, const vtkIdType* ids, const std::vector<vtkIdType>& newPointIds)
{
  const vtkIdType numberOfPoints = static_cast<vtkIdType>(newPointIds.size());
  CellStatus status = CellStatus::Drawable;
  for (vtkIdType k = 0; k < size; ++k)
  {
    if (ids[k] < 0 || ids[k] >= numberOfPoints)
    {
      return CellStatus::OutOfRange;
    }
    status = newPointIds[static_cast<size_t>(ids[k])] < 0 ? CellStatus::NonFinite : status;
  }
  return status;
}

// Copies the drawable cells of one kind, renumbering their points, with their cell data.
void CopyDrawableCells(vtkCellArray* cells, const std::vector<vtkIdType>& newPointIds,
  vtkIdType& inputCellId, vtkCellData* inputData, vtkCellData* outputData, vtkCellArray* kept)
{
  vtkIdType size = 0;
  const vtkIdType* ids = nullptr;
  std::vector<vtkIdType> renumbered;
  for (cells->InitTraversal(); cells->GetNextCell(size, ids); ++inputCellId)
  {
    if (Classify(size, ids, newPointIds) != CellStatus::Drawable)
    {
      continue;
    }
    renumbered.resize(static_cast<size_t>(size));
    for (vtkIdType k = 0; k < size; ++k)
    {
      renumbered[static_cast<size_t>(k)] = newPointIds[static_cast<size_t>(ids[k])];
    }
    kept->InsertNextCell(size, renumbered.data());
    outputData->CopyData(inputData, inputCellId, outputData->GetNumberOfTuples());
  }
}

}

vtkNPRDrawableSurface::CellCounts vtkNPRDrawableSurface::CountUndrawableCells(
  vtkPolyData* surface, const std::vector<vtkIdType>& newPointIds)
{
  CellCounts counts;
  for (vtkCellArray* cells :
    { surface->GetVerts(), surface->GetLines(), surface->GetPolys(), surface->GetStrips() })
  {
    vtkIdType size = 0;
    const vtkIdType* ids = nullptr;
    for (cells->InitTraversal(); cells->GetNextCell(size, ids);)
    {
      counts.Add(Classify(size, ids, newPointIds));
    }
  }
  return counts;
}

// For every point, its number among the finite ones (-1: a NaN or infinite coordinate); the
// test on every core.
std::vector<vtkIdType> vtkNPRDrawableSurface::NumberFinitePoints(
  vtkPoints* points, vtkIdType& finitePoints, vtkIdType& beyondFloat)
{
  const vtkIdType count = points->GetNumberOfPoints();
  // 1: drawable, 0: NaN or infinite, 2: finite but beyond float's range.
  std::vector<unsigned char> finite(static_cast<size_t>(count));
  const vtkNPRPointCoordinates data(points->GetData());
  vtkSMPTools::For(0, count,
    [&](vtkIdType begin, vtkIdType end)
    {
      double p[3];
      for (vtkIdType i = begin; i < end; ++i)
      {
        data.Get(i, p);
        const bool isFinite = std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
        const double largest = std::max({ std::abs(p[0]), std::abs(p[1]), std::abs(p[2]) });
        finite[static_cast<size_t>(i)] = !isFinite       ? 0
          : largest <= std::numeric_limits<float>::max() ? 1
                                                         : 2;
      }
    });
  std::vector<vtkIdType> newPointIds(static_cast<size_t>(count), -1);
  finitePoints = 0;
  beyondFloat = 0;
  for (size_t i = 0; i < finite.size(); ++i)
  {
    newPointIds[i] = finite[i] == 1 ? finitePoints++ : -1;
    beyondFloat += finite[i] == 2;
  }
  return newPointIds;
}

// The surface without its non-finite points and the cells that use them or name a point that
// does not exist, its point and cell data following.
void vtkNPRDrawableSurface::CopyDrawable(vtkPolyData* surface,
  const std::vector<vtkIdType>& newPointIds, vtkIdType finitePoints, vtkPolyData* output)
{
  vtkPoints* points = surface->GetPoints();
  vtkNew<vtkPoints> keptPoints;
  keptPoints->SetDataType(points->GetDataType());
  keptPoints->SetNumberOfPoints(finitePoints);
  output->GetPointData()->CopyAllocate(surface->GetPointData(), finitePoints);
  for (size_t i = 0; i < newPointIds.size(); ++i)
  {
    if (newPointIds[i] >= 0)
    {
      keptPoints->SetPoint(newPointIds[i], points->GetPoint(static_cast<vtkIdType>(i)));
      output->GetPointData()->CopyData(
        surface->GetPointData(), static_cast<vtkIdType>(i), newPointIds[i]);
    }
  }
  output->SetPoints(keptPoints);
  output->GetCellData()->CopyAllocate(surface->GetCellData(), surface->GetNumberOfCells());
  // vtkPolyData numbers its cells vertices first, then lines, polygons, strips.
  vtkIdType inputCellId = 0;
  vtkNew<vtkCellArray> verts, lines, polys, strips;
  CopyDrawableCells(surface->GetVerts(), newPointIds, inputCellId, surface->GetCellData(),
    output->GetCellData(), verts);
  CopyDrawableCells(surface->GetLines(), newPointIds, inputCellId, surface->GetCellData(),
    output->GetCellData(), lines);
  CopyDrawableCells(surface->GetPolys(), newPointIds, inputCellId, surface->GetCellData(),
    output->GetCellData(), polys);
  CopyDrawableCells(surface->GetStrips(), newPointIds, inputCellId, surface->GetCellData(),
    output->GetCellData(), strips);
  output->SetVerts(verts);
  output->SetLines(lines);
  output->SetPolys(polys);
  output->SetStrips(strips);
}

// How many of the three axes the points the cells use span no length along (2: on one line,
// 3: at one spot): the points marked, then their bounds on every core.
int vtkNPRDrawableSurface::CountFlatAxes(vtkPolyData* mesh, double& diagonal)
{
  std::vector<unsigned char> used(static_cast<size_t>(mesh->GetNumberOfPoints()), 0);
  for (vtkCellArray* cells :
    { mesh->GetVerts(), mesh->GetLines(), mesh->GetPolys(), mesh->GetStrips() })
  {
    vtkIdType size = 0;
    const vtkIdType* ids = nullptr;
    for (cells->InitTraversal(); cells->GetNextCell(size, ids);)
    {
      for (vtkIdType k = 0; k < size; ++k)
      {
        used[static_cast<size_t>(ids[k])] = 1;
      }
    }
  }
  using Bounds = std::array<double, 6>;
  vtkSMPThreadLocal<Bounds> local(Bounds{ VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX, VTK_DOUBLE_MAX,
    -VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX });
  const vtkNPRPointCoordinates data(mesh->GetPoints()->GetData());
  vtkSMPTools::For(0, mesh->GetNumberOfPoints(),
    [&](vtkIdType begin, vtkIdType end)
    {
      Bounds& bounds = local.Local();
      double p[3];
      for (vtkIdType i = begin; i < end; ++i)
      {
        if (used[static_cast<size_t>(i)])
        {
          data.Get(i, p);
          for (int axis = 0; axis < 3; ++axis)
          {
            bounds[2 * axis] = std::min(bounds[2 * axis], p[axis]);
            bounds[2 * axis + 1] = std::max(bounds[2 * axis + 1], p[axis]);
          }
        }
      }
    });
  Bounds all{ VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX, VTK_DOUBLE_MAX,
    -VTK_DOUBLE_MAX };
  for (const Bounds& bounds : local)
  {
    for (int axis = 0; axis < 3; ++axis)
    {
      all[2 * axis] = std::min(all[2 * axis], bounds[2 * axis]);
      all[2 * axis + 1] = std::max(all[2 * axis + 1], bounds[2 * axis + 1]);
    }
  }
  int flatAxes = 0;
  diagonal = 0.0;
  for (int axis = 0; axis < 3; ++axis)
  {
    const double side = all[2 * axis + 1] - all[2 * axis];
    flatAxes += !(side > 0.0);
    diagonal += side > 0.0 ? side * side : 0.0;
  }
  diagonal = std::sqrt(diagonal);
  return flatAxes;
}

bool vtkNPRDrawableSurface::HasOnlyZeroAreaPolygons(vtkPolyData* mesh)
{
  if (mesh->GetNumberOfVerts() || mesh->GetNumberOfLines() || mesh->GetNumberOfStrips() ||
    !mesh->GetNumberOfPolys())
  {
    return false;
  }
  const double diagonal2 = mesh->GetLength() * mesh->GetLength();
  const vtkNPRPointCoordinates data(mesh->GetPoints()->GetData());
  vtkCellArray* polys = mesh->GetPolys();
  vtkIdType size = 0;
  const vtkIdType* ids = nullptr;
  for (polys->InitTraversal(); polys->GetNextCell(size, ids);)
  {
    // Twice the area vector (Newell), from the first vertex.
    double first[3], a[3], b[3], area[3] = { 0.0, 0.0, 0.0 };
    if (size < 3)
    {
      continue;
    }
    data.Get(ids[0], first);
    data.Get(ids[1], a);
    for (vtkIdType k = 2; k < size; ++k)
    {
      data.Get(ids[k], b);
      const double u[3] = { a[0] - first[0], a[1] - first[1], a[2] - first[2] };
      const double v[3] = { b[0] - first[0], b[1] - first[1], b[2] - first[2] };
      area[0] += u[1] * v[2] - u[2] * v[1];
      area[1] += u[2] * v[0] - u[0] * v[2];
      area[2] += u[0] * v[1] - u[1] * v[0];
      std::copy_n(b, 3, a);
    }
    if (std::sqrt(area[0] * area[0] + area[1] * area[1] + area[2] * area[2]) > 1e-12 * diagonal2)
    {
      return false;
    }
  }
  return true;
}
