// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// The object-space ground truth of a view: vtkNPRReferenceMask's line mask of the CAD part,
// written as mask.png (Documentation/feature-lines.md shows its middle; run it from the
// repository root).
#include "nprSnippet.h" // the model's renderer, the headless window

#include "vtkImageData.h"
#include "vtkNPRReferenceMask.h"

int main()
{
  vtkSmartPointer<vtkRenderer> renderer = nprSnippetModel("Testing/Data/cad_part.vtp");
  vtkSmartPointer<vtkRenderWindow> window = nprSnippetWindow(renderer, 960, 540);
  if (!window)
  {
    return 1;
  }
  nprSnippetTurn(renderer, 30.0, 30.0);
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
  return writer->GetErrorCode() == 0 ? 0 : 1;
}
