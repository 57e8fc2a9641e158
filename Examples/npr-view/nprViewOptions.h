// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// npr-view's command line: its options, --help and their parsing.
#ifndef nprViewOptions_h
#define nprViewOptions_h

#include "nprCameraOptions.h"
#include "nprPassSettings.h"

#include <string>
#include <vector>

// With the models, the frame's options and the camera's start (nprSceneOptions).
struct nprViewOptions : nprSceneOptions
{
  std::string OutputPrefix = "npr-view-";
  int OrbitFrames = 0;  // --orbit-benchmark N
  nprPassSettings Pass; // --style and the flags of the styles, as npr-render takes them
};

// Prints --help and exits for -h; throws nprUsageError for anything else that is wrong.
nprViewOptions nprParseViewOptions(int argc, char* argv[]);

#endif
