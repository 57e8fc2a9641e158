// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNPRMeshAdjacency.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkMath.h"
#include "vtkNPRFeatureLines.h"
#include "vtkNPRSpatialOrder.h"
#include "vtkObject.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"
#include "vtkSetGet.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <bitset>
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <numeric>

namespace
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

// An edge's dihedral angle from the faces' single-precision normals is within 2e-7 radians
// (1.2e-5 degrees) of the exact one; within AngleMargin degrees of the crease angle, the exact
// angle decides.
constexpr double AngleMargin = 1e-4;

constexpr std::uint32_t NoFace = std::numeric_limits<std::uint32_t>::max();
constexpr std::uint64_t NoKey = std::numeric_limits<std::uint64_t>::max();

// The faces are ordered by the cell of their first points in a grid of 2^FaceOrderBits cells an
// axis, in the input's order within a cell: enough for the viewpoint pass's reads of FaceSides to
// stay near each other whatever the input's order (a cell holds a few thousand faces of a 20M
// face mesh), and an input in a good order stays in it, so that the build reads it in order.
constexpr int FaceOrderBits = 5;

// Edges and triangles are processed in blocks of this many, each listing what it finds in order.
constexpr vtkIdType BlockSize = 16384;

double Dot(const double a[3], const double b[3])
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

// Newell's normal of a face as the sum of a fan's cross products from its first point (the same
// vector, with coordinates relative to the face so that far-away meshes lose no digits), made
// unit length; false where the face has no orientation (see DegenerateNormal).
bool UnitNormal(const vtkNPRMeshFaces& mesh, vtkIdType size, const vtkIdType* ids, double unit[3])
{
  double normal[3] = { 0.0, 0.0, 0.0 }, size2 = 0.0, origin[3], p[3], q[3];
  mesh.GetPoint(ids[0], origin);
  mesh.GetPoint(ids[1], q);
  for (vtkIdType i = 1; i + 1 < size; ++i)
  {
    std::copy_n(q, 3, p);
    mesh.GetPoint(ids[i + 1], q);
    const double a[3] = { p[0] - origin[0], p[1] - origin[1], p[2] - origin[2] };
    const double b[3] = { q[0] - origin[0], q[1] - origin[1], q[2] - origin[2] };
    normal[0] += a[1] * b[2] - a[2] * b[1];
    normal[1] += a[2] * b[0] - a[0] * b[2];
    normal[2] += a[0] * b[1] - a[1] * b[0];
    size2 = std::max(size2, std::max(Dot(a, a), Dot(b, b)));
  }
  const double length = std::sqrt(Dot(normal, normal));
  if (!(length > DegenerateNormal * size2) || !std::isfinite(length))
  {
    return false;
  }
  for (int k = 0; k < 3; ++k)
  {
    unit[k] = normal[k] / length;
  }
  return true;
}

// The angle between two unit normals in degrees, the second flipped where the faces' windings
// disagree; atan2 keeps small angles exact where acos of the dot product would lose them.
double DihedralAngle(const double n0[3], const double normal1[3], bool flip)
{
  double n1[3], cross[3];
  for (int k = 0; k < 3; ++k)
  {
    n1[k] = flip ? -normal1[k] : normal1[k];
  }
  vtkMath::Cross(n0, n1, cross);
  return vtkMath::DegreesFromRadians(std::atan2(vtkMath::Norm(cross), Dot(n0, n1)));
}

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

// A face's number in the table, from the build's renumbering (empty: the input's order kept).
std::uint32_t NewNumber(const std::vector<std::uint32_t>& renumber, vtkIdType face)
{
  return renumber.empty() ? static_cast<std::uint32_t>(face) : renumber[face];
}

// Bits set from several threads.
class AtomicBits
{
public:
  explicit AtomicBits(vtkIdType size)
    : Words(new std::atomic<std::uint64_t>[static_cast<size_t>(size / 64 + 1)]())
  {
  }
  void Set(vtkIdType i)
  {
    this->Words[i / 64].fetch_or(1ull << (i % 64), std::memory_order_relaxed);
  }
  // Bits set in [first, last).
  vtkIdType Count(vtkIdType first, vtkIdType last) const
  {
    vtkIdType count = 0;
    while (first < last)
    {
      const vtkIdType end = std::min(last, (first / 64 + 1) * 64);
      const std::uint64_t word = this->Words[first / 64].load(std::memory_order_relaxed);
      const std::uint64_t above = word >> (first % 64);
      const vtkIdType bits = end - first;
      count += static_cast<vtkIdType>(
        std::bitset<64>(bits == 64 ? above : above & ((1ull << bits) - 1)).count());
      first = end;
    }
    return count;
  }

private:
  std::unique_ptr<std::atomic<std::uint64_t>[]> Words;
};
}

// One face's use of an edge: the face, which edge of it, and its points' input ids (smaller
// first, to tell split points; 0 where no points were merged).
struct vtkNPRMeshAdjacency::Use
{
  vtkIdType Face;
  vtkIdType Local;
  std::uint64_t InputPoints;
};

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
  size_t bytes = this->Mesh.GetMemorySize();
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
  add(this->Triangles);
  add(this->UnitNormals);
  add(this->Facing);
  for (const auto& block : this->ContourSegments)
  {
    add(block);
  }
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
  for (auto* array : { &this->Representatives, &this->FaceSource, &this->EdgeFaces,
         &this->EdgeLocal32, &this->Triangles })
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
  std::vector<double>().swap(this->UnitNormals);
  std::vector<double>().swap(this->Facing);
  std::vector<std::vector<ContourSegment>>().swap(this->ContourSegments);
  this->CreaseAngle = -1.0;
  this->DegenerateFaces = this->NonFiniteFaces = this->UnsureFaces = this->KeptFaces = 0;
  this->TrianglesValid = false;
  this->NormalsArray = nullptr;
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
          return x[0] == y[0] && x[1] == y[1] && x[2] == y[2];
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

vtkNPRMeshAdjacency::Use vtkNPRMeshAdjacency::ReadUse(std::uint64_t use) const
{
  Use read;
  read.Face = this->Mesh.GetFaceOfUse(static_cast<vtkIdType>(use));
  read.Local = static_cast<vtkIdType>(use) - this->Mesh.GetFirstUse(read.Face);
  read.InputPoints = 0;
  // Its points' input ids matter only where points were merged (else they are the edge's own).
  if (!this->Representatives.empty())
  {
    this->Mesh.VisitFace(read.Face,
      [&](vtkIdType size, const vtkIdType* ids)
      {
        const auto a = static_cast<std::uint64_t>(ids[read.Local]);
        const auto b = static_cast<std::uint64_t>(ids[(read.Local + 1) % size]);
        read.InputPoints = (std::min(a, b) << 32) | std::max(a, b);
      });
  }
  return read;
}

bool vtkNPRMeshAdjacency::FaceNormal(std::uint32_t face, double unit[3]) const
{
  bool oriented = false;
  this->Mesh.VisitFace(this->Source(face),
    [&](vtkIdType size, const vtkIdType* ids)
    { oriented = UnitNormal(this->Mesh, size, ids, unit); });
  return oriented;
}

void vtkNPRMeshAdjacency::FindEdges(const std::vector<std::uint32_t>& renumber)
{
  // Calls visit(use, a, b) for each edge of face f between two representatives a != b at
  // different coordinates (an edge from a point to itself is none).
  auto forEachUse = [this](vtkIdType f, auto&& visit)
  {
    this->Mesh.VisitFace(f,
      [&](vtkIdType size, const vtkIdType* ids)
      {
        const vtkIdType firstUse = this->Mesh.GetFirstUse(f);
        for (vtkIdType i = 0; i < size; ++i)
        {
          const std::uint32_t a = this->Representative(ids[i]);
          const std::uint32_t b = this->Representative(ids[(i + 1) % size]);
          if (a == b || (!this->Merged && this->SameCoordinates(a, b)))
          {
            continue;
          }
          visit(firstUse + i, a, b);
        }
      });
  };
  // The uses bucketed by their smaller point, each as (larger point, use x 2 + forward): in a
  // bucket sorted, each edge is a run, its uses in the faces' order. 8 bytes a use, where
  // sorting all uses by both points took 32.
  const vtkIdType points = this->Mesh.GetNumberOfPoints();
  const vtkIdType faces = this->Mesh.GetNumberOfFaces();
  std::unique_ptr<std::atomic<std::uint32_t>[]> start(
    new std::atomic<std::uint32_t>[static_cast<size_t>(points + 1)]());
  auto forEachKeptFace = [&](auto&& visit)
  {
    vtkSMPTools::For(0, faces,
      [&](vtkIdType first, vtkIdType last)
      {
        for (vtkIdType f = first; f < last; ++f)
        {
          if (NewNumber(renumber, f) != NoFace)
          {
            forEachUse(f, visit);
          }
        }
      });
  };
  forEachKeptFace([&](vtkIdType, std::uint32_t a, std::uint32_t b)
    { start[std::min(a, b)].fetch_add(1, std::memory_order_relaxed); });
  std::uint32_t total = 0;
  for (vtkIdType v = 0; v <= points; ++v)
  {
    total += start[v].exchange(total, std::memory_order_relaxed);
  }
  std::vector<std::uint64_t> uses(total);
  forEachKeptFace(
    [&](vtkIdType use, std::uint32_t a, std::uint32_t b)
    {
      const std::uint32_t slot = start[std::min(a, b)].fetch_add(1, std::memory_order_relaxed);
      uses[slot] = (static_cast<std::uint64_t>(std::max(a, b)) << 32) |
        (static_cast<std::uint64_t>(use) << 1) | (a < b ? 1u : 0u);
    });
  // Each start now holds the next bucket's: moved back by one.
  for (vtkIdType v = points - 1; v > 0; --v)
  {
    start[v].store(start[v - 1].load(std::memory_order_relaxed), std::memory_order_relaxed);
  }
  if (points > 0)
  {
    start[0] = 0;
  }
  vtkSMPTools::For(0, points,
    [&](vtkIdType first, vtkIdType last)
    {
      for (vtkIdType v = first; v < last; ++v)
      {
        std::sort(uses.begin() + start[v], uses.begin() + start[v + 1]);
      }
    });
  this->MakeEdges(uses, start.get(), renumber);
}

bool vtkNPRMeshAdjacency::SameCoordinates(std::uint32_t a, std::uint32_t b) const
{
  double pa[3], pb[3];
  this->Mesh.GetPoint(a, pa);
  this->Mesh.GetPoint(b, pb);
  return pa[0] == pb[0] && pa[1] == pb[1] && pa[2] == pb[2];
}

void vtkNPRMeshAdjacency::MakeEdges(const std::vector<std::uint64_t>& uses,
  const std::atomic<std::uint32_t>* start, const std::vector<std::uint32_t>& renumber)
{
  // Calls visit(first, last) for the uses [first, last) of each edge, in parallel.
  auto forEachEdge = [&](auto&& visit)
  {
    vtkSMPTools::For(0, this->Mesh.GetNumberOfPoints(),
      [&](vtkIdType firstPoint, vtkIdType lastPoint)
      {
        for (vtkIdType v = firstPoint; v < lastPoint; ++v)
        {
          const size_t end = start[v + 1];
          for (size_t first = start[v]; first < end;)
          {
            size_t last = first + 1;
            while (last < end && (uses[last] >> 32) == (uses[first] >> 32))
            {
              ++last;
            }
            visit(first, last);
            first = last;
          }
        }
      });
  };
  auto useOf = [&uses](size_t i) { return (uses[i] & 0xffffffffu) >> 1; };
  // Each edge is listed with the face of its first use, in the order that face uses its edges:
  // an edge's place is where its face's edges start, plus the first uses before its own.
  AtomicBits firstUses(this->Mesh.GetNumberOfUses());
  forEachEdge([&](size_t first, size_t) { firstUses.Set(static_cast<vtkIdType>(useOf(first))); });
  const vtkIdType kept = this->KeptFaces;
  std::vector<std::uint32_t> faceStart(kept + 1, 0);
  vtkSMPThreadLocal<vtkIdType> largest(0);
  vtkSMPTools::For(0, kept,
    [&](vtkIdType first, vtkIdType last)
    {
      vtkIdType& largestHere = largest.Local();
      for (vtkIdType n = first; n < last; ++n)
      {
        const vtkIdType size = this->Mesh.GetFaceSize(this->Source(n));
        const vtkIdType use = this->Mesh.GetFirstUse(this->Source(n));
        faceStart[n] = static_cast<std::uint32_t>(firstUses.Count(use, use + size));
        largestHere = std::max(largestHere, size);
      }
    });
  std::uint32_t edges = 0;
  for (std::uint32_t& count : faceStart)
  {
    edges += std::exchange(count, edges);
  }
  vtkIdType largestFace = 0;
  for (vtkIdType size : largest)
  {
    largestFace = std::max(largestFace, size);
  }
  this->EdgeFaces.resize(2 * static_cast<size_t>(edges));
  this->EdgeKinds.resize(edges);
  if (largestFace <= 256)
  {
    this->EdgeLocal8.resize(edges);
  }
  else
  {
    this->EdgeLocal32.resize(edges);
  }
  forEachEdge(
    [&](size_t first, size_t last)
    {
      const Use use0 = this->ReadUse(useOf(first));
      const std::uint32_t face0 = NewNumber(renumber, use0.Face);
      const vtkIdType firstOfFace = this->Mesh.GetFirstUse(use0.Face);
      const size_t e = faceStart[face0] +
        static_cast<size_t>(firstUses.Count(firstOfFace, static_cast<vtkIdType>(useOf(first))));
      this->EdgeFaces[2 * e] = face0;
      this->MakeEdge(e, use0, uses.data() + first, last - first, renumber);
    });
}

void vtkNPRMeshAdjacency::MakeEdge(size_t e, const Use& use0, const std::uint64_t* uses,
  size_t count, const std::vector<std::uint32_t>& renumber)
{
  if (this->EdgeLocal8.empty())
  {
    this->EdgeLocal32[e] = static_cast<std::uint32_t>(use0.Local);
  }
  else
  {
    this->EdgeLocal8[e] = static_cast<std::uint8_t>(use0.Local);
  }
  this->EdgeFaces[2 * e + 1] = 0;
  if (count == 1)
  {
    this->EdgeKinds[e] = Boundary;
    return;
  }
  const Use use1 = this->ReadUse((uses[1] & 0xffffffffu) >> 1);
  this->EdgeFaces[2 * e + 1] = NewNumber(renumber, use1.Face);
  if (count > 2)
  {
    this->EdgeKinds[e] = NonManifold;
    return;
  }
  const bool same = (uses[0] & 1u) == (uses[1] & 1u);
  const bool split = use0.InputPoints != use1.InputPoints;
  this->EdgeKinds[e] =
    static_cast<unsigned char>(TwoFaces | (same ? SameDirection : 0) | (split ? Split : 0));
}

void vtkNPRMeshAdjacency::MakeFaceView(
  vtkIdType n, vtkIdType size, const vtkIdType* ids, const double unit[3])
{
  // The single-precision copy of the face's plane, and the bound of the test's error.
  double single[3], q[3];
  for (int k = 0; k < 3; ++k)
  {
    this->FaceNormals[k][n] = static_cast<float>(unit[k]);
    single[k] = this->FaceNormals[k][n];
  }
  this->Mesh.GetPoint(ids[0], q);
  const double fromCentre[3] = { q[0] - this->Centre[0], q[1] - this->Centre[1],
    q[2] - this->Centre[2] };
  const double offset = Dot(single, fromCentre);
  this->FaceOffsets[n] = static_cast<float>(offset);
  // Its size, and how far its other points lie from the plane through q (rounding,
  // non-planarity).
  double extent = 0.0, offPlane = 0.0;
  for (vtkIdType i = 1; i < size; ++i)
  {
    double p[3];
    this->Mesh.GetPoint(ids[i], p);
    const double d[3] = { p[0] - q[0], p[1] - q[1], p[2] - q[2] };
    const double distance = std::sqrt(Dot(d, d));
    extent = std::max(extent, distance);
    offPlane = std::max(offPlane, std::abs(Dot(unit, d)) + 1e-15 * distance);
  }
  const double bound = std::abs(offset) + std::sqrt(Dot(fromCentre, fromCentre)) + extent +
    offPlane / FaceSideTolerance;
  // As the float 2^(b - 127) at or above it, b its exponent byte (255: infinite).
  int exponent = 0;
  std::frexp(bound, &exponent);
  this->FaceBounds[n] = static_cast<std::uint8_t>(
    std::isfinite(bound) ? std::min(255, std::max(1, exponent + 127)) : 255);
}

double vtkNPRMeshAdjacency::Angle(vtkIdType edge) const
{
  double n0[3], n1[3];
  this->FaceNormal(this->EdgeFaces[2 * edge], n0);
  this->FaceNormal(this->EdgeFaces[2 * edge + 1], n1);
  return DihedralAngle(n0, n1, (this->EdgeKinds[edge] & SameDirection) != 0);
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
          double n0[3], n1[3], cross[3];
          for (int k = 0; k < 3; ++k)
          {
            n0[k] = this->FaceNormals[k][this->EdgeFaces[2 * e]];
            n1[k] = flip * this->FaceNormals[k][this->EdgeFaces[2 * e + 1]];
          }
          vtkMath::Cross(n0, n1, cross);
          const double side = vtkMath::Norm(cross) * cosAngle - Dot(n0, n1) * sinAngle;
          const double bound = margin * std::sqrt(Dot(n0, n0) * Dot(n1, n1));
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
  double toEye[3];
  for (int k = 0; k < 3; ++k)
  {
    toEye[k] = parallel ? view[k] : view[k] - this->Centre[k];
  }
  const float ex = static_cast<float>(toEye[0]), ey = static_cast<float>(toEye[1]),
              ez = static_cast<float>(toEye[2]);
  const float toEyeLength = static_cast<float>(std::sqrt(Dot(toEye, toEye)) * (1.0 + 1e-6));
  const float tolerance = static_cast<float>(FaceSideTolerance);
  vtkSMPThreadLocal<vtkIdType> unsure(0);
  // In float, in a loop the compiler vectorises: FaceSideTolerance covers float arithmetic.
  vtkSMPTools::For(0, faceCount,
    [=, &unsure](vtkIdType first, vtkIdType last)
    {
      int unsureHere = 0;
      for (vtkIdType f = first; f < last; ++f)
      {
        const float projected = nx[f] * ex + ny[f] * ey + nz[f] * ez;
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
  double f0, f1;
  if (view.Parallel)
  {
    f0 = Dot(n0, view.Direction);
    f1 = Dot(n1, view.Direction);
  }
  else
  {
    std::uint32_t a, b;
    this->EdgePoints(edge, a, b);
    double p[3];
    this->Mesh.GetPoint(a, p);
    const double toPoint[3] = { p[0] - view.Eye[0], p[1] - view.Eye[1], p[2] - view.Eye[2] };
    f0 = Dot(n0, toPoint);
    f1 = Dot(n1, toPoint);
  }
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

vtkDataArray* vtkNPRMeshAdjacency::ContourNormals(vtkPolyData* input)
{
  vtkDataArray* normals = input->GetPointData()->GetNormals();
  const vtkIdType points = input->GetPoints() ? input->GetPoints()->GetNumberOfPoints() : 0;
  return normals && normals->GetNumberOfComponents() == 3 &&
      normals->GetNumberOfTuples() == points && points > 0 &&
      points <= static_cast<vtkIdType>(std::numeric_limits<std::uint32_t>::max())
    ? normals
    : nullptr;
}

void vtkNPRMeshAdjacency::MakeContourTables(vtkDataArray* normals)
{
  const vtkIdType pointCount = this->Mesh.GetNumberOfPoints();
  if (!this->TrianglesValid)
  {
    this->Triangles.clear();
    for (vtkIdType t = 0; t < this->Mesh.GetNumberOfTriangles(); ++t)
    {
      vtkIdType ids[3];
      this->Mesh.GetTriangle(t, ids);
      // A repeated point (strips repeat points to turn): no area, and a zero-length segment.
      const bool inRange =
        std::all_of(ids, ids + 3, [&](vtkIdType id) { return id >= 0 && id < pointCount; });
      if (inRange && ids[0] != ids[1] && ids[1] != ids[2] && ids[2] != ids[0])
      {
        this->Triangles.insert(this->Triangles.end(),
          { static_cast<std::uint32_t>(ids[0]), static_cast<std::uint32_t>(ids[1]),
            static_cast<std::uint32_t>(ids[2]) });
      }
    }
    this->TrianglesValid = true;
  }
  if (this->NormalsArray != normals || this->NormalsTime != normals->GetMTime())
  {
    this->UnitNormals.resize(3 * pointCount);
    double* unit = this->UnitNormals.data();
    vtkSMPTools::For(0, pointCount,
      [=](vtkIdType first, vtkIdType last)
      {
        for (vtkIdType i = first; i < last; ++i)
        {
          double n[3];
          normals->GetTuple(i, n);
          const double length = std::sqrt(Dot(n, n));
          const bool usable = length > 0.0 && std::isfinite(length);
          for (int k = 0; k < 3; ++k)
          {
            unit[3 * i + k] = usable ? n[k] / length : std::numeric_limits<double>::quiet_NaN();
          }
        }
      });
    this->NormalsArray = normals;
    this->NormalsTime = normals->GetMTime();
  }
}

void vtkNPRMeshAdjacency::ComputeContours(
  vtkPolyData*, vtkDataArray* normals, bool parallel, const double view[3])
{
  this->MakeContourTables(normals);
  // g per point: not finite where the normal or the point is unusable.
  const vtkIdType pointCount = this->Mesh.GetNumberOfPoints();
  this->Facing.resize(pointCount);
  const double* unit = this->UnitNormals.data();
  double* facing = this->Facing.data();
  vtkSMPTools::For(0, pointCount,
    [=](vtkIdType first, vtkIdType last)
    {
      for (vtkIdType i = first; i < last; ++i)
      {
        const double* n = unit + 3 * i;
        double p[3];
        this->Mesh.GetPoint(i, p);
        const double toPoint[3] = { p[0] - view[0], p[1] - view[1], p[2] - view[2] };
        facing[i] = parallel ? Dot(n, view) : Dot(n, toPoint);
      }
    });

  // The triangles where g changes sign, in blocks that list them in order.
  const vtkIdType triangleCount = static_cast<vtkIdType>(this->Triangles.size() / 3);
  const vtkIdType blockCount = (triangleCount + BlockSize - 1) / BlockSize;
  this->ContourSegments.resize(static_cast<size_t>(blockCount));
  const std::uint32_t* triangles = this->Triangles.data();
  vtkSMPThreadLocal<vtkIdType> skipped(0);
  vtkSMPTools::For(0, blockCount,
    [&](vtkIdType firstBlock, vtkIdType lastBlock)
    {
      vtkIdType skippedHere = 0;
      for (vtkIdType block = firstBlock; block < lastBlock; ++block)
      {
        auto& listed = this->ContourSegments[block];
        listed.clear();
        const vtkIdType last = std::min(triangleCount, (block + 1) * BlockSize);
        for (vtkIdType t = block * BlockSize; t < last; ++t)
        {
          const std::uint32_t* ids = triangles + 3 * t;
          const double g[3] = { facing[ids[0]], facing[ids[1]], facing[ids[2]] };
          if (!(std::isfinite(g[0]) && std::isfinite(g[1]) && std::isfinite(g[2])))
          {
            ++skippedHere;
            continue;
          }
          // g == 0 counts as positive, so that each edge is decided one way for all its faces.
          const bool positive[3] = { g[0] >= 0.0, g[1] >= 0.0, g[2] >= 0.0 };
          if (positive[0] == positive[1] && positive[1] == positive[2])
          {
            continue;
          }
          ContourSegment segment{ static_cast<std::uint32_t>(t), 0, 0 };
          for (unsigned char k = 0; k < 3; ++k)
          {
            const bool next = positive[(k + 1) % 3];
            if (positive[k] != next)
            {
              (next ? segment.Rise : segment.Fall) = k;
            }
          }
          listed.push_back(segment);
        }
      }
      skipped.Local() += skippedHere;
    });
  this->SkippedContourTriangles = 0;
  for (vtkIdType count : skipped)
  {
    this->SkippedContourTriangles += count;
  }
}
