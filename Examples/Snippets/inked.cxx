// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// The inked style on the bunny, rendered headless into inked.png
// (Documentation/classic-techniques.md shows its middle; run it from the repository root).
#include "vtkActor.h"
#include "vtkNPRInkPass.h"
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

int main()
{
  vtkNew<vtkNPRModelReader> reader;
  reader->SetFileName("Testing/Data/bunny.ply");
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(reader->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  renderer->SetBackground(1.0, 1.0, 1.0);

  vtkNew<vtkNPRPass> npr;
  npr->SetStyleToInked();
  npr->GetInkPass()->SetLineWidth(2.0); // visible pixels at 72 DPI, 0.5..16
  npr->GetInkPass()->SetInkColor(0.1, 0.1, 0.3);
  renderer->SetPass(npr);

  auto window =
    vtkSmartPointer<vtkRenderWindow>::Take(vtkNPRRenderWindowFactory::CreateRenderWindow());
  if (!window)
  {
    return 1;
  }
  window->SetSize(480, 360);
  window->AddRenderer(renderer);
  window->Render();

  vtkNew<vtkWindowToImageFilter> grabber;
  grabber->SetInput(window);
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputConnection(grabber->GetOutputPort());
  writer->SetFileName("inked.png");
  writer->Write();
  return 0;
}
