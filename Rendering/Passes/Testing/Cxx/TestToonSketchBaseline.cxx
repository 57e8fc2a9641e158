// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// Baseline images of the toon, toon+edges and sketch styles: toon (bunny), toon+edges (CAD
// part), sketch with screen noise (bunny), sketch on paper with toon fill and screen noise (CAD
// part), sketch with surface noise (the default; bunny and CAD part), against
// Testing/Data/Baseline/{toon,toon_edges,sketch}_*.png (the comparison: nprTesting.h).
//
// usage: TestToonSketchBaseline CASE [DATA_DIR]   (CASE: the NPR_TEST_CASE names below)
#include "nprTesting.h"

#include "vtkImageData.h"
#include "vtkNPRSketchPass.h"

#include <functional>
#include <map>
#include <string>

namespace
{
using Scene = nprPassScene;

// ---- Baselines ----
int Baseline(const char* model, const char* name, int style, bool paper,
  int noiseSpace = vtkNPRSketchPass::SURFACE)
{
  Scene scene(400, 300);
  nprAddBaselineModel(scene.Renderer, model);
  scene.Pass->SetStyle(style);
  scene.Sketch()->SetNoiseSpace(noiseSpace);
  scene.Sketch()->SetPaper(paper);
  scene.Pass->SetSketchToonShading(paper);
  NPR_CHECK(nprCompareWithBaseline(scene.Render(), name), name << " differs from its baseline");
  return nprTestResult();
}
NPR_TEST_CASE("baseline-toon-bunny",
  [] { return Baseline("bunny.ply", "toon_bunny", vtkNPRPass::TOON, false); });
NPR_TEST_CASE("baseline-toon-cad",
  [] { return Baseline("cad_part.vtp", "toon_edges_cad_part", vtkNPRPass::TOON_EDGES, false); });
NPR_TEST_CASE("baseline-sketch-bunny",
  []
  {
    return Baseline(
      "bunny.ply", "sketch_bunny", vtkNPRPass::SKETCH, false, vtkNPRSketchPass::SCREEN);
  });
NPR_TEST_CASE("baseline-sketch-cad",
  []
  {
    return Baseline(
      "cad_part.vtp", "sketch_cad_part", vtkNPRPass::SKETCH, true, vtkNPRSketchPass::SCREEN);
  });
NPR_TEST_CASE("baseline-sketch-surface-bunny",
  [] { return Baseline("bunny.ply", "sketch_surface_bunny", vtkNPRPass::SKETCH, false); });
NPR_TEST_CASE("baseline-sketch-surface-cad",
  [] { return Baseline("cad_part.vtp", "sketch_surface_cad_part", vtkNPRPass::SKETCH, true); });
}
