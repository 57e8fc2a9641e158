// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// The drawing style with hidden lines, rendered headless into drawing.png and written as a vector
// drawing, part.svg (Documentation/drawing.md shows its parts; run it from the repository root).
#include "nprSnippet.h" // the model's renderer, the headless window, the PNG

#include "vtkNPRDrawingExporter.h"
#include "vtkNPRDrawingPass.h"
#include "vtkNPREdgePass.h"
#include "vtkNPRPass.h"

#include <iostream>

int main()
{
  vtkSmartPointer<vtkRenderer> renderer = nprSnippetModel("Testing/Data/cad_part.vtp");

  vtkNew<vtkNPRPass> pass;
  pass->SetStyleToDrawing();
  pass->SetHiddenLines(true);             // dashed hidden lines
  pass->GetEdgePass()->SetLineWidth(1.0); // line types, colours, width, crease angle
  pass->GetEdgePass()->SetCreaseAngle(40.0);
  pass->GetDrawingPass()->SetFaceColor(1.0, 0.98, 0.92); // the drawing's own settings
  pass->GetDrawingPass()->SetDashLength(4.0);
  renderer->SetPass(pass);

  vtkSmartPointer<vtkRenderWindow> window = nprSnippetWindow(renderer, 800, 600);
  if (!window)
  {
    return 1;
  }
  nprSnippetTurn(renderer, 35.0, 25.0);
  window->Render(); // before the export: the first Render() sets the camera and sizes the window
  if (!nprSnippetWritePNG(window, "drawing.png"))
  {
    return 1;
  }

  vtkNew<vtkNPRDrawingExporter> exporter;
  exporter->SetRenderer(renderer);   // or SetRenderWindow(window): its first renderer
  exporter->SetFileName("part.svg"); // .svg, .pdf, .ps or .eps
  if (!exporter->Write())
  {
    std::cerr << exporter->GetErrorMessage() << "\n";
    return 1;
  }
  return 0;
}
