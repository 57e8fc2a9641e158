// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// Part of the TestDrawingExporter program: an empty scene gives a valid empty drawing in every
// format (SVG, PDF, PostScript and EPS), of the window's size in points.
//
// usage: TestDrawingExporter empty [DATA_DIR]
#include "TestDrawingExporter.h"

#include "vtkImageData.h"
#include "vtkNPRDrawingExporter.h"

#include <cstdlib>
#include <filesystem>
#include <string>

namespace
{
using namespace nprDrawingExporter;

int Empty()
{
  vtkSmartPointer<vtkRenderWindow> window = nprCreateTestWindow(320, 240, nullptr);
  NPR_CHECK(window, "no window");
  if (!window)
  {
    return nprTestResult();
  }
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(0.2, 0.3, 0.4);
  window->AddRenderer(renderer);
  window->Render();
  vtkNew<vtkNPRDrawingExporter> exporter;
  exporter->SetRenderer(renderer);
  for (const char* name :
    { "drawing_empty.svg", "drawing_empty.pdf", "drawing_empty.ps", "drawing_empty.eps" })
  {
    const std::string path = nprTestOutputPath(name);
    exporter->SetFileName(path.c_str());
    NPR_CHECK(exporter->Write(), name << ": " << exporter->GetErrorMessage());
    NPR_CHECK(exporter->GetNumberOfStrokes() == 0, name << ": strokes");
    const std::string text = ReadFile(path);
    std::cout << name << ": " << text.size() << " bytes\n";
    const std::string ext = std::filesystem::path(path).extension().string();
    if (ext == ".svg")
    {
      NPR_CHECK(text.find("<svg") != std::string::npos &&
          text.find("</svg>") != std::string::npos && Count(text, "<path") == 0 &&
          text.find("width=\"320pt\" height=\"240pt\"") != std::string::npos &&
          (text.find("fill:rgb(20%,30%,40%)") != std::string::npos ||       // Cairo 1.16
            text.find("fill=\"rgb(20%, 30%, 40%)\"") != std::string::npos), // 1.18
        "empty SVG:\n"
          << text.substr(0, 600));
    }
    else if (ext == ".pdf")
    {
      NPR_CHECK(
        text.rfind("%PDF-", 0) == 0 && text.find("%%EOF") != std::string::npos, "empty PDF");
      // Cairo 1.16 writes the page dictionary as text; 1.18 (PDF 1.7) in a compressed object
      // stream: there the page is measured by pdftoppm at 72 DPI, 1 pixel a point.
      int page[2] = { 0, 0 };
      if (text.find("/MediaBox [ 0 0 320 240 ]") != std::string::npos)
      {
        page[0] = 320;
        page[1] = 240;
      }
      else if (std::string(PDFTOPPM).find('/') != std::string::npos)
      {
        const std::string png = nprTestOutputPath("drawing_empty_page");
        const std::string command =
          std::string(PDFTOPPM) + " -r 72 -png -singlefile '" + path + "' '" + png + "'";
        NPR_CHECK(std::system(command.c_str()) == 0, "failed: " << command);
        if (vtkSmartPointer<vtkImageData> image = nprReadPNG(png + ".png"))
        {
          page[0] = image->GetDimensions()[0];
          page[1] = image->GetDimensions()[1];
        }
      }
      NPR_CHECK(page[0] == 320 && page[1] == 240,
        "PDF page size " << page[0] << " x " << page[1] << " pt, not 320 x 240");
    }
    else
    {
      NPR_CHECK(text.rfind("%!PS-Adobe-3.0", 0) == 0, name << ": PostScript header");
      NPR_CHECK((ext == ".eps") == (text.find("EPSF") != std::string::npos), name << ": EPSF");
      NPR_CHECK(text.find("%%BoundingBox: 0 0 320 240") != std::string::npos, name << ": bbox");
    }
  }
  return nprTestResult();
}
NPR_TEST_CASE("empty", Empty);
}
