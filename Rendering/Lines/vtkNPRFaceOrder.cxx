// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNPRFaceOrder.h"

#include "vtkNPRVectors.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>

#include <glm/common.hpp> // for glm::min, glm::max

namespace
{
// Distances within this of a plane (the frame's units: the scene spans [-1, 1]) are on it: float
// coordinates round the corners of coplanar faces (a sphere's quads) off their common plane by
// about 1e-8, which must not split them into slivers; 1e-7 of the scene is far below a pixel.
constexpr double OnPlane = 1e-7;
// Splitter candidates a node tries, and the polygons each is tried against.
constexpr int Candidates = 8;
constexpr int Samples = 32;

// xorshift64*: a fixed sequence, so that the partition, and the file written, never change.
std::uint64_t NextRandom(std::uint64_t& state)
{
  state ^= state >> 12;
  state ^= state << 25;
  state ^= state >> 27;
  return state * 0x2545F4914F6CDD1DULL;
}

int Classify(double distance)
{
  return distance > OnPlane ? 1 : (distance < -OnPlane ? -1 : 0);
}
}

bool vtkNPRFaceOrder::Add(const double* corners, int count, vtkIdType tag)
{
  if (count < 3 ||
    !std::all_of(corners, corners + 3 * count, [](double v) { return std::isfinite(v); }))
  {
    return false;
  }
  // Newell's normal: the polygon's area vector, zero for a degenerate one.
  glm::dvec3 area(0.0);
  for (int k = 0; k < count; ++k)
  {
    area +=
      glm::cross(vtkNPRVector(corners + 3 * k), vtkNPRVector(corners + 3 * ((k + 1) % count)));
  }
  if (!(glm::length(area) > 0.0))
  {
    return false;
  }
  Polygon polygon;
  polygon.First = static_cast<std::uint32_t>(this->InputCorners.size() / 3);
  polygon.Count = static_cast<std::uint32_t>(count);
  polygon.Plane = 0;
  polygon.Tag = tag;
  this->InputCorners.insert(this->InputCorners.end(), corners, corners + 3 * count);
  this->InputPolygons.push_back(polygon);
  return true;
}

void vtkNPRFaceOrder::SetFrame()
{
  glm::dvec3 low(std::numeric_limits<double>::max()), high(-std::numeric_limits<double>::max());
  for (size_t i = 0; i < this->InputCorners.size(); i += 3)
  {
    const glm::dvec3 x = vtkNPRVector(this->InputCorners.data() + i);
    low = glm::min(low, x);
    high = glm::max(high, x);
  }
  this->Center = 0.5 * (low + high);
  const double extent = std::max({ high.x - low.x, high.y - low.y, high.z - low.z });
  this->Scale = extent > 0.0 ? 2.0 / extent : 1.0;
  this->Corners.resize(this->InputCorners.size() / 3);
  for (size_t k = 0; k < this->Corners.size(); ++k)
  {
    this->Corners[k] =
      (vtkNPRVector(this->InputCorners.data() + 3 * k) - this->Center) * this->Scale;
  }
}

void vtkNPRFaceOrder::AddPlane(const Polygon& polygon)
{
  // The plane through the polygon's centroid along its area vector, both in the frame.
  glm::dvec3 area(0.0), centroid(0.0);
  for (std::uint32_t k = 0; k < polygon.Count; ++k)
  {
    const glm::dvec3& a = this->Corners[polygon.First + k];
    const glm::dvec3& b = this->Corners[polygon.First + (k + 1) % polygon.Count];
    area += glm::cross(a, b);
    centroid += a;
  }
  centroid /= static_cast<double>(polygon.Count);
  const double length = glm::length(area);
  Plane plane;
  plane.Normal = length > 0.0 ? area / length : glm::dvec3(0.0, 0.0, 1.0);
  plane.Offset = glm::dot(plane.Normal, centroid);
  this->Planes.push_back(plane);
}

void vtkNPRFaceOrder::Build()
{
  this->Nodes.clear();
  this->NodePolygons.clear();
  this->Planes.clear();
  this->Splits = 0;
  this->SetFrame();
  this->Polygons = this->InputPolygons;
  for (std::uint32_t p = 0; p < this->Polygons.size(); ++p)
  {
    this->Polygons[p].Plane = p;
    this->AddPlane(this->Polygons[p]);
  }
  if (this->Polygons.empty())
  {
    return;
  }
  // Depth first, with a stack of its own: no recursion however deep the tree.
  std::vector<Task> tasks(1);
  tasks[0].Parent = -1;
  tasks[0].FrontSide = true;
  tasks[0].Polygons.resize(this->Polygons.size());
  for (std::uint32_t p = 0; p < this->Polygons.size(); ++p)
  {
    tasks[0].Polygons[p] = p;
  }
  while (!tasks.empty())
  {
    Task task = std::move(tasks.back());
    tasks.pop_back();
    this->Partition(task, tasks);
  }
}

int vtkNPRFaceOrder::Side(std::uint32_t polygon, const Plane& plane) const
{
  const Polygon& p = this->Polygons[polygon];
  bool front = false, back = false;
  for (std::uint32_t k = 0; k < p.Count; ++k)
  {
    const int side = Classify(glm::dot(plane.Normal, this->Corners[p.First + k]) - plane.Offset);
    front = front || side > 0;
    back = back || side < 0;
  }
  return front && back ? 2 : (front ? 1 : (back ? -1 : 0));
}

void vtkNPRFaceOrder::Split(
  std::uint32_t polygon, const Plane& plane, std::uint32_t& front, std::uint32_t& back)
{
  const Polygon p = this->Polygons[polygon];
  std::vector<glm::dvec3> sides[2]; // front, back
  for (std::uint32_t k = 0; k < p.Count; ++k)
  {
    const glm::dvec3 a = this->Corners[p.First + k];
    const glm::dvec3 b = this->Corners[p.First + (k + 1) % p.Count];
    const double da = glm::dot(plane.Normal, a) - plane.Offset;
    const double db = glm::dot(plane.Normal, b) - plane.Offset;
    const int sa = Classify(da), sb = Classify(db);
    if (sa >= 0)
    {
      sides[0].push_back(a);
    }
    if (sa <= 0)
    {
      sides[1].push_back(a);
    }
    if (sa * sb < 0) // the edge crosses the plane
    {
      const glm::dvec3 x = vtkNPRPointAlong(a, b, da / (da - db));
      sides[0].push_back(x);
      sides[1].push_back(x);
    }
  }
  std::uint32_t made[2];
  for (int s = 0; s < 2; ++s)
  {
    Polygon piece = p;
    piece.First = static_cast<std::uint32_t>(this->Corners.size());
    piece.Count = static_cast<std::uint32_t>(sides[s].size());
    this->Corners.insert(this->Corners.end(), sides[s].begin(), sides[s].end());
    made[s] = static_cast<std::uint32_t>(this->Polygons.size());
    this->Polygons.push_back(piece);
  }
  front = made[0];
  back = made[1];
  ++this->Splits;
}

std::uint32_t vtkNPRFaceOrder::ChooseSplitter(
  const std::vector<std::uint32_t>& polygons, std::uint64_t& seed)
{
  const size_t n = polygons.size();
  if (n <= 2)
  {
    return polygons[0];
  }
  std::uint32_t best = polygons[0];
  int fewest = std::numeric_limits<int>::max();
  for (int c = 0; c < Candidates; ++c)
  {
    const std::uint32_t candidate = polygons[NextRandom(seed) % n];
    const Plane& plane = this->Planes[this->Polygons[candidate].Plane];
    int splits = 0;
    for (int s = 0; s < Samples && splits < fewest; ++s)
    {
      splits += this->Side(polygons[NextRandom(seed) % n], plane) == 2;
    }
    if (splits < fewest)
    {
      fewest = splits;
      best = candidate;
    }
  }
  return best;
}

void vtkNPRFaceOrder::Partition(Task& task, std::vector<Task>& tasks)
{
  std::uint64_t seed = 0x9E3779B97F4A7C15ULL ^ (this->Nodes.size() + 1);
  const std::uint32_t splitter = this->ChooseSplitter(task.Polygons, seed);
  Node node;
  node.Plane = this->Polygons[splitter].Plane;
  node.First = static_cast<std::uint32_t>(this->NodePolygons.size());
  const Plane plane = this->Planes[node.Plane];
  Task front{ 0, true, {} }, back{ 0, false, {} };
  for (std::uint32_t p : task.Polygons)
  {
    const int side = this->Polygons[p].Plane == node.Plane ? 0 : this->Side(p, plane);
    if (side == 0)
    {
      this->NodePolygons.push_back(p);
    }
    else if (side == 1)
    {
      front.Polygons.push_back(p);
    }
    else if (side == -1)
    {
      back.Polygons.push_back(p);
    }
    else
    {
      std::uint32_t inFront, behind;
      this->Split(p, plane, inFront, behind);
      front.Polygons.push_back(inFront);
      back.Polygons.push_back(behind);
    }
  }
  node.Count = static_cast<std::uint32_t>(this->NodePolygons.size()) - node.First;
  const std::int64_t index = static_cast<std::int64_t>(this->Nodes.size());
  this->Nodes.push_back(node);
  if (task.Parent >= 0)
  {
    (task.FrontSide ? this->Nodes[task.Parent].Front : this->Nodes[task.Parent].Back) = index;
  }
  task.Polygons = std::vector<std::uint32_t>(); // its memory freed before the children's
  for (Task* child : { &back, &front })
  {
    if (!child->Polygons.empty())
    {
      child->Parent = index;
      tasks.push_back(std::move(*child));
    }
  }
}

std::vector<std::uint32_t> vtkNPRFaceOrder::BackToFront(
  const double eye[3], const double direction[3], bool parallel) const
{
  std::vector<std::uint32_t> order;
  if (this->Nodes.empty())
  {
    return order;
  }
  const glm::dvec3 viewer = (vtkNPRVector(eye) - this->Center) * this->Scale;
  const glm::dvec3 towardsViewer = -vtkNPRVector(direction);
  // Entries: 2 n visits node n's subtree, 2 n + 1 paints node n's own polygons.
  std::vector<std::int64_t> stack{ 0 };
  while (!stack.empty())
  {
    const std::int64_t entry = stack.back();
    stack.pop_back();
    const Node& node = this->Nodes[entry / 2];
    if (entry % 2 == 1)
    {
      order.insert(order.end(), this->NodePolygons.begin() + node.First,
        this->NodePolygons.begin() + node.First + node.Count);
      continue;
    }
    const Plane& plane = this->Planes[node.Plane];
    const bool viewerInFront = parallel ? glm::dot(plane.Normal, towardsViewer) > 0.0
                                        : glm::dot(plane.Normal, viewer) - plane.Offset > 0.0;
    const std::int64_t nearSide = viewerInFront ? node.Front : node.Back;
    const std::int64_t farSide = viewerInFront ? node.Back : node.Front;
    // Popped in the reverse order: the far side, the node's polygons, the near side.
    if (nearSide >= 0)
    {
      stack.push_back(2 * nearSide);
    }
    stack.push_back(entry + 1);
    if (farSide >= 0)
    {
      stack.push_back(2 * farSide);
    }
  }
  return order;
}

void vtkNPRFaceOrder::GetCorner(std::uint32_t polygon, int k, double x[3]) const
{
  vtkNPRStore(this->Corners[this->Polygons[polygon].First + k] / this->Scale + this->Center, x);
}
