// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// Accuracy of an edge mask against a reference mask, in pixels (the benchmark's error figures).
//
// Masks are width x height bytes, row by row; a non-zero byte is a line pixel. With the method's
// line pixels M and the reference's line pixels R, and d(p, S) the Euclidean distance from pixel
// p to the nearest pixel of S:
// - precision@t: the fraction of M with d(p, R) <= t;
// - recall@t: the fraction of R with d(p, M) <= t;
// - F1@t: their harmonic mean, 2PR / (P + R);
// - mean symmetric distance: the mean of d(p, R) over M and of d(p, M) over R, together
//   (sum over both sets divided by |M| + |R|).
// Empty sets, so that no figure is ever NaN: precision is 1 when M is empty (no false line),
// recall is 1 when R is empty (nothing missed), F1 is 0 when P + R is 0; a distance to an empty
// set is the image's diagonal (the largest a distance can be), and the mean distance of two
// empty masks is 0.
//
// Distances come from an exact Euclidean distance transform (Felzenszwalb & Huttenlocher's
// lower envelope of parabolas, one 1D pass per column then per row): O(pixels).
#ifndef nprEdgeMetrics_h
#define nprEdgeMetrics_h

#include <vector>

// Squared Euclidean distance from every pixel to the nearest non-zero pixel of the mask, exact
// (an integer), row by row; every entry is Infinite when the mask has no such pixel.
class nprDistanceTransform
{
public:
  static constexpr double Infinite = 1e30;
  static std::vector<double> Compute(const unsigned char* mask, int width, int height);
};

class nprEdgeMetrics
{
public:
  // Compares the method's mask with the reference's (both width x height).
  void Compute(const unsigned char* method, const unsigned char* reference, int width, int height);

  // The figures at a tolerance t in pixels (t >= 0; 0 means the same pixel).
  double Precision(double tolerance) const;
  double Recall(double tolerance) const;
  double F1(double tolerance) const;
  double MeanSymmetricDistance() const;

  long long GetMethodPixels() const
  {
    return static_cast<long long>(this->MethodToReference.size());
  }
  long long GetReferencePixels() const
  {
    return static_cast<long long>(this->ReferenceToMethod.size());
  }
  // Method pixels farther than the tolerance from every reference pixel.
  long long CountFarMethodPixels(double tolerance) const;

private:
  // Fraction of the sorted squared distances that are <= tolerance^2; 1 for an empty list.
  static double FractionWithin(const std::vector<double>& squared, double tolerance);

  // Squared distances, sorted: of each method pixel to the reference, and the other way round.
  std::vector<double> MethodToReference;
  std::vector<double> ReferenceToMethod;
  double Diagonal = 0.0;
};

#endif
