// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// Baseline images of the edge style: the CAD part and the bunny with blue creases, against
// Testing/Data/Baseline/edges_*.png (the comparison: nprTesting.h).
//
// usage: TestEdgePassBaseline CASE [DATA_DIR]   (CASE: the NPR_TEST_CASE names below)
#include "nprTesting.h"

#include "vtkImageData.h"
#include "vtkNPREdgePass.h"
#include "vtkNPRModelReader.h"
#include "vtkNew.h"
#include "vtkPolyDataNormals.h"

#include <functional>
#include <map>
#include <string>

namespace
{
using Scene = nprPassScene;

// ---- Baseline images: the CAD part and the bunny ----
int Baseline(const char* model, const char* name)
{
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputConnection(nprReadTestModel(model)->GetOutputPort());
  normals->SetFeatureAngle(30.0);
  normals->SplittingOn();
  Scene scene(400, 300);
  const double color[3] = { 0.85, 0.82, 0.75 };
  nprAddActor(scene.Renderer, normals->GetOutputPort(), color);
  nprTurnBaselineCamera(scene.Renderer);
  scene.Edges()->SetCreaseColor(0.1, 0.2, 0.6);
  NPR_CHECK(nprCompareWithBaseline(scene.Render(), name), name << " differs from its baseline");
  return nprTestResult();
}
NPR_TEST_CASE("baseline-cad", [] { return Baseline("cad_part.vtp", "edges_cad_part"); });
NPR_TEST_CASE("baseline-bunny", [] { return Baseline("bunny.ply", "edges_bunny"); });
}
