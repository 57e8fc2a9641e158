// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// Part of the TestDrawingExporter program: the SVG of the CAD part with hidden lines, one <path>
// per stroke in a group per class (hidden strokes dashed and first), the raster of the edges
// style embedded, the page in points.
//
// usage: TestDrawingExporter svg-structure [DATA_DIR]
#include "TestDrawingExporter.h"

#include "vtkNPRDrawingExporter.h"
#include "vtkNPRDrawingLines.h"
#include "vtkNPRDrawingPass.h"
#include "vtkPolyData.h"

#include <string>

namespace
{
using namespace nprDrawingExporter;

int SvgStructure()
{
  CadScene scene;
  vtkNew<vtkNPRDrawingPass> drawing;
  drawing->HiddenLinesOn();
  vtkNew<vtkNPRDrawingExporter> exporter;
  exporter->SetRenderWindow(scene.Window); // its first renderer
  exporter->SetDrawingPass(drawing);
  const std::string path = nprTestOutputPath("drawing_cad_hidden.svg");
  exporter->SetFileName(path.c_str());
  NPR_CHECK(exporter->Write(), "write: " << exporter->GetErrorMessage());
  const std::string svg = ReadFile(path);
  vtkPolyData* strokes = exporter->GetDrawingLines()->GetStrokes();
  const vtkIdType total = exporter->GetNumberOfStrokes();
  std::cout << path << ": " << total << " strokes (" << strokes->GetNumberOfLines()
            << " computed; hidden " << exporter->GetNumberOfStrokes(0) << "), " << svg.size()
            << " bytes\n";
  NPR_CHECK(total == strokes->GetNumberOfLines(),
    "strokes painted " << total << " of " << strokes->GetNumberOfLines());
  NPR_CHECK(exporter->GetNumberOfStrokes(0) > 0 && exporter->GetNumberOfStrokes(1) > 0 &&
      exporter->GetNumberOfStrokes(3) > 0,
    "hidden, silhouette and crease strokes expected");
  NPR_CHECK(static_cast<vtkIdType>(Count(svg, "<path")) == total,
    Count(svg, "<path") << " <path> elements for " << total << " strokes");
  NPR_CHECK(exporter->GetClassesLabelled(), "classes not labelled");
  NPR_CHECK(exporter->GetImageEmbedded() && Count(svg, "<image") == 1, "the raster (edges style)");
  NPR_CHECK(
    svg.find("width=\"800pt\" height=\"600pt\" viewBox=\"0 0 800 600\"") != std::string::npos,
    "page size");
  const char* classes[] = { "npr-hidden", "npr-silhouette", "npr-boundary", "npr-crease",
    "npr-non-manifold", "npr-intersection" };
  for (int k = 0; k < 6; ++k)
  {
    const std::string open = std::string("<g class=\"") + classes[k] + "\">";
    const size_t start = svg.find(open);
    NPR_CHECK((start != std::string::npos) == (exporter->GetNumberOfStrokes(k) > 0),
      "group " << classes[k]);
    if (start == std::string::npos)
    {
      continue;
    }
    NPR_CHECK(Count(svg, open) == 1, "one group " << classes[k]);
    const std::string group = svg.substr(start, svg.find("</g>", start) - start);
    NPR_CHECK(static_cast<vtkIdType>(Count(group, "<path")) == exporter->GetNumberOfStrokes(k),
      classes[k] << ": " << Count(group, "<path") << " paths, " << exporter->GetNumberOfStrokes(k)
                 << " strokes");
    const size_t dashed = Count(group, "stroke-dasharray");
    NPR_CHECK(k == 0 ? dashed == Count(group, "<path") : dashed == 0,
      classes[k] << ": " << dashed << " dashed paths");
  }
  // Hidden strokes come first (under the visible ones).
  NPR_CHECK(svg.find("npr-hidden") < svg.find("npr-silhouette"), "hidden strokes first");
  return nprTestResult();
}
NPR_TEST_CASE("svg-structure", SvgStructure);
}
