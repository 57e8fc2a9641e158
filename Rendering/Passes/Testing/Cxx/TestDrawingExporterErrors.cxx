// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// Part of the TestDrawingExporter program: an unknown extension, a missing folder, a folder as
// the file and no renderer make Write() false with the error code, a message and one VTK error,
// leaving no file; the format from the extension in any case.
//
// usage: TestDrawingExporter errors [DATA_DIR]
#include "TestDrawingExporter.h"

#include "vtkErrorCode.h"
#include "vtkNPRDrawingExporter.h"

#include <filesystem>
#include <string>

namespace
{
using namespace nprDrawingExporter;

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
  expectError(
    nprTestOutputPath("drawing.png"), vtkErrorCode::FileFormatError, ".svg, .pdf, .ps, .eps");
  expectError(
    nprTestOutputPath("drawing.svgz"), vtkErrorCode::FileFormatError, "unsupported extension");
  expectError(nprTestOutputPath("drawing"), vtkErrorCode::FileFormatError, "unsupported extension");
  expectError(nprTestOutputPath("no-such-folder/drawing.svg"), vtkErrorCode::CannotOpenFileError,
    "no such directory");
  const std::string folder = nprTestOutputPath("drawing-folder.pdf");
  std::filesystem::create_directories(folder);
  const int before = output ? output->Errors : 0;
  exporter->SetFileName(folder.c_str());
  NPR_CHECK(!exporter->Write() && exporter->GetErrorCode() == vtkErrorCode::CannotOpenFileError &&
      std::string(exporter->GetErrorMessage()).find("is a directory") != std::string::npos,
    "a folder as the file: " << exporter->GetErrorMessage());
  NPR_CHECK(std::filesystem::is_directory(folder), "the folder is gone");
  vtkNew<vtkNPRDrawingExporter> lonely;
  lonely->SetFileName(nprTestOutputPath("lonely.svg").c_str());
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
}
