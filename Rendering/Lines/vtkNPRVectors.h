// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// The module's geometry in GLM's vectors (glm::dvec3 in double, glm::vec3 in float): VTK's
// double[3] in and out, the exact comparison of points, and the point along a segment. GLM is
// private to NPR::Lines: no installed header includes this one. Only GLM's functions that
// round as the component-wise expressions they replace are used (cross, dot, length; not
// normalize or mix, whose other formulas would change the output's bits).
#ifndef vtkNPRVectors_h
#define vtkNPRVectors_h

#include <algorithm> // for std::equal

#include <glm/geometric.hpp>    // for glm::cross, glm::dot, glm::length
#include <glm/gtc/type_ptr.hpp> // for glm::value_ptr
#include <glm/vec3.hpp>         // for glm::dvec3, glm::vec3

// The point or vector x[0..2].
inline glm::dvec3 vtkNPRVector(const double* x)
{
  return glm::dvec3(x[0], x[1], x[2]);
}

// v into out[0..2].
inline void vtkNPRStore(const glm::dvec3& v, double* out)
{
  out[0] = v.x;
  out[1] = v.y;
  out[2] = v.z;
}

// Whether a and b are the same point: the same doubles, -0 and +0 alike (not glm's ==, which
// takes two equal infinities for different).
inline bool vtkNPRSamePoint(const double* a, const double* b)
{
  return std::equal(a, a + 3, b);
}

// a + t (b - a): exactly a at t = 0 (glm::mix's a (1 - t) + b t rounds otherwise).
inline glm::dvec3 vtkNPRPointAlong(const glm::dvec3& a, const glm::dvec3& b, double t)
{
  return a + t * (b - a);
}

// The same for points in VTK's arrays, into out.
inline void vtkNPRPointAt(const double a[3], const double b[3], double t, double out[3])
{
  vtkNPRStore(vtkNPRPointAlong(vtkNPRVector(a), vtkNPRVector(b), t), out);
}

#endif
// VTK-HeaderTest-Exclude: vtkNPRVectors.h
