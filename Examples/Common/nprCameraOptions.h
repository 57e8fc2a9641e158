// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// What npr-render and npr-view share of their command lines: --azimuth, --elevation and --zoom
// (the camera moves after the reset that fits the models in view), and with them the models,
// --size, --background and --camera-in (nprSceneOptions).
#ifndef nprCameraOptions_h
#define nprCameraOptions_h

#include "nprCameraJson.h" // nprCameraState

#include <string>
#include <vector>

class nprArgumentReader;
class vtkRenderer;

// Their help text (ends with a newline).
extern const char* const nprCameraOptionsHelp;

struct nprCameraMove
{
  double Azimuth = 0.0;
  double Elevation = 0.0;
  double Zoom = 1.0;
  bool Given = false; // any of the three on the command line
};

// When the reader's current argument is one of the three, parses its value into move and returns
// true; false for any other argument. Throws nprUsageError for a bad value.
bool nprParseCameraOption(nprArgumentReader& arguments, nprCameraMove& move);

// Resets the renderer's camera to its props, then turns and zooms it by move.
void nprApplyCameraMove(vtkRenderer* renderer, const nprCameraMove& move);

// What both programs draw and from where: the models (the arguments that are not options), the
// frame's --size and --background, and where the camera starts (--camera-in or the moves).
struct nprSceneOptions
{
  std::vector<std::string> Models;
  int Width = 1024;
  int Height = 768;
  bool SizeGiven = false;
  double Background[3] = { 1.0, 1.0, 1.0 };
  std::string CameraIn;
  nprCameraMove Camera; // --azimuth, --elevation, --zoom
};

// When the reader's current argument is a model or one of the options above (the moves included),
// takes it into scene and returns true; false for any other option. Throws nprUsageError for a
// bad value.
bool nprParseSceneOption(nprArgumentReader& arguments, nprSceneOptions& scene);

// Throws nprUsageError when no model is given, or when the moves come with --camera-in (they move
// the reset camera).
void nprCheckSceneOptions(const nprSceneOptions& scene);

// The camera of --camera-in (a default state without one), read before the window so that a bad
// file fails fast. width and height: --size, else the size the file was saved at, else the
// default.
nprCameraState nprReadStartCamera(const nprSceneOptions& scene, int& width, int& height);

#endif
