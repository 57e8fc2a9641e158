// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// vtkNPRMeshAdjacency's passes for each viewpoint: the crease bits, the sides of the faces'
// planes the eye is on, and the typed edges.
#include "vtkNPRMeshAdjacency.h"

#include "vtkMath.h"
#include "vtkNPRFeatureLines.h"
#include "vtkNPRMeshAdjacencyInternals.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace
{
using vtkNPRMeshAdjacencyInternals::BlockSize;
using vtkNPRMeshAdjacencyInternals::FaceSideTolerance;
using vtkNPRMeshAdjacencyInternals::SideFacing;
using vtkNPRMeshAdjacencyInternals::SideUnsure;
using vtkNPRMeshAdjacencyInternals::UnitNormal;

// An edge's dihedral angle from the faces' single-precision normals is within 2e-7 radians
// (1.2e-5 degrees) of the exact one; within AngleMargin degrees of the crease angle, the exact
// angle decides.
constexpr double AngleMargin = 1e-4;

// The angle between two unit normals in degrees, the second flipped where the faces' windings
// disagree; atan2 keeps small angles exact where acos of the dot product would lose them.
double DihedralAngle(const glm::dvec3& n0, const glm::dvec3& normal1, bool flip)
{
  const glm::dvec3 n1 = flip ? -normal1 : normal1;
  return vtkMath::DegreesFromRadians(std::atan2(glm::length(glm::cross(n0, n1)), glm::dot(n0, n1)));
}
}

bool vtkNPRMeshAdjacency::FaceNormal(std::uint32_t face, double unit[3]) const
{
  bool oriented = false;
  this->Mesh.VisitFace(this->Source(face),
    [&](vtkIdType size, const vtkIdType* ids)
    { oriented = UnitNormal(this->Mesh, size, ids, unit); });
  return oriented;
}

double vtkNPRMeshAdjacency::Angle(vtkIdType edge) const
{
  double n0[3], n1[3];
  this->FaceNormal(this->EdgeFaces[2 * edge], n0);
  this->FaceNormal(this->EdgeFaces[2 * edge + 1], n1);
  return DihedralAngle(
    vtkNPRVector(n0), vtkNPRVector(n1), (this->EdgeKinds[edge] & SameDirection) != 0);
}

void vtkNPRMeshAdjacency::EdgePoints(vtkIdType edge, std::uint32_t& a, std::uint32_t& b) const
{
  const vtkIdType local = this->EdgeLocal(edge);
  this->Mesh.VisitFace(this->Source(this->EdgeFaces[2 * edge]),
    [&](vtkIdType size, const vtkIdType* ids)
    {
      a = this->Representative(ids[local]);
      b = this->Representative(ids[(local + 1) % size]);
    });
  if (b < a)
  {
    std::swap(a, b);
  }
}

void vtkNPRMeshAdjacency::UpdateCreases(double angle)
{
  if (this->CreaseAngle == angle)
  {
    return;
  }
  // From the faces' single-precision normals where they decide, else from the exact angle: with
  // theta the angle between the normals and r the product of their lengths, |n0 x n1| cos(angle)
  // - (n0 . n1) sin(angle) = r sin(theta - angle), which is positive for a crease.
  const double radians = vtkMath::RadiansFromDegrees(angle);
  const double cosAngle = std::cos(radians), sinAngle = std::sin(radians);
  const double margin = std::sin(vtkMath::RadiansFromDegrees(AngleMargin));
  auto single = [this](std::uint32_t face) // the face's single-precision normal
  {
    return glm::dvec3(
      this->FaceNormals[0][face], this->FaceNormals[1][face], this->FaceNormals[2][face]);
  };
  vtkSMPTools::For(0, this->GetNumberOfEdges(),
    [&](vtkIdType first, vtkIdType last)
    {
      for (vtkIdType e = first; e < last; ++e)
      {
        const unsigned char kind = this->EdgeKinds[e] & ~Crease;
        bool crease = false;
        if (kind & TwoFaces)
        {
          const double flip = (kind & SameDirection) ? -1.0 : 1.0;
          const glm::dvec3 n0 = single(this->EdgeFaces[2 * e]);
          const glm::dvec3 n1 = flip * single(this->EdgeFaces[2 * e + 1]);
          const double side =
            glm::length(glm::cross(n0, n1)) * cosAngle - glm::dot(n0, n1) * sinAngle;
          const double bound = margin * std::sqrt(glm::dot(n0, n0) * glm::dot(n1, n1));
          crease = side > bound || (side >= -bound && this->Angle(e) > angle);
        }
        this->EdgeKinds[e] = static_cast<unsigned char>(kind | (crease ? Crease : 0));
      }
    });
  this->CreaseAngle = angle;
}

void vtkNPRMeshAdjacency::ComputeFaceSides(bool parallel, const double view[3])
{
  const vtkIdType faceCount = static_cast<vtkIdType>(this->FaceOffsets.size());
  this->FaceSides.resize(this->FaceOffsets.size());
  const float* nx = this->FaceNormals[0].data();
  const float* ny = this->FaceNormals[1].data();
  const float* nz = this->FaceNormals[2].data();
  const float* offsets = this->FaceOffsets.data();
  const std::uint8_t* bounds = this->FaceBounds.data();
  unsigned char* sides = this->FaceSides.data();
  const glm::dvec3 toEye =
    parallel ? vtkNPRVector(view) : vtkNPRVector(view) - vtkNPRVector(this->Centre);
  const glm::vec3 eye(toEye);
  const float toEyeLength = static_cast<float>(glm::length(toEye) * (1.0 + 1e-6));
  const float tolerance = static_cast<float>(FaceSideTolerance);
  vtkSMPThreadLocal<vtkIdType> unsure(0);
  // In float, in a loop the compiler vectorises: FaceSideTolerance covers float arithmetic.
  vtkSMPTools::For(0, faceCount,
    [=, &unsure](vtkIdType first, vtkIdType last)
    {
      int unsureHere = 0;
      for (vtkIdType f = first; f < last; ++f)
      {
        const float projected = glm::dot(glm::vec3(nx[f], ny[f], nz[f]), eye);
        // Perspective: n.(q - eye) = offset - n.(eye - c); parallel: n.direction.
        const float value = parallel ? projected : offsets[f] - projected;
        // The bound 2^(b - 127): the float whose exponent bits are b.
        const std::uint32_t bits = static_cast<std::uint32_t>(bounds[f]) << 23;
        float bound;
        std::memcpy(&bound, &bits, sizeof(bound));
        const float error = parallel ? tolerance * toEyeLength : tolerance * (bound + toEyeLength);
        const bool facing = value < -error;
        const bool unsureFace = !facing && !(value > error);
        sides[f] =
          static_cast<unsigned char>((facing ? SideFacing : 0u) | (unsureFace ? SideUnsure : 0u));
        unsureHere += unsureFace ? 1 : 0;
      }
      unsure.Local() += unsureHere;
    });
  this->UnsureFaces = 0;
  for (vtkIdType count : unsure)
  {
    this->UnsureFaces += count;
  }
}

bool vtkNPRMeshAdjacency::IsSilhouette(vtkIdType edge, const View& view) const
{
  // The eye on the front side of exactly one of the faces' planes (edge-on counting as the
  // back), the second reversed where both faces traverse the edge the same way: from the faces'
  // sides where both are decided, else by the reference test in double precision, at the edge's
  // first point so that both terms are exact sides.
  const std::uint32_t face0 = this->EdgeFaces[2 * edge], face1 = this->EdgeFaces[2 * edge + 1];
  const unsigned side0 = this->FaceSides[face0];
  const unsigned side1 = this->FaceSides[face1];
  const bool same = (this->EdgeKinds[edge] & SameDirection) != 0;
  if (!((side0 | side1) & SideUnsure))
  {
    return ((side0 & SideFacing) != 0) != (((side1 & SideFacing) != 0) != same);
  }
  double n0[3], n1[3];
  this->FaceNormal(face0, n0);
  this->FaceNormal(face1, n1);
  // The line of sight: parallel, the direction of projection; else from the eye to the point.
  glm::dvec3 sight = vtkNPRVector(view.Direction);
  if (!view.Parallel)
  {
    std::uint32_t a, b;
    this->EdgePoints(edge, a, b);
    double p[3];
    this->Mesh.GetPoint(a, p);
    sight = vtkNPRVector(p) - vtkNPRVector(view.Eye);
  }
  double f0 = glm::dot(vtkNPRVector(n0), sight), f1 = glm::dot(vtkNPRVector(n1), sight);
  if (same)
  {
    f1 = -f1;
  }
  return (f0 < 0.0) != (f1 < 0.0);
}

std::vector<vtkNPRMeshAdjacency::TypedEdge> vtkNPRMeshAdjacency::ClassifyEdges(
  const View& view) const
{
  // In blocks of equal size, each listing its typed edges in order.
  const vtkIdType edgeCount = this->GetNumberOfEdges();
  const vtkIdType blockCount = (edgeCount + BlockSize - 1) / BlockSize;
  std::vector<std::vector<TypedEdge>> blocks(static_cast<size_t>(blockCount));
  vtkSMPTools::For(0, blockCount,
    [&](vtkIdType firstBlock, vtkIdType lastBlock)
    {
      for (vtkIdType block = firstBlock; block < lastBlock; ++block)
      {
        const vtkIdType last = std::min(edgeCount, (block + 1) * BlockSize);
        for (vtkIdType e = block * BlockSize; e < last; ++e)
        {
          const unsigned char type = this->EdgeType(e, view);
          if (type)
          {
            TypedEdge typed;
            this->EdgePoints(e, typed.A, typed.B);
            typed.Order = (static_cast<std::uint64_t>(this->Source(this->EdgeFaces[2 * e])) << 32) |
              this->EdgeLocal(e);
            typed.Type = type;
            blocks[block].push_back(typed);
          }
        }
      }
    });
  std::vector<TypedEdge> typed;
  for (const auto& block : blocks)
  {
    typed.insert(typed.end(), block.begin(), block.end());
  }
  std::sort(typed.begin(), typed.end());
  return typed;
}

unsigned char vtkNPRMeshAdjacency::EdgeType(vtkIdType e, const View& view) const
{
  const unsigned char kind = this->EdgeKinds[e];
  if (kind & Boundary)
  {
    return view.Boundaries ? vtkNPRFeatureLines::BOUNDARY : 0;
  }
  if (kind & NonManifold)
  {
    return view.NonManifoldEdges ? vtkNPRFeatureLines::NON_MANIFOLD : 0;
  }
  unsigned char type = view.Creases && (kind & Crease) ? vtkNPRFeatureLines::CREASE : 0;
  // Where the normals are split (an edge whose two faces reach it through different points),
  // the facing function jumps: the smooth contour runs along the edge if it is a silhouette.
  if ((view.Silhouettes || (view.SplitContours && (kind & Split))) && this->IsSilhouette(e, view))
  {
    type |= vtkNPRFeatureLines::SILHOUETTE;
  }
  return type;
}
