// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// Paints the strokes of vtkNPRDrawingLines with Cairo: onto an image for vtkNPRDrawingPass, into
// SVG, PDF and PostScript files for vtkNPRDrawingExporter, the same paths for both. Private to
// NPR::RenderingNPR.
#ifndef vtkNPRStrokePainter_h
#define vtkNPRStrokePainter_h

#include <string> // for the error message
#include <vector> // for the image

class vtkNPRDrawingPass;
class vtkNPREdgePass;
class vtkPolyData;
class vtkRenderer;

// How the strokes look, resolved to pixels of the image.
struct vtkNPRStrokeStyle
{
  double SilhouetteColor[3] = { 0.0, 0.0, 0.0 }; // silhouettes and boundaries
  double CreaseColor[3] = { 0.0, 0.0, 0.0 };     // creases and non-manifold edges
  double LineWidth = 1.5;
  bool Silhouettes = true; // silhouettes and boundaries
  bool Creases = true;     // creases and non-manifold edges
  bool HiddenLines = false;
  double HiddenLineColor[3] = { 0.45, 0.45, 0.45 };
  double HiddenLineWidth = 0.9; // pixels
  double DashLength = 6.0;      // pixels
  double GapLength = 4.0;       // pixels
};

// The style a drawing pass and its edge pass give for a renderer (widths and dashes scaled by the
// renderer's DPI / 72 and tile scale). Either pass may be null: defaults for its part.
vtkNPRStrokeStyle vtkNPRMakeStrokeStyle(
  vtkNPRDrawingPass* drawing, vtkNPREdgePass* edges, vtkRenderer* renderer);

// Rasterises the strokes (ImageCoordinates, FeatureType, Hidden) over a transparent image of
// width x height: premultiplied RGBA, 8 bits each, row 0 at the bottom (OpenGL's order).
// False, with `error` set, when Cairo fails.
bool vtkNPRRasterizeStrokes(vtkPolyData* strokes, const vtkNPRStrokeStyle& style, int width,
  int height, std::vector<unsigned char>& rgba, std::string& error);

#endif
// VTK-HeaderTest-Exclude: vtkNPRStrokePainter.h
