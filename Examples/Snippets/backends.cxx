// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// A headless window from vtkNPRRenderWindowFactory, one frame of a sphere, and the backend and
// OpenGL renderer it ran on (Documentation/backends.md shows the window's part).
#include "vtkActor.h"
#include "vtkNPRRenderWindowFactory.h"
#include "vtkNew.h"
#include "vtkPolyDataMapper.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"

#include <iostream>

int main()
{
  vtkNew<vtkSphereSource> sphere;
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);

  vtkSmartPointer<vtkRenderWindow> window =
    vtkSmartPointer<vtkRenderWindow>::Take(vtkNPRRenderWindowFactory::CreateRenderWindow());
  if (!window)
  {
    return 1; // the warning says why
  }
  window->SetSize(800, 600);
  window->AddRenderer(renderer); // your vtkRenderer
  window->Render();
  std::cout << vtkNPRRenderWindowFactory::GetBackendName(window) << ": "
            << vtkNPRRenderWindowFactory::GetGLRenderer(window) << "\n";
  return 0;
}
