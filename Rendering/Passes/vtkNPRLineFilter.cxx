// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNPRLineFilter.h"

#include "vtkShaderProgram.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace
{
// The standard deviation of the Gaussian that widens the one-pixel line image to a line width.
double LineSigma(double width)
{
  return std::max(0.6, 0.3 * width);
}

// The slope of the coverage mapping of a line of this width, filtered with the Gaussian of
// standard deviation sigma, in units of its level: one pixel of anti-aliasing, and none where
// there is no line at all (0.5 - level / slope < 0).
double CoverageSlopeOverLevel(double width, double sigma)
{
  return std::min(0.5 * width / (sigma * sigma), 1.95);
}
}

void vtkNPRLineFilter::Compute(const double widths[4], double nearScale, double farScale)
{
  if (std::equal(widths, widths + 4, this->Widths) && this->Scales[0] == nearScale &&
    this->Scales[1] == farScale)
  {
    return;
  }
  std::copy_n(widths, 4, this->Widths);
  this->Scales[0] = nearScale;
  this->Scales[1] = farScale;
  const double width =
    *std::max_element(widths, widths + 4) * std::max({ 1.0, nearScale, farScale });
  const double sigma = LineSigma(width);
  const double sum = this->ComputeTaps(width, sigma);
  for (int kind = 0; kind < 4; ++kind)
  {
    Coverage(widths[kind], width, sigma, sum, this->CoverageLevel[kind], this->CoverageSlope[kind]);
    for (int step = 0; step < FalloffSteps; ++step)
    {
      const double scale = nearScale + (farScale - nearScale) * step / (FalloffSteps - 1.0);
      Coverage(widths[kind] * scale, width, sigma, sum, this->FalloffLevels[step][kind],
        this->FalloffSlopes[step][kind]);
    }
  }
}

double vtkNPRLineFilter::ComputeTaps(double width, double sigma)
{
  this->Radius = std::max(1, static_cast<int>(std::floor(0.5 * width + 0.5)));
  std::vector<double> g(this->Radius + 2, 0.0);
  double sum = 0.0;
  for (int j = 0; j <= this->Radius; ++j)
  {
    g[j] = std::exp(-j * j / (2.0 * sigma * sigma));
    sum += j == 0 ? g[j] : 2.0 * g[j];
  }
  for (double& value : g)
  {
    value /= sum;
  }
  // One dimension: offsets and weights of bilinear taps reproducing the discrete kernel.
  std::vector<std::pair<double, double>> taps1D;
  if (this->Radius == 1)
  {
    // [a b a] = two taps at +-2a of weight 1/2.
    taps1D = { { -2.0 * g[1], 0.5 }, { 2.0 * g[1], 0.5 } };
  }
  else
  {
    taps1D.push_back({ 0.0, g[0] });
    for (int i = 1; i <= this->Radius; i += 2)
    {
      const double weight = g[i] + g[i + 1];
      const double offset = i + g[i + 1] / weight;
      taps1D.push_back({ offset, weight });
      taps1D.push_back({ -offset, weight });
    }
  }
  this->Taps.clear();
  for (const auto& y : taps1D)
  {
    for (const auto& x : taps1D)
    {
      this->Taps.insert(this->Taps.end(),
        { static_cast<float>(x.first), static_cast<float>(y.first),
          static_cast<float>(x.second * y.second) });
    }
  }
  return sum;
}

void vtkNPRLineFilter::Coverage(
  double kindWidth, double filterWidth, double sigma, double sum, float& level, float& slope)
{
  // Across a one-pixel line the filtered value is P(d) = g(d): coverage is P's level set at d =
  // width / 2, with the slope there giving one pixel of anti-aliasing. A kind narrower than the
  // filter's width meets a gentler slope of P there, which would leave its core grey: its slope
  // is steepened so that the line's centre is covered as much as a line of its width covers a
  // pixel (fully from one pixel up).
  const double peak = 1.0 / sum; // P(0)
  const double half = 0.5 * kindWidth;
  const double value = std::exp(-half * half / (2.0 * sigma * sigma)) / sum;
  double steepness = CoverageSlopeOverLevel(kindWidth, sigma) * value;
  const double centre = std::min(1.0, kindWidth); // the coverage wanted at d = 0
  if (kindWidth < filterWidth && centre > 0.5)
  {
    steepness = std::min(steepness, (peak - value) / (centre - 0.5));
  }
  level = static_cast<float>(value);
  slope = static_cast<float>(steepness);
}

void vtkNPRSetWidthLimitUniforms(vtkShaderProgram* program, const double widths[4], double fraction)
{
  const double widest = *std::max_element(widths, widths + 4);
  const double sigma = LineSigma(widest);
  const double exponent = 1.0 / (8.0 * sigma * sigma);
  float kindWidths[4], vanishing[4];
  for (int kind = 0; kind < 4; ++kind)
  {
    const double width = widths[kind];
    const double peakOverLevel = std::exp(width * width * exponent); // P(0) / P(w / 2)
    kindWidths[kind] = static_cast<float>(width);
    vanishing[kind] = static_cast<float>(
      std::max(0.0, (1.0 - 0.5 * CoverageSlopeOverLevel(width, sigma)) / peakOverLevel));
  }
  program->SetUniform4f("widthLimitWidths", kindWidths);
  program->SetUniformf("widthLimitFraction", static_cast<float>(fraction));
  program->SetUniformf("widthLimitExponent", static_cast<float>(exponent));
  program->SetUniform4f("widthLimitVanishing", vanishing);
  program->SetUniformi("widthLimitPixels", static_cast<int>(std::ceil(widest / fraction)));
}
