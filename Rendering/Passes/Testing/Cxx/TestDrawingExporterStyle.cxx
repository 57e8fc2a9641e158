// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// Part of the TestDrawingExporter program: the renderer in the drawing style.
//
// usage: TestDrawingExporter drawing-style [DATA_DIR]
#include "TestDrawingExporter.h"

#include "vtkNPRDrawingExporter.h"
#include "vtkNPRDrawingLines.h"
#include "vtkNPRDrawingPass.h"

#include <regex>
#include <string>

namespace
{
using namespace nprDrawingExporter;

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
  const std::string path = nprTestOutputPath("drawing_cad_style.svg");
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
  const std::string referencePath = nprTestOutputPath("drawing_cad_style_reference.svg");
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
}
