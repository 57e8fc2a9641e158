// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nprEdgeMetrics.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace
{
// One line of the transform: d[q] = min over p of (q - p)^2 + f[p], for f finite or Infinite.
// The lower envelope of the parabolas rooted at the finite samples is built left to right
// (v: their positions, z: where each starts to be the lowest), then read off in one sweep.
void Transform1D(const double* f, int n, double* d, std::vector<int>& v, std::vector<double>& z)
{
  const double infinity = std::numeric_limits<double>::infinity();
  int k = -1;
  for (int q = 0; q < n; ++q)
  {
    if (f[q] >= nprDistanceTransform::Infinite)
    {
      continue; // no parabola: infinite samples never win, and their arithmetic would overflow
    }
    double s = -infinity;
    while (k >= 0)
    {
      const int p = v[k];
      s = ((f[q] + static_cast<double>(q) * q) - (f[p] + static_cast<double>(p) * p)) /
        (2.0 * (q - p));
      if (s > z[k])
      {
        break;
      }
      --k; // parabola p is below q's nowhere
      s = -infinity;
    }
    ++k;
    v[k] = q;
    z[k] = s;
  }
  if (k < 0)
  {
    std::fill(d, d + n, nprDistanceTransform::Infinite);
    return;
  }
  z[k + 1] = infinity;
  int j = 0;
  for (int q = 0; q < n; ++q)
  {
    while (z[j + 1] < q)
    {
      ++j;
    }
    const double offset = q - v[j];
    d[q] = offset * offset + f[v[j]];
  }
}
}

std::vector<double> nprDistanceTransform::Compute(const unsigned char* mask, int width, int height)
{
  const size_t count = static_cast<size_t>(width) * height;
  std::vector<double> result(count, Infinite);
  if (count == 0)
  {
    return result;
  }
  const int longest = std::max(width, height);
  std::vector<double> line(longest), distance(longest), z(longest + 1);
  std::vector<int> v(longest);
  // Columns: squared vertical distance to the nearest line pixel of the column.
  for (int x = 0; x < width; ++x)
  {
    for (int y = 0; y < height; ++y)
    {
      line[y] = mask[static_cast<size_t>(y) * width + x] ? 0.0 : Infinite;
    }
    Transform1D(line.data(), height, distance.data(), v, z);
    for (int y = 0; y < height; ++y)
    {
      result[static_cast<size_t>(y) * width + x] = distance[y];
    }
  }
  // Rows over the column distances: the exact squared Euclidean distance.
  for (int y = 0; y < height; ++y)
  {
    double* row = result.data() + static_cast<size_t>(y) * width;
    std::copy(row, row + width, line.begin());
    Transform1D(line.data(), width, row, v, z);
  }
  return result;
}

void nprEdgeMetrics::Compute(
  const unsigned char* method, const unsigned char* reference, int width, int height)
{
  const std::vector<double> toReference = nprDistanceTransform::Compute(reference, width, height);
  const std::vector<double> toMethod = nprDistanceTransform::Compute(method, width, height);
  this->MethodToReference.clear();
  this->ReferenceToMethod.clear();
  const size_t count = static_cast<size_t>(width) * height;
  for (size_t i = 0; i < count; ++i)
  {
    if (method[i])
    {
      this->MethodToReference.push_back(toReference[i]);
    }
    if (reference[i])
    {
      this->ReferenceToMethod.push_back(toMethod[i]);
    }
  }
  std::sort(this->MethodToReference.begin(), this->MethodToReference.end());
  std::sort(this->ReferenceToMethod.begin(), this->ReferenceToMethod.end());
  this->Diagonal =
    std::sqrt(static_cast<double>(width) * width + static_cast<double>(height) * height);
}

double nprEdgeMetrics::FractionWithin(const std::vector<double>& squared, double tolerance)
{
  if (squared.empty())
  {
    return 1.0;
  }
  // Squared distances are integers: a small margin keeps t = 1, sqrt(2), ... inclusive.
  const double limit = tolerance * tolerance + 1e-6;
  const auto end = std::upper_bound(squared.begin(), squared.end(), limit);
  return static_cast<double>(end - squared.begin()) / static_cast<double>(squared.size());
}

double nprEdgeMetrics::Precision(double tolerance) const
{
  return FractionWithin(this->MethodToReference, tolerance);
}

double nprEdgeMetrics::Recall(double tolerance) const
{
  return FractionWithin(this->ReferenceToMethod, tolerance);
}

double nprEdgeMetrics::F1(double tolerance) const
{
  const double precision = this->Precision(tolerance);
  const double recall = this->Recall(tolerance);
  return precision + recall > 0.0 ? 2.0 * precision * recall / (precision + recall) : 0.0;
}

double nprEdgeMetrics::MeanSymmetricDistance() const
{
  const size_t count = this->MethodToReference.size() + this->ReferenceToMethod.size();
  if (count == 0)
  {
    return 0.0;
  }
  double sum = 0.0;
  for (const std::vector<double>* list : { &this->MethodToReference, &this->ReferenceToMethod })
  {
    for (double squared : *list)
    {
      // Infinite: the other set is empty; count the largest distance the image allows.
      sum += squared >= nprDistanceTransform::Infinite ? this->Diagonal : std::sqrt(squared);
    }
  }
  return sum / static_cast<double>(count);
}

long long nprEdgeMetrics::CountFarMethodPixels(double tolerance) const
{
  const double limit = tolerance * tolerance + 1e-6;
  const auto& squared = this->MethodToReference;
  return static_cast<long long>(
    squared.end() - std::upper_bound(squared.begin(), squared.end(), limit));
}
