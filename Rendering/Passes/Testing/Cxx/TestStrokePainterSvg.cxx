// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// Part of the TestStrokePainter program: the hand-made strokes (TestStrokePainter.h) painted into
// Cairo's SVG: one <path> a stroke, hidden first, y flipped, the loop closed (Z).
//
// usage: TestStrokePainter svg [DATA_DIR]
#include "TestStrokePainter.h"

#include <cairo-svg.h>
#include <cairo.h>

#include <string>
#include <vector>

namespace
{
using namespace nprStrokePainter;

cairo_status_t Append(void* closure, const unsigned char* data, unsigned int length)
{
  static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
  return CAIRO_STATUS_SUCCESS;
}

int Svg()
{
  std::string svg;
  cairo_surface_t* surface = cairo_svg_surface_create_for_stream(Append, &svg, Width, Height);
  cairo_t* cr = cairo_create(surface);
  vtkNPRStrokeCounts counts;
  std::string error;
  NPR_CHECK(vtkNPRPaintStrokes(cr, MakeStrokes(), TestStyle(), Height, counts, error), error);
  cairo_destroy(cr);
  cairo_surface_finish(surface);
  cairo_surface_destroy(surface);
  NPR_CHECK(counts[NPR_STROKES_HIDDEN] == 1 && counts[NPR_STROKES_SILHOUETTE] == 1 &&
      counts[NPR_STROKES_CREASE] == 1 && counts[NPR_STROKES_BOUNDARY] == 0,
    "counts");
  std::vector<std::string> paths;
  for (size_t at = svg.find("<path"); at != std::string::npos; at = svg.find("<path", at + 1))
  {
    paths.push_back(svg.substr(at, svg.find("/>", at) - at));
  }
  NPR_CHECK(paths.size() == 3, paths.size() << " paths, expected 3:\n" << svg);
  if (paths.size() == 3)
  {
    // Painted hidden first; y flipped (image y 60 is 40 from the top; Cairo merges the collinear
    // middle point); the loop closed.
    NPR_CHECK(paths[0].find("dasharray") != std::string::npos &&
        paths[0].find("M 10 40 L") != std::string::npos &&
        paths[0].find("190 40") != std::string::npos,
      "hidden path: " << paths[0]);
    NPR_CHECK(paths[1].find("dasharray") == std::string::npos &&
        paths[1].find("M 20 80 L 180 80") != std::string::npos,
      "visible path: " << paths[1]);
    NPR_CHECK(paths[2].find("M 130 70 L 170 70 L 170 50 L 130 50 Z") != std::string::npos,
      "closed loop: " << paths[2]);
    NPR_CHECK(paths[1].find("round") != std::string::npos, "round caps: " << paths[1]);
  }
  std::cout << "Cairo " << cairo_version_string() << "\n";
  return nprTestResult();
}
NPR_TEST_CASE("svg", Svg);
}
