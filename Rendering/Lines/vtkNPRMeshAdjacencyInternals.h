// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// What the files of vtkNPRMeshAdjacency (the face build, the edge table, the viewpoint passes)
// and vtkNPRSmoothContours share: the constants of the packed tables and the faces' normal.
// Private to NPR::Lines.
#ifndef vtkNPRMeshAdjacencyInternals_h
#define vtkNPRMeshAdjacencyInternals_h

#include "vtkNPRMeshFaces.h" // for vtkNPRMeshFaces
#include "vtkNPRVectors.h"   // for glm::dvec3
#include "vtkType.h"         // for vtkIdType

#include <algorithm> // for std::max
#include <cmath>     // for std::sqrt
#include <cstdint>   // for std::uint32_t
#include <limits>    // for NoFace

namespace vtkNPRMeshAdjacencyInternals
{
// A face whose normal is shorter than this, relative to its squared size, has no orientation:
// its points are collinear or coincident up to rounding.
constexpr double DegenerateNormal = 1e-12;

// The side of a face's plane the eye is on, per face and camera, from single-precision data:
// decided where the value is farther from zero than its error bound, which the double-precision
// test per edge (the reference) then cannot contradict; unsure faces take that test.
constexpr unsigned SideFacing = 1; // the double-precision term is negative (else positive)
constexpr unsigned SideUnsure = 2; // too close to zero to tell here, or not finite
// Relative error allowed for the single-precision terms: over five times the worst case (the
// normal's, the offset's and the eye's rounding to float, 2^-24 each, and the float products'
// and sums' rounding).
constexpr double FaceSideTolerance = 2e-6;

constexpr std::uint32_t NoFace = std::numeric_limits<std::uint32_t>::max();

// Edges and triangles are processed in blocks of this many, each listing what it finds in order.
constexpr vtkIdType BlockSize = 16384;

// Newell's normal of a face as the sum of a fan's cross products from its first point (the same
// vector, with coordinates relative to the face so that far-away meshes lose no digits), made
// unit length; false where the face has no orientation (see DegenerateNormal).
inline bool UnitNormal(
  const vtkNPRMeshFaces& mesh, vtkIdType size, const vtkIdType* ids, double unit[3])
{
  glm::dvec3 normal(0.0);
  double size2 = 0.0, x[3];
  mesh.GetPoint(ids[0], x);
  const glm::dvec3 origin = vtkNPRVector(x);
  mesh.GetPoint(ids[1], x);
  glm::dvec3 b = vtkNPRVector(x) - origin;
  for (vtkIdType i = 1; i + 1 < size; ++i)
  {
    const glm::dvec3 a = b;
    mesh.GetPoint(ids[i + 1], x);
    b = vtkNPRVector(x) - origin;
    normal += glm::cross(a, b);
    size2 = std::max(size2, std::max(glm::dot(a, a), glm::dot(b, b)));
  }
  const double length = glm::length(normal);
  if (!(length > DegenerateNormal * size2) || !std::isfinite(length))
  {
    return false;
  }
  vtkNPRStore(normal / length, unit);
  return true;
}
}

#endif
// VTK-HeaderTest-Exclude: vtkNPRMeshAdjacencyInternals.h
