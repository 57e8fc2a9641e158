// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// The drawing style with hidden lines, rendered headless into drawing.png and written as a vector
// drawing, part.svg (Documentation/drawing.md shows its parts; run it from the repository root).
#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkNPRDrawingExporter.h"
#include "vtkNPRDrawingPass.h"
#include "vtkNPREdgePass.h"
#include "vtkNPRModelReader.h"
#include "vtkNPRPass.h"
#include "vtkNPRRenderWindowFactory.h"
#include "vtkNew.h"
#include "vtkPNGWriter.h"
#include "vtkPolyDataMapper.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkWindowToImageFilter.h"

#include <iostream>

int main()
{
  vtkNew<vtkNPRModelReader> reader;
  reader->SetFileName("Testing/Data/cad_part.vtp");
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(reader->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  renderer->SetBackground(1.0, 1.0, 1.0);

  vtkNew<vtkNPRPass> pass;
  pass->SetStyleToDrawing();
  pass->SetHiddenLines(true);             // dashed hidden lines
  pass->GetEdgePass()->SetLineWidth(1.0); // line types, colours, width, crease angle
  pass->GetEdgePass()->SetCreaseAngle(40.0);
  pass->GetDrawingPass()->SetFaceColor(1.0, 0.98, 0.92); // the drawing's own settings
  pass->GetDrawingPass()->SetDashLength(4.0);
  renderer->SetPass(pass);

  auto window =
    vtkSmartPointer<vtkRenderWindow>::Take(vtkNPRRenderWindowFactory::CreateRenderWindow());
  if (!window)
  {
    return 1;
  }
  window->SetSize(800, 600);
  window->AddRenderer(renderer);
  renderer->GetActiveCamera()->Azimuth(35.0);
  renderer->GetActiveCamera()->Elevation(25.0);
  renderer->ResetCamera();
  window->Render(); // before the export: the first Render() sets the camera and sizes the window

  vtkNew<vtkWindowToImageFilter> grabber;
  grabber->SetInput(window);
  vtkNew<vtkPNGWriter> png;
  png->SetInputConnection(grabber->GetOutputPort());
  png->SetFileName("drawing.png");
  png->Write();

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
