// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// Paints the filled shapes of a vector drawing with Cairo, in the user space of the strokes
// (vtkNPRStrokePainter: one unit a pixel, row 0 at the top): the faces of
// vtkNPRDrawingLines::UpdateFaces() (vtkNPRDrawingExporter's and vtkNPRDrawingSheet's FillFaces)
// and the scene's visible points. Private to NPR::Passes.
#ifndef vtkNPRFillPainter_h
#define vtkNPRFillPainter_h

#include "vtkType.h" // for vtkIdType

#include <string> // for the error message

typedef struct _cairo cairo_t;
class vtkDataArray;
class vtkPolyData;

// Paints the point primitives of vtkNPRDrawingLines::GetVisiblePoints() onto `cr` (user space
// as for the strokes): each vertex cell a filled square of its PointSizes times `scale` pixels
// (at least half a pixel) centred on the point, as OpenGL draws a point, or a disc of that
// diameter where RoundPoints is 1, in its Colors. One path a point. Sets `painted` to how many
// were painted. False, with `error` set, when the points lack ImageCoordinates, Colors or
// PointSizes, or Cairo fails.
bool vtkNPRPaintPoints(cairo_t* cr, vtkPolyData* points, double scale, double height,
  vtkIdType& painted, std::string& error);

// Paints the faces of vtkNPRDrawingLines::GetFaces() onto `cr` (user space as for the strokes) in
// their order, back to front: each polygon filled in `color` (RGB in [0, 1]), or with a null
// `color` in its tuple of `colors` (RGB in [0, 255], one a face), and stroked in the same colour
// with `seam` pixels (0: not stroked), which closes the hairline gaps anti-aliasing leaves
// between neighbouring pieces. One path a polygon. Sets `painted` to how many were painted.
// False, with `error` set, when the faces lack ImageCoordinates, there are too few colours, or
// Cairo fails.
bool vtkNPRPaintFaces(cairo_t* cr, vtkPolyData* faces, const double* color, vtkDataArray* colors,
  double seam, double height, vtkIdType& painted, std::string& error);

#endif
// VTK-HeaderTest-Exclude: vtkNPRFillPainter.h
