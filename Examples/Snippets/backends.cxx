// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// A headless window from vtkNPRRenderWindowFactory (nprSnippetWindow), one frame of a sphere, and
// the backend and OpenGL renderer it ran on (Documentation/backends.md shows the window's part).
#include "nprSnippet.h" // the renderer, the headless window

#include "vtkSphereSource.h"

#include <iostream>

int main()
{
  vtkNew<vtkSphereSource> sphere;
  vtkSmartPointer<vtkRenderer> renderer = nprSnippetRenderer(sphere->GetOutputPort());

  vtkSmartPointer<vtkRenderWindow> window = nprSnippetWindow(renderer, 800, 600);
  if (!window)
  {
    return 1; // the warning says why
  }
  window->Render();
  std::cout << vtkNPRRenderWindowFactory::GetBackendName(window) << ": "
            << vtkNPRRenderWindowFactory::GetGLRenderer(window) << "\n";
  return 0;
}
