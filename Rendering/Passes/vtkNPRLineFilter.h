// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// vtkNPREdgePass's widening of its one-pixel line image: the Gaussian as bilinear taps, each line
// kind's coverage mapping of the filtered image (its width's level set, one pixel of
// anti-aliasing), and the constants with which the width limit (MaximumLineFraction) narrows a
// line through its value. Private to NPR::Passes.
#ifndef vtkNPRLineFilter_h
#define vtkNPRLineFilter_h

#include <vector> // for the taps

class vtkShaderProgram;

struct vtkNPRLineFilter
{
  std::vector<float> Taps; // x, y, weight
  int Radius = 1;          // texels
  // Each kind's (silhouettes, creases, contours, suggestive contours) coverage mapping.
  float CoverageLevel[4] = { 0.5f, 0.5f, 0.5f, 0.5f };
  float CoverageSlope[4] = { 1.0f, 1.0f, 1.0f, 1.0f };
  double Widths[4] = { -1.0, -1.0, -1.0, -1.0 }; // the widths the filter was computed for
  // With a depth falloff (vtkNPREdgePass's DepthFalloff): the widths' scales at the near and far
  // clipping planes, and each kind's mapping at FalloffSteps scales evenly between them.
  static constexpr int FalloffSteps = 8;
  double Scales[2] = { 1.0, 1.0 };
  float FalloffLevels[FalloffSteps][4] = {};
  float FalloffSlopes[FalloffSteps][4] = {};

  // The taps for the widest line (at the larger scale), and each kind's level set of their
  // result at its own width (in pixels), at scale 1 and at the falloff's steps. Nothing to do
  // when the widths and scales are those of the last call.
  void Compute(const double widths[4], double nearScale = 1.0, double farScale = 1.0);
  bool HasFalloff() const { return this->Scales[0] != 1.0 || this->Scales[1] != 1.0; }

private:
  // The taps of the Gaussian of standard deviation sigma; returns the discrete kernel's sum.
  double ComputeTaps(double width, double sigma);
  // The level and slope of one kind's width with the filter of this width, sigma and sum.
  static void Coverage(
    double kindWidth, double filterWidth, double sigma, double sum, float& level, float& slope);
};

// The width limit's uniforms (glsl/vtkNPREdgeLimitFS.glsl) for the kinds' widths in pixels,
// filtered with the widest one's Gaussian, and the fraction of an object's width a line may take.
void vtkNPRSetWidthLimitUniforms(
  vtkShaderProgram* program, const double widths[4], double fraction);

#endif
