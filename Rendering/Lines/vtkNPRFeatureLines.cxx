// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNPRFeatureLines.h"

#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkNPROccluders.h" // for vtkNPRForEachTriangle
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <unordered_map>
#include <utility>
#include <vector>

namespace
{
// A face whose normal is shorter than this, relative to its squared size, has no orientation:
// its points are collinear or coincident up to rounding.
constexpr double DegenerateNormal = 1e-12;

// Exact coordinates as a sort key (-0 and +0 are the same coordinate).
struct CoordinateKey
{
  std::uint64_t Bits[3];
  bool operator==(const CoordinateKey& other) const
  {
    return this->Bits[0] == other.Bits[0] && this->Bits[1] == other.Bits[1] &&
      this->Bits[2] == other.Bits[2];
  }
  bool operator<(const CoordinateKey& other) const
  {
    return std::lexicographical_compare(this->Bits, this->Bits + 3, other.Bits, other.Bits + 3);
  }
};

CoordinateKey MakeCoordinateKey(const double x[3])
{
  CoordinateKey key;
  for (int i = 0; i < 3; ++i)
  {
    const double value = x[i] == 0.0 ? 0.0 : x[i];
    std::memcpy(&key.Bits[i], &value, sizeof(double));
  }
  return key;
}

// The kinds of edge the viewpoint pass tells apart.
enum ViewKind : unsigned char
{
  ViewBoundary = 1,      // one face
  ViewNonManifold = 2,   // more than two faces
  ViewTwoFaces = 4,      // two faces: crease and silhouette tests
  ViewSameDirection = 8, // the two faces traverse the edge the same way: flip the second
  ViewSplit = 16,        // two faces that reach it through different points (merged coordinates)
};

double Dot(const double a[3], const double b[3])
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

// The side of a face's plane the eye is on, per face and camera, from single-precision data:
// decided where the value is farther from zero than its error bound, which the double-precision
// test per edge (the reference) then cannot contradict; unsure faces take that test.
constexpr unsigned SideFacing = 1; // the double-precision term is negative (else positive)
constexpr unsigned SideUnsure = 2; // too close to zero to tell here, or not finite
// Relative error allowed for the single-precision terms: over five times the worst case (the
// normal's, the offset's and the eye's rounding to float, 2^-24 each, and the float products'
// and sums' rounding).
constexpr double FaceSideTolerance = 2e-6;
}

// The mesh's edges with their faces, built once per mesh.
struct vtkNPRFeatureLines::Adjacency
{
  struct Edge
  {
    vtkIdType A, B;     // point ids, A < B (representatives when merging)
    vtkIdType Faces[2]; // the first two faces (indices into Normals / 3)
    int Count;          // faces that use the edge
    bool FirstForward;  // the first face goes from A to B
    bool SameDirection; // the second face goes the same way as the first (winding differs)
    bool Split;         // the two faces use different points at its ends (normals split there)
    double Angle;       // between the two faces' normals, degrees (Count == 2)
  };

  // What the table was built from.
  vtkPolyData* Input = nullptr;
  vtkPoints* Points = nullptr;
  vtkCellArray* Polys = nullptr;
  vtkCellArray* Strips = nullptr;
  vtkMTimeType InputTime = 0, PointsTime = 0, PointsDataTime = 0, PolysTime = 0, StripsTime = 0;
  bool Merged = true;
  bool Valid = false;

  std::vector<double> Coordinates; // of every input point, double
  std::vector<double> Normals;     // unit normal of every oriented face
  // Per face, for the side-of-plane test of each camera (20 bytes instead of reading the
  // normal and a point in double for each edge): the unit normal in float, its offset n.(q - c)
  // for the face's first point q relative to the mesh's centre c, and the terms that bound the
  // error of the test, FaceSideTolerance * (Bound + |eye - c|): |offset|, |q - c|, the face's
  // size, and how far its other points lie from the plane through q (rounding, non-planarity).
  struct FaceView
  {
    float Normal[3];
    float Offset;
    float Bound;
  };
  std::vector<FaceView> FaceViews; // while building
  // The same in the faces' Z order, an array per member, for the viewpoint pass.
  std::vector<float> FaceNormals[3], FaceOffsets, FaceBounds;
  double Centre[3] = { 0.0, 0.0, 0.0 };
  std::vector<Edge> Edges;
  vtkIdType DegenerateFaces = 0;
  // What the viewpoint pass reads, packed (10 bytes an edge, 21 with those read only for a typed
  // edge or an unsure face, instead of the Edge's 48: the pass is bound by memory traffic), in
  // the order of the edges' first faces (Z order): each edge's index in Edges, its two faces and
  // two points (A, B), its kind (ViewKind bits), and whether it is a crease at CreaseAngle
  // (computed again when the angle changes).
  std::vector<std::uint32_t> ViewEdges;  // index in Edges
  std::vector<std::uint32_t> ViewFaces;  // 2 an edge
  std::vector<std::uint32_t> ViewPoints; // 2 an edge
  std::vector<unsigned char> ViewKinds;
  std::vector<unsigned char> Creases;
  double CreaseAngle = -1.0; // of Creases; < 0: none computed
  // Scratch of the viewpoint pass, kept to save their allocation: per block of edges its typed
  // edges (index in Edges, points, type; the serial output then never reads the large Edges),
  // each input point's output id (all -1 between updates), each face's side (SideFacing,
  // SideUnsure bits) for the last viewpoint.
  struct TypedEdge
  {
    std::uint32_t Edge, A, B;
    unsigned char Type;
    bool operator<(const TypedEdge& other) const { return this->Edge < other.Edge; }
  };
  std::vector<std::vector<TypedEdge>> TypedEdges;
  std::vector<vtkIdType> OutputIds;
  std::vector<unsigned char> FaceSides;
  vtkIdType UnsureFaces = 0;
  vtkIdType NonFiniteFaces = 0;

  // Smooth contours, made only when asked for: the triangles (fans of the polygons, the strips'
  // triangles in their winding, none with a repeated or out-of-range point) and the unit point
  // normals (NaN where zero or not finite), both kept per mesh; each point's facing term for
  // the last viewpoint; per block of triangles, the segments found: the triangle and its edges
  // (0: points 0-1, 1: 1-2, 2: 2-0) where g turns from negative to positive (Rise) and back.
  std::vector<std::uint32_t> Triangles;
  bool TrianglesValid = false;
  vtkDataArray* NormalsArray = nullptr;
  vtkMTimeType NormalsTime = 0;
  std::vector<double> UnitNormals;
  std::vector<double> Facing;
  struct ContourSegment
  {
    std::uint32_t Triangle;
    unsigned char Rise, Fall;
  };
  std::vector<std::vector<ContourSegment>> ContourSegments;
  vtkIdType SkippedContourTriangles = 0;

  bool IsCurrent(vtkPolyData* input, bool merge) const
  {
    vtkPoints* points = input->GetPoints();
    return this->Valid && this->Input == input && this->InputTime == input->GetMTime() &&
      this->Points == points && this->PointsTime == (points ? points->GetMTime() : 0) &&
      this->PointsDataTime == (points ? points->GetData()->GetMTime() : 0) &&
      this->Polys == input->GetPolys() && this->PolysTime == input->GetPolys()->GetMTime() &&
      this->Strips == input->GetStrips() && this->StripsTime == input->GetStrips()->GetMTime() &&
      this->Merged == merge;
  }

  void Build(vtkPolyData* input, bool merge, vtkNPRFeatureLines* self);
  // The point normals a smooth contour can use: 3 components, one per point; else nullptr.
  static vtkDataArray* ContourNormals(vtkPolyData* input);
  // Facing, ContourSegments and SkippedContourTriangles for an eye (perspective) or a direction
  // of projection (parallel), from the input's point normals (ContourNormals).
  void ComputeContours(
    vtkPolyData* input, vtkDataArray* normals, bool parallel, const double view[3]);
  // FaceSides and UnsureFaces for an eye (perspective) or a direction of projection (parallel).
  void ComputeFaceSides(bool parallel, const double view[3]);
};

void vtkNPRFeatureLines::Adjacency::ComputeFaceSides(bool parallel, const double view[3])
{
  const vtkIdType faceCount = static_cast<vtkIdType>(this->FaceOffsets.size());
  this->FaceSides.resize(this->FaceOffsets.size());
  const float* nx = this->FaceNormals[0].data();
  const float* ny = this->FaceNormals[1].data();
  const float* nz = this->FaceNormals[2].data();
  const float* offsets = this->FaceOffsets.data();
  const float* bounds = this->FaceBounds.data();
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
        const float error =
          parallel ? tolerance * toEyeLength : tolerance * (bounds[f] + toEyeLength);
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

vtkDataArray* vtkNPRFeatureLines::Adjacency::ContourNormals(vtkPolyData* input)
{
  vtkDataArray* normals = input->GetPointData()->GetNormals();
  const vtkIdType points = input->GetPoints() ? input->GetPoints()->GetNumberOfPoints() : 0;
  return normals && normals->GetNumberOfComponents() == 3 &&
      normals->GetNumberOfTuples() == points && points > 0 &&
      points <= static_cast<vtkIdType>(std::numeric_limits<std::uint32_t>::max())
    ? normals
    : nullptr;
}

void vtkNPRFeatureLines::Adjacency::ComputeContours(
  vtkPolyData* input, vtkDataArray* normals, bool parallel, const double view[3])
{
  const vtkIdType pointCount = static_cast<vtkIdType>(this->Coordinates.size() / 3);
  if (!this->TrianglesValid)
  {
    this->Triangles.clear();
    auto addTriangle = [&](vtkIdType a, vtkIdType b, vtkIdType c)
    {
      for (vtkIdType id : { a, b, c })
      {
        if (id < 0 || id >= pointCount)
        {
          return;
        }
      }
      // A repeated point (strips repeat points to turn): no area, and a zero-length segment.
      if (a != b && b != c && c != a)
      {
        this->Triangles.insert(this->Triangles.end(),
          { static_cast<std::uint32_t>(a), static_cast<std::uint32_t>(b),
            static_cast<std::uint32_t>(c) });
      }
    };
    vtkNPRForEachTriangle(input, addTriangle);
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

  // g per point: not finite where the normal or the point is unusable.
  this->Facing.resize(pointCount);
  const double* coordinates = this->Coordinates.data();
  const double* unit = this->UnitNormals.data();
  double* facing = this->Facing.data();
  vtkSMPTools::For(0, pointCount,
    [=](vtkIdType first, vtkIdType last)
    {
      for (vtkIdType i = first; i < last; ++i)
      {
        const double* n = unit + 3 * i;
        const double* p = coordinates + 3 * i;
        const double toPoint[3] = { p[0] - view[0], p[1] - view[1], p[2] - view[2] };
        facing[i] = parallel ? Dot(n, view) : Dot(n, toPoint);
      }
    });

  // The triangles where g changes sign, in blocks that list them in order.
  const vtkIdType triangleCount = static_cast<vtkIdType>(this->Triangles.size() / 3);
  const vtkIdType blockSize = 16384;
  const vtkIdType blockCount = (triangleCount + blockSize - 1) / blockSize;
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
        const vtkIdType last = std::min(triangleCount, (block + 1) * blockSize);
        for (vtkIdType t = block * blockSize; t < last; ++t)
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

void vtkNPRFeatureLines::Adjacency::Build(vtkPolyData* input, bool merge, vtkNPRFeatureLines* self)
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
  this->Normals.clear();
  this->FaceViews.clear();
  for (auto* array : { &this->FaceNormals[0], &this->FaceNormals[1], &this->FaceNormals[2],
         &this->FaceOffsets, &this->FaceBounds })
  {
    array->clear();
  }
  this->Edges.clear();
  this->DegenerateFaces = 0;
  this->NonFiniteFaces = 0;
  this->Triangles.clear();
  this->TrianglesValid = false;
  this->NormalsArray = nullptr;

  const vtkIdType numberOfPoints = points ? points->GetNumberOfPoints() : 0;
  this->Coordinates.resize(3 * numberOfPoints);
  std::vector<char> finite(numberOfPoints);
  for (vtkIdType i = 0; i < numberOfPoints; ++i)
  {
    double* x = &this->Coordinates[3 * i];
    points->GetPoint(i, x);
    finite[i] = std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]);
  }
  // The centre of the finite points' bounds: the face offsets are taken relative to it, so that
  // a mesh far from the origin keeps its digits in float.
  double lower[3] = { VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, VTK_DOUBLE_MAX };
  double upper[3] = { -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
  for (vtkIdType i = 0; i < numberOfPoints; ++i)
  {
    for (int k = 0; finite[i] && k < 3; ++k)
    {
      lower[k] = std::min(lower[k], this->Coordinates[3 * i + k]);
      upper[k] = std::max(upper[k], this->Coordinates[3 * i + k]);
    }
  }
  for (int k = 0; k < 3; ++k)
  {
    this->Centre[k] = lower[k] <= upper[k] ? lower[k] + 0.5 * (upper[k] - lower[k]) : 0.0;
  }
  if (numberOfPoints > static_cast<vtkIdType>(std::numeric_limits<std::uint32_t>::max()))
  {
    vtkErrorWithObjectMacro(self, "more than 2^32 points: the edge keys cannot hold their ids");
    return;
  }

  // Each point's representative: the first point at the same coordinates. Points sorted by
  // their exact coordinates (then id) put equal ones side by side, the first of them first.
  std::vector<vtkIdType> representative(numberOfPoints);
  for (vtkIdType i = 0; i < numberOfPoints; ++i)
  {
    representative[i] = i;
  }
  if (merge)
  {
    std::vector<CoordinateKey> keys(numberOfPoints);
    std::vector<vtkIdType> order;
    order.reserve(numberOfPoints);
    for (vtkIdType i = 0; i < numberOfPoints; ++i)
    {
      keys[i] = MakeCoordinateKey(&this->Coordinates[3 * i]);
      if (finite[i])
      {
        order.push_back(i);
      }
    }
    vtkSMPTools::Sort(order.begin(), order.end(),
      [&keys](vtkIdType a, vtkIdType b)
      { return keys[a] < keys[b] || (keys[a] == keys[b] && a < b); });
    for (size_t k = 1; k < order.size(); ++k)
    {
      if (keys[order[k]] == keys[order[k - 1]])
      {
        representative[order[k]] = representative[order[k - 1]];
      }
    }
  }

  // The faces' edges, found in pairs by sorting them by their two point ids.
  struct HalfEdge
  {
    std::uint64_t Key; // the smaller point id, then the larger
    std::uint64_t Use; // the order the faces use the edges in (face, then edge), x2 + forward
  };
  std::vector<HalfEdge> halfEdges;
  halfEdges.reserve(static_cast<size_t>(
    this->Polys->GetNumberOfConnectivityIds() + this->Strips->GetNumberOfConnectivityIds()));
  std::vector<vtkIdType> faceOfUse;
  faceOfUse.reserve(halfEdges.capacity());
  // The input's own point ids of each use (smaller, larger): where two faces reach an edge
  // through different points at the same coordinates, their point data (normals) may differ.
  std::vector<std::uint64_t> pointsOfUse;
  pointsOfUse.reserve(halfEdges.capacity());
  const double* coordinates = this->Coordinates.data();

  // The single-precision copy of a face's plane for the side-of-plane test, and the bound of its
  // error (FaceView).
  const double* centre = this->Centre;
  auto makeFaceView = [&](const double unit[3], vtkIdType size, const vtkIdType* ids)
  {
    FaceView view;
    double single[3];
    for (int k = 0; k < 3; ++k)
    {
      view.Normal[k] = static_cast<float>(unit[k]);
      single[k] = view.Normal[k];
    }
    const double* q = coordinates + 3 * ids[0];
    const double fromCentre[3] = { q[0] - centre[0], q[1] - centre[1], q[2] - centre[2] };
    const double offset = Dot(single, fromCentre);
    view.Offset = static_cast<float>(offset);
    double extent = 0.0, offPlane = 0.0;
    for (vtkIdType i = 1; i < size; ++i)
    {
      const double* p = coordinates + 3 * ids[i];
      const double d[3] = { p[0] - q[0], p[1] - q[1], p[2] - q[2] };
      const double distance = std::sqrt(Dot(d, d));
      extent = std::max(extent, distance);
      offPlane = std::max(offPlane, std::abs(Dot(unit, d)) + 1e-15 * distance);
    }
    const double bound = std::abs(offset) + std::sqrt(Dot(fromCentre, fromCentre)) + extent +
      offPlane / FaceSideTolerance;
    view.Bound = static_cast<float>(bound * (1.0 + 1e-6)); // rounded up, or infinite
    return view;
  };

  std::vector<vtkIdType> faceFirstPoints; // for the faces' Z order below

  // Adds one face (point ids in its winding order) to the table.
  auto addFace = [&](vtkIdType size, const vtkIdType* ids)
  {
    if (size < 3)
    {
      ++this->DegenerateFaces;
      return;
    }
    for (vtkIdType i = 0; i < size; ++i)
    {
      if (ids[i] < 0 || ids[i] >= numberOfPoints)
      {
        ++this->DegenerateFaces; // names no point: nothing to orient
        return;
      }
    }
    for (vtkIdType i = 0; i < size; ++i)
    {
      if (!finite[ids[i]])
      {
        ++this->NonFiniteFaces;
        return;
      }
    }
    // Newell's normal as the sum of a fan's cross products from the first point: the same
    // vector, with coordinates relative to the face so that far-away meshes lose no digits.
    double normal[3] = { 0.0, 0.0, 0.0 }, size2 = 0.0;
    const double* origin = coordinates + 3 * ids[0];
    for (vtkIdType i = 1; i + 1 < size; ++i)
    {
      const double* p = coordinates + 3 * ids[i];
      const double* q = coordinates + 3 * ids[i + 1];
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
      ++this->DegenerateFaces;
      return;
    }
    const vtkIdType face = static_cast<vtkIdType>(this->Normals.size() / 3);
    double unit[3];
    for (int k = 0; k < 3; ++k)
    {
      unit[k] = normal[k] / length;
      this->Normals.push_back(unit[k]);
    }
    this->FaceViews.push_back(makeFaceView(unit, size, ids));
    faceFirstPoints.push_back(ids[0]);
    for (vtkIdType i = 0; i < size; ++i)
    {
      vtkIdType a = representative[ids[i]];
      vtkIdType b = representative[ids[(i + 1) % size]];
      const double* pa = coordinates + 3 * a;
      const double* pb = coordinates + 3 * b;
      if (a == b || (pa[0] == pb[0] && pa[1] == pb[1] && pa[2] == pb[2]))
      {
        continue; // no edge: one point twice
      }
      const bool forward = a < b;
      if (!forward)
      {
        std::swap(a, b);
      }
      const std::uint64_t key =
        (static_cast<std::uint64_t>(a) << 32) | static_cast<std::uint64_t>(b);
      halfEdges.push_back({ key, 2 * static_cast<std::uint64_t>(faceOfUse.size()) + forward });
      faceOfUse.push_back(face);
      const vtkIdType ia = ids[i], ib = ids[(i + 1) % size];
      pointsOfUse.push_back((static_cast<std::uint64_t>(std::min(ia, ib)) << 32) |
        static_cast<std::uint64_t>(std::max(ia, ib)));
    }
  };

  auto iterator = vtk::TakeSmartPointer(this->Polys->NewIterator());
  for (iterator->GoToFirstCell(); !iterator->IsDoneWithTraversal(); iterator->GoToNextCell())
  {
    vtkIdType size;
    const vtkIdType* ids;
    iterator->GetCurrentCell(size, ids);
    addFace(size, ids);
  }
  // Strips: triangle k is (k, k+1, k+2), every other one reversed to keep the winding.
  iterator = vtk::TakeSmartPointer(this->Strips->NewIterator());
  for (iterator->GoToFirstCell(); !iterator->IsDoneWithTraversal(); iterator->GoToNextCell())
  {
    vtkIdType size;
    const vtkIdType* ids;
    iterator->GetCurrentCell(size, ids);
    for (vtkIdType k = 0; k + 2 < size; ++k)
    {
      const vtkIdType triangle[3] = { ids[k + (k & 1)], ids[k + 1 - (k & 1)], ids[k + 2] };
      addFace(3, triangle);
    }
  }

  // Each run of equal keys is one edge, its uses in the faces' order; the edges then in the order
  // of their first use.
  vtkSMPTools::Sort(halfEdges.begin(), halfEdges.end(),
    [](const HalfEdge& x, const HalfEdge& y)
    { return x.Key < y.Key || (x.Key == y.Key && x.Use < y.Use); });
  std::vector<std::pair<std::uint64_t, size_t>> firstUses; // first use, first half-edge
  for (size_t first = 0; first < halfEdges.size();)
  {
    size_t last = first + 1;
    while (last < halfEdges.size() && halfEdges[last].Key == halfEdges[first].Key)
    {
      ++last;
    }
    firstUses.emplace_back(halfEdges[first].Use, first);
    first = last;
  }
  vtkSMPTools::Sort(firstUses.begin(), firstUses.end());
  this->Edges.reserve(firstUses.size());
  for (const auto& use : firstUses)
  {
    const HalfEdge* run = &halfEdges[use.second];
    const HalfEdge* end = halfEdges.data() + halfEdges.size();
    const std::uint64_t key = run->Key;
    Edge edge{ static_cast<vtkIdType>(key >> 32), static_cast<vtkIdType>(key & 0xffffffffull),
      { faceOfUse[run->Use / 2], -1 }, 0, (run->Use & 1) != 0, false, false, 0.0 };
    for (const HalfEdge* h = run; h != end && h->Key == key; ++h)
    {
      if (edge.Count == 1)
      {
        edge.Faces[1] = faceOfUse[h->Use / 2];
        edge.SameDirection = ((h->Use & 1) != 0) == edge.FirstForward;
        edge.Split = pointsOfUse[h->Use / 2] != pointsOfUse[run->Use / 2];
      }
      ++edge.Count;
    }
    this->Edges.push_back(edge);
  }

  // Dihedral angles: the second normal flipped where the two faces' windings disagree.
  for (Edge& edge : this->Edges)
  {
    if (edge.Count != 2)
    {
      continue;
    }
    const double* n0 = &this->Normals[3 * edge.Faces[0]];
    double n1[3];
    for (int k = 0; k < 3; ++k)
    {
      n1[k] = edge.SameDirection ? -this->Normals[3 * edge.Faces[1] + k]
                                 : this->Normals[3 * edge.Faces[1] + k];
    }
    double cross[3];
    vtkMath::Cross(n0, n1, cross);
    // atan2 keeps small angles exact where acos of the dot product would lose them.
    edge.Angle = vtkMath::DegreesFromRadians(std::atan2(vtkMath::Norm(cross), Dot(n0, n1)));
  }

  // The faces renumbered in the Z order of their first points, for the viewpoint pass: an
  // edge's two faces are then near each other in its table of sides, whatever the input's order.
  const size_t faceCount = this->FaceViews.size();
  std::vector<std::pair<std::uint64_t, std::uint32_t>> zOrder(faceCount);
  vtkSMPTools::For(0, static_cast<vtkIdType>(faceCount),
    [&](vtkIdType first, vtkIdType last)
    {
      for (vtkIdType f = first; f < last; ++f)
      {
        const double* p = coordinates + 3 * faceFirstPoints[f];
        std::uint64_t code = 0;
        for (int k = 0; k < 3; ++k)
        {
          const double extent = upper[k] - lower[k];
          const double t = extent > 0.0 ? (p[k] - lower[k]) / extent : 0.0;
          const std::uint64_t cell =
            static_cast<std::uint64_t>(std::min(std::max(t, 0.0), 1.0) * 2097151.0);
          for (int bit = 0; bit < 21; ++bit)
          {
            code |= ((cell >> bit) & 1u) << (3 * bit + k);
          }
        }
        zOrder[f] = { code, static_cast<std::uint32_t>(f) };
      }
    });
  vtkSMPTools::Sort(zOrder.begin(), zOrder.end());
  std::vector<std::uint32_t> renumbered(faceCount);
  {
    std::vector<double> normals(3 * faceCount);
    for (auto* array : { &this->FaceNormals[0], &this->FaceNormals[1], &this->FaceNormals[2],
           &this->FaceOffsets, &this->FaceBounds })
    {
      array->resize(faceCount);
    }
    for (size_t f = 0; f < faceCount; ++f)
    {
      const std::uint32_t old = zOrder[f].second;
      renumbered[old] = static_cast<std::uint32_t>(f);
      const FaceView& view = this->FaceViews[old];
      for (int k = 0; k < 3; ++k)
      {
        this->FaceNormals[k][f] = view.Normal[k];
      }
      this->FaceOffsets[f] = view.Offset;
      this->FaceBounds[f] = view.Bound;
      std::copy_n(&this->Normals[3 * old], 3, &normals[3 * f]);
    }
    this->Normals.swap(normals);
    std::vector<FaceView>().swap(this->FaceViews);
  }
  for (Edge& edge : this->Edges)
  {
    for (int i = 0; i < std::min(edge.Count, 2); ++i)
    {
      edge.Faces[i] = renumbered[edge.Faces[i]];
    }
  }

  // The packed copy the viewpoint pass reads, its edges in the order of their first faces' new
  // numbers (ViewEdges: each one's index in Edges), so that it reads the sides in order too.
  const size_t edgeCount = this->Edges.size();
  std::vector<std::uint64_t> byFirstFace(edgeCount);
  for (size_t e = 0; e < edgeCount; ++e)
  {
    byFirstFace[e] = (static_cast<std::uint64_t>(this->Edges[e].Faces[0]) << 32) | e;
  }
  vtkSMPTools::Sort(byFirstFace.begin(), byFirstFace.end());
  this->ViewEdges.resize(edgeCount);
  this->ViewFaces.resize(2 * edgeCount);
  this->ViewPoints.resize(2 * edgeCount);
  this->ViewKinds.resize(edgeCount);
  this->Creases.clear();
  this->CreaseAngle = -1.0;
  for (size_t e = 0; e < edgeCount; ++e)
  {
    this->ViewEdges[e] = static_cast<std::uint32_t>(byFirstFace[e] & 0xffffffffu);
    const Edge& edge = this->Edges[this->ViewEdges[e]];
    this->ViewFaces[2 * e] = static_cast<std::uint32_t>(edge.Faces[0]);
    this->ViewFaces[2 * e + 1] = static_cast<std::uint32_t>(edge.Count >= 2 ? edge.Faces[1] : 0);
    this->ViewPoints[2 * e] = static_cast<std::uint32_t>(edge.A);
    this->ViewPoints[2 * e + 1] = static_cast<std::uint32_t>(edge.B);
    this->ViewKinds[e] = static_cast<unsigned char>(edge.Count == 1
        ? ViewBoundary
        : (edge.Count > 2 ? ViewNonManifold
                          : ViewTwoFaces | (edge.SameDirection ? ViewSameDirection : 0) |
                (edge.Split ? ViewSplit : 0)));
  }

  if (this->NonFiniteFaces > 0)
  {
    vtkWarningWithObjectMacro(
      self, << this->NonFiniteFaces << " faces with NaN or infinite coordinates skipped");
  }
}

vtkStandardNewMacro(vtkNPRFeatureLines);

vtkNPRFeatureLines::vtkNPRFeatureLines()
  : Internal(new Adjacency)
{
}

vtkNPRFeatureLines::~vtkNPRFeatureLines() = default;

vtkIdType vtkNPRFeatureLines::GetNumberOfEdges() const
{
  return static_cast<vtkIdType>(this->Internal->Edges.size());
}

vtkIdType vtkNPRFeatureLines::GetNumberOfDegenerateFaces() const
{
  return this->Internal->DegenerateFaces;
}

vtkIdType vtkNPRFeatureLines::GetNumberOfNonFiniteFaces() const
{
  return this->Internal->NonFiniteFaces;
}

vtkIdType vtkNPRFeatureLines::GetNumberOfUnsureFaces() const
{
  return this->Internal->UnsureFaces;
}

vtkIdType vtkNPRFeatureLines::GetNumberOfSkippedContourTriangles() const
{
  return this->Internal->SkippedContourTriangles;
}

void vtkNPRFeatureLines::SetCamera(vtkCamera* camera, vtkMatrix4x4* modelMatrix)
{
  if (!camera)
  {
    vtkErrorMacro("SetCamera: no camera");
    return;
  }
  double eye[4] = { 0.0, 0.0, 0.0, 1.0 };
  double direction[4] = { 0.0, 0.0, 0.0, 0.0 };
  camera->GetPosition(eye);
  camera->GetDirectionOfProjection(direction);
  if (modelMatrix)
  {
    const double determinant = modelMatrix->Determinant();
    if (determinant == 0.0 || !std::isfinite(determinant))
    {
      vtkErrorMacro("SetCamera: the model matrix is singular");
      return;
    }
    vtkNew<vtkMatrix4x4> inverse;
    vtkMatrix4x4::Invert(modelMatrix, inverse);
    inverse->MultiplyPoint(eye, eye);
    inverse->MultiplyPoint(direction, direction); // w = 0: a direction, no translation
    for (int i = 0; i < 3; ++i)
    {
      eye[i] /= eye[3];
    }
  }
  this->SetEyePosition(eye);
  this->SetDirectionOfProjection(direction);
  this->SetParallelProjection(camera->GetParallelProjection() != 0);
}

int vtkNPRFeatureLines::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  if (!input || !output)
  {
    return 0;
  }
  Adjacency& adjacency = *this->Internal;
  if (!adjacency.IsCurrent(input, this->MergeCoincidentPoints))
  {
    adjacency.Build(input, this->MergeCoincidentPoints, this);
    ++this->NumberOfAdjacencyBuilds;
  }

  // For this viewpoint, in parallel on packed arrays: the side of each face's plane the eye is
  // on, then each edge's type, in blocks that list their typed edges in order; then the output
  // from those lists (few edges: the output is small).
  const double* coordinates = adjacency.Coordinates.data();
  const double* normals = adjacency.Normals.data();
  const std::vector<Adjacency::Edge>& edges = adjacency.Edges;
  const vtkIdType edgeCount = static_cast<vtkIdType>(edges.size());
  if (this->Creases && adjacency.CreaseAngle != this->FeatureAngle)
  {
    adjacency.Creases.resize(edges.size());
    const double angle = this->FeatureAngle;
    vtkSMPTools::For(0, edgeCount,
      [&](vtkIdType first, vtkIdType last)
      {
        for (vtkIdType e = first; e < last; ++e)
        {
          const Adjacency::Edge& edge = edges[adjacency.ViewEdges[e]];
          adjacency.Creases[e] = edge.Count == 2 && edge.Angle > angle ? CREASE : 0;
        }
      });
    adjacency.CreaseAngle = this->FeatureAngle;
  }
  const bool parallel = this->ParallelProjection;
  const double eye[3] = { this->EyePosition[0], this->EyePosition[1], this->EyePosition[2] };
  const double direction[3] = { this->DirectionOfProjection[0], this->DirectionOfProjection[1],
    this->DirectionOfProjection[2] };
  // Smooth contours replace the mesh silhouettes only where the input has point normals.
  vtkDataArray* contourNormals =
    this->Silhouettes && this->SmoothContours ? Adjacency::ContourNormals(input) : nullptr;
  const bool smooth = contourNormals && adjacency.Edges.size() > 0;
  const bool silhouettes = this->Silhouettes && !smooth;
  adjacency.SkippedContourTriangles = 0;
  if (smooth)
  {
    adjacency.ComputeContours(input, contourNormals, parallel, parallel ? direction : eye);
  }
  // Where the normals are split (an edge whose two faces reach it through different points),
  // the facing function jumps: the smooth contour runs along the edge if it is a silhouette.
  if (silhouettes || smooth)
  {
    adjacency.ComputeFaceSides(parallel, parallel ? direction : eye);
  }
  else
  {
    adjacency.UnsureFaces = 0;
  }

  // The edges in blocks of equal size, each listing its typed edges.
  const vtkIdType blockSize = 16384;
  const vtkIdType blockCount = (edgeCount + blockSize - 1) / blockSize;
  auto& typedEdges = adjacency.TypedEdges;
  typedEdges.resize(static_cast<size_t>(blockCount));
  const std::uint32_t* viewEdges = adjacency.ViewEdges.data();
  const std::uint32_t* faces = adjacency.ViewFaces.data();
  const std::uint32_t* points = adjacency.ViewPoints.data();
  const unsigned char* kinds = adjacency.ViewKinds.data();
  const unsigned char* creases = this->Creases ? adjacency.Creases.data() : nullptr;
  const unsigned char* sides = adjacency.FaceSides.data();
  const unsigned char boundary = this->Boundaries ? BOUNDARY : 0;
  const unsigned char nonManifold = this->NonManifoldEdges ? NON_MANIFOLD : 0;
  // An edge of two faces is a silhouette where the eye is on the front side of exactly one of
  // their planes (edge-on counting as the back), the second reversed where both faces traverse
  // the edge the same way: from the faces' sides where both are decided, else by the reference
  // test in double precision, at the edge's first point so that both terms are exact sides.
  auto isSilhouette = [=](vtkIdType e, bool sameDirection)
  {
    const unsigned side0 = sides[faces[2 * e]];
    const unsigned side1 = sides[faces[2 * e + 1]];
    if (!((side0 | side1) & SideUnsure))
    {
      return ((side0 & SideFacing) != 0) != (((side1 & SideFacing) != 0) != sameDirection);
    }
    const double* n0 = normals + 3 * static_cast<size_t>(faces[2 * e]);
    const double* n1 = normals + 3 * static_cast<size_t>(faces[2 * e + 1]);
    double f0, f1;
    if (parallel)
    {
      f0 = Dot(n0, direction);
      f1 = Dot(n1, direction);
    }
    else
    {
      const double* p = coordinates + 3 * static_cast<size_t>(points[2 * e]);
      const double toPoint[3] = { p[0] - eye[0], p[1] - eye[1], p[2] - eye[2] };
      f0 = Dot(n0, toPoint);
      f1 = Dot(n1, toPoint);
    }
    if (sameDirection)
    {
      f1 = -f1;
    }
    return (f0 < 0.0) != (f1 < 0.0);
  };
  vtkSMPTools::For(0, blockCount,
    [&](vtkIdType firstBlock, vtkIdType lastBlock)
    {
      for (vtkIdType block = firstBlock; block < lastBlock; ++block)
      {
        auto& listed = typedEdges[block];
        listed.clear();
        const vtkIdType last = std::min(edgeCount, (block + 1) * blockSize);
        for (vtkIdType e = block * blockSize; e < last; ++e)
        {
          const unsigned char kind = kinds[e];
          unsigned char type = 0;
          if (kind & ViewBoundary)
          {
            type = boundary;
          }
          else if (kind & ViewNonManifold)
          {
            type = nonManifold;
          }
          else
          {
            type = creases ? creases[e] : 0;
            if ((silhouettes || (smooth && (kind & ViewSplit))) &&
              isSilhouette(e, (kind & ViewSameDirection) != 0))
            {
              type |= SILHOUETTE;
            }
          }
          if (type)
          {
            listed.push_back({ viewEdges[e], points[2 * e], points[2 * e + 1], type });
          }
        }
      }
    });

  vtkNew<vtkPoints> outputPoints;
  outputPoints->SetDataTypeToDouble();
  vtkNew<vtkCellArray> lines;
  vtkNew<vtkUnsignedCharArray> types;
  types->SetName("FeatureType");
  vtkNew<vtkIdTypeArray> inputIds;
  inputIds->SetName("InputPointIds");
  inputIds->SetNumberOfComponents(2);
  // Each input point's output id (-1: none yet), kept between updates and reset where used.
  std::vector<vtkIdType>& outputId = adjacency.OutputIds;
  outputId.resize(adjacency.Coordinates.size() / 3, -1);
  std::vector<vtkIdType> used;
  auto outputPoint = [&](vtkIdType id)
  {
    if (outputId[id] < 0)
    {
      outputId[id] = outputPoints->InsertNextPoint(coordinates + 3 * id);
      used.push_back(id);
    }
    return outputId[id];
  };
  // The typed edges in the order of Edges (the order the faces first use them).
  std::vector<Adjacency::TypedEdge> typed;
  for (const auto& listed : typedEdges)
  {
    typed.insert(typed.end(), listed.begin(), listed.end());
  }
  std::sort(typed.begin(), typed.end());
  const vtkIdType typedCount = static_cast<vtkIdType>(typed.size());
  lines->AllocateExact(typedCount, 2 * typedCount);
  types->SetNumberOfValues(typedCount);
  inputIds->SetNumberOfTuples(typedCount);
  for (vtkIdType i = 0; i < typedCount; ++i)
  {
    const Adjacency::TypedEdge& edge = typed[i];
    const vtkIdType ends[2] = { outputPoint(edge.A), outputPoint(edge.B) };
    lines->InsertNextCell(2, ends);
    types->SetValue(i, edge.Type);
    inputIds->SetValue(2 * i, edge.A);
    inputIds->SetValue(2 * i + 1, edge.B);
  }
  for (vtkIdType id : used)
  {
    outputId[id] = -1;
  }

  // The smooth contours after the mesh edges: one output point per crossed edge, so that the
  // segments chain; each edge's zero point interpolated from its smaller id to its larger.
  vtkNew<vtkIdTypeArray> contourTriangles;
  if (smooth)
  {
    const double* facing = adjacency.Facing.data();
    const std::uint32_t* triangles = adjacency.Triangles.data();
    std::unordered_map<std::uint64_t, vtkIdType> edgePoints;
    auto zeroPoint = [&](std::uint32_t a, std::uint32_t b)
    {
      if (b < a)
      {
        std::swap(a, b);
      }
      const std::uint64_t key = (static_cast<std::uint64_t>(a) << 32) | b;
      auto found = edgePoints.find(key);
      if (found != edgePoints.end())
      {
        return found->second;
      }
      const double t = facing[a] / (facing[a] - facing[b]); // the signs differ: in [0, 1]
      const double* pa = coordinates + 3 * static_cast<size_t>(a);
      const double* pb = coordinates + 3 * static_cast<size_t>(b);
      const double x[3] = { pa[0] + t * (pb[0] - pa[0]), pa[1] + t * (pb[1] - pa[1]),
        pa[2] + t * (pb[2] - pa[2]) };
      const vtkIdType id = outputPoints->InsertNextPoint(x);
      edgePoints.emplace(key, id);
      return id;
    };
    contourTriangles->SetName("ContourTriangle");
    contourTriangles->SetNumberOfComponents(3);
    contourTriangles->SetNumberOfTuples(typedCount);
    contourTriangles->Fill(-1);
    const unsigned char type = SILHOUETTE | SMOOTH_CONTOUR;
    for (const auto& listed : adjacency.ContourSegments)
    {
      for (const Adjacency::ContourSegment& segment : listed)
      {
        const std::uint32_t* ids = triangles + 3 * static_cast<size_t>(segment.Triangle);
        const std::uint32_t rise[2] = { ids[segment.Rise], ids[(segment.Rise + 1) % 3] };
        const std::uint32_t fall[2] = { ids[segment.Fall], ids[(segment.Fall + 1) % 3] };
        const vtkIdType ends[2] = { zeroPoint(rise[0], rise[1]), zeroPoint(fall[0], fall[1]) };
        lines->InsertNextCell(2, ends);
        types->InsertNextValue(type);
        const vtkIdType edge[2] = { std::min(rise[0], rise[1]), std::max(rise[0], rise[1]) };
        inputIds->InsertNextTypedTuple(edge);
        const vtkIdType corners[3] = { ids[0], ids[1], ids[2] };
        contourTriangles->InsertNextTypedTuple(corners);
      }
    }
  }
  output->SetPoints(outputPoints);
  output->SetLines(lines);
  output->GetCellData()->AddArray(types);
  output->GetCellData()->AddArray(inputIds);
  if (smooth)
  {
    output->GetCellData()->AddArray(contourTriangles);
  }
  return 1;
}

void vtkNPRFeatureLines::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "EyePosition: " << this->EyePosition[0] << ", " << this->EyePosition[1] << ", "
     << this->EyePosition[2] << "\n";
  os << indent << "ParallelProjection: " << this->ParallelProjection << "\n";
  os << indent << "DirectionOfProjection: " << this->DirectionOfProjection[0] << ", "
     << this->DirectionOfProjection[1] << ", " << this->DirectionOfProjection[2] << "\n";
  os << indent << "Silhouettes: " << this->Silhouettes << "\n";
  os << indent << "Creases: " << this->Creases << "\n";
  os << indent << "Boundaries: " << this->Boundaries << "\n";
  os << indent << "NonManifoldEdges: " << this->NonManifoldEdges << "\n";
  os << indent << "FeatureAngle: " << this->FeatureAngle << "\n";
  os << indent << "MergeCoincidentPoints: " << this->MergeCoincidentPoints << "\n";
  os << indent << "SmoothContours: " << this->SmoothContours << "\n";
  os << indent << "NumberOfAdjacencyBuilds: " << this->NumberOfAdjacencyBuilds << "\n";
  os << indent << "NumberOfEdges: " << this->GetNumberOfEdges() << "\n";
  os << indent << "NumberOfSkippedContourTriangles: " << this->GetNumberOfSkippedContourTriangles()
     << "\n";
}
