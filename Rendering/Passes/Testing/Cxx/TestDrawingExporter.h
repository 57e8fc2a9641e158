// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// What the sources of the TestDrawingExporter program share: the image size, the CAD part's
// scene and the reading of the files written (their definitions are TestDrawingExporter.cxx's).
#ifndef TestDrawingExporter_h
#define TestDrawingExporter_h

#include "nprTesting.h"

#include "vtkImageData.h"
#include "vtkSmartPointer.h"

#include <string>

namespace nprDrawingExporter
{
constexpr int ImageWidth = 800, ImageHeight = 600;

// The bytes of a file (empty where it cannot be read).
std::string ReadFile(const std::string& path);

// A written .svg (rsvg-convert) or .pdf (pdftoppm) file rasterised at width x height, row 0 at
// the bottom; null, after a failed check, when the program fails.
vtkSmartPointer<vtkImageData> Rasterise(const std::string& path, int width, int height);

// How often what occurs in text.
size_t Count(const std::string& text, const std::string& what);

// The CAD part in the baseline scenes' view, 1 px lines, edges style.
struct CadScene : nprPassScene
{
  CadScene();
};
}

#endif
