// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// The inked style on the bunny, rendered headless into inked.png
// (Documentation/classic-techniques.md shows its middle; run it from the repository root).
#include "nprSnippet.h" // the model's renderer, the headless window, the PNG

#include "vtkNPRInkPass.h"
#include "vtkNPRPass.h"

int main()
{
  vtkSmartPointer<vtkRenderer> renderer = nprSnippetModel("Testing/Data/bunny.ply");

  vtkNew<vtkNPRPass> npr;
  npr->SetStyleToInked();
  npr->GetInkPass()->SetLineWidth(2.0); // visible pixels at 72 DPI, 0.5..16
  npr->GetInkPass()->SetInkColor(0.1, 0.1, 0.3);
  renderer->SetPass(npr);

  vtkSmartPointer<vtkRenderWindow> window = nprSnippetWindow(renderer, 480, 360);
  if (!window)
  {
    return 1;
  }
  window->Render();
  return nprSnippetWritePNG(window, "inked.png") ? 0 : 1;
}
