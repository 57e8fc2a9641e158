// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// The benchmark's error figures (nprEdgeMetrics): the distance transform against brute force,
// and precision, recall, F1 and mean distance on masks whose answers are known.
#include "nprEdgeMetrics.h"
#include "nprTesting.h"

#include <cmath>
#include <cstdlib>
#include <random>
#include <vector>

namespace
{
struct Mask
{
  int Width, Height;
  std::vector<unsigned char> Pixels;
  Mask(int width, int height)
    : Width(width)
    , Height(height)
    , Pixels(static_cast<size_t>(width) * height, 0)
  {
  }
  void Set(int x, int y)
  {
    if (x >= 0 && y >= 0 && x < this->Width && y < this->Height)
    {
      this->Pixels[static_cast<size_t>(y) * this->Width + x] = 255;
    }
  }
  void VerticalLine(int x, int y0, int y1)
  {
    for (int y = y0; y <= y1; ++y)
    {
      this->Set(x, y);
    }
  }
  const unsigned char* Data() const { return this->Pixels.data(); }
};

// A width x height mask of one vertical line, at x from y0 to y1.
Mask LineMask(int width, int height, int x, int y0, int y1)
{
  Mask mask(width, height);
  mask.VerticalLine(x, y0, y1);
  return mask;
}

// The figures of the method's mask against the reference's (of the same size).
nprEdgeMetrics Compare(const Mask& method, const Mask& reference)
{
  nprEdgeMetrics m;
  m.Compute(method.Data(), reference.Data(), reference.Width, reference.Height);
  return m;
}

bool Near(double a, double b, double tolerance = 1e-9)
{
  return std::abs(a - b) <= tolerance;
}

bool Finite(const nprEdgeMetrics& m)
{
  for (double t : { 0.0, 1.0, 2.0 })
  {
    if (!std::isfinite(m.Precision(t)) || !std::isfinite(m.Recall(t)) || !std::isfinite(m.F1(t)))
    {
      return false;
    }
  }
  return std::isfinite(m.MeanSymmetricDistance());
}

void TestDistanceTransform()
{
  // Random sparse masks (including a single pixel and full rows) against brute force.
  std::mt19937 random(7);
  for (int trial = 0; trial < 20; ++trial)
  {
    const int width = 5 + trial * 3, height = 3 + (trial * 7) % 29;
    Mask mask(width, height);
    std::uniform_int_distribution<int> pick(0, width * height - 1);
    const int points = trial == 0 ? 1 : 1 + trial % 9;
    for (int i = 0; i < points; ++i)
    {
      const int index = pick(random);
      mask.Set(index % width, index / width);
    }
    if (trial == 5)
    {
      for (int x = 0; x < width; ++x)
      {
        mask.Set(x, height / 2);
      }
    }
    const std::vector<double> squared = nprDistanceTransform::Compute(mask.Data(), width, height);
    int wrong = 0;
    for (int y = 0; y < height; ++y)
    {
      for (int x = 0; x < width; ++x)
      {
        double best = nprDistanceTransform::Infinite;
        for (int v = 0; v < height; ++v)
        {
          for (int u = 0; u < width; ++u)
          {
            if (mask.Pixels[static_cast<size_t>(v) * width + u])
            {
              best = std::min(best, static_cast<double>((x - u) * (x - u) + (y - v) * (y - v)));
            }
          }
        }
        wrong += squared[static_cast<size_t>(y) * width + x] == best ? 0 : 1;
      }
    }
    NPR_CHECK(wrong == 0, wrong << " wrong distances in a " << width << "x" << height << " mask");
  }
  Mask empty(13, 9);
  const std::vector<double> none = nprDistanceTransform::Compute(empty.Data(), 13, 9);
  NPR_CHECK(
    none[0] == nprDistanceTransform::Infinite && none.back() == nprDistanceTransform::Infinite,
    "an empty mask's distances are Infinite");
}

void TestIdentical()
{
  Mask mask(64, 48);
  mask.VerticalLine(20, 5, 40);
  for (int x = 10; x < 50; ++x)
  {
    mask.Set(x, 30 + x / 7); // a slanted line
  }
  nprEdgeMetrics m;
  m.Compute(mask.Data(), mask.Data(), 64, 48);
  for (double t : { 0.0, 1.0, 2.0 })
  {
    NPR_CHECK(m.Precision(t) == 1.0 && m.Recall(t) == 1.0 && m.F1(t) == 1.0,
      "identical masks at " << t << ": " << m.Precision(t) << " " << m.Recall(t));
  }
  NPR_CHECK(
    m.MeanSymmetricDistance() == 0.0, "identical masks: distance " << m.MeanSymmetricDistance());
  NPR_CHECK(m.GetMethodPixels() == m.GetReferencePixels() && m.GetMethodPixels() > 70,
    "pixel counts " << m.GetMethodPixels());
}

void TestShifted()
{
  const Mask reference = LineMask(64, 48, 20, 5, 40);
  nprEdgeMetrics m = Compare(LineMask(64, 48, 21, 5, 40), reference);
  NPR_CHECK(m.F1(0.0) == 0.0, "shifted by 1: F1@0 " << m.F1(0.0));
  NPR_CHECK(m.F1(1.0) == 1.0 && m.F1(2.0) == 1.0, "shifted by 1: F1@1 " << m.F1(1.0));
  NPR_CHECK(
    Near(m.MeanSymmetricDistance(), 1.0), "shifted by 1: distance " << m.MeanSymmetricDistance());

  // Diagonally by one pixel: sqrt(2) away, within 2 but not within 1.
  m = Compare(LineMask(64, 48, 21, 6, 41), reference);
  NPR_CHECK(m.Precision(1.0) < 1.0 && m.Precision(2.0) == 1.0 && m.Recall(2.0) == 1.0,
    "diagonal shift: precision@1 " << m.Precision(1.0) << ", @2 " << m.Precision(2.0));
  // The shared rows are at distance 1 (one pixel across), the end rows at sqrt(2).
  NPR_CHECK(m.Precision(1.0) > 0.9, "diagonal shift: precision@1 " << m.Precision(1.0));
}

void TestDisjoint()
{
  const Mask reference = LineMask(128, 64, 10, 10, 50);
  nprEdgeMetrics m = Compare(LineMask(128, 64, 60, 10, 50), reference);
  NPR_CHECK(m.F1(1.0) == 0.0 && m.F1(2.0) == 0.0, "far apart: F1@2 " << m.F1(2.0));
  NPR_CHECK(
    Near(m.MeanSymmetricDistance(), 50.0), "far apart: distance " << m.MeanSymmetricDistance());
  NPR_CHECK(m.CountFarMethodPixels(3.0) == 41, "far pixels " << m.CountFarMethodPixels(3.0));

  // The reference plus a stray blob: precision is the reference's share, recall stays 1.
  Mask stray = reference;
  for (int y = 0; y < 10; ++y)
  {
    stray.VerticalLine(100 + y, 20, 29); // 100 pixels
  }
  m = Compare(stray, reference);
  NPR_CHECK(Near(m.Precision(2.0), 41.0 / 141.0) && m.Recall(0.0) == 1.0,
    "stray blob: precision " << m.Precision(2.0) << ", recall " << m.Recall(0.0));
  NPR_CHECK(m.CountFarMethodPixels(3.0) == 100, "stray pixels " << m.CountFarMethodPixels(3.0));
}

void TestEmpty()
{
  Mask empty(40, 30), line(40, 30);
  line.VerticalLine(5, 0, 29);
  nprEdgeMetrics m;
  m.Compute(empty.Data(), empty.Data(), 40, 30);
  NPR_CHECK(Finite(m) && m.F1(1.0) == 1.0 && m.MeanSymmetricDistance() == 0.0,
    "both empty: F1 " << m.F1(1.0) << ", distance " << m.MeanSymmetricDistance());
  m.Compute(empty.Data(), line.Data(), 40, 30);
  NPR_CHECK(Finite(m) && m.Precision(1.0) == 1.0 && m.Recall(1.0) == 0.0 && m.F1(1.0) == 0.0,
    "empty method: P " << m.Precision(1.0) << " R " << m.Recall(1.0) << " F1 " << m.F1(1.0));
  NPR_CHECK(Near(m.MeanSymmetricDistance(), 50.0),
    "empty method: distance is the diagonal, " << m.MeanSymmetricDistance());
  m.Compute(line.Data(), empty.Data(), 40, 30);
  NPR_CHECK(Finite(m) && m.Precision(1.0) == 0.0 && m.Recall(1.0) == 1.0 && m.F1(1.0) == 0.0,
    "empty reference: P " << m.Precision(1.0) << " R " << m.Recall(1.0));
  m.Compute(empty.Data(), empty.Data(), 0, 0);
  NPR_CHECK(Finite(m) && m.F1(1.0) == 1.0, "zero-sized masks");
}
}

int main(int, char*[])
{
  TestDistanceTransform();
  TestIdentical();
  TestShifted();
  TestDisjoint();
  TestEmpty();
  return nprTestResult();
}
