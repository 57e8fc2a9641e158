// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// Images out of a render window, and PNG files.
#ifndef nprWindowImage_h
#define nprWindowImage_h

#include "vtkSmartPointer.h"

#include <string>

class vtkImageData;
class vtkRenderWindow;

// The window's colour buffer as RGB, read from the back buffer. rerender: render the window
// first; otherwise the image is the frame last rendered.
vtkSmartPointer<vtkImageData> nprReadWindowImage(vtkRenderWindow* window, bool rerender);

// Throws std::runtime_error "PATH: cannot write the PNG".
void nprWritePNG(vtkImageData* image, const std::string& path);

// Renders the window and writes it as a PNG: RGB, or (grey) its first channel as 8-bit grey.
void nprWriteWindowPNG(vtkRenderWindow* window, const std::string& path, bool grey);

#endif
