// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// Temporal coherence of drawn lines between two frames of a camera path: each line pixel of a
// frame is carried into the next through its depth and the two cameras, and counted as landing
// when a line pixel of the next frame lies within 1 pixel. For npr-benchmark --coherence and the
// sketch pass's tests.
#ifndef nprCoherence_h
#define nprCoherence_h

#include <vector>

class vtkCamera;
class vtkRenderWindow;
class vtkRenderer;

// A rendered frame: its line pixels (ink: luminance below 60 of 255), window depths and the
// camera's world to normalised device matrix (row major) for the renderer's aspect.
struct nprCoherenceFrame
{
  int Width = 0;
  int Height = 0;
  std::vector<unsigned char> Lines; // row 0 = bottom, 1 = line pixel
  std::vector<float> Depth;         // window depth, 1 = nothing drawn
  double WorldToDevice[16] = {};
};

// Reads the frame last rendered into the window (the renderer fills it).
nprCoherenceFrame nprCaptureCoherenceFrame(vtkRenderWindow* window, vtkRenderer* renderer);

struct nprCoherenceStep
{
  long long Lines = 0;              // line pixels of the first frame
  long long Carried = 0;            // of those, with a depth, that land inside the second frame
  long long Landed = 0;             // of those, within 1 pixel of a line pixel of the second frame
  long long LandedExactly = 0;      // of those, on a line pixel of the second frame
  long long NextLines = 0;          // line pixels of the second frame
  long long Appeared = 0;           // of those, with no carried line pixel within 1 pixel
  double LandedFraction = 0;        // Landed / Carried
  double LandedExactlyFraction = 0; // LandedExactly / Carried
  double AppearedFraction = 0;      // Appeared / NextLines
  double VanishedFraction = 0;      // 1 - LandedFraction
};

// The first frame's line pixels carried into the second (margin: pixels this close to the
// border are left out, as what is outside the first frame may come into view).
nprCoherenceStep nprCompareCoherenceFrames(
  const nprCoherenceFrame& first, const nprCoherenceFrame& second, int margin = 2);

// Intersection over union of the line pixels of first and of second moved by (dx, dy) pixels,
// over the pixels at least margin from the border in both.
double nprShiftedLineIoU(
  const nprCoherenceFrame& first, const nprCoherenceFrame& second, int dx, int dy, int margin);

// Moves a parallel camera right by pixels of a viewport of the given height (the image moves
// left by as many).
void nprPanParallelCamera(vtkCamera* camera, double pixels, int height);

#endif
