// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNPRFillPainter.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkNPRStrokePainter.h"
#include "vtkNPRVectorFile.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <cairo.h>

#include <algorithm>
#include <cmath>

bool vtkNPRPaintFaces(cairo_t* cr, vtkPolyData* faces, const double* color, vtkDataArray* colors,
  double seam, double height, vtkIdType& painted, std::string& error)
{
  painted = 0;
  vtkCellArray* polys = faces ? faces->GetPolys() : nullptr;
  if (!polys || polys->GetNumberOfCells() == 0)
  {
    return true;
  }
  vtkDataArray* coordinates = faces->GetPointData()->GetArray("ImageCoordinates");
  if (!coordinates || coordinates->GetNumberOfComponents() < 2 ||
    (!color &&
      (!colors || colors->GetNumberOfComponents() < 3 ||
        colors->GetNumberOfTuples() < polys->GetNumberOfCells())))
  {
    error = "the faces lack their ImageCoordinates or their colours";
    return false;
  }
  cairo_save(cr);
  cairo_set_dash(cr, nullptr, 0, 0.0);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  cairo_set_line_width(cr, seam);
  if (color)
  {
    cairo_set_source_rgb(cr, color[0], color[1], color[2]);
  }
  auto iterator = vtk::TakeSmartPointer(polys->NewIterator());
  for (iterator->GoToFirstCell(); !iterator->IsDoneWithTraversal(); iterator->GoToNextCell())
  {
    vtkIdType size;
    const vtkIdType* ids;
    iterator->GetCurrentCell(size, ids);
    if (size < 3)
    {
      continue;
    }
    if (!color)
    {
      const vtkIdType cell = iterator->GetCurrentCellId();
      cairo_set_source_rgb(cr, colors->GetComponent(cell, 0) / 255.0,
        colors->GetComponent(cell, 1) / 255.0, colors->GetComponent(cell, 2) / 255.0);
    }
    vtkNPRTraceStroke(cr, size, ids, coordinates, height);
    cairo_close_path(cr);
    if (seam > 0.0)
    {
      cairo_fill_preserve(cr);
      cairo_stroke(cr);
    }
    else
    {
      cairo_fill(cr);
    }
    ++painted;
  }
  cairo_restore(cr);
  return vtkNPRCairoSucceeded(cr, error);
}

bool vtkNPRPaintPoints(cairo_t* cr, vtkPolyData* points, double scale, double height,
  vtkIdType& painted, std::string& error)
{
  painted = 0;
  vtkCellArray* verts = points ? points->GetVerts() : nullptr;
  if (!verts || verts->GetNumberOfCells() == 0)
  {
    return true;
  }
  const vtkIdType cells = verts->GetNumberOfCells();
  vtkDataArray* coordinates = points->GetPointData()->GetArray("ImageCoordinates");
  vtkDataArray* colors = points->GetCellData()->GetArray("Colors");
  vtkDataArray* sizes = points->GetCellData()->GetArray("PointSizes");
  vtkDataArray* round = points->GetCellData()->GetArray("RoundPoints");
  if (!coordinates || coordinates->GetNumberOfComponents() < 2 || !colors ||
    colors->GetNumberOfComponents() < 3 || colors->GetNumberOfTuples() < cells || !sizes ||
    sizes->GetNumberOfTuples() < cells)
  {
    error = "the points lack their ImageCoordinates, Colors or PointSizes arrays";
    return false;
  }
  cairo_save(cr);
  auto iterator = vtk::TakeSmartPointer(verts->NewIterator());
  vtkIdType cell = 0;
  for (iterator->GoToFirstCell(); !iterator->IsDoneWithTraversal();
       iterator->GoToNextCell(), ++cell)
  {
    vtkIdType size;
    const vtkIdType* ids;
    iterator->GetCurrentCell(size, ids);
    if (size < 1)
    {
      continue;
    }
    const double x = coordinates->GetComponent(ids[0], 0);
    const double y = height - coordinates->GetComponent(ids[0], 1);
    const double half = 0.5 * std::max(0.5, sizes->GetComponent(cell, 0) * scale);
    if (round && round->GetNumberOfTuples() > cell && round->GetComponent(cell, 0) != 0.0)
    {
      cairo_new_sub_path(cr);
      cairo_arc(cr, x, y, half, 0.0, 2.0 * M_PI);
      cairo_close_path(cr);
    }
    else // a path, not cairo_rectangle: every point one <path> element of an SVG file
    {
      cairo_move_to(cr, x - half, y - half);
      cairo_line_to(cr, x + half, y - half);
      cairo_line_to(cr, x + half, y + half);
      cairo_line_to(cr, x - half, y + half);
      cairo_close_path(cr);
    }
    cairo_set_source_rgb(cr, colors->GetComponent(cell, 0) / 255.0,
      colors->GetComponent(cell, 1) / 255.0, colors->GetComponent(cell, 2) / 255.0);
    cairo_fill(cr);
    ++painted;
  }
  cairo_restore(cr);
  return vtkNPRCairoSucceeded(cr, error);
}
