// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// The geometric tests of vtkNPROccluders, in the frame where the scene's extent is 1: whether a
// segment meets a triangle (the ray test), and where two triangles cross (the intersection
// curves). Private to NPR::FiltersNPR.
#ifndef vtkNPRTriangleTests_h
#define vtkNPRTriangleTests_h

#include "vtkMath.h" // for vtkMath::Cross, vtkMath::Dot

#include <algorithm> // for std::lexicographical_compare
#include <cmath>     // for std::abs, std::acos

// d . ((p - o) x (q - p)): on which side of the edge p q the line o + t d passes. Computed from
// the edge's ends in one order whichever way a triangle runs along it, so that triangles that
// share an edge get the same value up to its sign: a line through the edge meets one of them.
// (It equals d . ((p - o) x (q - o)), with less rounding: q - p is short.)
inline double vtkNPREdgeSide(const double o[3], const double d[3], const double* p, const double* q)
{
  if (std::lexicographical_compare(q, q + 3, p, p + 3))
  {
    return -vtkNPREdgeSide(o, d, q, p);
  }
  const double op[3] = { p[0] - o[0], p[1] - o[1], p[2] - o[2] };
  const double pq[3] = { q[0] - p[0], q[1] - p[1], q[2] - p[2] };
  return d[0] * (op[1] * pq[2] - op[2] * pq[1]) + d[1] * (op[2] * pq[0] - op[0] * pq[2]) +
    d[2] * (op[0] * pq[1] - op[1] * pq[0]);
}

// Whether the segment o + t d, t in [0, 1], meets the triangle (a, b, c), its edges included
// (from either side). t from the triangle's normal, not from the sum of the sides: that loses
// digits when the segment grazes the plane, as a sample's does on the faces of its line, where
// t must be right to well below OcclusionEpsilon.
inline bool vtkNPRSegmentMeetsTriangle(
  const double o[3], const double d[3], const double* a, const double* b, const double* c)
{
  const double u = vtkNPREdgeSide(o, d, b, c), v = vtkNPREdgeSide(o, d, c, a),
               w = vtkNPREdgeSide(o, d, a, b);
  if (!((u >= 0.0 && v >= 0.0 && w >= 0.0) || (u <= 0.0 && v <= 0.0 && w <= 0.0)))
  {
    return false;
  }
  const double ab[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
  const double ac[3] = { c[0] - a[0], c[1] - a[1], c[2] - a[2] };
  double n[3];
  vtkMath::Cross(ab, ac, n);
  const double along = vtkMath::Dot(n, d); // 0: parallel to the plane, or degenerate
  if (along == 0.0)
  {
    return false;
  }
  const double oa[3] = { a[0] - o[0], a[1] - o[1], a[2] - o[2] };
  const double t = vtkMath::Dot(n, oa) / along;
  return t >= 0.0 && t <= 1.0;
}

// The segment where triangles a and b cross (in the occluders' frame, where the scene's extent
// is 1), and the angle between their planes in degrees. False where they do not cross along a
// segment: apart, touching at a point, or coplanar.
inline bool vtkNPRCrossTriangles(
  const double* const a[3], const double* const b[3], double p[3], double q[3], double& angle)
{
  constexpr double eps = 1e-12;
  auto normal = [](const double* const t[3], double n[3])
  {
    const double u[3] = { t[1][0] - t[0][0], t[1][1] - t[0][1], t[1][2] - t[0][2] };
    const double v[3] = { t[2][0] - t[0][0], t[2][1] - t[0][1], t[2][2] - t[0][2] };
    vtkMath::Cross(u, v, n);
    return vtkMath::Normalize(n) > 0.0;
  };
  double na[3], nb[3];
  if (!normal(a, na) || !normal(b, nb))
  {
    return false;
  }
  // Each triangle's corners against the other's plane, then the piece of it on that plane.
  auto cut = [](const double* const t[3], const double n[3], const double* o, double out[2][3])
  {
    double d[3];
    for (int k = 0; k < 3; ++k)
    {
      const double r[3] = { t[k][0] - o[0], t[k][1] - o[1], t[k][2] - o[2] };
      d[k] = vtkMath::Dot(n, r);
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
        std::copy_n(t[k], 3, out[count++]);
      }
      else if ((d[k] > eps && d[next] < -eps) || (d[k] < -eps && d[next] > eps))
      {
        const double s = d[k] / (d[k] - d[next]);
        for (int i = 0; i < 3; ++i)
        {
          out[count][i] = t[k][i] + s * (t[next][i] - t[k][i]);
        }
        ++count;
      }
    }
    return count;
  };
  double pa[2][3], pb[2][3];
  if (cut(a, nb, b[0], pa) != 2 || cut(b, na, a[0], pb) != 2)
  {
    return false;
  }
  // Both pieces lie on the planes' common line: their overlap along it.
  double line[3];
  vtkMath::Cross(na, nb, line);
  const double sa[2] = { vtkMath::Dot(pa[0], line), vtkMath::Dot(pa[1], line) };
  const double sb[2] = { vtkMath::Dot(pb[0], line), vtkMath::Dot(pb[1], line) };
  const double low = std::max(std::min(sa[0], sa[1]), std::min(sb[0], sb[1]));
  const double high = std::min(std::max(sa[0], sa[1]), std::max(sb[0], sb[1]));
  if (!(high - low > eps) || sa[1] == sa[0])
  {
    return false;
  }
  for (int i = 0; i < 3; ++i)
  {
    p[i] = pa[0][i] + (low - sa[0]) / (sa[1] - sa[0]) * (pa[1][i] - pa[0][i]);
    q[i] = pa[0][i] + (high - sa[0]) / (sa[1] - sa[0]) * (pa[1][i] - pa[0][i]);
  }
  angle = vtkMath::DegreesFromRadians(std::acos(std::min(1.0, std::abs(vtkMath::Dot(na, nb)))));
  return true;
}

#endif
// VTK-HeaderTest-Exclude: vtkNPRTriangleTests.h
