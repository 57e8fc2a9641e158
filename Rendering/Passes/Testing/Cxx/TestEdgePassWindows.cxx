// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// The edge pass in several windows of one process, through resizes and
// ReleaseGraphicsResources: lines every time.
//
// usage: TestEdgePassWindows CASE [DATA_DIR]   (CASE: the NPR_TEST_CASE names below)
#include "nprTesting.h"

#include "vtkCamera.h"
#include "vtkImageData.h"
#include "vtkRenderWindow.h"

#include <functional>
#include <map>
#include <string>

namespace
{
using Scene = nprPassScene;

// ---- Resizes, releases and several windows in one process ----
int Windows()
{
  for (int round = 0; round < 2; ++round)
  {
    Scene first(200, 150);
    Scene second(160, 120);
    for (Scene* scene : { &first, &second })
    {
      const double origin[3] = { 0, 0, 0 }, grey[3] = { 0.8, 0.8, 0.8 };
      nprAddCube(scene->Renderer, origin, 1.0, grey);
      scene->Camera()->Azimuth(30);
      scene->Camera()->Elevation(30);
      scene->Renderer->ResetCamera();
      NPR_CHECK(nprCountAbove(scene->Mask(), 127) > 100, "no lines in a window");
    }
    first.Window->SetSize(320, 240);
    auto mask = first.Mask();
    NPR_CHECK(
      mask->GetDimensions()[0] == 320 && nprCountAbove(mask, 127) > 150, "no lines after a resize");
    first.Renderer->ReleaseGraphicsResources(first.Window);
    first.Camera()->Azimuth(10);
    NPR_CHECK(nprCountAbove(first.Mask(), 127) > 150, "no lines after ReleaseGraphicsResources");
    NPR_CHECK(nprCountAbove(second.Mask(), 127) > 100, "the second window lost its lines");
  }
  return nprTestResult();
}
NPR_TEST_CASE("windows", Windows);
}
