// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// Images out of a render window: PNG files, and vector drawings (SVG, PDF, PostScript).
#ifndef nprWindowImage_h
#define nprWindowImage_h

#include "vtkSmartPointer.h"

#include <string>

class vtkImageData;
class vtkRenderWindow;
class vtkRenderer;

// The window's colour buffer as RGB, read from the back buffer. rerender: render the window
// first; otherwise the image is the frame last rendered.
vtkSmartPointer<vtkImageData> nprReadWindowImage(vtkRenderWindow* window, bool rerender);

// Makes the folders above path that are missing. Throws std::runtime_error
// "PATH: cannot write the PNG: REASON".
void nprWritePNG(vtkImageData* image, const std::string& path);

// Writes the window as a PNG: RGB, or (grey) its first channel as 8-bit grey. It renders the
// window first unless rerender is false, for a caller whose last render drew what it writes (on
// a 5M-triangle model a render of VTK's own takes a second).
void nprWriteWindowPNG(
  vtkRenderWindow* window, const std::string& path, bool grey, bool rerender = true);

// Whether -o PATH names a vector drawing: .svg, .pdf, .ps or .eps, any case
// (vtkNPRDrawingExporter's formats).
bool nprIsDrawingFile(const std::string& path);

// The extensions -o accepts without --orbit, for error messages: ".png, .svg, .pdf, .ps, .eps".
std::string nprOutputExtensions();

// Writes the renderer's lines as a vector drawing (vtkNPRDrawingExporter; the format from the
// extension) in its vtkNPRPass's style, over the window's image unless the style is "drawing"
// or fillFaces asks for the faces as filled regions (in fillColors, FillColorModes).
// Throws std::runtime_error with the exporter's message.
void nprWriteDrawing(
  vtkRenderer* renderer, const std::string& path, bool fillFaces = false, int fillColors = 0);

#endif
