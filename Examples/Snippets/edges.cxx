// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// The edge style on a model from Testing/Data, rendered headless into edges.png
// (Documentation/edges.md shows this program; run it from the repository root).
#include "nprSnippet.h" // the model's renderer, the headless window, the PNG

#include "vtkNPREdgePass.h"
#include "vtkNPRPass.h"

int main()
{
  vtkSmartPointer<vtkRenderer> renderer = nprSnippetModel("Testing/Data/cad_part.vtp");

  vtkNew<vtkNPRPass> npr; // style EDGES: silhouettes, creases and contours, black, 1.5 px
  renderer->SetPass(npr);

  vtkNPREdgePass* edges = npr->GetEdgePass();
  edges->SetLineWidth(2.0);
  edges->SetCreaseAngle(40.0);
  edges->SetSilhouetteColor(0.8, 0.0, 0.0);
  edges->SetContourSideToBoth();
  edges->CreasesOff(); // a line type off: the G-buffer then holds no normals

  vtkSmartPointer<vtkRenderWindow> window = nprSnippetWindow(renderer, 800, 600);
  if (!window)
  {
    return 1;
  }
  nprSnippetTurn(renderer, 30.0, 30.0);
  window->Render();
  return nprSnippetWritePNG(window, "edges.png") ? 0 : 1;
}
