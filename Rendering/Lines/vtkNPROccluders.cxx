// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNPROccluders.h"

#include "vtkMath.h"
#include "vtkNPRSpatialOrder.h"
#include "vtkNPRTriangleTests.h"
#include "vtkNPRVectors.h"
#include "vtkPolyData.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace
{
constexpr std::uint64_t NoKey = std::numeric_limits<std::uint64_t>::max();
// Triangles per leaf of the hierarchy, at most (halving leaves 6 to 12: 7 bytes a triangle of
// nodes; at most 8 took 11 and cast rays no faster, at most 16 slower).
constexpr std::uint32_t LeafSize = 8;
// The nodes' boxes are widened by this much of the scene's size (1 in the frame): the box test
// can only let through more segments than touch the triangles, never fewer.
constexpr double BoxMargin = 1e-6;

// World point x in the frame centred at `center` and scaled by `scale` (the scene's extent 1).
glm::dvec3 ToFrame(const double x[3], const double center[3], double scale)
{
  return (vtkNPRVector(x) - vtkNPRVector(center)) * scale;
}

// How many of `count` triangles (ranges start at a group's start) go to a node's first child:
// whole groups while there are several, so that a group is a subtree; within one, half.
std::uint32_t FirstPart(std::uint32_t count, std::uint32_t group)
{
  const std::uint32_t groups = (count + group - 1) / group;
  return groups > 1 ? (groups / 2) * group : count / 2;
}

// The nodes of the hierarchy over `count` triangles.
std::uint32_t CountNodes(std::uint32_t count, std::uint32_t group)
{
  if (count <= LeafSize)
  {
    return 1;
  }
  const std::uint32_t first = FirstPart(count, group);
  return 1 + CountNodes(first, group) + CountNodes(count - first, group);
}

// A float bound of a double: below it (lower) or above it (upper).
float FloatBelow(double value)
{
  const auto rounded = static_cast<float>(value);
  return static_cast<double>(rounded) > value
    ? std::nextafter(rounded, -std::numeric_limits<float>::infinity())
    : rounded;
}
float FloatAbove(double value)
{
  const auto rounded = static_cast<float>(value);
  return static_cast<double>(rounded) < value
    ? std::nextafter(rounded, std::numeric_limits<float>::infinity())
    : rounded;
}

// Depth first through the hierarchy: the nodes `enter` accepts, and `visit` for each triangle
// position of a leaf entered. Stops, returning true, as soon as `visit` returns true.
template <typename NodeT, typename Enter, typename Visit>
bool Traverse(const std::vector<NodeT>& nodes, Enter&& enter, Visit&& visit)
{
  std::uint32_t stack[64];
  int depth = 0;
  if (!nodes.empty())
  {
    stack[depth++] = 0;
  }
  while (depth > 0)
  {
    const std::uint32_t n = stack[--depth];
    const NodeT& node = nodes[n];
    if (!enter(node))
    {
      continue;
    }
    if (node.Count == 0)
    {
      stack[depth++] = node.Index;
      stack[depth++] = n + 1;
      continue;
    }
    for (std::uint32_t i = 0; i < node.Count; ++i)
    {
      if (visit(node.Index + i))
      {
        return true;
      }
    }
  }
  return false;
}
}

void vtkNPROccluders::Build(const std::vector<vtkNPRMeshInstance>& actors, int trianglesPerGroup)
{
  this->SetMeshes(actors);
  std::vector<double> points = this->WorldPoints();
  const size_t count = this->SortTriangles(points);
  this->GatherPoints(points);
  // Split first at the groups, so that their number changes the tree, never a result.
  const auto group = static_cast<std::uint32_t>(std::max(1, trianglesPerGroup));
  std::vector<Node>().swap(this->Nodes);
  if (count > 0)
  {
    this->Nodes.reserve(CountNodes(static_cast<std::uint32_t>(count), group));
    this->AddNodes(0, static_cast<std::uint32_t>(count), group);
  }
  this->BoundNodes();
  this->Crossings.clear();
  this->CrossingsValid = false;
}

void vtkNPROccluders::SetMeshes(const std::vector<vtkNPRMeshInstance>& actors)
{
  this->Meshes.clear();
  this->MeshFirstTriangles.clear();
  vtkIdType triangles = 0, points = 0;
  for (const vtkNPRMeshInstance& state : actors)
  {
    if (!state.Mesh->GetPoints())
    {
      continue;
    }
    Mesh mesh;
    mesh.Faces.Set(state.Mesh);
    mesh.Matrix = state.Matrix;
    mesh.FirstTriangle = triangles;
    mesh.FirstPoint = points;
    triangles += mesh.Faces.GetNumberOfTriangles();
    points += mesh.Faces.GetNumberOfPoints();
    this->MeshFirstTriangles.push_back(mesh.FirstTriangle);
    this->Meshes.push_back(std::move(mesh));
  }
}

void vtkNPROccluders::FramePoint(const Mesh& mesh, vtkIdType id, double x[3]) const
{
  double local[3];
  mesh.Faces.GetPoint(id, local);
  vtkNPRTransformPoint(mesh.Matrix.data(), local, x);
  vtkNPRStore(ToFrame(x, this->FrameCenter, this->FrameScale), x);
}

bool vtkNPROccluders::SceneTriangle(vtkIdType triangle, vtkIdType ids[3]) const
{
  const size_t m =
    std::upper_bound(this->MeshFirstTriangles.begin(), this->MeshFirstTriangles.end(), triangle) -
    this->MeshFirstTriangles.begin() - 1;
  const Mesh& mesh = this->Meshes[m];
  mesh.Faces.GetTriangle(triangle - mesh.FirstTriangle, ids);
  bool named = true;
  for (int k = 0; k < 3; ++k)
  {
    named = named && ids[k] >= 0 && ids[k] < mesh.Faces.GetNumberOfPoints();
    ids[k] += mesh.FirstPoint;
  }
  return named;
}

std::vector<double> vtkNPROccluders::WorldPoints() const
{
  const vtkIdType count = this->Meshes.empty()
    ? 0
    : this->Meshes.back().FirstPoint + this->Meshes.back().Faces.GetNumberOfPoints();
  std::vector<double> points(3 * static_cast<size_t>(count));
  for (const Mesh& mesh : this->Meshes)
  {
    vtkSMPTools::For(0, mesh.Faces.GetNumberOfPoints(),
      [&](vtkIdType first, vtkIdType last)
      {
        for (vtkIdType i = first; i < last; ++i)
        {
          double local[3];
          mesh.Faces.GetPoint(i, local);
          vtkNPRTransformPoint(mesh.Matrix.data(), local, &points[3 * (mesh.FirstPoint + i)]);
        }
      });
  }
  return points;
}

size_t vtkNPROccluders::SortTriangles(std::vector<double>& points)
{
  // Triangles with a corner that names no point or is not finite in world coordinates are left
  // out (keyed NoKey); the others set the frame, centred on the scene and scaled to its size,
  // where the tests keep their digits far from the origin and at any scale.
  const vtkIdType count = this->MeshFirstTriangles.empty()
    ? 0
    : this->Meshes.back().FirstTriangle + this->Meshes.back().Faces.GetNumberOfTriangles();
  std::vector<std::uint64_t> keys(count);
  this->FindFrame(points, keys);
  // Then the kept triangles in Morton order of their centroids, then their numbers.
  vtkSMPTools::For(0, count,
    [&](vtkIdType first, vtkIdType last)
    {
      for (vtkIdType t = first; t < last; ++t)
      {
        vtkIdType ids[3];
        if (keys[t] == NoKey || !this->SceneTriangle(t, ids))
        {
          continue;
        }
        double centroid[3];
        const glm::dvec3 sum = vtkNPRVector(&points[3 * ids[0]]) +
          vtkNPRVector(&points[3 * ids[1]]) + vtkNPRVector(&points[3 * ids[2]]);
        vtkNPRStore(sum / 3.0, centroid);
        keys[t] = (this->MortonCode(centroid) << 32) | static_cast<std::uint64_t>(t);
      }
    });
  vtkNPRRadixSort(keys, 30);
  // Their scene numbers, in that order, where their corners will be.
  const size_t kept = std::lower_bound(keys.begin(), keys.end(), NoKey) - keys.begin();
  std::vector<std::uint32_t>(3 * kept).swap(this->Triangles);
  for (size_t i = 0; i < kept; ++i)
  {
    this->Triangles[3 * i] = static_cast<std::uint32_t>(keys[i]);
  }
  return kept;
}

void vtkNPROccluders::FindFrame(std::vector<double>& points, std::vector<std::uint64_t>& keys)
{
  using Bounds = std::array<double, 6>;
  vtkSMPThreadLocal<Bounds> bounds(Bounds{ VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, VTK_DOUBLE_MAX,
    -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX });
  vtkSMPTools::For(0, static_cast<vtkIdType>(keys.size()),
    [&](vtkIdType first, vtkIdType last)
    {
      Bounds& local = bounds.Local();
      for (vtkIdType t = first; t < last; ++t)
      {
        vtkIdType ids[3];
        bool kept = this->SceneTriangle(t, ids);
        for (int c = 0; kept && c < 3; ++c)
        {
          const double* x = &points[3 * ids[c]];
          kept = std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]);
        }
        keys[t] = kept ? 0 : NoKey;
        for (int c = 0; kept && c < 3; ++c)
        {
          for (int k = 0; k < 3; ++k)
          {
            local[k] = std::min(local[k], points[3 * ids[c] + k]);
            local[3 + k] = std::max(local[3 + k], points[3 * ids[c] + k]);
          }
        }
      }
    });
  Bounds scene{ VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX,
    -VTK_DOUBLE_MAX };
  for (const Bounds& local : bounds)
  {
    for (int k = 0; k < 3; ++k)
    {
      scene[k] = std::min(scene[k], local[k]);
      scene[3 + k] = std::max(scene[3 + k], local[3 + k]);
    }
  }
  this->FrameScale = 1.0;
  std::fill_n(this->FrameCenter, 3, 0.0);
  if (scene[0] <= scene[3])
  {
    for (int k = 0; k < 3; ++k)
    {
      this->FrameCenter[k] = 0.5 * (scene[k] + scene[3 + k]);
    }
    const double extent =
      std::max({ scene[3] - scene[0], scene[4] - scene[1], scene[5] - scene[2] });
    this->FrameScale = extent > 0.0 ? 1.0 / extent : 1.0;
  }
  for (int k = 0; k < 3; ++k)
  {
    this->FrameLow[k] = (scene[k] - this->FrameCenter[k]) * this->FrameScale;
    this->FrameHigh[k] = (scene[3 + k] - this->FrameCenter[k]) * this->FrameScale;
  }
  vtkSMPTools::For(0, static_cast<vtkIdType>(points.size() / 3),
    [&](vtkIdType first, vtkIdType last)
    {
      for (size_t i = 3 * first; i < 3 * static_cast<size_t>(last); ++i)
      {
        points[i] = (points[i] - this->FrameCenter[i % 3]) * this->FrameScale;
      }
    });
}

std::uint64_t vtkNPROccluders::MortonCode(const double x[3]) const
{
  return vtkNPRMortonCode(x, this->FrameLow, this->FrameHigh, 10);
}

void vtkNPROccluders::GatherPoints(std::vector<double>& points)
{
  // The finite points in Morton order, so that a leaf's corners lie together in memory: each
  // one's place in that order.
  const auto count = static_cast<vtkIdType>(points.size() / 3);
  std::vector<std::uint64_t> order(count);
  vtkSMPTools::For(0, count,
    [&](vtkIdType first, vtkIdType last)
    {
      for (vtkIdType i = first; i < last; ++i)
      {
        const double* x = &points[3 * i];
        const bool finite = std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]);
        order[i] = finite ? (this->MortonCode(x) << 32) | static_cast<std::uint64_t>(i) : NoKey;
      }
    });
  vtkNPRRadixSort(order, 30);
  const auto kept =
    static_cast<vtkIdType>(std::lower_bound(order.begin(), order.end(), NoKey) - order.begin());
  std::vector<std::uint32_t> place(count);
  vtkSMPTools::For(0, kept,
    [&](vtkIdType first, vtkIdType last)
    {
      for (vtkIdType p = first; p < last; ++p)
      {
        place[order[p] & 0xffffffffu] = static_cast<std::uint32_t>(p);
      }
    });
  std::vector<std::uint64_t>().swap(order);
  std::vector<double>(3 * static_cast<size_t>(kept)).swap(this->Points);
  vtkSMPTools::For(0, count,
    [&](vtkIdType first, vtkIdType last)
    {
      for (vtkIdType i = first; i < last; ++i)
      {
        if (std::isfinite(points[3 * i]) && std::isfinite(points[3 * i + 1]) &&
          std::isfinite(points[3 * i + 2]))
        {
          std::copy_n(&points[3 * i], 3, &this->Points[3 * static_cast<size_t>(place[i])]);
        }
      }
    });
  std::vector<double>().swap(points);
  // Each triangle's corners as places.
  vtkSMPTools::For(0, static_cast<vtkIdType>(this->Triangles.size() / 3),
    [&](vtkIdType first, vtkIdType last)
    {
      for (vtkIdType i = first; i < last; ++i)
      {
        vtkIdType ids[3];
        this->SceneTriangle(this->Triangles[3 * i], ids);
        for (int k = 0; k < 3; ++k)
        {
          this->Triangles[3 * i + k] = place[ids[k]];
        }
      }
    });
}

std::uint32_t vtkNPROccluders::AddNodes(
  std::uint32_t first, std::uint32_t last, std::uint32_t group)
{
  const auto index = static_cast<std::uint32_t>(this->Nodes.size());
  this->Nodes.push_back(Node{ { 0.0f, 0.0f, 0.0f }, { 0.0f, 0.0f, 0.0f }, first, last - first });
  const std::uint32_t count = last - first;
  if (count <= LeafSize)
  {
    return index;
  }
  const std::uint32_t middle = first + FirstPart(count, group);
  this->AddNodes(first, middle, group);
  const std::uint32_t second = this->AddNodes(middle, last, group);
  this->Nodes[index].Index = second;
  this->Nodes[index].Count = 0;
  return index;
}

void vtkNPROccluders::BoundNodes()
{
  // The leaves' boxes from their triangles, rounded outwards and widened by BoxMargin; then each
  // inner node's from its children's (which follow it).
  vtkSMPTools::For(0, static_cast<vtkIdType>(this->Nodes.size()),
    [&](vtkIdType first, vtkIdType last)
    {
      for (vtkIdType n = first; n < last; ++n)
      {
        Node& node = this->Nodes[n];
        double low[3] = { VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, VTK_DOUBLE_MAX };
        double high[3] = { -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
        for (std::uint32_t i = 0; i < node.Count; ++i)
        {
          const double* corners[3];
          this->Corners(node.Index + i, corners);
          for (const double* corner : corners)
          {
            for (int k = 0; k < 3; ++k)
            {
              low[k] = std::min(low[k], corner[k]);
              high[k] = std::max(high[k], corner[k]);
            }
          }
        }
        for (int k = 0; node.Count > 0 && k < 3; ++k)
        {
          node.Low[k] = FloatBelow(low[k] - BoxMargin);
          node.High[k] = FloatAbove(high[k] + BoxMargin);
        }
      }
    });
  for (size_t n = this->Nodes.size(); n-- > 0;)
  {
    Node& node = this->Nodes[n];
    if (node.Count == 0)
    {
      const Node& a = this->Nodes[n + 1];
      const Node& b = this->Nodes[node.Index];
      for (int k = 0; k < 3; ++k)
      {
        node.Low[k] = std::min(a.Low[k], b.Low[k]);
        node.High[k] = std::max(a.High[k], b.High[k]);
      }
    }
  }
}

size_t vtkNPROccluders::GetMemorySize() const
{
  size_t bytes = sizeof(Node) * this->Nodes.capacity() +
    sizeof(std::uint32_t) * this->Triangles.capacity() + sizeof(double) * this->Points.capacity() +
    sizeof(Crossing) * this->Crossings.capacity();
  for (const Mesh& mesh : this->Meshes)
  {
    bytes += mesh.Faces.GetMemorySize();
  }
  return bytes;
}

bool vtkNPROccluders::SegmentHitsNode(
  const Node& node, const double from[3], const double to[3]) const
{
  // Slab test of the segment against the node's box.
  double t0 = 0.0, t1 = 1.0;
  for (int k = 0; k < 3 && t0 <= t1; ++k)
  {
    const double d = to[k] - from[k];
    const double low = node.Low[k], high = node.High[k];
    if (d == 0.0)
    {
      if (from[k] < low || from[k] > high)
      {
        return false;
      }
      continue;
    }
    double a = (low - from[k]) / d, b = (high - from[k]) / d;
    if (a > b)
    {
      std::swap(a, b);
    }
    t0 = std::max(t0, a);
    t1 = std::min(t1, b);
  }
  return t0 <= t1;
}

bool vtkNPROccluders::Hidden(const double fromWorld[3], const double toWorld[3],
  const vtkIdType* ignored, int ignoredCount) const
{
  // The ignored points as the triangles' corners are computed: the same doubles, so compared
  // exactly (which also ignores the faces of points merely coincident with them, split by
  // vtkPolyDataNormals).
  double ignoredPoints[3][3];
  int ignoring = 0;
  for (int i = 0; i < ignoredCount && ignoring < 3; ++i)
  {
    for (const Mesh& mesh : this->Meshes)
    {
      const vtkIdType id = ignored[i] - mesh.FirstPoint;
      if (ignored[i] >= 0 && id >= 0 && id < mesh.Faces.GetNumberOfPoints())
      {
        this->FramePoint(mesh, id, ignoredPoints[ignoring++]);
        break;
      }
    }
  }
  const glm::dvec3 from = ToFrame(fromWorld, this->FrameCenter, this->FrameScale);
  const glm::dvec3 to = ToFrame(toWorld, this->FrameCenter, this->FrameScale);
  // Also the triangles with a corner within the ignored triangle's longest edge of the ray's
  // end: a grazing ray enters the surface that far from a contour (it lies about a sagitta
  // inside the smooth surface), often beyond the triangles next to its own.
  double reach = 0.0;
  for (int i = 0; i < ignoring; ++i)
  {
    reach = std::max(reach,
      glm::distance(
        vtkNPRVector(ignoredPoints[i]), vtkNPRVector(ignoredPoints[(i + 1) % ignoring])));
  }
  auto isIgnored = [&](const double* corner)
  {
    for (int i = 0; i < ignoring; ++i)
    {
      if (vtkNPRSamePoint(corner, ignoredPoints[i]))
      {
        return true;
      }
    }
    return glm::distance(vtkNPRVector(corner), to) < reach;
  };
  const glm::dvec3 direction = to - from;
  return Traverse(
    this->Nodes,
    [&](const Node& node)
    { return this->SegmentHitsNode(node, glm::value_ptr(from), glm::value_ptr(to)); },
    [&](std::uint32_t position)
    {
      const double* c[3];
      this->Corners(position, c);
      return vtkNPRSegmentMeetsTriangle(from, direction, c[0], c[1], c[2]) &&
        !(ignoring && (isIgnored(c[0]) || isIgnored(c[1]) || isIgnored(c[2])));
    });
}

const std::vector<vtkNPROccluders::Crossing>& vtkNPROccluders::GetCrossings()
{
  if (this->CrossingsValid)
  {
    return this->Crossings;
  }
  this->CrossingsValid = true;
  this->Crossings.clear();
  // Each pair once: the other triangle later in the hierarchy's order. In blocks that list
  // their crossings in that order.
  const auto count = static_cast<vtkIdType>(this->Triangles.size() / 3);
  const vtkIdType blockSize = 4096;
  std::vector<std::vector<Crossing>> blocks(
    static_cast<size_t>((count + blockSize - 1) / blockSize));
  vtkSMPTools::For(0, static_cast<vtkIdType>(blocks.size()),
    [&](vtkIdType firstBlock, vtkIdType lastBlock)
    {
      for (vtkIdType block = firstBlock; block < lastBlock; ++block)
      {
        const vtkIdType last = std::min(count, (block + 1) * blockSize);
        for (vtkIdType p = block * blockSize; p < last; ++p)
        {
          this->CrossingsOf(static_cast<std::uint32_t>(p), blocks[block]);
        }
      }
    });
  for (const auto& block : blocks)
  {
    this->Crossings.insert(this->Crossings.end(), block.begin(), block.end());
  }
  return this->Crossings;
}

void vtkNPROccluders::CrossingsOf(std::uint32_t position, std::vector<Crossing>& found) const
{
  const double* a[3];
  this->Corners(position, a);
  double box[6];
  for (int k = 0; k < 3; ++k)
  {
    box[2 * k] = std::min({ a[0][k], a[1][k], a[2][k] }) - 1e-12;
    box[2 * k + 1] = std::max({ a[0][k], a[1][k], a[2][k] }) + 1e-12;
  }
  auto overlaps = [&](const Node& node)
  {
    bool overlap = true;
    for (int k = 0; k < 3; ++k)
    {
      overlap = overlap && box[2 * k] <= node.High[k] && box[2 * k + 1] >= node.Low[k];
    }
    return overlap;
  };
  // A's plane, for a cheap first test: most triangles whose boxes overlap A's lie on one side
  // of it. The same arithmetic and tolerance as vtkNPRCrossTriangles' first test, which would
  // reject them too.
  const glm::dvec3 origin = vtkNPRVector(a[0]);
  glm::dvec3 normal = glm::cross(vtkNPRVector(a[1]) - origin, vtkNPRVector(a[2]) - origin);
  const double length = glm::length(normal);
  normal = length > 0.0 ? normal / length : glm::dvec3(0.0);
  auto oneSide = [&](const double* const b[3])
  {
    double d[3];
    for (int k = 0; k < 3; ++k)
    {
      d[k] = glm::dot(normal, vtkNPRVector(b[k]) - origin);
    }
    const bool above = d[0] > 1e-12 || d[1] > 1e-12 || d[2] > 1e-12;
    const bool below = d[0] < -1e-12 || d[1] < -1e-12 || d[2] < -1e-12;
    return !above || !below;
  };
  Traverse(this->Nodes, overlaps,
    [&](std::uint32_t other)
    {
      if (other <= position)
      {
        return false;
      }
      const double* b[3];
      this->Corners(other, b);
      if (length > 0.0 && oneSide(b))
      {
        return false;
      }
      // Neighbours (a corner at the same coordinates) meet along their shared edge or point.
      bool neighbours = false;
      for (int u = 0; u < 3 && !neighbours; ++u)
      {
        for (int v = 0; v < 3 && !neighbours; ++v)
        {
          neighbours = vtkNPRSamePoint(a[u], b[v]);
        }
      }
      Crossing crossing;
      double p[3], q[3];
      if (!neighbours && vtkNPRCrossTriangles(a, b, p, q, crossing.Angle))
      {
        const glm::dvec3 center = vtkNPRVector(this->FrameCenter);
        vtkNPRStore(vtkNPRVector(p) / this->FrameScale + center, crossing.A);
        vtkNPRStore(vtkNPRVector(q) / this->FrameScale + center, crossing.B);
        found.push_back(crossing);
      }
      return false; // on through every overlapping leaf
    });
}
