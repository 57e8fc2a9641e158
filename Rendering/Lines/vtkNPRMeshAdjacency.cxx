// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// vtkNPRMeshAdjacency: what the table was built from, and the build's first steps (the points'
// bounds and representatives, the faces' planes and order). The edge table is
// vtkNPRMeshAdjacencyEdges.cxx, the viewpoint passes vtkNPRMeshAdjacencyView.cxx.
#include "vtkNPRMeshAdjacency.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkNPRMeshAdjacencyInternals.h"
#include "vtkNPRSpatialOrder.h"
#include "vtkNPRVectors.h"
#include "vtkObject.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"
#include "vtkSetGet.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <numeric>

namespace
{
using vtkNPRMeshAdjacencyInternals::FaceSideTolerance;
using vtkNPRMeshAdjacencyInternals::NoFace;
using vtkNPRMeshAdjacencyInternals::UnitNormal;

constexpr std::uint64_t NoKey = std::numeric_limits<std::uint64_t>::max();

// The faces are ordered by the cell of their first points in a grid of 2^FaceOrderBits cells an
// axis, in the input's order within a cell: enough for the viewpoint pass's reads of FaceSides to
// stay near each other whatever the input's order (a cell holds a few thousand faces of a 20M
// face mesh), and an input in a good order stays in it, so that the build reads it in order.
constexpr int FaceOrderBits = 5;

// A 31-bit hash of exact coordinates (-0 and +0 the same), to sort equal points together (below
// NoKey's 32 bits).
std::uint32_t CoordinateHash(const double x[3])
{
  std::uint64_t h = 0x9e3779b97f4a7c15ull;
  for (int k = 0; k < 3; ++k)
  {
    const double value = x[k] == 0.0 ? 0.0 : x[k];
    std::uint64_t bits;
    std::memcpy(&bits, &value, sizeof(bits));
    h ^= bits + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2);
    h = (h ^ (h >> 30)) * 0xbf58476d1ce4e5b9ull;
    h = (h ^ (h >> 27)) * 0x94d049bb133111ebull;
  }
  return static_cast<std::uint32_t>(h >> 33);
}

// Whether faces keyed by their cells (in the input's order) are in a good order already:
// consecutive faces in different cells at most once in 8.
bool InGoodOrder(const std::vector<std::uint64_t>& keys)
{
  vtkSMPThreadLocal<vtkIdType> changes(0);
  vtkSMPTools::For(1, static_cast<vtkIdType>(keys.size()),
    [&](vtkIdType first, vtkIdType last)
    {
      vtkIdType& changesHere = changes.Local();
      for (vtkIdType f = first; f < last; ++f)
      {
        changesHere += (keys[f] >> 32) != (keys[f - 1] >> 32) ? 1 : 0;
      }
    });
  vtkIdType changed = 0;
  for (vtkIdType count : changes)
  {
    changed += count;
  }
  return 8 * changed <= static_cast<vtkIdType>(keys.size());
}
}

bool vtkNPRMeshAdjacency::IsCurrent(vtkPolyData* input, bool merge) const
{
  vtkPoints* points = input->GetPoints();
  return this->Valid && this->Input == input && this->InputTime == input->GetMTime() &&
    this->Points == points && this->PointsTime == (points ? points->GetMTime() : 0) &&
    this->PointsDataTime == (points ? points->GetData()->GetMTime() : 0) &&
    this->Polys == input->GetPolys() && this->PolysTime == input->GetPolys()->GetMTime() &&
    this->Strips == input->GetStrips() && this->StripsTime == input->GetStrips()->GetMTime() &&
    this->Merged == merge;
}

size_t vtkNPRMeshAdjacency::GetMemorySize() const
{
  size_t bytes = this->Mesh.GetMemorySize() + this->Contours.GetMemorySize();
  auto add = [&bytes](const auto& array)
  { bytes += array.capacity() * sizeof(typename std::decay<decltype(array)>::type::value_type); };
  add(this->Representatives);
  add(this->FaceSource);
  for (const auto& array :
    { &this->FaceNormals[0], &this->FaceNormals[1], &this->FaceNormals[2], &this->FaceOffsets })
  {
    add(*array);
  }
  add(this->FaceBounds);
  add(this->EdgeFaces);
  add(this->EdgeKinds);
  add(this->EdgeLocal8);
  add(this->EdgeLocal32);
  add(this->FaceSides);
  return bytes;
}

void vtkNPRMeshAdjacency::Build(vtkPolyData* input, bool merge, vtkObject* self)
{
  this->Reset(input, merge);
  const vtkIdType points = this->Mesh.GetNumberOfPoints();
  std::vector<unsigned char> finite = this->FindFinitePoints();
  if (points > static_cast<vtkIdType>(std::numeric_limits<std::uint32_t>::max()))
  {
    vtkErrorWithObjectMacro(self, "more than 2^32 points: the edge keys cannot hold their ids");
    return;
  }
  if (this->Mesh.GetNumberOfUses() >= (vtkIdType(1) << 31) ||
    this->Mesh.GetNumberOfFaces() >= static_cast<vtkIdType>(NoFace))
  {
    vtkErrorWithObjectMacro(self, "more than 2^31 edge uses: the edge table cannot number them");
    return;
  }
  if (merge)
  {
    this->MergePoints(finite);
  }
  std::vector<std::uint32_t> renumber = this->OrderFaces(finite);
  std::vector<unsigned char>().swap(finite);
  this->FindEdges(renumber);
  if (this->NonFiniteFaces > 0)
  {
    vtkWarningWithObjectMacro(
      self, << this->NonFiniteFaces << " faces with NaN or infinite coordinates skipped");
  }
}

void vtkNPRMeshAdjacency::Reset(vtkPolyData* input, bool merge)
{
  vtkPoints* points = input->GetPoints();
  this->Input = input;
  this->Points = points;
  this->Polys = input->GetPolys();
  this->Strips = input->GetStrips();
  this->InputTime = input->GetMTime();
  this->PointsTime = points ? points->GetMTime() : 0;
  this->PointsDataTime = points ? points->GetData()->GetMTime() : 0;
  this->PolysTime = this->Polys->GetMTime();
  this->StripsTime = this->Strips->GetMTime();
  this->Merged = merge;
  this->Valid = true;
  // Emptied and freed: a rebuild never holds the old table beside the new one.
  for (auto* array :
    { &this->Representatives, &this->FaceSource, &this->EdgeFaces, &this->EdgeLocal32 })
  {
    std::vector<std::uint32_t>().swap(*array);
  }
  for (auto* array :
    { &this->FaceNormals[0], &this->FaceNormals[1], &this->FaceNormals[2], &this->FaceOffsets })
  {
    std::vector<float>().swap(*array);
  }
  for (auto* array : { &this->FaceBounds, &this->EdgeKinds, &this->EdgeLocal8, &this->FaceSides })
  {
    std::vector<unsigned char>().swap(*array);
  }
  this->Contours.Reset();
  this->CreaseAngle = -1.0;
  this->DegenerateFaces = this->NonFiniteFaces = this->UnsureFaces = this->KeptFaces = 0;
  this->Mesh.Set(input);
}

std::vector<unsigned char> vtkNPRMeshAdjacency::FindFinitePoints()
{
  const vtkIdType count = this->Mesh.GetNumberOfPoints();
  std::vector<unsigned char> finite(count);
  // The finite points' bounds, whose centre the face offsets are taken from (so that a mesh far
  // from the origin keeps its digits in float).
  using Bounds = std::array<double, 6>;
  vtkSMPThreadLocal<Bounds> bounds(Bounds{ VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, VTK_DOUBLE_MAX,
    -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX });
  vtkSMPTools::For(0, count,
    [&](vtkIdType first, vtkIdType last)
    {
      Bounds& local = bounds.Local();
      for (vtkIdType i = first; i < last; ++i)
      {
        double x[3];
        this->Mesh.GetPoint(i, x);
        finite[i] = std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]);
        for (int k = 0; finite[i] && k < 3; ++k)
        {
          local[k] = std::min(local[k], x[k]);
          local[3 + k] = std::max(local[3 + k], x[k]);
        }
      }
    });
  for (int k = 0; k < 3; ++k)
  {
    this->Lower[k] = VTK_DOUBLE_MAX;
    this->Upper[k] = -VTK_DOUBLE_MAX;
  }
  for (const Bounds& local : bounds)
  {
    for (int k = 0; k < 3; ++k)
    {
      this->Lower[k] = std::min(this->Lower[k], local[k]);
      this->Upper[k] = std::max(this->Upper[k], local[3 + k]);
    }
  }
  for (int k = 0; k < 3; ++k)
  {
    this->Centre[k] = this->Lower[k] <= this->Upper[k]
      ? this->Lower[k] + 0.5 * (this->Upper[k] - this->Lower[k])
      : 0.0;
  }
  return finite;
}

void vtkNPRMeshAdjacency::MergePoints(const std::vector<unsigned char>& finite)
{
  // Each point's representative: the first point at the same coordinates. Sorted by a hash of
  // their coordinates, then id, equal points are in one run, the first of them first.
  const vtkIdType count = this->Mesh.GetNumberOfPoints();
  std::vector<std::uint64_t> keys(count);
  vtkSMPTools::For(0, count,
    [&](vtkIdType first, vtkIdType last)
    {
      for (vtkIdType i = first; i < last; ++i)
      {
        double x[3];
        this->Mesh.GetPoint(i, x);
        keys[i] = finite[i]
          ? (static_cast<std::uint64_t>(CoordinateHash(x)) << 32) | static_cast<std::uint64_t>(i)
          : NoKey;
      }
    });
  vtkNPRRadixSort(keys, 31);
  std::vector<std::uint32_t> distinct; // first point of each coordinate of a run
  for (size_t first = 0; first < keys.size() && keys[first] != NoKey;)
  {
    size_t last = first + 1;
    while (last < keys.size() && (keys[last] >> 32) == (keys[first] >> 32) && keys[last] != NoKey)
    {
      ++last;
    }
    distinct.clear();
    for (size_t k = first; last - first > 1 && k < last; ++k)
    {
      const auto id = static_cast<std::uint32_t>(keys[k]);
      double x[3], y[3];
      this->Mesh.GetPoint(id, x);
      auto same = std::find_if(distinct.begin(), distinct.end(),
        [&](std::uint32_t other)
        {
          this->Mesh.GetPoint(other, y);
          return vtkNPRSamePoint(x, y);
        });
      if (same == distinct.end())
      {
        distinct.push_back(id);
        continue;
      }
      if (this->Representatives.empty())
      {
        this->Representatives.resize(count);
        std::iota(this->Representatives.begin(), this->Representatives.end(), 0u);
      }
      this->Representatives[id] = *same;
    }
    first = last;
  }
}

std::vector<std::uint32_t> vtkNPRMeshAdjacency::OrderFaces(const std::vector<unsigned char>& finite)
{
  std::vector<std::uint64_t> keys = this->KeyFaces(finite);
  const vtkIdType faces = this->Mesh.GetNumberOfFaces();
  this->KeptFaces = faces - this->DegenerateFaces - this->NonFiniteFaces;
  if (this->KeptFaces == faces && InGoodOrder(keys))
  {
    return {};
  }
  vtkNPRRadixSort(keys, 3 * FaceOrderBits);
  const auto kept = static_cast<size_t>(this->KeptFaces);
  this->FaceSource.resize(kept);
  std::vector<std::uint32_t> renumber(faces, NoFace);
  vtkSMPTools::For(0, static_cast<vtkIdType>(kept),
    [&](vtkIdType first, vtkIdType last)
    {
      for (vtkIdType n = first; n < last; ++n)
      {
        const auto source = static_cast<std::uint32_t>(keys[n]);
        this->FaceSource[n] = source;
        renumber[source] = static_cast<std::uint32_t>(n);
      }
    });
  this->ReorderFaceViews();
  return renumber;
}

void vtkNPRMeshAdjacency::ReorderFaceViews()
{
  // The planes were made per input face: kept in the faces' new order.
  auto reorder = [this](auto& array)
  {
    std::decay_t<decltype(array)> ordered(this->FaceSource.size());
    vtkSMPTools::For(0, static_cast<vtkIdType>(ordered.size()),
      [&](vtkIdType first, vtkIdType last)
      {
        for (vtkIdType n = first; n < last; ++n)
        {
          ordered[n] = array[this->FaceSource[n]];
        }
      });
    array.swap(ordered);
  };
  for (auto* array :
    { &this->FaceNormals[0], &this->FaceNormals[1], &this->FaceNormals[2], &this->FaceOffsets })
  {
    reorder(*array);
  }
  reorder(this->FaceBounds);
}

std::vector<std::uint64_t> vtkNPRMeshAdjacency::KeyFaces(const std::vector<unsigned char>& finite)
{
  // The oriented faces, each keyed by the cell of its first point, then its input number, and
  // its plane made; the others NoKey, counted.
  const vtkIdType faces = this->Mesh.GetNumberOfFaces();
  const vtkIdType points = this->Mesh.GetNumberOfPoints();
  std::vector<std::uint64_t> keys(faces);
  for (auto* array :
    { &this->FaceNormals[0], &this->FaceNormals[1], &this->FaceNormals[2], &this->FaceOffsets })
  {
    array->resize(faces);
  }
  this->FaceBounds.resize(faces);
  vtkSMPThreadLocal<std::array<vtkIdType, 2>> left(std::array<vtkIdType, 2>{ 0, 0 });
  vtkSMPTools::For(0, faces,
    [&](vtkIdType first, vtkIdType last)
    {
      std::array<vtkIdType, 2>& counts = left.Local(); // degenerate, not finite
      for (vtkIdType f = first; f < last; ++f)
      {
        keys[f] = NoKey;
        this->Mesh.VisitFace(f,
          [&](vtkIdType size, const vtkIdType* ids)
          {
            bool named = size >= 3, allFinite = true;
            for (vtkIdType i = 0; named && i < size; ++i)
            {
              named = ids[i] >= 0 && ids[i] < points;
            }
            for (vtkIdType i = 0; named && allFinite && i < size; ++i)
            {
              allFinite = finite[ids[i]] != 0;
            }
            double unit[3], p[3];
            if (!named || (allFinite && !UnitNormal(this->Mesh, size, ids, unit)))
            {
              ++counts[0]; // names no point, or has no orientation
              return;
            }
            if (!allFinite)
            {
              ++counts[1];
              return;
            }
            this->Mesh.GetPoint(ids[0], p);
            const std::uint32_t cell = vtkNPRMortonCode(p, this->Lower, this->Upper, FaceOrderBits);
            keys[f] = (static_cast<std::uint64_t>(cell) << 32) | static_cast<std::uint64_t>(f);
            this->MakeFaceView(f, size, ids, unit);
          });
      }
    });
  for (const auto& counts : left)
  {
    this->DegenerateFaces += counts[0];
    this->NonFiniteFaces += counts[1];
  }
  return keys;
}

void vtkNPRMeshAdjacency::MakeFaceView(
  vtkIdType n, vtkIdType size, const vtkIdType* ids, const double unit[3])
{
  // The single-precision copy of the face's plane, and the bound of the test's error.
  glm::dvec3 single;
  for (int k = 0; k < 3; ++k)
  {
    this->FaceNormals[k][n] = static_cast<float>(unit[k]);
    single[k] = this->FaceNormals[k][n];
  }
  double x[3];
  this->Mesh.GetPoint(ids[0], x);
  const glm::dvec3 q = vtkNPRVector(x);
  const glm::dvec3 fromCentre = q - vtkNPRVector(this->Centre);
  const double offset = glm::dot(single, fromCentre);
  this->FaceOffsets[n] = static_cast<float>(offset);
  // Its size, and how far its other points lie from the plane through q (rounding,
  // non-planarity).
  double extent = 0.0, offPlane = 0.0;
  for (vtkIdType i = 1; i < size; ++i)
  {
    this->Mesh.GetPoint(ids[i], x);
    const glm::dvec3 d = vtkNPRVector(x) - q;
    const double distance = glm::length(d);
    extent = std::max(extent, distance);
    offPlane = std::max(offPlane, std::abs(glm::dot(vtkNPRVector(unit), d)) + 1e-15 * distance);
  }
  const double bound =
    std::abs(offset) + glm::length(fromCentre) + extent + offPlane / FaceSideTolerance;
  // As the float 2^(b - 127) at or above it, b its exponent byte (255: infinite).
  int exponent = 0;
  std::frexp(bound, &exponent);
  this->FaceBounds[n] = static_cast<std::uint8_t>(
    std::isfinite(bound) ? std::min(255, std::max(1, exponent + 127)) : 255);
}
