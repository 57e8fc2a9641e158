// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// What vtkNPRDrawingExporter and vtkNPRDrawingSheet share to write a vector file: the path
// checked before any work, a Cairo surface of the format that paints into memory, and the
// bytes written only once everything succeeded. Private to NPR::Passes.
#ifndef vtkNPRVectorFile_h
#define vtkNPRVectorFile_h

#include <cairo.h> // for cairo_surface_t

#include <string> // for the paths and bytes

// The format (vtkNPRDrawingExporter::Formats) of a file that can be written at `path`: its
// extension known, not a folder, its folder there. -1, with `code` (a vtkErrorCode) and
// `error`, when not.
int vtkNPRCheckVectorPath(const char* path, unsigned long& code, std::string& error);

// A surface of width x height points of the format that appends what it writes to `bytes`.
cairo_surface_t* vtkNPRCreateVectorSurface(
  int format, std::string& bytes, double width, double height);

// True when `cr` is in no error state; false, with `error` ("Cairo: " and its status), when it is.
bool vtkNPRCairoSucceeded(cairo_t* cr, std::string& error);

// Finishes and destroys the surface; false, with `error`, when Cairo failed.
bool vtkNPRFinishVectorSurface(cairo_surface_t* surface, std::string& error);

// Writes the bytes to `path`; false, with `code` and `error` and no file left, on a failure.
bool vtkNPRWriteVectorFile(
  const std::string& path, const std::string& bytes, unsigned long& code, std::string& error);

#endif
// VTK-HeaderTest-Exclude: vtkNPRVectorFile.h
