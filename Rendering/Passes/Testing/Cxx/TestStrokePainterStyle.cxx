// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// Part of the TestStrokePainter program: vtkNPRMakeStrokeStyle from an edge pass and a drawing
// pass, scaled by DPI / 72, and its defaults without passes.
//
// usage: TestStrokePainter style [DATA_DIR]
#include "nprTesting.h"

#include "vtkNPRDrawingPass.h"
#include "vtkNPREdgePass.h"
#include "vtkNPRStrokePainter.h"
#include "vtkNew.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include <cmath>

namespace
{
int Style()
{
  vtkNew<vtkNPREdgePass> edges;
  edges->SetLineWidth(2.0);
  edges->SetSilhouetteColor(0.1, 0.2, 0.3);
  edges->SetCreaseColor(0.4, 0.5, 0.6);
  edges->CreasesOff();
  vtkNew<vtkNPRDrawingPass> drawing;
  drawing->HiddenLinesOn();
  drawing->SetHiddenLineWidth(0.5);
  drawing->SetDashLength(3.0);
  drawing->SetGapLength(2.0);
  drawing->SetHiddenLineColor(0.7, 0.7, 0.7);
  vtkNPRStrokeStyle style = vtkNPRMakeStrokeStyle(drawing, edges, nullptr);
  NPR_CHECK(style.LineWidth == 2.0 && style.HiddenLineWidth == 1.0, "widths");
  NPR_CHECK(style.DashLength == 3.0 && style.GapLength == 2.0, "dashes");
  NPR_CHECK(style.HiddenLines && style.Silhouettes && !style.Creases, "flags");
  NPR_CHECK(style.SilhouetteColor[2] == 0.3 && style.CreaseColor[0] == 0.4 &&
      style.HiddenLineColor[1] == 0.7,
    "colours");
  // At 144 DPI every length doubles.
  vtkSmartPointer<vtkRenderWindow> window = nprCreateTestWindow(64, 64, nullptr);
  NPR_CHECK(window, "no window");
  if (!window)
  {
    return nprTestResult();
  }
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  window->SetDPI(144);
  style = vtkNPRMakeStrokeStyle(drawing, edges, renderer);
  NPR_CHECK(style.LineWidth == 4.0 && style.HiddenLineWidth == 2.0 && style.DashLength == 6.0 &&
      style.GapLength == 4.0,
    "at 144 DPI: " << style.LineWidth << " " << style.HiddenLineWidth << " " << style.DashLength
                   << " " << style.GapLength);
  // A width of their own for silhouettes and creases (at 144 DPI); hidden lines follow the
  // silhouettes' width; a kind's width of 0 is LineWidth.
  edges->SetSilhouetteLineWidth(3.0);
  edges->SetCreaseLineWidth(0.75);
  style = vtkNPRMakeStrokeStyle(drawing, edges, renderer);
  NPR_CHECK(style.LineWidth == 6.0 && style.CreaseLineWidth == 1.5 && style.HiddenLineWidth == 3.0,
    "kind widths at 144 DPI: " << style.LineWidth << " " << style.CreaseLineWidth << " "
                               << style.HiddenLineWidth);
  edges->SetCreaseLineWidth(0.0);
  style = vtkNPRMakeStrokeStyle(drawing, edges, renderer);
  NPR_CHECK(style.CreaseLineWidth == 4.0, "a crease width of 0: " << style.CreaseLineWidth);
  // Without passes: the defaults (1.5 px lines, hidden lines off, 0.6 of the width, 6/4 dashes).
  style = vtkNPRMakeStrokeStyle(nullptr, nullptr, nullptr);
  NPR_CHECK(style.LineWidth == 1.5 && style.CreaseLineWidth == 1.5 && !style.HiddenLines &&
      std::abs(style.HiddenLineWidth - 0.9) < 1e-12 && style.DashLength == 6.0,
    "defaults");
  return nprTestResult();
}
NPR_TEST_CASE("style", Style);
}
