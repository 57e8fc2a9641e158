// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nprCameraOptions.h"

#include "nprArguments.h"

#include "vtkCamera.h"
#include "vtkRenderer.h"

const char* const nprCameraOptionsHelp =
  R"(  --azimuth DEG            rotate the camera about the view up after the reset
  --elevation DEG          rotate the camera up or down after the reset
  --zoom FACTOR            zoom (> 1 closer) after the reset
)";

bool nprParseCameraOption(nprArgumentReader& arguments, nprCameraMove& move)
{
  const std::string& arg = arguments.Current();
  if (arg == "--azimuth")
  {
    move.Azimuth = nprParseNumber(arg, arguments.Value());
  }
  else if (arg == "--elevation")
  {
    move.Elevation = nprParseNumber(arg, arguments.Value());
  }
  else if (arg == "--zoom")
  {
    move.Zoom = nprParseNumber(arg, arguments.Value());
    if (move.Zoom <= 0.0)
    {
      throw nprUsageError("--zoom expects a positive factor");
    }
  }
  else
  {
    return false;
  }
  move.Given = true;
  return true;
}

void nprApplyCameraMove(vtkRenderer* renderer, const nprCameraMove& move)
{
  vtkCamera* camera = renderer->GetActiveCamera();
  renderer->ResetCamera();
  camera->Azimuth(move.Azimuth);
  camera->Elevation(move.Elevation);
  camera->OrthogonalizeViewUp();
  camera->Zoom(move.Zoom);
  renderer->ResetCameraClippingRange();
}
