// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// The geometric tests of vtkNPROccluders, in the frame where the scene's extent is 1: whether a
// segment meets a triangle (the ray test), and where two triangles cross (the intersection
// curves). Private to NPR::Lines.
#ifndef vtkNPRTriangleTests_h
#define vtkNPRTriangleTests_h

#include "vtkMath.h"       // for vtkMath::DegreesFromRadians
#include "vtkNPRVectors.h" // for glm::dvec3

#include <algorithm> // for std::lexicographical_compare
#include <cmath>     // for std::abs, std::acos

// d . ((p - o) x (q - p)): on which side of the edge p q the line o + t d passes. Computed from
// the edge's ends in one order whichever way a triangle runs along it, so that triangles that
// share an edge get the same value up to its sign: a line through the edge meets one of them.
// (It equals d . ((p - o) x (q - o)), with less rounding: q - p is short.)
inline double vtkNPREdgeSide(
  const glm::dvec3& o, const glm::dvec3& d, const double* p, const double* q)
{
  if (std::lexicographical_compare(q, q + 3, p, p + 3))
  {
    return -vtkNPREdgeSide(o, d, q, p);
  }
  const glm::dvec3 from = vtkNPRVector(p);
  return glm::dot(d, glm::cross(from - o, vtkNPRVector(q) - from));
}

// Whether the segment o + t d, t in [0, 1], meets the triangle (a, b, c), its edges included
// (from either side). t from the triangle's normal, not from the sum of the sides: that loses
// digits when the segment grazes the plane, as a sample's does on the faces of its line, where
// t must be right to well below OcclusionEpsilon.
inline bool vtkNPRSegmentMeetsTriangle(
  const glm::dvec3& o, const glm::dvec3& d, const double* a, const double* b, const double* c)
{
  const double u = vtkNPREdgeSide(o, d, b, c), v = vtkNPREdgeSide(o, d, c, a),
               w = vtkNPREdgeSide(o, d, a, b);
  if (!((u >= 0.0 && v >= 0.0 && w >= 0.0) || (u <= 0.0 && v <= 0.0 && w <= 0.0)))
  {
    return false;
  }
  const glm::dvec3 corner = vtkNPRVector(a);
  const glm::dvec3 n = glm::cross(vtkNPRVector(b) - corner, vtkNPRVector(c) - corner);
  const double along = glm::dot(n, d); // 0: parallel to the plane, or degenerate
  if (along == 0.0)
  {
    return false;
  }
  const double t = glm::dot(n, corner - o) / along;
  return t >= 0.0 && t <= 1.0;
}

// The segment where triangles a and b cross (in the occluders' frame, where the scene's extent
// is 1), and the angle between their planes in degrees. False where they do not cross along a
// segment: apart, touching at a point, or coplanar.
inline bool vtkNPRCrossTriangles(
  const double* const a[3], const double* const b[3], double p[3], double q[3], double& angle)
{
  constexpr double eps = 1e-12;
  auto normal = [](const double* const t[3], glm::dvec3& n)
  {
    const glm::dvec3 first = vtkNPRVector(t[0]);
    n = glm::cross(vtkNPRVector(t[1]) - first, vtkNPRVector(t[2]) - first);
    const double length = glm::length(n);
    n /= length;
    return length > 0.0;
  };
  glm::dvec3 na, nb;
  if (!normal(a, na) || !normal(b, nb))
  {
    return false;
  }
  // Each triangle's corners against the other's plane, then the piece of it on that plane.
  auto cut = [](const double* const t[3], const glm::dvec3& n, const double* o, glm::dvec3 out[2])
  {
    const glm::dvec3 corners[3] = { vtkNPRVector(t[0]), vtkNPRVector(t[1]), vtkNPRVector(t[2]) };
    const glm::dvec3 origin = vtkNPRVector(o);
    double d[3];
    for (int k = 0; k < 3; ++k)
    {
      d[k] = glm::dot(n, corners[k] - origin);
    }
    const bool above = d[0] > eps || d[1] > eps || d[2] > eps;
    const bool below = d[0] < -eps || d[1] < -eps || d[2] < -eps;
    if (!above || !below)
    {
      return 0; // on one side, or in the plane (coplanar, or touching it)
    }
    int count = 0;
    for (int k = 0; k < 3 && count < 2; ++k)
    {
      const int next = (k + 1) % 3;
      if (std::abs(d[k]) <= eps)
      {
        out[count++] = corners[k];
      }
      else if ((d[k] > eps && d[next] < -eps) || (d[k] < -eps && d[next] > eps))
      {
        out[count++] = vtkNPRPointAlong(corners[k], corners[next], d[k] / (d[k] - d[next]));
      }
    }
    return count;
  };
  glm::dvec3 pa[2], pb[2];
  if (cut(a, nb, b[0], pa) != 2 || cut(b, na, a[0], pb) != 2)
  {
    return false;
  }
  // Both pieces lie on the planes' common line: their overlap along it.
  const glm::dvec3 line = glm::cross(na, nb);
  const double sa[2] = { glm::dot(pa[0], line), glm::dot(pa[1], line) };
  const double sb[2] = { glm::dot(pb[0], line), glm::dot(pb[1], line) };
  const double low = std::max(std::min(sa[0], sa[1]), std::min(sb[0], sb[1]));
  const double high = std::min(std::max(sa[0], sa[1]), std::max(sb[0], sb[1]));
  if (!(high - low > eps) || sa[1] == sa[0])
  {
    return false;
  }
  vtkNPRStore(pa[0] + (low - sa[0]) / (sa[1] - sa[0]) * (pa[1] - pa[0]), p);
  vtkNPRStore(pa[0] + (high - sa[0]) / (sa[1] - sa[0]) * (pa[1] - pa[0]), q);
  angle = vtkMath::DegreesFromRadians(std::acos(std::min(1.0, std::abs(glm::dot(na, nb)))));
  return true;
}

#endif
// VTK-HeaderTest-Exclude: vtkNPRTriangleTests.h
