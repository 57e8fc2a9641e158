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

bool nprParseSceneOption(nprArgumentReader& arguments, nprSceneOptions& scene)
{
  const std::string& arg = arguments.Current();
  if (arg == "--size")
  {
    const auto size = nprParseSize("--size", arguments.Value(), 1, 16384, "WxH (e.g. 1024x768)");
    scene.Width = size.first;
    scene.Height = size.second;
    scene.SizeGiven = true;
  }
  else if (arg == "--background")
  {
    nprParseColor(arg, arguments.Value(), scene.Background);
  }
  else if (arg == "--camera-in")
  {
    scene.CameraIn = arguments.Value();
  }
  else if (arg.size() > 1 && arg[0] == '-')
  {
    return nprParseCameraOption(arguments, scene.Camera);
  }
  else
  {
    scene.Models.push_back(arg);
  }
  return true;
}

void nprCheckSceneOptions(const nprSceneOptions& scene)
{
  if (scene.Models.empty())
  {
    throw nprUsageError("no model file given (see --help)");
  }
  if (!scene.CameraIn.empty() && scene.Camera.Given)
  {
    throw nprUsageError("--azimuth, --elevation and --zoom move the reset camera; they cannot be "
                        "combined with --camera-in");
  }
}

nprCameraState nprReadStartCamera(const nprSceneOptions& scene, int& width, int& height)
{
  width = scene.Width;
  height = scene.Height;
  nprCameraState start;
  if (!scene.CameraIn.empty())
  {
    start = nprReadCameraFile(scene.CameraIn);
    if (!scene.SizeGiven && start.Size[0] > 0)
    {
      width = start.Size[0];
      height = start.Size[1];
    }
  }
  return start;
}
