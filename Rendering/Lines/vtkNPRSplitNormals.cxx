// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNPRSplitNormals.h"

#include "vtkAOSDataArrayTemplate.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkFloatArray.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkMath.h"
#include "vtkNPRPointCoordinates.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolygon.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"
#include "vtkTriangle.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace
{
// The polygons as offsets and connectivity, read in place.
struct Polygons
{
  vtkIdType Count = 0;
  const vtkIdType* Offsets = nullptr;
  vtkIdType* Connectivity = nullptr;
  vtkSmartPointer<vtkCellArray> Storage; // the input's, or a copy of vtkIdType ids

  explicit Polygons(vtkCellArray* polys)
    : Storage(polys)
  {
    // Read in place where the storage holds vtkIdType ids (the merge's output); any other
    // storage (32-bit ids, VTK 9.6's other layouts) is copied into that form first. The arrays
    // are taken from the cell array itself, so writes go to what the output will hold.
    if (!this->Take())
    {
      vtkNew<vtkIdTypeArray> offsets, connectivity;
      offsets->DeepCopy(polys->GetOffsetsArray());
      connectivity->DeepCopy(polys->GetConnectivityArray());
      this->Storage = vtkSmartPointer<vtkCellArray>::New();
      this->Storage->SetData(offsets, connectivity);
      this->Take();
    }
  }

  // Whether the storage's arrays hold vtkIdType ids, read in place.
  bool Take()
  {
    using IdArray = vtkAOSDataArrayTemplate<vtkIdType>;
    IdArray* offsets = IdArray::FastDownCast(this->Storage->GetOffsetsArray());
    IdArray* connectivity = IdArray::FastDownCast(this->Storage->GetConnectivityArray());
    this->Count = offsets && connectivity ? this->Storage->GetNumberOfCells() : 0;
    this->Offsets = offsets ? offsets->GetPointer(0) : nullptr;
    this->Connectivity = connectivity ? connectivity->GetPointer(0) : nullptr;
    return offsets && connectivity;
  }

  bool Valid() const { return this->Offsets && this->Connectivity; }

  vtkIdType Size(vtkIdType face) const { return this->Offsets[face + 1] - this->Offsets[face]; }
  const vtkIdType* Points(vtkIdType face) const { return this->Connectivity + this->Offsets[face]; }
  vtkIdType Corners() const { return this->Offsets[this->Count]; }
};

// Face numbers in the links: 32 bits, half the memory (meshes of 2^31 faces or more are left to
// vtkPolyDataNormals).
using FaceId = int32_t;

// The faces around each point in increasing order, once per corner, as vtkCellLinks lists them.
struct PointFaces
{
  std::vector<vtkIdType> Offsets;
  std::vector<FaceId> Faces;

  PointFaces(const Polygons& polygons, vtkIdType pointCount)
    : Offsets(static_cast<size_t>(pointCount) + 1, 0)
    , Faces(static_cast<size_t>(polygons.Corners()))
  {
    for (vtkIdType k = 0; k < polygons.Corners(); ++k)
    {
      ++this->Offsets[static_cast<size_t>(polygons.Connectivity[k]) + 1];
    }
    for (size_t p = 1; p < this->Offsets.size(); ++p)
    {
      this->Offsets[p] += this->Offsets[p - 1];
    }
    std::vector<vtkIdType> next(this->Offsets.begin(), this->Offsets.end() - 1);
    for (vtkIdType face = 0; face < polygons.Count; ++face)
    {
      for (vtkIdType k = 0; k < polygons.Size(face); ++k)
      {
        this->Faces[static_cast<size_t>(next[polygons.Points(face)[k]]++)] =
          static_cast<FaceId>(face);
      }
    }
  }
};

// Each face's unit normal (vtkPolygon::ComputeNormal, kept as float as vtkPolyDataNormals keeps
// it), on every core. A triangle takes vtkPolygon's own shortcut, vtkTriangle::ComputeNormal, with
// the coordinates read without a virtual call: the same doubles, so the same normal.
std::vector<float> FaceNormals(vtkPoints* points, const Polygons& polygons)
{
  std::vector<float> normals(3 * static_cast<size_t>(polygons.Count));
  const vtkNPRPointCoordinates coordinates(points->GetData());
  vtkSMPTools::For(0, polygons.Count,
    [&](vtkIdType begin, vtkIdType end)
    {
      double n[3], corners[3][3];
      for (vtkIdType face = begin; face < end; ++face)
      {
        const vtkIdType size = polygons.Size(face);
        const vtkIdType* ids = polygons.Points(face);
        if (size == 3)
        {
          coordinates.Get(ids[0], corners[0]);
          coordinates.Get(ids[1], corners[1]);
          coordinates.Get(ids[2], corners[2]);
          vtkTriangle::ComputeNormal(corners[0], corners[1], corners[2], n);
        }
        else
        {
          vtkPolygon::ComputeNormal(points, static_cast<int>(size), ids, n);
        }
        for (int c = 0; c < 3; ++c)
        {
          normals[3 * static_cast<size_t>(face) + c] = static_cast<float>(n[c]);
        }
      }
    });
  return normals;
}

// The regions of faces around one point, found as vtkPolyDataNormals::MarkAndSplit finds them:
// from each face not yet in a region, a walk across the point's two edges of it, on through the
// next face across each edge while exactly one face shares the edge, it is in no region yet, and
// its normal is within the feature angle.
class FanSplitter
{
public:
  FanSplitter(const Polygons& polygons, const PointFaces& links, const std::vector<float>& normals,
    double cosAngle)
    : Polys(polygons)
    , Links(links)
    , Normals(normals)
    , CosAngle(cosAngle)
  {
  }

  // One point's fan, gathered once: each entry's face, its first entry, the point's two
  // neighbours in it (as vtkPolyDataNormals picks them) and whether it is a triangle, so that the
  // walks read a few cache lines instead of every face's points at each step.
  struct Fan
  {
    const FaceId* Faces = nullptr;
    vtkIdType Count = 0;
    std::vector<vtkIdType> First;
    std::vector<std::array<vtkIdType, 2>> Neighbours;
    std::vector<char> Triangle;
  };

  // Writes the region of each of the point's link entries; returns the number of regions.
  int Split(vtkIdType point, Fan& fan, int* regions) const
  {
    this->Gather(point, fan);
    std::fill(regions, regions + fan.Count, -1);
    int regionCount = 0;
    for (vtkIdType j = 0; j < fan.Count; ++j)
    {
      if (regions[fan.First[j]] >= 0)
      {
        continue;
      }
      regions[fan.First[j]] = regionCount;
      for (vtkIdType neighbour : fan.Neighbours[j])
      {
        this->Walk(fan, j, neighbour, regionCount, regions);
      }
      ++regionCount;
    }
    for (vtkIdType j = 0; j < fan.Count; ++j) // a face listed twice: both entries in its region
    {
      regions[j] = regions[fan.First[j]];
    }
    return regionCount;
  }

private:
  void Gather(vtkIdType point, Fan& fan) const
  {
    fan.Faces = this->Links.Faces.data() + this->Links.Offsets[point];
    fan.Count = this->Links.Offsets[point + 1] - this->Links.Offsets[point];
    fan.First.resize(static_cast<size_t>(fan.Count));
    fan.Neighbours.resize(static_cast<size_t>(fan.Count));
    fan.Triangle.resize(static_cast<size_t>(fan.Count));
    for (vtkIdType j = 0; j < fan.Count; ++j)
    {
      fan.First[j] = j > 0 && fan.Faces[j] == fan.Faces[j - 1] ? fan.First[j - 1] : j;
      const vtkIdType size = this->Polys.Size(fan.Faces[j]);
      const vtkIdType* pts = this->Polys.Points(fan.Faces[j]);
      const vtkIdType spot = std::find(pts, pts + size, point) - pts;
      fan.Neighbours[j] = { spot == size - 1 ? pts[spot - 1] : pts[spot + 1],
        spot == 0 ? pts[size - 1] : (spot == size - 1 ? pts[0] : pts[spot - 1]) };
      fan.Triangle[j] = size == 3;
    }
  }

  // Whether entry k's face has the point neighbour (a triangle's: one of the two others).
  bool Contains(const Fan& fan, vtkIdType k, vtkIdType neighbour) const
  {
    if (fan.Triangle[k])
    {
      return fan.Neighbours[k][0] == neighbour || fan.Neighbours[k][1] == neighbour;
    }
    const vtkIdType* pts = this->Polys.Points(fan.Faces[k]);
    const vtkIdType* end = pts + this->Polys.Size(fan.Faces[k]);
    return std::find(pts, end, neighbour) != end;
  }

  // The entries of faces other than entry j's that share the edge (point, neighbour), counted
  // once per entry (as vtkPolyData::GetCellEdgeNeighbors counts them); the first in found.
  vtkIdType EdgeNeighbours(const Fan& fan, vtkIdType j, vtkIdType neighbour, vtkIdType& found) const
  {
    vtkIdType shared = 0;
    for (vtkIdType k = 0; k < fan.Count; ++k)
    {
      if (fan.Faces[k] != fan.Faces[j] && this->Contains(fan, k, neighbour))
      {
        found = shared++ == 0 ? k : found;
      }
    }
    return shared;
  }

  double Dot(vtkIdType a, vtkIdType b) const
  {
    const float* na = this->Normals.data() + 3 * a;
    const float* nb = this->Normals.data() + 3 * b;
    const double x[3] = { na[0], na[1], na[2] };
    const double y[3] = { nb[0], nb[1], nb[2] };
    return vtkMath::Dot(x, y);
  }

  // From entry j across the edge to neighbour, on while exactly one face shares the edge, it is
  // in no region yet and its normal is within the feature angle.
  void Walk(const Fan& fan, vtkIdType j, vtkIdType neighbour, int region, int* regions) const
  {
    for (;;)
    {
      vtkIdType next = -1;
      if (this->EdgeNeighbours(fan, j, neighbour, next) != 1 || regions[fan.First[next]] >= 0 ||
        !(this->Dot(fan.Faces[j], fan.Faces[next]) > this->CosAngle))
      {
        return; // a boundary, a non-manifold edge, a region met, or a crease
      }
      regions[fan.First[next]] = region;
      const std::array<vtkIdType, 2>& around = fan.Neighbours[next];
      neighbour = around[0] != neighbour ? around[0] : around[1];
      j = next;
    }
  }

  const Polygons& Polys;
  const PointFaces& Links;
  const std::vector<float>& Normals;
  const double CosAngle;
};

// The regions of every point's link entries, and each point's number of regions.
struct Split
{
  std::vector<uint8_t> Regions; // a point of more regions is left to vtkPolyDataNormals
  bool TooManyRegions = false;
  std::vector<int> RegionCounts;
  std::vector<vtkIdType> FirstAdded; // the output number of each point's region 1
  vtkIdType OutputPoints = 0;
};

Split SplitFans(const Polygons& polygons, const PointFaces& links,
  const std::vector<float>& normals, double featureAngle, vtkIdType pointCount)
{
  Split split;
  split.Regions.resize(links.Faces.size());
  split.RegionCounts.resize(static_cast<size_t>(pointCount));
  const FanSplitter splitter(
    polygons, links, normals, std::cos(vtkMath::RadiansFromDegrees(featureAngle)));
  vtkSMPThreadLocal<std::vector<int>> scratch;
  vtkSMPThreadLocal<FanSplitter::Fan> fans;
  std::atomic<bool> tooMany(false);
  vtkSMPTools::For(0, pointCount,
    [&](vtkIdType begin, vtkIdType end)
    {
      std::vector<int>& regions = scratch.Local();
      FanSplitter::Fan& fan = fans.Local();
      for (vtkIdType p = begin; p < end; ++p)
      {
        const vtkIdType first = links.Offsets[static_cast<size_t>(p)];
        regions.resize(static_cast<size_t>(links.Offsets[static_cast<size_t>(p) + 1] - first));
        const int count = splitter.Split(p, fan, regions.data());
        split.RegionCounts[static_cast<size_t>(p)] = count;
        if (count > std::numeric_limits<uint8_t>::max())
        {
          tooMany = true; // written only then: no shared cache line per point
        }
        std::copy(regions.begin(), regions.end(), split.Regions.begin() + first);
      }
    });
  split.TooManyRegions = tooMany;
  // Points added in point order, and region order within a point, as vtkPolyDataNormals adds
  // them.
  split.FirstAdded.resize(static_cast<size_t>(pointCount));
  split.OutputPoints = pointCount;
  for (size_t p = 0; p < split.FirstAdded.size(); ++p)
  {
    split.FirstAdded[p] = split.OutputPoints;
    split.OutputPoints += std::max(split.RegionCounts[p] - 1, 0);
  }
  return split;
}

// The output number of the point in a face of the given region.
vtkIdType SplitPoint(const Split& split, vtkIdType point, int region)
{
  return region <= 0 ? point : split.FirstAdded[static_cast<size_t>(point)] + region - 1;
}

// The polygons with each point replaced by its region's copy, rewritten in place face by face
// (each face by one thread), so that the output shares the merged mesh's storage.
void SplitPolygons(Polygons& polygons, const PointFaces& links, const Split& split)
{
  vtkSMPTools::For(0, polygons.Count,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType face = begin; face < end; ++face)
      {
        for (vtkIdType c = polygons.Offsets[face]; c < polygons.Offsets[face + 1]; ++c)
        {
          const vtkIdType p = polygons.Connectivity[c];
          const FaceId* first = links.Faces.data() + links.Offsets[p];
          const FaceId* entry = std::lower_bound(
            first, links.Faces.data() + links.Offsets[p + 1], static_cast<FaceId>(face));
          const int region = split.Regions[static_cast<size_t>(entry - links.Faces.data())];
          polygons.Connectivity[c] = SplitPoint(split, p, region);
        }
      }
    });
}

// Each output point's normal: the sum of its faces' normals in face order, as float, normalised.
vtkSmartPointer<vtkFloatArray> PointNormals(const PointFaces& links, const Split& split,
  const std::vector<float>& faceNormals, vtkIdType pointCount)
{
  auto normals = vtkSmartPointer<vtkFloatArray>::New();
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  normals->SetNumberOfTuples(split.OutputPoints);
  float* out = normals->GetPointer(0);
  vtkSMPThreadLocal<std::vector<std::array<float, 3>>> scratch;
  vtkSMPTools::For(0, pointCount,
    [&](vtkIdType begin, vtkIdType end)
    {
      std::vector<std::array<float, 3>>& sums = scratch.Local();
      for (vtkIdType p = begin; p < end; ++p)
      {
        sums.assign(static_cast<size_t>(std::max(split.RegionCounts[static_cast<size_t>(p)], 1)),
          { 0.f, 0.f, 0.f });
        for (vtkIdType k = links.Offsets[p]; k < links.Offsets[p + 1]; ++k)
        {
          const float* n = faceNormals.data() + 3 * links.Faces[static_cast<size_t>(k)];
          std::array<float, 3>& sum = sums[static_cast<size_t>(split.Regions[k])];
          sum = { sum[0] + n[0], sum[1] + n[1], sum[2] + n[2] };
        }
        for (size_t r = 0; r < sums.size(); ++r)
        {
          const std::array<float, 3>& s = sums[r];
          const double length =
            std::sqrt(static_cast<double>(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]));
          float* target = out + 3 * SplitPoint(split, p, static_cast<int>(r));
          for (int c = 0; c < 3; ++c)
          {
            target[c] = length != 0.0 ? static_cast<float>(s[c] / length) : s[c];
          }
        }
      }
    });
  return normals;
}

// The output points: the input's, then the copies in the order they were added, each with its
// point data.
void WritePoints(vtkPolyData* input, const Split& split, vtkPolyData* output)
{
  const vtkIdType count = input->GetNumberOfPoints();
  vtkNew<vtkIdList> copiedFrom, copies; // the added points only: no list of every point
  for (vtkIdType p = 0; p < count; ++p)
  {
    for (int r = 1; r < split.RegionCounts[static_cast<size_t>(p)]; ++r)
    {
      copiedFrom->InsertNextId(p);
      copies->InsertNextId(SplitPoint(split, p, r));
    }
  }
  // The input's points, grown in place (realloc: no second copy of them at the peak).
  vtkSmartPointer<vtkPoints> points = input->GetPoints();
  points->Resize(split.OutputPoints);
  points->SetNumberOfPoints(split.OutputPoints);
  points->GetData()->InsertTuples(copies, copiedFrom, points->GetData());
  output->SetPoints(points);
  vtkPointData* pointData = output->GetPointData();
  pointData->CopyNormalsOff();
  pointData->CopyAllocate(input->GetPointData(), split.OutputPoints);
  pointData->CopyData(input->GetPointData(), 0, count, 0);
  pointData->CopyData(input->GetPointData(), copiedFrom, copies);
  input->SetPoints(nullptr);
}
}

bool vtkNPRSplitNormals::Compute(vtkPolyData* input, double featureAngle, vtkPolyData* output)
{
  if (input->GetNumberOfStrips() > 0 || input->GetNumberOfPolys() == 0 ||
    input->GetNumberOfPoints() == 0 ||
    input->GetNumberOfPolys() >= std::numeric_limits<FaceId>::max())
  {
    return false;
  }
  const vtkIdType pointCount = input->GetNumberOfPoints();
  Polygons polygons(input->GetPolys());
  if (!polygons.Valid())
  {
    return false;
  }
  const PointFaces links(polygons, pointCount);
  const std::vector<float> faceNormals = FaceNormals(input->GetPoints(), polygons);
  const Split split = SplitFans(polygons, links, faceNormals, featureAngle, pointCount);
  if (split.TooManyRegions)
  {
    return false;
  }
  output->Initialize();
  WritePoints(input, split, output);
  output->GetPointData()->SetNormals(PointNormals(links, split, faceNormals, pointCount));
  SplitPolygons(polygons, links, split);
  output->SetPolys(polygons.Storage);
  input->SetPolys(vtkNew<vtkCellArray>()); // its polygons are the output's now
  output->SetVerts(input->GetVerts());
  output->SetLines(input->GetLines());
  output->GetCellData()->PassData(input->GetCellData());
  return true;
}
