// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNPRStrokePainter.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkNPRDrawingLines.h"
#include "vtkNPRDrawingPass.h"
#include "vtkNPREdgePass.h"
#include "vtkNPRPassUtilities.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"

#include <cairo.h>

#include <algorithm>
#include <cstdint>
#include <cstring>

namespace
{
// The vtkNPRFeatureLines::FeatureTypes bits (Lines's header is not needed for four values).
constexpr unsigned char SilhouetteBit = 1, CreaseBit = 2, BoundaryBit = 4, NonManifoldBit = 8,
                        IntersectionBit = 32;

// The class of a visible stroke of this line type; -1 for an unknown type.
int VisibleClass(unsigned char type)
{
  switch (type)
  {
    case SilhouetteBit:
      return NPR_STROKES_SILHOUETTE;
    case CreaseBit:
      return NPR_STROKES_CREASE;
    case BoundaryBit:
      return NPR_STROKES_BOUNDARY;
    case NonManifoldBit:
      return NPR_STROKES_NON_MANIFOLD;
    case IntersectionBit:
      return NPR_STROKES_INTERSECTION;
    default:
      return -1;
  }
}

// Whether the style draws this line type (Silhouettes: silhouettes and boundaries; Creases:
// creases, non-manifold edges and intersection curves).
bool Drawn(const vtkNPRStrokeStyle& style, unsigned char type)
{
  if (type == SilhouetteBit || type == BoundaryBit)
  {
    return style.Silhouettes;
  }
  if (type == CreaseBit || type == NonManifoldBit || type == IntersectionBit)
  {
    return style.Creases;
  }
  return false;
}
}

const char* vtkNPRStrokeClassName(int strokeClass)
{
  switch (strokeClass)
  {
    case NPR_STROKES_HIDDEN:
      return "npr-hidden";
    case NPR_STROKES_SILHOUETTE:
      return "npr-silhouette";
    case NPR_STROKES_BOUNDARY:
      return "npr-boundary";
    case NPR_STROKES_CREASE:
      return "npr-crease";
    case NPR_STROKES_NON_MANIFOLD:
      return "npr-non-manifold";
    case NPR_STROKES_INTERSECTION:
      return "npr-intersection";
    default:
      return "";
  }
}

vtkNPRStrokeStyle vtkNPRMakeStrokeStyle(
  vtkNPRDrawingPass* drawing, vtkNPREdgePass* edges, vtkRenderer* renderer)
{
  vtkNPRStrokeStyle style;
  // Widths and dashes are given at 72 DPI; the image's pixels are the renderer's.
  const double scale = vtkNPRWindowScale(renderer);
  if (edges)
  {
    double widths[4]; // silhouettes, creases, contours, suggestive contours
    edges->GetEffectiveLineWidths(renderer, widths);
    style.LineWidth = widths[0];
    style.CreaseLineWidth = widths[1];
    edges->GetSilhouetteColor(style.SilhouetteColor);
    edges->GetCreaseColor(style.CreaseColor);
    style.Silhouettes = edges->GetSilhouettes();
    style.Creases = edges->GetCreases();
  }
  else
  {
    style.LineWidth = vtkNPREffectiveLineWidth(renderer, 1.5); // the edge pass's default
    style.CreaseLineWidth = style.LineWidth;
  }
  double hiddenWidth = 0.6; // the drawing pass's defaults
  double dash = 6.0, gap = 4.0;
  if (drawing)
  {
    style.HiddenLines = drawing->GetHiddenLines();
    drawing->GetHiddenLineColor(style.HiddenLineColor);
    hiddenWidth = drawing->GetHiddenLineWidth();
    dash = drawing->GetDashLength();
    gap = drawing->GetGapLength();
  }
  style.HiddenLineWidth = hiddenWidth * style.LineWidth;
  style.DashLength = dash * scale;
  style.GapLength = gap * scale;
  return style;
}

void vtkNPRSelectStrokeLines(
  vtkNPRDrawingLines* lines, const vtkNPRStrokeStyle& style, vtkNPREdgePass* edges)
{
  vtkNPRLineSettings* settings = lines->GetLineSettings();
  settings->SetSilhouettes(style.Silhouettes);
  settings->SetBoundaries(style.Silhouettes);
  settings->SetCreases(style.Creases);
  settings->SetNonManifoldEdges(style.Creases);
  if (edges)
  {
    settings->SetCreaseAngle(edges->GetCreaseAngle());
    lines->SetSmoothContours(edges->GetSmoothSilhouettes());
  }
  lines->SetHiddenLines(style.HiddenLines);
}

namespace
{
// The strokes of each class, in their order in the poly data; those the style leaves out in none.
void SortStrokes(vtkPolyData* strokes, vtkDataArray* types, vtkDataArray* hidden,
  const vtkNPRStrokeStyle& style, std::vector<vtkIdType> byClass[NPR_STROKE_CLASSES])
{
  const vtkIdType cells = strokes->GetLines()->GetNumberOfCells();
  // Cells of the Lines array are numbered after the vertices in a vtkPolyData's cell data.
  const vtkIdType firstLine = strokes->GetNumberOfVerts();
  for (vtkIdType cell = 0; cell < cells; ++cell)
  {
    const auto type = static_cast<unsigned char>(types->GetComponent(firstLine + cell, 0));
    if (!Drawn(style, type))
    {
      continue;
    }
    if (hidden->GetComponent(firstLine + cell, 0) != 0.0)
    {
      if (style.HiddenLines)
      {
        byClass[NPR_STROKES_HIDDEN].push_back(cell);
      }
    }
    else if (VisibleClass(type) >= 0)
    {
      byClass[VisibleClass(type)].push_back(cell);
    }
  }
}

// The colour, width and dashes of a class's strokes.
void SetPen(cairo_t* cr, const vtkNPRStrokeStyle& style, int strokeClass)
{
  const double* color = style.SilhouetteColor;
  double width = style.LineWidth;
  if (strokeClass == NPR_STROKES_HIDDEN)
  {
    color = style.HiddenLineColor;
    width = style.HiddenLineWidth;
    const double dashes[2] = { style.DashLength, style.GapLength };
    cairo_set_dash(cr, dashes, 2, 0.0);
  }
  else
  {
    cairo_set_dash(cr, nullptr, 0, 0.0);
    if (strokeClass == NPR_STROKES_CREASE || strokeClass == NPR_STROKES_NON_MANIFOLD ||
      strokeClass == NPR_STROKES_INTERSECTION)
    {
      color = style.CreaseColor;
      width = style.CreaseLineWidth;
    }
  }
  cairo_set_source_rgb(cr, color[0], color[1], color[2]);
  cairo_set_line_width(cr, width);
}

// One stroke's path, through the point ids of a cell, with y flipped; false for an empty cell.
bool TraceStroke(
  cairo_t* cr, vtkIdType size, const vtkIdType* ids, vtkDataArray* coordinates, double height)
{
  if (size < 1)
  {
    return false;
  }
  // A closed loop repeats its first point id last.
  const bool closed = size >= 3 && ids[size - 1] == ids[0];
  const vtkIdType last = closed ? size - 1 : size;
  for (vtkIdType k = 0; k < last; ++k)
  {
    const double x = coordinates->GetComponent(ids[k], 0);
    const double y = height - coordinates->GetComponent(ids[k], 1);
    if (k == 0)
    {
      cairo_move_to(cr, x, y);
    }
    else
    {
      cairo_line_to(cr, x, y);
    }
  }
  if (closed)
  {
    cairo_close_path(cr);
  }
  return true;
}
}

bool vtkNPRPaintStrokes(cairo_t* cr, vtkPolyData* strokes, const vtkNPRStrokeStyle& style,
  double height, vtkNPRStrokeCounts& counts, std::string& error)
{
  counts.fill(0);
  vtkCellArray* lines = strokes ? strokes->GetLines() : nullptr;
  if (!lines || lines->GetNumberOfCells() == 0)
  {
    return true; // nothing to paint: an empty drawing
  }
  vtkDataArray* coordinates = strokes->GetPointData()->GetArray("ImageCoordinates");
  vtkDataArray* types = strokes->GetCellData()->GetArray("FeatureType");
  vtkDataArray* hidden = strokes->GetCellData()->GetArray("Hidden");
  if (!coordinates || coordinates->GetNumberOfComponents() < 2 || !types || !hidden ||
    types->GetNumberOfTuples() < lines->GetNumberOfCells() ||
    hidden->GetNumberOfTuples() < lines->GetNumberOfCells())
  {
    error = "the strokes lack their ImageCoordinates, FeatureType or Hidden arrays";
    return false;
  }
  std::vector<vtkIdType> byClass[NPR_STROKE_CLASSES];
  SortStrokes(strokes, types, hidden, style, byClass);

  cairo_save(cr);
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  auto iterator = vtk::TakeSmartPointer(lines->NewIterator());
  for (int strokeClass = 0; strokeClass < NPR_STROKE_CLASSES; ++strokeClass)
  {
    SetPen(cr, style, strokeClass);
    for (vtkIdType cell : byClass[strokeClass])
    {
      vtkIdType size;
      const vtkIdType* ids;
      iterator->GetCellAtId(cell, size, ids);
      if (TraceStroke(cr, size, ids, coordinates, height))
      {
        cairo_stroke(cr); // one path per stroke: an SVG <path> each
        ++counts[strokeClass];
      }
    }
  }
  cairo_restore(cr);
  if (cairo_status(cr) != CAIRO_STATUS_SUCCESS)
  {
    error = std::string("Cairo: ") + cairo_status_to_string(cairo_status(cr));
    return false;
  }
  return true;
}

bool vtkNPRPaintFaces(cairo_t* cr, vtkPolyData* faces, const double* color, double seam,
  double height, vtkIdType& painted, std::string& error)
{
  painted = 0;
  vtkCellArray* polys = faces ? faces->GetPolys() : nullptr;
  if (!polys || polys->GetNumberOfCells() == 0)
  {
    return true;
  }
  vtkDataArray* coordinates = faces->GetPointData()->GetArray("ImageCoordinates");
  vtkDataArray* colors = faces->GetCellData()->GetArray("Colors");
  if (!coordinates || coordinates->GetNumberOfComponents() < 2 ||
    (!color &&
      (!colors || colors->GetNumberOfComponents() < 3 ||
        colors->GetNumberOfTuples() < polys->GetNumberOfCells())))
  {
    error = "the faces lack their ImageCoordinates or Colors arrays";
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
      const vtkIdType cell =
        faces->GetNumberOfVerts() + faces->GetNumberOfLines() + iterator->GetCurrentCellId();
      cairo_set_source_rgb(cr, colors->GetComponent(cell, 0) / 255.0,
        colors->GetComponent(cell, 1) / 255.0, colors->GetComponent(cell, 2) / 255.0);
    }
    TraceStroke(cr, size, ids, coordinates, height);
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
  if (cairo_status(cr) != CAIRO_STATUS_SUCCESS)
  {
    error = std::string("Cairo: ") + cairo_status_to_string(cairo_status(cr));
    return false;
  }
  return true;
}

bool vtkNPRRasterizeStrokes(vtkPolyData* strokes, const vtkNPRStrokeStyle& style, int width,
  int height, std::vector<unsigned char>& rgba, std::string& error)
{
  if (width <= 0 || height <= 0)
  {
    error = "no image size";
    return false;
  }
  cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, width, height);
  if (cairo_surface_status(surface) != CAIRO_STATUS_SUCCESS)
  {
    error = std::string("Cairo: ") + cairo_status_to_string(cairo_surface_status(surface));
    cairo_surface_destroy(surface);
    return false;
  }
  cairo_t* cr = cairo_create(surface); // a new image surface is transparent
  vtkNPRStrokeCounts counts;
  bool ok = vtkNPRPaintStrokes(cr, strokes, style, height, counts, error);
  cairo_destroy(cr);
  if (ok)
  {
    cairo_surface_flush(surface);
    // ARGB32: one native-endian 32-bit word a pixel, alpha in the high byte, premultiplied; rows
    // `stride` bytes apart, row 0 at the top. The output's row 0 is the bottom.
    const unsigned char* data = cairo_image_surface_get_data(surface);
    const int stride = cairo_image_surface_get_stride(surface);
    rgba.resize(static_cast<size_t>(width) * height * 4);
    for (int j = 0; j < height; ++j)
    {
      const unsigned char* row = data + static_cast<size_t>(height - 1 - j) * stride;
      unsigned char* out = rgba.data() + static_cast<size_t>(j) * width * 4;
      for (int i = 0; i < width; ++i)
      {
        std::uint32_t pixel;
        std::memcpy(&pixel, row + 4 * i, 4);
        out[4 * i + 0] = static_cast<unsigned char>(pixel >> 16);
        out[4 * i + 1] = static_cast<unsigned char>(pixel >> 8);
        out[4 * i + 2] = static_cast<unsigned char>(pixel);
        out[4 * i + 3] = static_cast<unsigned char>(pixel >> 24);
      }
    }
  }
  cairo_surface_destroy(surface);
  return ok;
}
