// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// Paints the strokes of vtkNPRDrawingLines with Cairo: onto an image for vtkNPRDrawingPass, into
// SVG, PDF and PostScript files for vtkNPRDrawingExporter, the same paths for both. Private to
// NPR::Passes.
#ifndef vtkNPRStrokePainter_h
#define vtkNPRStrokePainter_h

#include "vtkType.h" // for vtkIdType

#include <array>  // for the counts
#include <string> // for the error message
#include <vector> // for the image

typedef struct _cairo cairo_t;
class vtkDataArray;
class vtkNPRDrawingLines;
class vtkNPRDrawingPass;
class vtkNPREdgePass;
class vtkPolyData;
class vtkRenderer;

// How the strokes look, resolved to pixels of the image.
struct vtkNPRStrokeStyle
{
  double SilhouetteColor[3] = { 0.0, 0.0, 0.0 }; // silhouettes and boundaries
  double CreaseColor[3] = { 0.0, 0.0, 0.0 };     // creases, non-manifold edges, intersections
  double LineWidth = 1.5;                        // silhouettes and boundaries, pixels
  double CreaseLineWidth = 1.5;                  // creases, non-manifold edges, intersections
  bool Silhouettes = true;                       // silhouettes and boundaries
  bool Creases = true;                           // creases, non-manifold edges, intersections
  bool HiddenLines = false;
  double HiddenLineColor[3] = { 0.45, 0.45, 0.45 };
  double HiddenLineWidth = 0.9; // pixels
  double DashLength = 6.0;      // pixels
  double GapLength = 4.0;       // pixels
  double Scale = 1.0;           // pixels a point at 72 DPI: a line cell's LineWidths
  // The visible strokes' width along them (vtkNPRDrawingPass's TaperLength and CurvatureWidth,
  // vtkNPREdgePass's DepthFalloff): a factor from the distance to an open end, the bend and the
  // depth (between the clipping planes ClippingRange of a parallel or perspective camera).
  double TaperLength = 0.0; // pixels; 0: none
  double CurvatureWidth = 0.0;
  bool DepthFalloff = false;
  double NearScale = 1.5, FarScale = 0.5;
  double ClippingRange[2] = { 0.1, 1000.0 };
  bool Parallel = false;
  bool VariableWidth() const
  {
    return this->TaperLength > 0.0 || this->CurvatureWidth > 0.0 || this->DepthFalloff;
  }
};

// The style a drawing pass and its edge pass give for a renderer (widths and dashes scaled by the
// renderer's DPI / 72 and tile scale). Either pass may be null: defaults for its part.
vtkNPRStrokeStyle vtkNPRMakeStrokeStyle(
  vtkNPRDrawingPass* drawing, vtkNPREdgePass* edges, vtkRenderer* renderer);

// Asks `lines` for the strokes `style` draws: its Silhouettes as silhouettes and boundaries, its
// Creases as creases, non-manifold edges and intersection curves, its HiddenLines; with an edge
// pass, its crease angle and, with its SmoothSilhouettes, silhouettes as smooth contours.
void vtkNPRSelectStrokeLines(
  vtkNPRDrawingLines* lines, const vtkNPRStrokeStyle& style, vtkNPREdgePass* edges);

// Adds one stroke's path to `cr`: through the ImageCoordinates of the point ids of a cell, y
// flipped (`height` - y), closed where the last id is the first (a loop). False for an empty cell.
bool vtkNPRTraceStroke(
  cairo_t* cr, vtkIdType size, const vtkIdType* ids, vtkDataArray* coordinates, double height);

// Rasterises the strokes (ImageCoordinates, FeatureType, Hidden) over a transparent image of
// width x height: premultiplied RGBA, 8 bits each, row 0 at the bottom (OpenGL's order).
// False, with `error` set, when Cairo fails.
bool vtkNPRRasterizeStrokes(vtkPolyData* strokes, const vtkNPRStrokeStyle& style, int width,
  int height, std::vector<unsigned char>& rgba, std::string& error);

// The classes of strokes, in the order they are painted (hidden ones first, under the visible
// ones): the groups of an SVG file, class="npr-hidden", "npr-silhouette", ...
enum vtkNPRStrokeClass
{
  NPR_STROKES_HIDDEN = 0,
  NPR_STROKES_SILHOUETTE,   // visible silhouettes
  NPR_STROKES_BOUNDARY,     // visible boundary edges
  NPR_STROKES_CREASE,       // visible creases
  NPR_STROKES_NON_MANIFOLD, // visible non-manifold edges
  NPR_STROKES_INTERSECTION, // visible curves where surfaces cross
  NPR_STROKES_LINE,         // visible line cells of the scene, each in its actor's colour and width
  NPR_STROKES_POINT,        // visible point primitives of the scene (vtkNPRPaintPoints)
  NPR_STROKES_TEXT,         // the 2D text over the scene, as glyph outlines (vtkNPROverlays)
  NPR_STROKE_CLASSES
};
// "npr-hidden", "npr-silhouette", "npr-boundary", "npr-crease", "npr-non-manifold",
// "npr-intersection", "npr-line", "npr-point", "npr-text".
const char* vtkNPRStrokeClassName(int strokeClass);

// How many strokes of each class were painted.
using vtkNPRStrokeCounts = std::array<vtkIdType, NPR_STROKE_CLASSES>;

// Paints the strokes onto `cr`, whose user space is the image's: one unit a pixel, the image
// `height` pixels high with row 0 at the top (ImageCoordinates' y is flipped here). One path a
// stroke (move_to, line_to through its points, close_path for a closed loop), one cairo_stroke
// each: round caps and joins; hidden strokes first, dashed (the pattern running on along the
// stroke), then the visible ones class by class (vtkNPRStrokeClass); with a VariableWidth style,
// each visible stroke is one filled outline of its width point by point (a disc at each point and
// a quadrilateral between two, filled as their union). Strokes of a line type the style leaves
// out are skipped. Counts what it painted. False, with `error` set, when the strokes
// lack ImageCoordinates, FeatureType or Hidden, or Cairo fails.
bool vtkNPRPaintStrokes(cairo_t* cr, vtkPolyData* strokes, const vtkNPRStrokeStyle& style,
  double height, vtkNPRStrokeCounts& counts, std::string& error);

#endif
// VTK-HeaderTest-Exclude: vtkNPRStrokePainter.h
