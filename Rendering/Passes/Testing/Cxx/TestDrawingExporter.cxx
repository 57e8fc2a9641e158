// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// vtkNPRDrawingExporter on the CAD part (Testing/Data/cad_part.vtp) at 800x600:
//   svg-accuracy  the SVG rasterised by rsvg-convert at the image size, its line pixels against
//                 vtkNPRReferenceMask of the same camera: F1@1 >= 0.98
//   pdf-accuracy  the same for the PDF, rasterised by pdftoppm
//   svg-structure one <path> per stroke, the class groups, hidden strokes dashed, the raster
//   errors        unknown extension, missing folder, a folder as the file, no renderer: false,
//                 the error code and a message; no file left
//   empty         an empty scene: a valid empty drawing in every format
//   drawing-style the renderer in the drawing style: the export uses the pass's lines (no second
//                 edge table or occluders) and writes the same SVG as a new drawing pass's lines
// Programs: RSVG_CONVERT and PDFTOPPM (compile definitions; the accuracy cases need them).
#include "nprEdgeMetrics.h"
#include "nprTesting.h"

#include "vtkErrorCode.h"
#include "vtkImageData.h"
#include "vtkNPRDrawingExporter.h"
#include "vtkNPRDrawingLines.h"
#include "vtkNPRDrawingPass.h"
#include "vtkNPREdgePass.h"
#include "vtkNPRReferenceMask.h"
#include "vtkPolyData.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace
{
constexpr int ImageWidth = 800, ImageHeight = 600;

std::string OutputPath(const std::string& name)
{
  const char* dir = std::getenv("NPR_TEST_OUTPUT_DIR");
  return std::string(dir && *dir ? dir : ".") + "/" + name;
}

std::string ReadFile(const std::string& path)
{
  std::ifstream file(path, std::ios::binary);
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

size_t Count(const std::string& text, const std::string& what)
{
  size_t count = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1))
  {
    ++count;
  }
  return count;
}

// The CAD part in the baseline scenes' view, 1 px lines, edges style.
struct CadScene : nprPassScene
{
  CadScene()
    : nprPassScene(ImageWidth, ImageHeight)
  {
    nprAddBaselineModel(this->Renderer, "cad_part.vtp");
    this->Edges()->SetLineWidth(1.0);
    this->Window->Render();
  }
};

// The dark pixels of a rasterised drawing (lines black on white), row 0 at the bottom.
std::vector<unsigned char> LinePixels(vtkImageData* image)
{
  std::vector<unsigned char> mask(static_cast<size_t>(ImageWidth) * ImageHeight, 0);
  for (int y = 0; y < ImageHeight; ++y)
  {
    for (int x = 0; x < ImageWidth; ++x)
    {
      mask[static_cast<size_t>(y) * ImageWidth + x] = nprPixel(image, x, y, 0) < 160 ? 255 : 0;
    }
  }
  return mask;
}

int Accuracy(bool pdf)
{
  CadScene scene;
  vtkNew<vtkNPRDrawingExporter> exporter;
  exporter->SetRenderer(scene.Renderer);
  exporter->SetEmbedImage(0); // the lines alone, on the white background
  const std::string path = OutputPath(pdf ? "drawing_cad.pdf" : "drawing_cad.svg");
  const std::string png = OutputPath(pdf ? "drawing_cad_pdf" : "drawing_cad_svg");
  exporter->SetFileName(path.c_str());
  NPR_CHECK(exporter->Write(), "write: " << exporter->GetErrorMessage());
  std::cout << path << ": " << exporter->GetNumberOfStrokes() << " strokes, "
            << std::filesystem::file_size(path) << " bytes, strokes " << exporter->GetStrokesTime()
            << " s, painting and writing " << exporter->GetWriteTime() << " s\n";
  std::string command;
  if (pdf)
  {
    command = std::string(PDFTOPPM) + " -png -singlefile -scale-to-x " +
      std::to_string(ImageWidth) + " -scale-to-y " + std::to_string(ImageHeight) + " '" + path +
      "' '" + png + "'";
  }
  else
  {
    command = std::string(RSVG_CONVERT) + " -w " + std::to_string(ImageWidth) + " -h " +
      std::to_string(ImageHeight) + " -o '" + png + ".png' '" + path + "'";
  }
  NPR_CHECK(std::system(command.c_str()) == 0, "failed: " << command);
  vtkSmartPointer<vtkImageData> image = nprReadPNG(png + ".png");
  NPR_CHECK(image, "no image " << png << ".png");
  if (!image)
  {
    return nprTestResult();
  }
  const int* dimensions = image->GetDimensions();
  NPR_CHECK(dimensions[0] == ImageWidth && dimensions[1] == ImageHeight,
    "rasterised at " << dimensions[0] << "x" << dimensions[1]);
  if (dimensions[0] != ImageWidth || dimensions[1] != ImageHeight)
  {
    return nprTestResult();
  }
  vtkNew<vtkNPRReferenceMask> reference;
  reference->SetRenderer(scene.Renderer);
  reference->SetSize(ImageWidth, ImageHeight);
  NPR_CHECK(reference->Update(), "reference mask");
  nprEdgeMetrics metrics;
  const std::vector<unsigned char> lines = LinePixels(image);
  metrics.Compute(lines.data(),
    static_cast<const unsigned char*>(reference->GetMask()->GetScalarPointer()), ImageWidth,
    ImageHeight);
  std::cout << (pdf ? "PDF" : "SVG") << " against the reference mask: " << metrics.GetMethodPixels()
            << " line pixels, " << metrics.GetReferencePixels() << " reference pixels, P@1 "
            << metrics.Precision(1.0) << ", R@1 " << metrics.Recall(1.0) << ", F1@1 "
            << metrics.F1(1.0) << ", F1@0 " << metrics.F1(0.0) << "\n";
  NPR_CHECK(metrics.F1(1.0) >= 0.98, "F1@1 " << metrics.F1(1.0) << " < 0.98");
  return nprTestResult();
}
NPR_TEST_CASE("svg-accuracy", [] { return Accuracy(false); });
NPR_TEST_CASE("pdf-accuracy", [] { return Accuracy(true); });

int SvgStructure()
{
  CadScene scene;
  vtkNew<vtkNPRDrawingPass> drawing;
  drawing->HiddenLinesOn();
  vtkNew<vtkNPRDrawingExporter> exporter;
  exporter->SetRenderWindow(scene.Window); // its first renderer
  exporter->SetDrawingPass(drawing);
  const std::string path = OutputPath("drawing_cad_hidden.svg");
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
    "npr-non-manifold" };
  for (int k = 0; k < 5; ++k)
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

int Errors()
{
  auto* output = nprCountingOutputWindow::SafeDownCast(vtkOutputWindow::GetInstance());
  CadScene scene;
  vtkNew<vtkNPRDrawingExporter> exporter;
  exporter->SetRenderer(scene.Renderer);
  auto expectError = [&](const std::string& path, unsigned long code, const std::string& text)
  {
    const int before = output ? output->Errors : 0;
    exporter->SetFileName(path.c_str());
    NPR_CHECK(!exporter->Write(), path << ": written");
    NPR_CHECK(exporter->GetErrorCode() == code,
      path << ": error code " << exporter->GetErrorCode() << ", expected " << code);
    const std::string message = exporter->GetErrorMessage();
    NPR_CHECK(message.find(text) != std::string::npos,
      path << ": message '" << message << "' lacks '" << text << "'");
    NPR_CHECK(!std::filesystem::is_regular_file(path), path << ": a file was left");
    std::cout << "error: " << message << "\n";
    if (output)
    {
      NPR_CHECK(output->Errors == before + 1, "one VTK error");
      output->Errors = before; // expected
    }
  };
  expectError(OutputPath("drawing.png"), vtkErrorCode::FileFormatError, ".svg, .pdf, .ps, .eps");
  expectError(OutputPath("drawing.svgz"), vtkErrorCode::FileFormatError, "unsupported extension");
  expectError(OutputPath("drawing"), vtkErrorCode::FileFormatError, "unsupported extension");
  expectError(OutputPath("no-such-folder/drawing.svg"), vtkErrorCode::CannotOpenFileError,
    "no such directory");
  const std::string folder = OutputPath("drawing-folder.pdf");
  std::filesystem::create_directories(folder);
  const int before = output ? output->Errors : 0;
  exporter->SetFileName(folder.c_str());
  NPR_CHECK(!exporter->Write() && exporter->GetErrorCode() == vtkErrorCode::CannotOpenFileError &&
      std::string(exporter->GetErrorMessage()).find("is a directory") != std::string::npos,
    "a folder as the file: " << exporter->GetErrorMessage());
  NPR_CHECK(std::filesystem::is_directory(folder), "the folder is gone");
  vtkNew<vtkNPRDrawingExporter> lonely;
  lonely->SetFileName(OutputPath("lonely.svg").c_str());
  NPR_CHECK(!lonely->Write() && std::string(lonely->GetErrorMessage()).find("no renderer") == 0,
    "no renderer: " << lonely->GetErrorMessage());
  if (output)
  {
    NPR_CHECK(output->Errors == before + 2, "two VTK errors");
    output->Errors = before;
  }
  // The extension's case does not matter.
  NPR_CHECK(vtkNPRDrawingExporter::GetFormatFromFileName("A.SVG") == vtkNPRDrawingExporter::SVG &&
      vtkNPRDrawingExporter::GetFormatFromFileName("b.Pdf") == vtkNPRDrawingExporter::PDF &&
      vtkNPRDrawingExporter::GetFormatFromFileName("c.eps") == vtkNPRDrawingExporter::EPS &&
      vtkNPRDrawingExporter::GetFormatFromFileName("d.ps") == vtkNPRDrawingExporter::PS &&
      vtkNPRDrawingExporter::GetFormatFromFileName("e.png") == -1,
    "formats from names");
  return nprTestResult();
}
NPR_TEST_CASE("errors", Errors);

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
    const std::string path = OutputPath(name);
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
        const std::string png = OutputPath("drawing_empty_page");
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

// In the drawing style the exporter takes the pass's vtkNPRDrawingLines, whose edge table and
// occluders the frame built: no second build (twice the time and memory on a large model), the
// renderer not held after (a cycle), and the same file as lines built from nothing.
int DrawingStyle()
{
  CadScene scene;
  scene.Pass->SetStyleToDrawing();
  scene.Pass->GetDrawingPass()->HiddenLinesOn();
  scene.Window->Render();
  vtkNPRDrawingLines* passLines = scene.Pass->GetDrawingPass()->GetDrawingLines();
  NPR_CHECK(passLines->GetNumberOfLocatorBuilds() == 1,
    "locator builds after the frame: " << passLines->GetNumberOfLocatorBuilds());
  const int before = scene.Renderer->GetReferenceCount();

  vtkNew<vtkNPRDrawingExporter> exporter;
  exporter->SetRenderer(scene.Renderer);
  const std::string path = OutputPath("drawing_cad_style.svg");
  exporter->SetFileName(path.c_str());
  NPR_CHECK(exporter->Write(), "write: " << exporter->GetErrorMessage());
  NPR_CHECK(exporter->GetDrawingLines() == passLines, "the exporter built lines of its own");
  NPR_CHECK(passLines->GetNumberOfLocatorBuilds() == 1,
    "locator builds after the export: " << passLines->GetNumberOfLocatorBuilds());
  NPR_CHECK(!passLines->GetRenderer() && scene.Renderer->GetReferenceCount() == before + 1,
    "the pass's lines keep the renderer (references "
      << before << " -> " << scene.Renderer->GetReferenceCount() << ")");
  NPR_CHECK(exporter->GetNumberOfStrokes(0) > 0 && !exporter->GetImageEmbedded(),
    "hidden strokes " << exporter->GetNumberOfStrokes(0) << ", raster "
                      << exporter->GetImageEmbedded());

  // The same settings on a drawing pass of its own: its lines are built from nothing.
  vtkNew<vtkNPRDrawingPass> fresh;
  fresh->HiddenLinesOn();
  vtkNew<vtkNPRDrawingExporter> reference;
  reference->SetRenderer(scene.Renderer);
  reference->SetDrawingPass(fresh);
  const std::string referencePath = OutputPath("drawing_cad_style_reference.svg");
  reference->SetFileName(referencePath.c_str());
  NPR_CHECK(reference->Write(), "write: " << reference->GetErrorMessage());
  NPR_CHECK(reference->GetDrawingLines() == fresh->GetDrawingLines(), "not the given pass's lines");
  // Cairo numbers its surfaces in the process: the files are compared without those numbers.
  const std::regex surface("surface[0-9]+");
  NPR_CHECK(std::regex_replace(ReadFile(path), surface, "surface") ==
      std::regex_replace(ReadFile(referencePath), surface, "surface"),
    path << " and " << referencePath << " differ (" << exporter->GetNumberOfStrokes() << " and "
         << reference->GetNumberOfStrokes() << " strokes)");
  return nprTestResult();
}
NPR_TEST_CASE("drawing-style", DrawingStyle);
