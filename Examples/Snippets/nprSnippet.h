// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// What the snippets share, so that each shows only its style: a renderer of a model, a headless
// window, a turned camera and a PNG of the window. Plain VTK and vtkNPRRenderWindowFactory; copy
// it with the snippet you copy.
#ifndef nprSnippet_h
#define nprSnippet_h

#include "vtkActor.h"
#include "vtkAlgorithmOutput.h"
#include "vtkCamera.h"
#include "vtkNPRModelReader.h"
#include "vtkNPRRenderWindowFactory.h"
#include "vtkNew.h"
#include "vtkPNGWriter.h"
#include "vtkPolyDataMapper.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkWindowToImageFilter.h"

// A renderer of one actor that shows the polygons of a pipeline's output.
inline vtkSmartPointer<vtkRenderer> nprSnippetRenderer(vtkAlgorithmOutput* polygons)
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(polygons);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  auto renderer = vtkSmartPointer<vtkRenderer>::New();
  renderer->AddActor(actor);
  return renderer;
}

// The same of a model file (.stl .obj .ply .vtp .vtk .gltf .glb .off), on white.
inline vtkSmartPointer<vtkRenderer> nprSnippetModel(const char* fileName)
{
  vtkNew<vtkNPRModelReader> reader;
  reader->SetFileName(fileName);
  vtkSmartPointer<vtkRenderer> renderer = nprSnippetRenderer(reader->GetOutputPort());
  renderer->SetBackground(1.0, 1.0, 1.0);
  return renderer;
}

// A headless window of width x height showing the renderer: EGL, or the backend named by
// NPR_BACKEND; null, with a warning that says why, if none renders.
inline vtkSmartPointer<vtkRenderWindow> nprSnippetWindow(
  vtkRenderer* renderer, int width, int height)
{
  vtkSmartPointer<vtkRenderWindow> window =
    vtkSmartPointer<vtkRenderWindow>::Take(vtkNPRRenderWindowFactory::CreateRenderWindow());
  if (window)
  {
    window->SetSize(width, height);
    window->AddRenderer(renderer); // your vtkRenderer
  }
  return window;
}

// The camera turned about the model (degrees), then moved to frame it all; after
// nprSnippetWindow, so that the framing fits the window's shape.
inline void nprSnippetTurn(vtkRenderer* renderer, double azimuth, double elevation)
{
  renderer->GetActiveCamera()->Azimuth(azimuth);
  renderer->GetActiveCamera()->Elevation(elevation);
  renderer->ResetCamera();
}

// The window's last frame written as a PNG file; false if it could not be written.
inline bool nprSnippetWritePNG(vtkRenderWindow* window, const char* fileName)
{
  vtkNew<vtkWindowToImageFilter> grabber;
  grabber->SetInput(window);
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputConnection(grabber->GetOutputPort());
  writer->SetFileName(fileName);
  writer->Write();
  return writer->GetErrorCode() == 0;
}

#endif
