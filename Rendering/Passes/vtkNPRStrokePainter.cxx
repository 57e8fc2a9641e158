// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNPRStrokePainter.h"

#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkNPRDrawingLines.h"
#include "vtkNPRDrawingPass.h"
#include "vtkNPREdgePass.h"
#include "vtkNPRPassUtilities.h"
#include "vtkNPRVectorFile.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"

#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace
{
// The vtkNPRFeatureLines::FeatureTypes bits (Lines's header is not needed for a few values).
constexpr unsigned char SilhouetteBit = 1, CreaseBit = 2, BoundaryBit = 4, NonManifoldBit = 8,
                        IntersectionBit = 32, LineBit = 64, MeshEdgeBit = 128;

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
    case LineBit:
    case MeshEdgeBit:
      return NPR_STROKES_LINE;
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
  return type == LineBit ||
    type == MeshEdgeBit; // the scene's own lines, when the strokes have them
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
    case NPR_STROKES_LINE:
      return "npr-line";
    case NPR_STROKES_POINT:
      return "npr-point";
    case NPR_STROKES_TEXT:
      return "npr-text";
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
  style.Scale = scale;
  if (drawing)
  {
    style.TaperLength = drawing->GetTaperLength() * scale;
    style.CurvatureWidth = drawing->GetCurvatureWidth();
  }
  if (edges && edges->GetDepthFalloff())
  {
    style.DepthFalloff = true;
    style.NearScale = edges->GetNearLineScale();
    style.FarScale = edges->GetFarLineScale();
  }
  if (vtkCamera* camera = renderer ? renderer->GetActiveCamera() : nullptr)
  {
    camera->GetClippingRange(style.ClippingRange);
    style.Parallel = camera->GetParallelProjection() != 0;
  }
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

// A line cell's stroke: its actor's colour and line width (at least a hairline).
void SetLinePen(cairo_t* cr, vtkPolyData* strokes, vtkIdType line, const vtkNPRStrokeStyle& style)
{
  const vtkIdType cell = strokes->GetNumberOfVerts() + line;
  vtkDataArray* colors = strokes->GetCellData()->GetArray("Colors");
  vtkDataArray* widths = strokes->GetCellData()->GetArray("LineWidths");
  double rgb[3] = { 0.0, 0.0, 0.0 };
  if (colors && colors->GetNumberOfComponents() >= 3 && cell < colors->GetNumberOfTuples())
  {
    for (int c = 0; c < 3; ++c)
    {
      rgb[c] = colors->GetComponent(cell, c) / 255.0;
    }
  }
  const double width =
    widths && cell < widths->GetNumberOfTuples() ? widths->GetComponent(cell, 0) : 1.0;
  cairo_set_source_rgb(cr, rgb[0], rgb[1], rgb[2]);
  cairo_set_line_width(cr, std::max(0.25, width * style.Scale));
}

}

namespace
{
// A point of a stroke in Cairo's user space, with its depth and its distance along the stroke.
struct StrokePoint
{
  double X, Y, Depth, Along;
};

// The stroke's points, y flipped; with a taper or a width from curvature, long segments cut so
// that the width ramps along the taper and a bend widens the stroke only about it (4 px).
std::vector<StrokePoint> SampleStroke(vtkIdType size, const vtkIdType* ids,
  vtkDataArray* coordinates, double height, const vtkNPRStrokeStyle& style)
{
  std::vector<StrokePoint> points;
  double step = style.TaperLength > 0.0 ? std::max(0.5, style.TaperLength / 8.0) : 1e300;
  step = style.CurvatureWidth > 0.0 ? std::min(step, 4.0) : step;
  for (vtkIdType k = 0; k < size; ++k)
  {
    const StrokePoint p = { coordinates->GetComponent(ids[k], 0),
      height - coordinates->GetComponent(ids[k], 1),
      coordinates->GetNumberOfComponents() > 2 ? coordinates->GetComponent(ids[k], 2) : 0.0, 0.0 };
    if (!points.empty())
    {
      const StrokePoint q = points.back();
      const double length = std::hypot(p.X - q.X, p.Y - q.Y);
      const int pieces = static_cast<int>(std::min(4096.0, std::ceil(length / step)));
      for (int i = 1; i < pieces; ++i)
      {
        const double t = static_cast<double>(i) / pieces;
        points.push_back({ q.X + t * (p.X - q.X), q.Y + t * (p.Y - q.Y),
          q.Depth + t * (p.Depth - q.Depth), q.Along + t * length });
      }
      points.push_back({ p.X, p.Y, p.Depth, q.Along + length });
    }
    else
    {
      points.push_back(p);
    }
  }
  return points;
}

// The width factor of the depth: NearScale at the near clipping plane to FarScale at the far one,
// linear in the distance (window depth z in [0, 1] converted back through the projection).
double DepthScale(double z, const vtkNPRStrokeStyle& style)
{
  const double n = style.ClippingRange[0], f = style.ClippingRange[1];
  double t = z;
  if (!style.Parallel)
  {
    const double ndc = 2.0 * z - 1.0;
    const double distance = 2.0 * f * n / ((f + n) - ndc * (f - n));
    t = (distance - n) / (f - n);
  }
  t = std::clamp(t, 0.0, 1.0);
  return style.NearScale + t * (style.FarScale - style.NearScale);
}

// Each point's width: the class's width times the depth's, the taper's and the bend's factors.
std::vector<double> StrokeWidths(
  const std::vector<StrokePoint>& points, bool closed, double width, const vtkNPRStrokeStyle& style)
{
  const size_t n = points.size();
  const double total = points.back().Along;
  std::vector<double> widths(n, width);
  for (size_t i = 0; i < n; ++i)
  {
    if (style.DepthFalloff)
    {
      widths[i] *= DepthScale(points[i].Depth, style);
    }
    if (style.TaperLength > 0.0 && !closed)
    {
      const double toEnd = std::min(points[i].Along, total - points[i].Along);
      widths[i] *= std::clamp(toEnd / style.TaperLength, 0.0, 1.0);
    }
    const bool inner = closed || (i > 0 && i + 1 < n);
    if (style.CurvatureWidth > 0.0 && inner && n > 2)
    {
      const StrokePoint& a = points[(i + n - 1) % n];
      const StrokePoint& c = points[(i + 1) % n];
      const double ux = points[i].X - a.X, uy = points[i].Y - a.Y;
      const double vx = c.X - points[i].X, vy = c.Y - points[i].Y;
      const double lengths = 0.5 * (std::hypot(ux, uy) + std::hypot(vx, vy));
      const double turn = std::abs(std::atan2(ux * vy - uy * vx, ux * vx + uy * vy));
      const double curvature = lengths > 0.0 ? turn / lengths : 0.0; // per pixel
      widths[i] *= 1.0 + style.CurvatureWidth * std::min(1.0, 8.0 * curvature);
    }
  }
  return widths;
}

// Adds the outline of a stroke of varying width to the path: a disc at each point and a
// quadrilateral between two, all wound alike so that the non-zero rule fills their union.
void TraceOutline(cairo_t* cr, const std::vector<StrokePoint>& points,
  const std::vector<double>& widths, bool closed)
{
  const size_t n = points.size();
  for (size_t i = 0; i < n; ++i)
  {
    const double r = 0.5 * widths[i];
    if (r > 1e-3)
    {
      cairo_new_sub_path(cr);
      cairo_arc(cr, points[i].X, points[i].Y, r, 0.0, 2.0 * M_PI);
      cairo_close_path(cr);
    }
  }
  const size_t segments = closed ? n : n - 1;
  for (size_t i = 0; i < segments; ++i)
  {
    const StrokePoint &a = points[i], &b = points[(i + 1) % n];
    const double length = std::hypot(b.X - a.X, b.Y - a.Y);
    if (!(length > 0.0))
    {
      continue;
    }
    const double nx = (a.Y - b.Y) / length, ny = (b.X - a.X) / length;
    const double ra = 0.5 * widths[i], rb = 0.5 * widths[(i + 1) % n];
    double corners[4][2] = { { a.X + nx * ra, a.Y + ny * ra }, { b.X + nx * rb, b.Y + ny * rb },
      { b.X - nx * rb, b.Y - ny * rb }, { a.X - nx * ra, a.Y - ny * ra } };
    double area = 0.0;
    for (int k = 0; k < 4; ++k)
    {
      area += corners[k][0] * corners[(k + 1) % 4][1] - corners[(k + 1) % 4][0] * corners[k][1];
    }
    if (area < 0.0) // the discs' winding
    {
      std::swap(corners[1], corners[3]);
    }
    cairo_move_to(cr, corners[0][0], corners[0][1]);
    for (int k = 1; k < 4; ++k)
    {
      cairo_line_to(cr, corners[k][0], corners[k][1]);
    }
    cairo_close_path(cr);
  }
}

// One visible stroke of varying width, filled; false for an empty cell.
bool FillStroke(cairo_t* cr, vtkIdType size, const vtkIdType* ids, vtkDataArray* coordinates,
  double height, double width, const vtkNPRStrokeStyle& style)
{
  if (size < 1)
  {
    return false;
  }
  const bool closed = size >= 3 && ids[size - 1] == ids[0];
  std::vector<StrokePoint> loop = SampleStroke(size, ids, coordinates, height, style);
  if (closed)
  {
    loop.pop_back(); // the first point again
  }
  TraceOutline(cr, loop, StrokeWidths(loop, closed, width, style), closed);
  cairo_set_fill_rule(cr, CAIRO_FILL_RULE_WINDING);
  cairo_fill(cr);
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
      if (strokeClass == NPR_STROKES_LINE)
      {
        SetLinePen(cr, strokes, cell, style);
      }
      if (strokeClass != NPR_STROKES_HIDDEN && style.VariableWidth())
      {
        counts[strokeClass] +=
          FillStroke(cr, size, ids, coordinates, height, cairo_get_line_width(cr), style);
      }
      else if (vtkNPRTraceStroke(cr, size, ids, coordinates, height))
      {
        cairo_stroke(cr); // one path per stroke: an SVG <path> each
        ++counts[strokeClass];
      }
    }
  }
  cairo_restore(cr);
  return vtkNPRCairoSucceeded(cr, error);
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

bool vtkNPRTraceStroke(
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
