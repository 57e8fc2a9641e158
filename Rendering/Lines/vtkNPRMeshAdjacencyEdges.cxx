// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// vtkNPRMeshAdjacency's edge table: the faces' edge uses bucketed by point and sorted, each run
// of uses one edge, listed with the face of its first use.
#include "vtkNPRMeshAdjacency.h"

#include "vtkNPRMeshAdjacencyInternals.h"
#include "vtkNPRVectors.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <atomic>
#include <bitset>
#include <memory>
#include <utility>

namespace
{
using vtkNPRMeshAdjacencyInternals::NoFace;

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
  return vtkNPRSamePoint(pa, pb);
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
