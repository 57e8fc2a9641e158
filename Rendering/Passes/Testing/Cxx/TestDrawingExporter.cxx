// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// vtkNPRDrawingExporter on the CAD part (Testing/Data/cad_part.vtp) at 800x600:
//   svg-accuracy  the SVG rasterised by rsvg-convert at the image size, its line pixels against
//                 vtkNPRReferenceMask of the same camera: F1@1 >= 0.98
//   pdf-accuracy  the same for the PDF, rasterised by pdftoppm
//   svg-structure one <path> per stroke, the class groups, hidden strokes dashed, the raster
//                 (TestDrawingExporterSvg.cxx)
//   errors        unknown extension, missing folder, a folder as the file, no renderer: false,
//                 the error code and a message; no file left (TestDrawingExporterErrors.cxx)
//   empty         an empty scene: a valid empty drawing in every format
//                 (TestDrawingExporterEmpty.cxx)
//   drawing-style the renderer in the drawing style: the export uses the pass's lines (no second
//                 edge table or occluders) and writes the same SVG as a new drawing pass's lines
//                 (TestDrawingExporterStyle.cxx)
//   points        vertex cells and a point cloud as painted points, against the render
//   overlays      2D text as glyph outlines and a scalar bar as an image, against the render
//                 (TestDrawingExporterOverlays.cxx)
// Programs: RSVG_CONVERT and PDFTOPPM (compile definitions; the accuracy cases need them).
//
// usage: TestDrawingExporter CASE [DATA_DIR]
#include "TestDrawingExporter.h"

#include "nprEdgeMetrics.h"

#include "vtkImageData.h"
#include "vtkNPRDrawingExporter.h"
#include "vtkNPREdgePass.h"
#include "vtkNPRReferenceMask.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

std::string nprDrawingExporter::ReadFile(const std::string& path)
{
  std::ifstream file(path, std::ios::binary);
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

vtkSmartPointer<vtkImageData> nprDrawingExporter::Rasterise(
  const std::string& path, int width, int height)
{
  const bool pdf = path.size() > 4 && path.compare(path.size() - 4, 4, ".pdf") == 0;
  const std::string png = path.substr(0, path.size() - 4) + (pdf ? "_pdf" : "_svg");
  const std::string size =
    std::to_string(width) + (pdf ? " -scale-to-y " : " -h ") + std::to_string(height);
  const std::string command = pdf
    ? std::string(PDFTOPPM) + " -png -singlefile -scale-to-x " + size + " '" + path + "' '" + png +
      "'"
    : std::string(RSVG_CONVERT) + " -w " + size + " -o '" + png + ".png' '" + path + "'";
  NPR_CHECK(std::system(command.c_str()) == 0, "failed: " << command);
  vtkSmartPointer<vtkImageData> image = nprReadPNG(png + ".png");
  NPR_CHECK(image, "no image " << png << ".png");
  return image;
}

size_t nprDrawingExporter::Count(const std::string& text, const std::string& what)
{
  size_t count = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1))
  {
    ++count;
  }
  return count;
}

nprDrawingExporter::CadScene::CadScene()
  : nprPassScene(ImageWidth, ImageHeight)
{
  nprAddBaselineModel(this->Renderer, "cad_part.vtp");
  this->Edges()->SetLineWidth(1.0);
  this->Window->Render();
}

namespace
{
using namespace nprDrawingExporter;

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
  const std::string path = nprTestOutputPath(pdf ? "drawing_cad.pdf" : "drawing_cad.svg");
  exporter->SetFileName(path.c_str());
  NPR_CHECK(exporter->Write(), "write: " << exporter->GetErrorMessage());
  std::cout << path << ": " << exporter->GetNumberOfStrokes() << " strokes, "
            << std::filesystem::file_size(path) << " bytes, strokes " << exporter->GetStrokesTime()
            << " s, painting and writing " << exporter->GetWriteTime() << " s\n";
  vtkSmartPointer<vtkImageData> image = Rasterise(path, ImageWidth, ImageHeight);
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
}
