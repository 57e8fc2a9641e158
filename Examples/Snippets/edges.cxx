// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// The edge style on a model from Testing/Data, rendered headless into edges.png
// (Documentation/edges.md shows this program; run it from the repository root).
#include "vtkActor.h"
#include "vtkCamera.h"
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

int main()
{
  vtkNew<vtkNPRModelReader> reader; // .stl .obj .ply .vtp .vtk .gltf .glb .off
  reader->SetFileName("Testing/Data/cad_part.vtp");
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(reader->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  renderer->SetBackground(1.0, 1.0, 1.0);

  vtkNew<vtkNPRPass> npr; // style EDGES: silhouettes, creases and contours, black, 1.5 px
  renderer->SetPass(npr);

  vtkNPREdgePass* edges = npr->GetEdgePass();
  edges->SetLineWidth(2.0);
  edges->SetCreaseAngle(40.0);
  edges->SetSilhouetteColor(0.8, 0.0, 0.0);
  edges->SetContourSideToBoth();
  edges->CreasesOff(); // a line type off: the G-buffer then holds no normals

  // Headless: EGL, or the backend named by NPR_BACKEND; null (with a warning) if none renders.
  auto window =
    vtkSmartPointer<vtkRenderWindow>::Take(vtkNPRRenderWindowFactory::CreateRenderWindow());
  if (!window)
  {
    return 1;
  }
  window->SetSize(800, 600);
  window->AddRenderer(renderer);
  renderer->GetActiveCamera()->Azimuth(30.0);
  renderer->GetActiveCamera()->Elevation(30.0);
  renderer->ResetCamera();
  window->Render();

  vtkNew<vtkWindowToImageFilter> grabber;
  grabber->SetInput(window);
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputConnection(grabber->GetOutputPort());
  writer->SetFileName("edges.png");
  writer->Write();
  return 0;
}
