// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// The settings of a vtkNPRPass that the command-line programs expose, and the pass made from
// them. The defaults are the passes' own.
#ifndef nprPassSettings_h
#define nprPassSettings_h

#include "vtkNPREdgePass.h"
#include "vtkNPRSketchPass.h"
#include "vtkSmartPointer.h"

#include <set>
#include <string>

class vtkNPRPass;

struct nprPassSettings
{
  std::string Style = "shaded"; // vtkNPRPass::GetStyleName()

  // Lines (edges, toon+edges, sketch); LineWidth and SilhouetteColor also ink (inked).
  bool Silhouettes = true;
  bool Creases = true;
  bool Contours = true;
  double SilhouetteThreshold = 0.005;
  bool SmoothSilhouettes = false;
  bool SuggestiveContours = false;
  double SuggestiveContourThreshold = 0.01;
  double CreaseAngle = 30.0;
  int ContourSide = vtkNPREdgePass::INSIDE;
  double LineWidth = 1.5;
  // Each kind's width (0: LineWidth).
  double SilhouetteLineWidth = 0.0;
  double CreaseLineWidth = 0.0;
  double ContourLineWidth = 0.0;
  double SuggestiveContourLineWidth = 0.0;
  double MaximumLineFraction = 0.0;
  double SurfaceLineShade = 0.0;
  bool DepthFalloff = false; // widths from NearLineScale to FarLineScale over the depth
  double NearLineScale = 1.5;
  double FarLineScale = 0.5;
  double SilhouetteColor[3] = { 0.0, 0.0, 0.0 };
  double CreaseColor[3] = { 0.0, 0.0, 0.0 };
  double ContourColor[3] = { 0.0, 0.0, 0.0 };
  double SuggestiveContourColor[3] = { 0.0, 0.0, 0.0 };
  bool FaceCreases = false;
  bool AntiAliasing = true;
  int Encoding = vtkNPREdgePass::FLOAT;
  double PackedThreshold = 0.1;
  bool PackedBlur = false;

  // Toon shading (toon, toon+edges, and sketch with SketchToon)
  int ToonBands = 3;
  bool ToonPerVertex = false;

  // Sketch
  double Uncertainty = 3.0;
  int NoiseSeed = 1;
  double NoiseFrequency = 2.0;
  int NoiseSpace = vtkNPRSketchPass::SURFACE;
  bool Paper = false;
  double PaperColor[3] = { 1.0, 0.98, 0.92 };
  bool SketchToon = false;

  // Technical drawing
  bool HiddenLines = false;
  double TaperLength = 0.0;
  double CurvatureWidth = 0.0;

  // The flags given on the command line (nprParsePassOption), for nprCheckPassOptions.
  std::set<std::string> GivenFlags;
};

// A vtkNPRPass of settings.Style with every setting applied (also for "shaded": whether to use
// it, rather than VTK's own chain, is the caller's choice).
vtkSmartPointer<vtkNPRPass> nprMakePass(const nprPassSettings& settings);

// Sets settings on an existing pass (style included): what nprMakePass does to a new one. The
// pass keeps its shaders and buffers, so a viewer can change settings from frame to frame.
void nprApplyPassSettings(vtkNPRPass* pass, const nprPassSettings& settings);

#endif
