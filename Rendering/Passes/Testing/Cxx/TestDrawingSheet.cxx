// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// Drawing sheets (vtkNPRDrawingSheet), part of the TestDrawingExporter program:
//   sheet-layout  a 2 x 1 x 0.5 block in four views on A4: one scale, the views' boxes against
//                 the block's dimensions, first- and third-angle places, the margins, and the
//                 SVG rasterised by rsvg-convert: ink on each view's outline where its box says;
//                 the CAD part's sheet in PDF, PS and EPS
//   sheet-errors  unknown, repeated and no views, no renderer, an unknown extension, nothing to
//                 draw: false, the message, no file
//
// usage: TestDrawingExporter CASE [DATA_DIR]
#include "TestDrawingExporter.h"

#include "vtkActor.h"
#include "vtkCubeSource.h"
#include "vtkImageData.h"
#include "vtkNPRDrawingSheet.h"
#include "vtkNPRPass.h"
#include "vtkNew.h"
#include "vtkOutputWindow.h"
#include "vtkPolyDataMapper.h"
#include "vtkRenderer.h"

#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <string>

namespace
{
using namespace nprDrawingExporter;
using Box = std::array<double, 4>; // x0, y0, x1, y1 in points from the page's top left

std::map<std::string, Box> Boxes(vtkNPRDrawingSheet* sheet)
{
  std::map<std::string, Box> boxes;
  for (int i = 0; i < sheet->GetNumberOfViews(); ++i)
  {
    sheet->GetViewBox(i, boxes[sheet->GetViewName(i)].data());
  }
  return boxes;
}

// The number an attribute of the file's <svg> element starts with (its first occurrence).
double Attribute(const std::string& svg, const std::string& name)
{
  const size_t at = svg.find(" " + name + "=\"", svg.find("<svg"));
  return at == std::string::npos ? -1.0 : std::atof(svg.c_str() + at + name.size() + 3);
}

bool Near(double a, double b)
{
  return std::abs(a - b) < 1e-6 * std::max(1.0, std::abs(b));
}

// Whether the rasterised page (1 px = 1 pt, row 0 at the bottom) has ink within 2 px of (x, y).
bool InkNear(vtkImageData* page, double x, double y)
{
  const int height = page->GetDimensions()[1];
  for (int dy = -2; dy <= 2; ++dy)
  {
    for (int dx = -2; dx <= 2; ++dx)
    {
      const int px = static_cast<int>(std::floor(x)) + dx;
      const int py = height - 1 - static_cast<int>(std::floor(y)) + dy;
      if (nprPixel(page, px, py, 0) < 128)
      {
        return true;
      }
    }
  }
  return false;
}

// The block's four views: each box the block's faces at one scale; ink on each box's outline.
void CheckBlock(vtkNPRDrawingSheet* sheet, bool third)
{
  const double s = sheet->GetScale();
  std::map<std::string, Box> box = Boxes(sheet);
  auto width = [&](const char* view) { return box[view][2] - box[view][0]; };
  auto height = [&](const char* view) { return box[view][3] - box[view][1]; };
  NPR_CHECK(Near(width("front"), 2.0 * s) && Near(height("front"), 1.0 * s) &&
      Near(width("top"), 2.0 * s) && Near(height("top"), 0.5 * s) &&
      Near(width("right"), 0.5 * s) && Near(height("right"), 1.0 * s),
    "the views are not the block's faces at one scale");
  const double isoWidth = std::sqrt(2.0) * 0.5 * (2.0 + 0.5); // the box's extent along iso's x
  NPR_CHECK(std::abs(width("iso") - isoWidth * s) < 1e-6 * s, "the iso view's width");
  // Projection lines: a column shares its x, a row its y.
  const double frontX = 0.5 * (box["front"][0] + box["front"][2]);
  const double frontY = 0.5 * (box["front"][1] + box["front"][3]);
  NPR_CHECK(Near(0.5 * (box["top"][0] + box["top"][2]), frontX) &&
      Near(0.5 * (box["right"][1] + box["right"][3]), frontY),
    "the top view is not under or over the front view, or the right one beside it");
  const bool topBelow = box["top"][1] > box["front"][3];
  const bool rightLeft = box["right"][2] < box["front"][0];
  NPR_CHECK(topBelow != third && rightLeft != third,
    (third ? "third" : "first") << " angle: the top view " << (topBelow ? "below" : "above")
                                << ", the right view " << (rightLeft ? "left" : "right")
                                << " of the front view");
  NPR_CHECK(box["iso"][3] < box["front"][1], "the iso view is not above the front row");
  double page[2];
  sheet->GetPageSize(page);
  const double margin = 10.0 * 72.0 / 25.4;
  NPR_CHECK(Near(page[0], 297.0 * 72.0 / 25.4) && Near(page[1], 210.0 * 72.0 / 25.4),
    "A4 landscape: " << page[0] << " x " << page[1]);
  for (const auto& view : box)
  {
    NPR_CHECK(view.second[0] >= margin - 1e-9 && view.second[1] >= margin - 1e-9 &&
        view.second[2] <= page[0] - margin + 1e-9 && view.second[3] <= page[1] - margin + 1e-9,
      view.first << " outside the margins");
  }
}

void CheckInk(const std::string& svg, vtkNPRDrawingSheet* sheet)
{
  if (!*RSVG_CONVERT)
  {
    std::cout << "rsvg-convert not found: the ink checks are skipped\n";
    return;
  }
  double page[2];
  sheet->GetPageSize(page);
  const std::string png = nprTestOutputPath("sheet_block.png");
  const std::string command = std::string(RSVG_CONVERT) + " -b white -w " +
    std::to_string(std::lround(page[0])) + " -h " + std::to_string(std::lround(page[1])) + " -o '" +
    png + "' '" + svg + "'";
  NPR_CHECK(std::system(command.c_str()) == 0, "failed: " << command);
  vtkSmartPointer<vtkImageData> image = nprReadPNG(png);
  NPR_CHECK(image, "no image " << png);
  for (const char* view : { "front", "top", "right" })
  {
    Box b = Boxes(sheet)[view];
    const double cx = 0.5 * (b[0] + b[2]), cy = 0.5 * (b[1] + b[3]);
    NPR_CHECK(image && InkNear(image, b[0], cy) && InkNear(image, b[2], cy) &&
        InkNear(image, cx, b[1]) && InkNear(image, cx, b[3]) && !InkNear(image, cx, cy),
      view << ": no ink on its outline, or ink in its middle");
  }
}

int SheetLayout()
{
  vtkNew<vtkRenderer> renderer;
  vtkNew<vtkCubeSource> block;
  block->SetXLength(2.0);
  block->SetYLength(1.0);
  block->SetZLength(0.5);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(block->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  renderer->AddActor(actor);
  vtkNew<vtkNPRDrawingSheet> sheet;
  sheet->SetRenderer(renderer);
  for (bool third : { false, true })
  {
    const std::string svg = nprTestOutputPath(third ? "sheet_third.svg" : "sheet_first.svg");
    sheet->SetFileName(svg.c_str());
    sheet->SetArrangement(
      third ? vtkNPRDrawingSheet::THIRD_ANGLE : vtkNPRDrawingSheet::FIRST_ANGLE);
    NPR_CHECK(sheet->Write(), "write: " << sheet->GetErrorMessage());
    std::cout << svg << ": scale " << sheet->GetScale() << " points a unit, " << sheet->GetTime()
              << " s\n";
    CheckBlock(sheet, third);
    const std::string text = ReadFile(svg);
    NPR_CHECK(std::abs(Attribute(text, "width") - 841.89) < 0.01 &&
        std::abs(Attribute(text, "height") - 595.28) < 0.01,
      "the SVG's page is not A4 landscape");
    if (!third)
    {
      CheckInk(svg, sheet);
    }
  }
  // The CAD part, with hidden lines, in the other formats.
  CadScene scene;
  scene.Pass->SetStyleToDrawing();
  scene.Pass->SetHiddenLines(true);
  sheet->SetRenderer(scene.Renderer);
  sheet->SetArrangement(vtkNPRDrawingSheet::FIRST_ANGLE);
  for (const char* name : { "sheet_cad.pdf", "sheet_cad.ps", "sheet_cad.eps" })
  {
    const std::string path = nprTestOutputPath(name);
    sheet->SetFileName(path.c_str());
    NPR_CHECK(sheet->Write(), path << ": " << sheet->GetErrorMessage());
    const std::string text = ReadFile(path);
    const bool pdf = std::string(name).find(".pdf") != std::string::npos;
    NPR_CHECK(
      text.rfind(pdf ? "%PDF" : "%!PS", 0) == 0, path << " does not start as its format does");
    std::cout << path << ": " << text.size() << " bytes in " << sheet->GetTime() << " s, strokes";
    for (int i = 0; i < sheet->GetNumberOfViews(); ++i)
    {
      std::cout << " " << sheet->GetViewName(i) << " " << sheet->GetNumberOfStrokes(i);
      NPR_CHECK(sheet->GetNumberOfStrokes(i) > 5, sheet->GetViewName(i) << ": few strokes");
    }
    std::cout << "\n";
  }
  return nprTestResult();
}
NPR_TEST_CASE("sheet-layout", SheetLayout);

int SheetErrors()
{
  vtkNew<vtkRenderer> renderer;
  vtkNew<vtkNPRDrawingSheet> sheet;
  const std::string path = nprTestOutputPath("sheet_error.svg");
  std::filesystem::remove(path);
  sheet->SetFileName(path.c_str());
  auto* output = nprCountingOutputWindow::SafeDownCast(vtkOutputWindow::GetInstance());
  auto fails = [&](const char* what, const char* message)
  {
    const int before = output ? output->Errors : 0;
    NPR_CHECK(!sheet->Write() &&
        std::string(sheet->GetErrorMessage()).find(message) != std::string::npos &&
        sheet->GetErrorCode() != 0 && !std::filesystem::exists(path),
      what << ": " << sheet->GetErrorMessage());
    if (output)
    {
      NPR_CHECK(output->Errors == before + 1, what << ": not one VTK error");
      output->Errors = before; // expected
    }
  };
  fails("no renderer", "no renderer");
  sheet->SetRenderer(renderer);
  fails("an empty scene", "nothing visible");
  nprAddCube(renderer, std::array<double, 3>{ 0, 0, 0 }.data(), 1.0);
  sheet->SetViews("front,side");
  fails("an unknown view", "unknown view 'side'");
  sheet->SetViews("front, top,Front");
  fails("a repeated view", "given twice");
  sheet->SetViews("");
  fails("no view", "no views");
  sheet->SetViews("front");
  sheet->SetFileName(nprTestOutputPath("sheet_error.png").c_str());
  fails("an unknown extension", "unsupported extension");
  sheet->SetFileName(path.c_str());
  NPR_CHECK(sheet->Write() && sheet->GetNumberOfViews() == 1, sheet->GetErrorMessage());
  NPR_CHECK(vtkNPRDrawingSheet::GetPaperSizeFromName("Letter") == vtkNPRDrawingSheet::LETTER &&
      vtkNPRDrawingSheet::GetPaperSizeFromName("a3") == vtkNPRDrawingSheet::A3 &&
      vtkNPRDrawingSheet::GetPaperSizeFromName("B5") == -1,
    "paper names");
  return nprTestResult();
}
NPR_TEST_CASE("sheet-errors", SheetErrors);
}
