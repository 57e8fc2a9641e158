// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// The object-space ground truth of a view: vtkNPRReferenceMask's line mask of the CAD part,
// written as mask.png (Documentation/feature-lines.md shows its middle; run it from the
// repository root).
#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkImageData.h"
#include "vtkNPRModelReader.h"
#include "vtkNPRReferenceMask.h"
#include "vtkNPRRenderWindowFactory.h"
#include "vtkNew.h"
#include "vtkPNGWriter.h"
#include "vtkPolyDataMapper.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"

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
  auto window =
    vtkSmartPointer<vtkRenderWindow>::Take(vtkNPRRenderWindowFactory::CreateRenderWindow());
  if (!window)
  {
    return 1;
  }
  window->SetSize(960, 540);
  window->AddRenderer(renderer);
  renderer->GetActiveCamera()->Azimuth(30.0);
  renderer->GetActiveCamera()->Elevation(30.0);
  renderer->ResetCamera();
  window->Render(); // sets the clipping range the mask is computed with

  vtkNew<vtkNPRReferenceMask> reference;
  reference->SetRenderer(renderer);          // its active camera and actors
  reference->SetSize(1920, 1080);            // default 0, 0: the renderer's size in its window
  reference->Update();                       // false, with an error, without renderer or size
  vtkImageData* mask = reference->GetMask(); // 1 x unsigned char, 255 on lines, row 0 at the bottom

  vtkNew<vtkPNGWriter> writer;
  writer->SetInputData(mask);
  writer->SetFileName("mask.png");
  writer->Write();
  return 0;
}
