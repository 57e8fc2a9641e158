// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// Convex polygons in the order a painter paints them: back to front as a camera sees them, split
// where needed, so that a polygon painted later is never behind one painted earlier where the
// two overlap in the image. A binary space partition of the polygons' own planes (an
// autopartition, splitters chosen at random among a few candidates by the splits they cause, a
// fixed seed so the output is the same every time): exact for any arrangement, surfaces that
// pass through each other and cyclic overlaps included, which sorting by depth is not. The
// partition does not depend on the camera; BackToFront() walks it for one. Private to NPR::Lines.
#ifndef vtkNPRFaceOrder_h
#define vtkNPRFaceOrder_h

#include "vtkType.h" // for vtkIdType

#include <cstdint> // for the indices
#include <vector>  // for the polygons

#include <glm/vec3.hpp> // for glm::dvec3

class vtkNPRFaceOrder
{
public:
  // Adds a planar convex polygon of `count` corners (world coordinates, x y z each) with a tag of
  // the caller's (its source face). A polygon whose corners are not finite or span no area is
  // left out; Add returns whether it was kept.
  bool Add(const double* corners, int count, vtkIdType tag);
  vtkIdType GetNumberOfInputs() const { return static_cast<vtkIdType>(this->InputPolygons.size()); }

  // Builds the partition of everything added (again after more Add()s).
  void Build();

  // The polygons (pieces of the inputs) in painting order for an eye at `eye`, or with
  // `parallel`, for a view along `direction`: each later one is in front of, or apart from,
  // every earlier one it overlaps.
  std::vector<std::uint32_t> BackToFront(
    const double eye[3], const double direction[3], bool parallel) const;

  // Polygon `polygon`: its corners in world coordinates, and its input's tag.
  int GetNumberOfCorners(std::uint32_t polygon) const { return this->Polygons[polygon].Count; }
  void GetCorner(std::uint32_t polygon, int k, double x[3]) const;
  vtkIdType GetTag(std::uint32_t polygon) const { return this->Polygons[polygon].Tag; }
  // Pieces made by splitting (the polygons less the inputs kept).
  vtkIdType GetNumberOfSplits() const { return this->Splits; }

private:
  // In the frame (world - centre) x scale, the inputs' box within [-1, 1].
  struct Plane
  {
    glm::dvec3 Normal; // unit
    double Offset;     // Normal . x for x on the plane
  };
  struct Polygon
  {
    std::uint32_t First; // corners at Corners[First, First + Count)
    std::uint32_t Count;
    std::uint32_t Plane; // its input's plane, in Planes
    vtkIdType Tag;
  };
  struct Node
  {
    std::uint32_t Plane;
    std::uint32_t First, Count; // its polygons (on its plane) in NodePolygons
    std::int64_t Front = -1, Back = -1;
  };
  struct Task
  {
    std::int64_t Parent; // -1: the root
    bool FrontSide;
    std::vector<std::uint32_t> Polygons;
  };

  void SetFrame();
  void AddPlane(const Polygon& polygon);
  std::uint32_t ChooseSplitter(const std::vector<std::uint32_t>& polygons, std::uint64_t& seed);
  int Side(std::uint32_t polygon, const Plane& plane) const; // 1 front, -1 back, 0 on, 2 both
  void Split(std::uint32_t polygon, const Plane& plane, std::uint32_t& front, std::uint32_t& back);
  void Partition(Task& task, std::vector<Task>& tasks);

  std::vector<double> InputCorners; // world coordinates, as added
  std::vector<Polygon> InputPolygons;
  std::vector<glm::dvec3> Corners; // in the frame
  std::vector<Plane> Planes;
  std::vector<Polygon> Polygons;
  std::vector<Node> Nodes;
  std::vector<std::uint32_t> NodePolygons;
  glm::dvec3 Center{ 0.0 };
  double Scale = 1.0;
  vtkIdType Splits = 0;
};

#endif
// VTK-HeaderTest-Exclude: vtkNPRFaceOrder.h
