// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// npr-render's command line: its options, --help and their parsing.
#ifndef nprRenderOptions_h
#define nprRenderOptions_h

#include "nprCameraOptions.h"
#include "nprPassSettings.h"

#include <set>
#include <string>
#include <vector>

// With the models, the frame's options and the camera's start (nprSceneOptions).
struct nprRenderOptions : nprSceneOptions
{
  std::string Output;
  std::string CameraOut;
  int Frames = 0;
  int Orbit = 0;             // --orbit N frames
  double OrbitDegrees = 360; // --orbit-degrees
  double Rate = 25;          // --fps
  std::string Backend;
  std::string EdgeMask;
  std::string ReferenceMask;
  std::vector<std::string> CompareStyles;
  bool Quiet = false; // --quiet: no progress lines
  std::string Sheet;  // --sheet VIEWS: a drawing sheet of these views
  std::string SheetPaper = "A4";
  bool SheetThirdAngle = false;
  double SheetMargin = 10.0;        // millimetres
  std::set<std::string> SheetFlags; // the --sheet-* flags given
  bool FillFaces = false;           // --fill-faces: filled faces in the vector drawing
  int FillColors = 0;               // --fill-colors: vtkNPRDrawingExporter::FillColorModes
  bool FillColorsGiven = false;
  nprPassSettings Pass; // --style and the flags of the styles
};

// Prints --help and exits for -h; throws nprUsageError for anything else that is wrong.
nprRenderOptions nprParseRenderOptions(int argc, char* argv[]);

#endif
