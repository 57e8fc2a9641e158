// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// Renders a sphere headless with an installed vtkNPR, in the edge style, and counts the pixels it
// covers and its outline's dark pixels.
#include "vtkActor.h"
#include "vtkNPRPass.h"
#include "vtkNPRRenderWindowFactory.h"
#include "vtkNew.h"
#include "vtkPolyDataMapper.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"
#include "vtkUnsignedCharArray.h"

#include <iostream>

int main(int argc, char* argv[])
{
  const char* backend = argc > 1 ? argv[1] : nullptr;
  auto window =
    vtkSmartPointer<vtkRenderWindow>::Take(vtkNPRRenderWindowFactory::CreateRenderWindow(backend));
  if (!window)
  {
    std::cerr << "consumer: no render window\n";
    return 1;
  }
  vtkNew<vtkSphereSource> sphere;
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  renderer->SetBackground(1.0, 1.0, 1.0);
  vtkNew<vtkNPRPass> edges; // the default style: edges over the shaded surface
  renderer->SetPass(edges);
  window->AddRenderer(renderer);
  window->SetSize(64, 64);
  window->Render();
  vtkNew<vtkUnsignedCharArray> pixels;
  window->GetPixelData(0, 0, 63, 63, 0, pixels);
  long objectPixels = 0, linePixels = 0;
  for (vtkIdType i = 0; i < 64 * 64; ++i)
  {
    objectPixels += pixels->GetValue(3 * i + 2) < 250 ? 1 : 0;
    linePixels += pixels->GetValue(3 * i) < 60 ? 1 : 0;
  }
  std::cout << "consumer: rendered " << objectPixels << " object pixels, " << linePixels
            << " line pixels with " << vtkNPRRenderWindowFactory::GetBackendName(window) << "\n";
  return objectPixels > 400 && linePixels > 40 ? 0 : 1;
}
