// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// What the sources of the TestFeatureLinesTable program share: the plain edge table built from
// the documented rules (TestFeatureLinesTablePlain.cxx), which TestFeatureLinesTable.cxx holds
// vtkNPRFeatureLines's table against.
#ifndef TestFeatureLinesTable_h
#define TestFeatureLinesTable_h

#include "nprFeatureLineTesting.h"

#include <array>
#include <map>
#include <utility>
#include <vector>

class vtkPolyData;

namespace nprFeatureLinesTable
{
using nprFeatureLineTesting::Point;

struct Line
{
  vtkIdType A, B; // input ids (representatives when merging), A < B
  int Type;
};

struct Viewpoint
{
  bool Parallel;
  double View[3]; // the eye, or the direction of projection
  double Angle;   // the crease angle
  bool Merge;
  bool Smooth; // smooth contours (where the mesh has point normals)
};

// A map from each edge's two points to the faces that use it, all in double.
class PlainTable
{
public:
  PlainTable(vtkPolyData* mesh, bool merge);

  // The angles between the faces' normals at the two-face edges, degrees.
  std::vector<double> Angles() const;

  // The lines for a viewpoint, in the order the faces first use their edges.
  std::vector<Line> Lines(const Viewpoint& viewpoint) const;

private:
  struct Use
  {
    size_t Face;
    bool Forward;
    std::pair<vtkIdType, vtkIdType> InputIds;
  };
  struct Edge
  {
    vtkIdType A, B;
    std::vector<Use> Uses;
  };

  void ReadPoints(vtkPolyData* mesh, bool merge);
  bool Normal(const std::vector<vtkIdType>& ids, std::array<double, 3>& unit) const;
  void AddFace(const std::vector<vtkIdType>& ids);
  double Angle(const Edge& edge) const;
  int Type(const Edge& edge, const Viewpoint& viewpoint) const;

  std::vector<Point> Points;
  std::vector<vtkIdType> Representatives;
  std::vector<std::array<double, 3>> Normals;
  std::vector<Edge> Edges;
  std::map<std::pair<vtkIdType, vtkIdType>, size_t> Index;
};
}

#endif
