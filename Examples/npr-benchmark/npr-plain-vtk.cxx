// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// npr-plain-vtk: what a VTK user writes to look at a PLY file (vtkPLYReader, vtkPolyDataNormals
// with its defaults, one render, a PNG), the baseline of npr-benchmark --scale. Only the window
// is the project's (vtkNPRRenderWindowFactory), so that it draws headless through the same
// OpenGL as npr-render.
// usage: npr-plain-vtk FILE.ply WIDTHxHEIGHT OUT.png
#include "vtkActor.h"
#include "vtkNPRRenderWindowFactory.h"
#include "vtkNew.h"
#include "vtkPLYReader.h"
#include "vtkPNGWriter.h"
#include "vtkPolyDataMapper.h"
#include "vtkPolyDataNormals.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkWindowToImageFilter.h"

#include <cstdio>
#include <iostream>

int main(int argc, char* argv[])
{
  int width = 0, height = 0;
  if (argc != 4 || std::sscanf(argv[2], "%dx%d", &width, &height) != 2 || width <= 0 || height <= 0)
  {
    std::cerr << "usage: npr-plain-vtk FILE.ply WIDTHxHEIGHT OUT.png\n";
    return 2;
  }
  vtkNew<vtkPLYReader> reader;
  reader->SetFileName(argv[1]);
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputConnection(reader->GetOutputPort());
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(normals->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);

  vtkSmartPointer<vtkRenderWindow> window =
    vtkSmartPointer<vtkRenderWindow>::Take(vtkNPRRenderWindowFactory::CreateRenderWindow());
  if (!window)
  {
    return 1;
  }
  window->SetSize(width, height);
  window->AddRenderer(renderer);
  renderer->ResetCamera();
  window->Render();

  vtkNew<vtkWindowToImageFilter> image;
  image->SetInput(window);
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputConnection(image->GetOutputPort());
  writer->SetFileName(argv[3]);
  writer->Write();
  return writer->GetErrorCode() == 0 && reader->GetOutput()->GetNumberOfCells() > 0 ? 0 : 1;
}
