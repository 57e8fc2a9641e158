// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// Object-space feature lines (vtkNPRFeatureLines) checked against what can be stated
// analytically: a box's creases; its silhouettes from chosen viewpoints, also through an actor
// matrix; the boundaries of an open box and a non-manifold fin; the edge adjacency built once per
// mesh; the bunny's silhouettes from many viewpoints, edge-on ones among them, against the
// double-precision test written out here, also far from the origin and at a tiny scale; smooth
// contours (SmoothContours) of a sphere and a torus against their analytic contours, without
// normals, and with zero or NaN normals; the line settings the filter, the reference mask and the
// drawing lines share (vtkNPRLineSettings).
//
// usage: TestFeatureLines CASE [DATA_DIR]   (CASE: see the table at the end of this file)
#include "nprFeatureLineTesting.h"

#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCubeSource.h"
#include "vtkDoubleArray.h"
#include "vtkIdTypeArray.h"
#include "vtkMath.h"
#include "vtkNPRDrawingLines.h"
#include "vtkNPRLineSettings.h"
#include "vtkNPRModelReader.h"
#include "vtkNPRReferenceMask.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSphereSource.h"
#include "vtkTransform.h"
#include "vtkTransformPolyDataFilter.h"
#include "vtkTriangleFilter.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace
{
using namespace nprFeatureLineTesting;

// ---- Creases of a box: exactly its 12 edges, with and without triangulation ----
int CubeCreases()
{
  const std::set<Edge> twelve = AllBoxEdges();
  for (bool triangulate : { false, true })
  {
    vtkSmartPointer<vtkPolyData> cube = CubeSource();
    if (triangulate)
    {
      cube = Triangulated(cube);
    }
    const std::string name = triangulate ? "triangulated cube" : "cube";
    auto filter = MakeFilter(vtkNPRFeatureLines::CREASE);
    filter->SetInputData(cube);
    filter->Update();
    const auto lines = Lines(filter);
    CheckEdges(EdgesOf(lines, AllTypes), twelve, name + " creases");
    for (const auto& line : lines)
    {
      NPR_CHECK(line.second == vtkNPRFeatureLines::CREASE, name << ": type " << line.second);
    }
    vtkPolyData* output = filter->GetOutput();
    NPR_CHECK(output->GetPoints()->GetDataType() == VTK_DOUBLE, "output points are not double");
    NPR_CHECK(output->GetNumberOfPoints() == 8,
      name << ": " << output->GetNumberOfPoints() << " output points, only the 8 used expected");
    auto* ids = vtkIdTypeArray::SafeDownCast(output->GetCellData()->GetArray("InputPointIds"));
    NPR_CHECK(ids && ids->GetNumberOfComponents() == 2 && ids->GetNumberOfTuples() == 12,
      "InputPointIds missing");
    for (vtkIdType i = 0; ids && i < 12; ++i)
    {
      double in[3], out[3];
      cube->GetPoint(ids->GetTypedComponent(i, 0), in);
      vtkIdType size;
      const vtkIdType* pts;
      output->GetLines()->GetCellAtId(i, size, pts);
      output->GetPoint(pts[0], out);
      NPR_CHECK(in[0] == out[0] && in[1] == out[1] && in[2] == out[2],
        "InputPointIds does not name the line's first point");
    }
    // A right angle is a crease below 90 degrees only; flat diagonals never are.
    filter->SetFeatureAngle(89.9);
    filter->Update();
    NPR_CHECK(filter->GetOutput()->GetNumberOfCells() == 12, name << ": creases at 89.9 degrees");
    filter->SetFeatureAngle(90.1);
    filter->Update();
    NPR_CHECK(filter->GetOutput()->GetNumberOfCells() == 0, name << ": creases at 90.1 degrees");
    filter->SetFeatureAngle(0.0);
    filter->Update();
    NPR_CHECK(filter->GetOutput()->GetNumberOfCells() == 12, name << ": diagonals are flat");

    // Without merging, vtkCubeSource's faces share no point: 24 boundary edges, no crease.
    auto separate = MakeFilter(AllTypes);
    separate->MergeCoincidentPointsOff();
    separate->SetInputData(cube);
    separate->Update();
    const long long boundaries = CountCells(separate, vtkNPRFeatureLines::BOUNDARY);
    NPR_CHECK(separate->GetOutput()->GetNumberOfCells() == 24 && boundaries == 24,
      name << " unmerged: " << separate->GetOutput()->GetNumberOfCells() << " lines, " << boundaries
           << " boundaries; 24 expected (each face's own)");
  }
  return nprTestResult();
}

// ---- Silhouettes of a box from viewpoints where they can be stated ----
struct View
{
  const char* Name;
  bool Parallel;
  double Vector[3]; // eye, or direction of projection
  size_t Count;     // silhouette edges expected
};
const View Views[] = {
  { "corner, perspective", false, { 2.2, 1.7, 2.9 }, 6 },
  { "corner, parallel", true, { -1.0, -0.8, -1.3 }, 6 },
  { "along -z, parallel", true, { 0.0, 0.0, -1.0 }, 4 },
  { "along -z, perspective", false, { 0.0, 0.0, 5.0 }, 4 },
  { "off axis, perspective", false, { 0.2, -0.3, 5.0 }, 4 },
  { "two faces, perspective", false, { 0.7, 0.0, 5.0 }, 6 },
  { "inside", false, { 0.1, 0.2, 0.3 }, 0 },
};

void SetView(vtkNPRFeatureLines* filter, const View& view)
{
  filter->SetParallelProjection(view.Parallel);
  const double* v = view.Vector;
  if (view.Parallel)
  {
    filter->SetDirectionOfProjection(v[0], v[1], v[2]);
  }
  else
  {
    filter->SetEyePosition(v[0], v[1], v[2]);
  }
}
int CubeSilhouettes()
{
  for (bool triangulate : { false, true })
  {
    vtkSmartPointer<vtkPolyData> cube = CubeSource();
    if (triangulate)
    {
      cube = Triangulated(cube);
    }
    auto filter = MakeFilter(vtkNPRFeatureLines::SILHOUETTE);
    filter->SetInputData(cube);
    for (const View& view : Views)
    {
      SetView(filter, view);
      filter->Update();
      const std::set<Edge> expected = BoxSilhouettes(view.Parallel, view.Vector);
      NPR_CHECK(expected.size() == view.Count,
        view.Name << ": the analytic outline has " << expected.size() << " edges");
      const auto lines = Lines(filter);
      CheckEdges(EdgesOf(lines, AllTypes), expected,
        std::string(view.Name) + (triangulate ? " (triangles)" : ""));
    }
  }

  // Both types: the union, with both bits on the outline.
  auto both = MakeFilter(vtkNPRFeatureLines::SILHOUETTE | vtkNPRFeatureLines::CREASE);
  both->SetInputData(CubeSource());
  SetView(both, Views[0]);
  both->Update();
  const auto lines = Lines(both);
  CheckEdges(EdgesOf(lines, AllTypes), AllBoxEdges(), "silhouettes and creases");
  CheckEdges(EdgesOf(lines, vtkNPRFeatureLines::SILHOUETTE), BoxSilhouettes(false, Views[0].Vector),
    "silhouette bits of the union");
  CheckEdges(EdgesOf(lines, vtkNPRFeatureLines::CREASE), AllBoxEdges(), "crease bits of the union");

  // SetCamera with an actor matrix (rotation, non-uniform scale, translation): the silhouettes
  // are those of the transformed mesh seen from the camera directly.
  vtkNew<vtkTransform> transform;
  transform->Translate(3.0, -1.0, 2.0);
  transform->RotateWXYZ(35.0, 1.0, 2.0, 0.5);
  transform->Scale(2.0, 0.5, 1.3);
  vtkNew<vtkTransformPolyDataFilter> moved;
  moved->SetInputData(Triangulated(CubeSource()));
  moved->SetTransform(transform);
  moved->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  moved->Update();
  for (bool parallel : { false, true })
  {
    vtkNew<vtkCamera> camera;
    camera->SetPosition(7.0, 4.0, 9.0);
    camera->SetFocalPoint(3.0, -1.0, 2.0);
    camera->SetParallelProjection(parallel);
    auto model = MakeFilter(vtkNPRFeatureLines::SILHOUETTE);
    model->SetInputData(Triangulated(CubeSource()));
    model->SetCamera(camera, transform->GetMatrix());
    model->Update();
    auto world = MakeFilter(vtkNPRFeatureLines::SILHOUETTE);
    world->SetInputData(moved->GetOutput());
    world->SetCamera(camera);
    world->Update();
    auto ids = [](vtkNPRFeatureLines* filter)
    {
      std::set<std::pair<vtkIdType, vtkIdType>> pairs;
      auto* array =
        vtkIdTypeArray::SafeDownCast(filter->GetOutput()->GetCellData()->GetArray("InputPointIds"));
      for (vtkIdType i = 0; array && i < array->GetNumberOfTuples(); ++i)
      {
        pairs.insert({ array->GetTypedComponent(i, 0), array->GetTypedComponent(i, 1) });
      }
      return pairs;
    };
    const auto inModel = ids(model), inWorld = ids(world);
    std::cout << (parallel ? "parallel" : "perspective")
              << " camera through a matrix: " << inModel.size()
              << " silhouette edges in model coordinates, " << inWorld.size()
              << " in world coordinates\n";
    NPR_CHECK(inModel.size() == 6 && inModel == inWorld,
      "SetCamera with a matrix finds other silhouettes than the transformed mesh");
  }
  return nprTestResult();
}

// ---- Boundaries of an open box; a non-manifold fin ----
int BoundaryAndNonManifold()
{
  const int top = 2 * 2 + 1; // face +z
  auto filter = MakeFilter(vtkNPRFeatureLines::BOUNDARY);
  filter->SetInputData(MakeBox(top));
  filter->Update();
  std::set<Edge> rim;
  for (const BoxEdge& edge : BoxEdges())
  {
    if (edge.Ends.first[2] > 0 && edge.Ends.second[2] > 0)
    {
      rim.insert(edge.Ends);
    }
  }
  CheckEdges(EdgesOf(Lines(filter), AllTypes), rim, "open box boundary");

  auto all = MakeFilter(AllTypes);
  all->SetInputData(MakeBox(top));
  all->SetEyePosition(2.2, 1.7, 2.9);
  all->Update();
  const auto lines = Lines(all);
  CheckEdges(EdgesOf(lines, vtkNPRFeatureLines::BOUNDARY), rim, "open box boundary, all types");
  NPR_CHECK(EdgesOf(lines, vtkNPRFeatureLines::CREASE).size() == 8,
    "open box: the 8 edges between its walls are creases");

  // Three triangles on one edge: one non-manifold edge, six boundary edges.
  vtkNew<vtkPolyData> fin;
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0, 0, 0);
  points->InsertNextPoint(1, 0, 0);
  points->InsertNextPoint(0.5, 1, 0);
  points->InsertNextPoint(0.5, -1, 0.3);
  points->InsertNextPoint(0.5, 0, 1);
  vtkNew<vtkCellArray> triangles;
  const vtkIdType t0[3] = { 0, 1, 2 }, t1[3] = { 1, 0, 3 }, t2[3] = { 0, 1, 4 };
  triangles->InsertNextCell(3, t0);
  triangles->InsertNextCell(3, t1);
  triangles->InsertNextCell(3, t2);
  fin->SetPoints(points);
  fin->SetPolys(triangles);
  auto nonManifold = MakeFilter(vtkNPRFeatureLines::NON_MANIFOLD);
  nonManifold->SetInputData(fin);
  nonManifold->Update();
  const Edge spine = MakeEdge({ 0, 0, 0 }, { 1, 0, 0 });
  CheckEdges(EdgesOf(Lines(nonManifold), AllTypes), { spine }, "non-manifold fin");
  auto finAll = MakeFilter(AllTypes);
  finAll->SetInputData(fin);
  finAll->SetEyePosition(0.3, 3, 2);
  finAll->Update();
  const auto finLines = Lines(finAll);
  NPR_CHECK(finLines.size() == 7 && finLines.count(spine) &&
      finLines.at(spine) == vtkNPRFeatureLines::NON_MANIFOLD &&
      EdgesOf(finLines, vtkNPRFeatureLines::BOUNDARY).size() == 6,
    "fin: the spine only non-manifold, six boundary edges (" << finLines.size() << " lines)");
  return nprTestResult();
}

// ---- The adjacency is built once per mesh ----
int Reuse()
{
  vtkNew<vtkCubeSource> source;
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(source->GetOutputPort());
  auto filter = MakeFilter(AllTypes);
  filter->SetInputConnection(triangles->GetOutputPort());
  filter->SetEyePosition(2.2, 1.7, 2.9);
  filter->Update();
  NPR_CHECK(filter->GetNumberOfAdjacencyBuilds() == 1, "first update");
  NPR_CHECK(filter->GetNumberOfEdges() == 18,
    "a triangulated cube has 18 edges, got " << filter->GetNumberOfEdges());
  const auto before = Lines(filter);

  filter->SetEyePosition(-2.0, 3.0, -1.5);
  filter->Update();
  const auto after = Lines(filter);
  NPR_CHECK(filter->GetNumberOfAdjacencyBuilds() == 1, "a new eye rebuilt the adjacency");
  const double eye[3] = { -2.0, 3.0, -1.5 };
  CheckEdges(EdgesOf(after, vtkNPRFeatureLines::SILHOUETTE), BoxSilhouettes(false, eye),
    "silhouettes after the eye moved");
  NPR_CHECK(EdgesOf(before, vtkNPRFeatureLines::SILHOUETTE) !=
      EdgesOf(after, vtkNPRFeatureLines::SILHOUETTE),
    "the silhouettes did not change with the eye");
  filter->SetFeatureAngle(60.0);
  filter->ParallelProjectionOn();
  filter->CreasesOff();
  filter->Update();
  NPR_CHECK(filter->GetNumberOfAdjacencyBuilds() == 1, "settings rebuilt the adjacency");

  // The same points changed in place: rebuilt.
  vtkPolyData* mesh = triangles->GetOutput();
  double p[3];
  mesh->GetPoints()->GetPoint(0, p);
  p[0] -= 0.25;
  mesh->GetPoints()->SetPoint(0, p);
  mesh->GetPoints()->Modified();
  filter->Modified();
  filter->Update();
  NPR_CHECK(filter->GetNumberOfAdjacencyBuilds() == 2,
    "modified points did not rebuild: " << filter->GetNumberOfAdjacencyBuilds());
  // A new mesh upstream: rebuilt.
  source->SetXLength(2.0);
  filter->Update();
  NPR_CHECK(filter->GetNumberOfAdjacencyBuilds() == 3, "a new upstream mesh did not rebuild");
  filter->MergeCoincidentPointsOff();
  filter->Update();
  NPR_CHECK(filter->GetNumberOfAdjacencyBuilds() == 4, "merging switched did not rebuild");
  filter->SetEyePosition(1, 1, 1);
  filter->Update();
  NPR_CHECK(filter->GetNumberOfAdjacencyBuilds() == 4, "rebuilt with nothing changed");
  return nprTestResult();
}

// ---- The single-precision side test decides as the double-precision one, edge for edge ----
// The reference, written out for a triangle mesh without merging: each face's unit normal (the
// cross product from its first point, as Newell's sum from zero), faces with no orientation left
// out as the filter does; an edge of two faces is a silhouette where n.(A - eye), A its smaller
// point id (or n.direction), is negative for exactly one face, the second negated where both
// faces traverse the edge the same way.
struct ReferenceMesh
{
  std::vector<Point> Points;
  std::vector<std::array<double, 3>> Normals;
  struct Use
  {
    size_t Face;
    bool Forward;
  };
  std::map<std::pair<vtkIdType, vtkIdType>, std::vector<Use>> Edges;

  explicit ReferenceMesh(vtkPolyData* mesh)
  {
    for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
    {
      Point p;
      mesh->GetPoint(i, p.data());
      this->Points.push_back(p);
    }
    vtkIdType size;
    const vtkIdType* ids;
    vtkCellArray* polys = mesh->GetPolys();
    for (polys->InitTraversal(); polys->GetNextCell(size, ids);)
    {
      NPR_CHECK(size == 3, "the reference takes triangles only");
      const Point& o = this->Points[ids[0]];
      const Point& p = this->Points[ids[1]];
      const Point& q = this->Points[ids[2]];
      const double a[3] = { p[0] - o[0], p[1] - o[1], p[2] - o[2] };
      const double b[3] = { q[0] - o[0], q[1] - o[1], q[2] - o[2] };
      double n[3] = { 0.0, 0.0, 0.0 };
      n[0] += a[1] * b[2] - a[2] * b[1];
      n[1] += a[2] * b[0] - a[0] * b[2];
      n[2] += a[0] * b[1] - a[1] * b[0];
      const double size2 = std::max(Dot3(a, a), Dot3(b, b));
      const double length = std::sqrt(Dot3(n, n));
      if (!(length > 1e-12 * size2) || !std::isfinite(length))
      {
        continue;
      }
      this->Normals.push_back({ n[0] / length, n[1] / length, n[2] / length });
      for (int i = 0; i < 3; ++i)
      {
        const vtkIdType u = ids[i], v = ids[(i + 1) % 3];
        if (this->Points[u] == this->Points[v])
        {
          continue;
        }
        this->Edges[{ std::min(u, v), std::max(u, v) }].push_back(
          { this->Normals.size() - 1, u < v });
      }
    }
  }

  static double Dot3(const double a[3], const double b[3])
  {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  }

  std::set<Edge> Silhouettes(bool parallel, const double view[3]) const
  {
    std::set<Edge> silhouettes;
    for (const auto& edge : this->Edges)
    {
      if (edge.second.size() != 2)
      {
        continue;
      }
      const Point& a = this->Points[edge.first.first];
      const double toPoint[3] = { a[0] - view[0], a[1] - view[1], a[2] - view[2] };
      double terms[2];
      for (int k = 0; k < 2; ++k)
      {
        const double* n = this->Normals[edge.second[k].Face].data();
        terms[k] = Dot3(n, parallel ? view : toPoint);
      }
      if (edge.second[0].Forward == edge.second[1].Forward)
      {
        terms[1] = -terms[1];
      }
      if ((terms[0] < 0.0) != (terms[1] < 0.0))
      {
        silhouettes.insert(MakeEdge(a, this->Points[edge.first.second]));
      }
    }
    return silhouettes;
  }
};

// The bunny moved by `offset` and scaled by `scale` about its centre, in double precision.
vtkSmartPointer<vtkPolyData> MovedBunny(double scale, const double offset[3])
{
  vtkSmartPointer<vtkNPRModelReader> reader = nprReadTestModel("bunny.ply");
  vtkNew<vtkTransform> transform;
  transform->Translate(offset);
  transform->Scale(scale, scale, scale);
  vtkNew<vtkTransformPolyDataFilter> moved;
  moved->SetInputConnection(reader->GetOutputPort());
  moved->SetTransform(transform);
  moved->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(moved->GetOutputPort());
  triangles->PassLinesOff();
  triangles->PassVertsOff();
  triangles->Update();
  vtkSmartPointer<vtkPolyData> mesh = triangles->GetOutput();
  return mesh;
}

int ExactSides()
{
  struct Placement
  {
    const char* Name;
    double Scale;
    double Offset[3];
  };
  const Placement placements[] = {
    { "as read", 1.0, { 0.0, 0.0, 0.0 } },
    { "10^7 from the origin", 1.0, { 1.0e7, -3.0e6, 2.0e7 } },
    { "scaled by 10^-6", 1.0e-6, { 0.0, 0.0, 0.0 } },
  };
  for (const Placement& placement : placements)
  {
    vtkSmartPointer<vtkPolyData> mesh = MovedBunny(placement.Scale, placement.Offset);
    const ReferenceMesh reference(mesh);
    auto filter = MakeFilter(vtkNPRFeatureLines::SILHOUETTE);
    filter->MergeCoincidentPointsOff();
    filter->SetInputData(mesh);
    double bounds[6];
    mesh->GetBounds(bounds);
    const double centre[3] = { 0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]),
      0.5 * (bounds[4] + bounds[5]) };
    const double radius = 0.5 *
      std::sqrt((bounds[1] - bounds[0]) * (bounds[1] - bounds[0]) +
        (bounds[3] - bounds[2]) * (bounds[3] - bounds[2]) +
        (bounds[5] - bounds[4]) * (bounds[5] - bounds[4]));

    std::mt19937 random(7);
    std::normal_distribution<double> gaussian;
    std::uniform_int_distribution<size_t> anyFace(0, reference.Normals.size() - 1);
    std::uniform_real_distribution<double> uniform(-20.0, 20.0);
    vtkCellArray* polys = mesh->GetPolys();
    long long views = 0, generalUnsure = 0, inPlaneUnsure = 0, silhouettes = 0;
    for (int view = 0; view < 160; ++view)
    {
      const bool parallel = view % 2 == 1;
      const bool inPlane = view >= 80; // the eye in a face's plane, or the view along it
      double vector[3];
      if (!inPlane)
      {
        double d[3] = { gaussian(random), gaussian(random), gaussian(random) };
        vtkMath::Normalize(d);
        for (int k = 0; k < 3; ++k)
        {
          vector[k] = parallel ? d[k] : centre[k] + 3.0 * radius * d[k];
        }
      }
      else
      {
        // A face's points: the eye at q + t (p - q) + s (r - q), or the direction p - q.
        vtkIdType size;
        const vtkIdType* ids;
        polys->GetCellAtId(static_cast<vtkIdType>(anyFace(random)), size, ids);
        const double* q = mesh->GetPoint(ids[0]);
        double p[3], r[3];
        mesh->GetPoint(ids[1], p);
        mesh->GetPoint(ids[2], r);
        const double t = uniform(random), s = uniform(random);
        for (int k = 0; k < 3; ++k)
        {
          vector[k] = parallel ? p[k] - q[k] : q[k] + t * (p[k] - q[k]) + s * (r[k] - q[k]);
        }
      }
      filter->SetParallelProjection(parallel);
      if (parallel)
      {
        filter->SetDirectionOfProjection(vector);
      }
      else
      {
        filter->SetEyePosition(vector);
      }
      filter->Update();
      const std::set<Edge> expected = reference.Silhouettes(parallel, vector);
      const long long cells = CountCells(filter, vtkNPRFeatureLines::SILHOUETTE);
      NPR_CHECK(cells == static_cast<long long>(expected.size()),
        placement.Name << ", view " << view << ": " << cells
                       << " silhouette edges, the reference has " << expected.size());
      CheckEdges(EdgesOf(Lines(filter), vtkNPRFeatureLines::SILHOUETTE), expected,
        std::string(placement.Name) + ", view " + std::to_string(view));
      (inPlane ? inPlaneUnsure : generalUnsure) += filter->GetNumberOfUnsureFaces();
      silhouettes += cells;
      ++views;
    }
    const long long faces = static_cast<long long>(reference.Normals.size());
    std::cout << placement.Name << ": " << views << " views, " << silhouettes
              << " silhouette edges in all, identical to the reference; faces left to the "
                 "double-precision test: "
              << generalUnsure << " in 80 general views, " << inPlaneUnsure
              << " in 80 edge-on views (of " << faces << " faces each)\n";
    // The edge-on views reach the fallback (so it is tested); general views hardly ever do.
    NPR_CHECK(inPlaneUnsure >= 80,
      placement.Name << ": the edge-on views left only " << inPlaneUnsure << " faces undecided");
    NPR_CHECK(generalUnsure <= 80 * faces / 1000,
      placement.Name << ": " << generalUnsure << " faces undecided in general views");
  }
  return nprTestResult();
}

// ---- Smooth contours: the zero set of the interpolated facing function ----
// The smooth-contour segments of the output, chained by their shared points.
struct Contour
{
  std::vector<std::array<vtkIdType, 2>> Segments;  // output point ids
  std::vector<std::array<vtkIdType, 3>> Triangles; // ContourTriangle of each
  std::map<vtkIdType, int> Uses;                   // segments per point
  int Loops = 0;                                   // connected pieces
  bool Closed = false;                             // every point used by exactly two segments
};

Contour SmoothContour(vtkNPRFeatureLines* filter)
{
  Contour contour;
  vtkPolyData* output = filter->GetOutput();
  auto* types = vtkUnsignedCharArray::SafeDownCast(output->GetCellData()->GetArray("FeatureType"));
  auto* triangles =
    vtkIdTypeArray::SafeDownCast(output->GetCellData()->GetArray("ContourTriangle"));
  for (vtkIdType i = 0; types && i < output->GetNumberOfCells(); ++i)
  {
    const int type = types->GetValue(i);
    if (!(type & vtkNPRFeatureLines::SMOOTH_CONTOUR))
    {
      continue;
    }
    NPR_CHECK(type == (vtkNPRFeatureLines::SMOOTH_CONTOUR | vtkNPRFeatureLines::SILHOUETTE),
      "a smooth contour of type " << type);
    vtkIdType size;
    const vtkIdType* ids;
    output->GetLines()->GetCellAtId(i, size, ids);
    contour.Segments.push_back({ ids[0], ids[1] });
    std::array<vtkIdType, 3> corners = { -1, -1, -1 };
    for (int k = 0; triangles && k < 3; ++k)
    {
      corners[k] = triangles->GetTypedComponent(i, k);
    }
    contour.Triangles.push_back(corners);
    ++contour.Uses[ids[0]];
    ++contour.Uses[ids[1]];
  }
  NPR_CHECK(contour.Segments.empty() || triangles, "smooth contours without ContourTriangle");
  // Pieces: union-find over the points.
  std::map<vtkIdType, vtkIdType> parent;
  std::function<vtkIdType(vtkIdType)> root = [&](vtkIdType x)
  { return parent[x] == x ? x : parent[x] = root(parent[x]); };
  for (const auto& use : contour.Uses)
  {
    parent[use.first] = use.first;
  }
  for (const auto& s : contour.Segments)
  {
    parent[root(s[0])] = root(s[1]);
  }
  contour.Closed = !contour.Uses.empty();
  for (const auto& use : contour.Uses)
  {
    contour.Loops += root(use.first) == use.first ? 1 : 0;
    contour.Closed = contour.Closed && use.second == 2;
  }
  return contour;
}

vtkSmartPointer<vtkPolyData> Sphere(int theta, int phi)
{
  vtkNew<vtkSphereSource> source;
  source->SetRadius(1.0);
  source->SetThetaResolution(theta);
  source->SetPhiResolution(phi);
  source->Update();
  return source->GetOutput();
}

// Each segment end is the zero of g interpolated along one of its triangle's edges, from the
// input's normals made unit length: recomputed here independently.
double WorstZeroPoint(vtkNPRFeatureLines* filter, vtkPolyData* mesh, const Contour& contour)
{
  vtkDataArray* normals = mesh->GetPointData()->GetNormals();
  const double* eye = filter->GetEyePosition();
  const double* d = filter->GetDirectionOfProjection();
  auto g = [&](vtkIdType id)
  {
    double n[3], p[3];
    normals->GetTuple(id, n);
    mesh->GetPoint(id, p);
    vtkMath::Normalize(n);
    const double v[3] = { p[0] - eye[0], p[1] - eye[1], p[2] - eye[2] };
    return filter->GetParallelProjection() ? vtkMath::Dot(n, d) : vtkMath::Dot(n, v);
  };
  double worst = 0.0;
  for (size_t s = 0; s < contour.Segments.size(); ++s)
  {
    for (vtkIdType end : contour.Segments[s])
    {
      double x[3];
      filter->GetOutput()->GetPoint(end, x);
      double best = 1e300;
      for (int k = 0; k < 3; ++k)
      {
        vtkIdType a = contour.Triangles[s][k], b = contour.Triangles[s][(k + 1) % 3];
        if (a > b)
        {
          std::swap(a, b);
        }
        const double ga = g(a), gb = g(b);
        if ((ga >= 0.0) == (gb >= 0.0))
        {
          continue;
        }
        double pa[3], pb[3];
        mesh->GetPoint(a, pa);
        mesh->GetPoint(b, pb);
        const double t = ga / (ga - gb);
        const double z[3] = { pa[0] + t * (pb[0] - pa[0]), pa[1] + t * (pb[1] - pa[1]),
          pa[2] + t * (pb[2] - pa[2]) };
        best = std::min(best, std::sqrt(vtkMath::Distance2BetweenPoints(x, z)));
      }
      worst = std::max(worst, best);
    }
  }
  return worst;
}

// A sphere seen along -z in parallel: g = -z, the contour is the equator, one closed loop.
int SmoothSphereParallel()
{
  const double pi = vtkMath::Pi();
  // vtkSphereSource's phi resolution counts the rings, poles included: 63 puts a ring on the
  // equator (also with exact zeros there: ties count as positive), 64 puts the equator
  // between two rings, so the contour crosses their edges.
  for (int variant = 0; variant < 3; ++variant)
  {
    const int phi = variant == 0 ? 64 : 63;
    vtkSmartPointer<vtkPolyData> sphere = Sphere(64, phi);
    std::string name = "sphere 64x" + std::to_string(phi);
    if (variant == 1)
    {
      name += ", exact zeros on the equator";
      vtkNew<vtkPoints> points;
      points->SetDataTypeToDouble();
      points->DeepCopy(sphere->GetPoints());
      vtkDataArray* normals = sphere->GetPointData()->GetNormals();
      int zeros = 0;
      for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
      {
        double p[3], n[3];
        points->GetPoint(i, p);
        normals->GetTuple(i, n);
        if (std::abs(p[2]) < 1e-6)
        {
          p[2] = n[2] = 0.0;
          points->SetPoint(i, p);
          normals->SetTuple(i, n);
          ++zeros;
        }
      }
      sphere->SetPoints(points);
      NPR_CHECK(zeros == 64, zeros << " equator points");
    }
    auto filter = MakeFilter(AllTypes);
    filter->SmoothContoursOn();
    filter->ParallelProjectionOn();
    filter->SetDirectionOfProjection(0, 0, -1);
    filter->SetInputData(sphere);
    filter->Update();
    const Contour contour = SmoothContour(filter);
    // The chord bound: an edge's points lie at least cos(half its angle) from the centre.
    const double chord = std::cos(pi / 64) * (phi % 2 ? 1.0 : std::cos(pi / (2 * (phi - 1))));
    double worstZ = 0.0, lowest = 1.0, highest = 0.0;
    for (const auto& use : contour.Uses)
    {
      double x[3];
      filter->GetOutput()->GetPoint(use.first, x);
      worstZ = std::max(worstZ, std::abs(x[2]));
      const double r = std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
      lowest = std::min(lowest, r);
      highest = std::max(highest, r);
    }
    const double zero = WorstZeroPoint(filter, sphere, contour);
    std::cout << name << ": " << contour.Segments.size() << " segments, " << contour.Uses.size()
              << " points, " << contour.Loops << " loop(s), closed " << contour.Closed
              << "; |z| <= " << worstZ << ", radius " << lowest << " to " << highest
              << " (chord bound " << chord << "), zero points within " << zero << "\n";
    NPR_CHECK(
      contour.Segments.size() >= 64, name << ": " << contour.Segments.size() << " segments");
    NPR_CHECK(contour.Closed && contour.Loops == 1,
      name << ": " << contour.Loops << " pieces, closed " << contour.Closed);
    NPR_CHECK(worstZ <= 1e-9, name << ": a contour point at z = " << worstZ);
    NPR_CHECK(lowest >= chord - 1e-6 && highest <= 1.0 + 1e-6,
      name << ": radius from " << lowest << " to " << highest);
    NPR_CHECK(zero <= 1e-12, name << ": a zero point " << zero << " from its edge's");
    NPR_CHECK(filter->GetNumberOfSkippedContourTriangles() == 0, "skipped triangles");
    NPR_CHECK(CountCells(filter, vtkNPRFeatureLines::SILHOUETTE) == 0,
      name << ": mesh edges still silhouettes");
  }
  return nprTestResult();
}

// In perspective from (0, 0, D): on the unit sphere g = 1 - D z is linear along every edge,
// so the contour lies on the plane z = 1/D, inside the analytic circle by the chord sag.
int SmoothSpherePerspective()
{
  const double pi = vtkMath::Pi();
  const double D = 5.0;
  vtkSmartPointer<vtkPolyData> sphere = Sphere(64, 64);
  auto filter = MakeFilter(vtkNPRFeatureLines::SILHOUETTE);
  filter->SmoothContoursOn();
  filter->SetEyePosition(0, 0, D);
  filter->SetInputData(sphere);
  filter->Update();
  const Contour contour = SmoothContour(filter);
  const double circle = std::sqrt(1.0 - 1.0 / (D * D));
  // Sag of the longest edges (the quads' diagonals), for points on a chord of the sphere.
  const double sag = 1.0 - std::cos(0.5 * std::hypot(2 * pi / 64, pi / 64));
  double worstPlane = 0.0, worstIn = 0.0, worstOut = 0.0;
  for (const auto& use : contour.Uses)
  {
    double x[3];
    filter->GetOutput()->GetPoint(use.first, x);
    worstPlane = std::max(worstPlane, std::abs(x[2] - 1.0 / D));
    const double rho = std::hypot(x[0], x[1]);
    worstIn = std::max(worstIn, circle - rho);
    worstOut = std::max(worstOut, rho - circle);
  }
  const double zero = WorstZeroPoint(filter, sphere, contour);
  std::cout << "perspective: " << contour.Segments.size() << " segments, " << contour.Loops
            << " loop(s), closed " << contour.Closed << "; |z - 1/D| <= " << worstPlane
            << " (float normals and points), inside the circle by <= " << worstIn << ", outside by "
            << worstOut << " (sag " << sag << "), zero points within " << zero << "\n";
  NPR_CHECK(contour.Closed && contour.Loops == 1, contour.Loops << " pieces");
  NPR_CHECK(worstPlane <= 1e-6, "off the plane z = 1/D by " << worstPlane);
  NPR_CHECK(worstIn <= sag && worstOut <= 1e-6,
    "from the analytic circle: inside " << worstIn << ", outside " << worstOut);
  NPR_CHECK(zero <= 1e-12, "a zero point " << zero << " from its edge's");

  // Normals of other lengths (1/4 to 4, per point) are made unit: the same contour.
  vtkNew<vtkPolyData> scaled;
  scaled->DeepCopy(sphere);
  vtkDataArray* normals = scaled->GetPointData()->GetNormals();
  std::mt19937 random(11);
  std::uniform_real_distribution<double> power(-2.0, 2.0);
  for (vtkIdType i = 0; i < normals->GetNumberOfTuples(); ++i)
  {
    const double factor = std::pow(2.0, power(random));
    double n[3];
    normals->GetTuple(i, n);
    normals->SetTuple3(i, factor * n[0], factor * n[1], factor * n[2]);
  }
  filter->SetInputData(scaled);
  filter->Update();
  const Contour other = SmoothContour(filter);
  double moved = other.Segments.size() == contour.Segments.size() ? 0.0 : 1e300;
  for (const auto& use : other.Uses)
  {
    double x[3];
    filter->GetOutput()->GetPoint(use.first, x);
    moved = std::max(moved, std::abs(x[2] - 1.0 / D));
  }
  std::cout << "normals scaled by 1/4 to 4: " << other.Segments.size()
            << " segments, |z - 1/D| <= " << moved << "\n";
  NPR_CHECK(moved <= 1e-6, "normals not made unit: the contour moved by " << moved);
  return nprTestResult();
}

// A torus (ring R, tube r) with analytic normals, seen obliquely in perspective: an outer loop
// and interior contours, every point near the analytic contour generator and that generator
// covered.
int SmoothTorus()
{
  const double pi = vtkMath::Pi();
  const double R = 1.0, r = 0.35;
  const int nu = 96, nv = 48;
  vtkNew<vtkPolyData> torus;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> normals;
  normals->SetNumberOfComponents(3);
  normals->SetName("Normals");
  for (int i = 0; i < nu; ++i)
  {
    for (int j = 0; j < nv; ++j)
    {
      const double u = 2 * pi * i / nu, v = 2 * pi * j / nv;
      const double c = R + r * std::cos(v);
      points->InsertNextPoint(c * std::cos(u), c * std::sin(u), r * std::sin(v));
      normals->InsertNextTuple3(std::cos(v) * std::cos(u), std::cos(v) * std::sin(u), std::sin(v));
    }
  }
  vtkNew<vtkCellArray> cells;
  auto id = [&](int i, int j) { return static_cast<vtkIdType>((i % nu) * nv + (j % nv)); };
  for (int i = 0; i < nu; ++i)
  {
    for (int j = 0; j < nv; ++j)
    {
      const vtkIdType a[3] = { id(i, j), id(i + 1, j), id(i + 1, j + 1) };
      const vtkIdType b[3] = { id(i, j), id(i + 1, j + 1), id(i, j + 1) };
      cells->InsertNextCell(3, a);
      cells->InsertNextCell(3, b);
    }
  }
  torus->SetPoints(points);
  torus->SetPolys(cells);
  torus->GetPointData()->SetNormals(normals);

  const double eye[3] = { 0.3, -3.0, 1.6 };
  auto filter = MakeFilter(AllTypes);
  filter->SmoothContoursOn();
  filter->SetEyePosition(eye);
  filter->SetInputData(torus);
  filter->Update();
  const Contour contour = SmoothContour(filter);

  // The analytic facing cosine at the torus point nearest a point x.
  auto facing = [&](const double x[3], double surface[3])
  {
    const double u = std::atan2(x[1], x[0]);
    const double v = std::atan2(x[2], std::hypot(x[0], x[1]) - R);
    const double n[3] = { std::cos(v) * std::cos(u), std::cos(v) * std::sin(u), std::sin(v) };
    const double c = R + r * std::cos(v);
    const double s[3] = { c * std::cos(u), c * std::sin(u), r * std::sin(v) };
    std::copy_n(s, 3, surface);
    const double toEye[3] = { s[0] - eye[0], s[1] - eye[1], s[2] - eye[2] };
    return vtkMath::Dot(n, toEye) / vtkMath::Norm(toEye);
  };
  // Linear interpolation of g along an edge of length l errs by l^2/8 max|g''|, with
  // |g''| <= k^2 |p - eye| + 3k on a surface of largest curvature k = 1/r; the nearest
  // surface point is within the sag l^2 k / 8, which moves g by about that (|n| = 1) and the
  // cosine by that over the distance.
  const double longest = std::hypot(2 * pi * (R + r) / nu, 2 * pi * r / nv);
  const double k = 1.0 / r;
  const double farthest = vtkMath::Norm(eye) + R + r, nearest = vtkMath::Norm(eye) - R - r;
  const double tolerance = (longest * longest / 8.0) * (k * k * farthest + 3.0 * k + k) / nearest;
  double worst = 0.0;
  std::vector<std::array<double, 3>> contourPoints;
  for (const auto& use : contour.Uses)
  {
    double x[3], s[3];
    filter->GetOutput()->GetPoint(use.first, x);
    worst = std::max(worst, std::abs(facing(x, s)));
    contourPoints.push_back({ x[0], x[1], x[2] });
  }
  // Coverage: the analytic generator, found along v for 360 values of u, near the contour.
  double farthestMiss = 0.0;
  int roots = 0;
  for (int i = 0; i < 360; ++i)
  {
    const double u = 2 * pi * i / 360;
    auto h = [&](double v)
    {
      const double c = R + r * std::cos(v);
      const double x[3] = { c * std::cos(u), c * std::sin(u), r * std::sin(v) };
      const double n[3] = { std::cos(v) * std::cos(u), std::cos(v) * std::sin(u), std::sin(v) };
      const double toEye[3] = { x[0] - eye[0], x[1] - eye[1], x[2] - eye[2] };
      return vtkMath::Dot(n, toEye);
    };
    for (int j = 0; j < 720; ++j)
    {
      double a = 2 * pi * j / 720, b = 2 * pi * (j + 1) / 720;
      if ((h(a) >= 0.0) == (h(b) >= 0.0))
      {
        continue;
      }
      for (int step = 0; step < 60; ++step)
      {
        const double m = 0.5 * (a + b);
        ((h(m) >= 0.0) == (h(a) >= 0.0) ? a : b) = m;
      }
      const double c = R + r * std::cos(a);
      const double x[3] = { c * std::cos(u), c * std::sin(u), r * std::sin(a) };
      double best = 1e300;
      for (const auto& p : contourPoints)
      {
        best = std::min(best, std::sqrt(vtkMath::Distance2BetweenPoints(x, p.data())));
      }
      farthestMiss = std::max(farthestMiss, best);
      ++roots;
    }
  }
  // The loops' sizes: the outer one reaches beyond the ring, the others stay inside R + r.
  std::vector<double> reach;
  {
    std::map<vtkIdType, std::vector<vtkIdType>> next;
    for (const auto& s : contour.Segments)
    {
      next[s[0]].push_back(s[1]);
      next[s[1]].push_back(s[0]);
    }
    std::set<vtkIdType> seen;
    for (const auto& start : next)
    {
      if (seen.count(start.first))
      {
        continue;
      }
      double most = 0.0;
      std::vector<vtkIdType> stack = { start.first };
      while (!stack.empty())
      {
        const vtkIdType p = stack.back();
        stack.pop_back();
        if (!seen.insert(p).second)
        {
          continue;
        }
        double x[3];
        filter->GetOutput()->GetPoint(p, x);
        most = std::max(most, std::hypot(x[0], x[1]));
        for (vtkIdType q : next[p])
        {
          stack.push_back(q);
        }
      }
      reach.push_back(most);
    }
  }
  std::sort(reach.rbegin(), reach.rend());
  std::cout << "torus " << nu << "x" << nv << ": " << contour.Segments.size() << " segments, "
            << contour.Loops << " loops, closed " << contour.Closed << "; loop reach";
  for (double x : reach)
  {
    std::cout << " " << x;
  }
  std::cout << "; facing cosine <= " << worst << " (bound " << tolerance << "); " << roots
            << " analytic points, farthest " << farthestMiss << " from the contour (edge "
            << longest << ")\n";
  NPR_CHECK(contour.Closed, "the torus contour is not closed");
  NPR_CHECK(
    contour.Loops >= 2 && reach.size() >= 2 && reach[0] > R + 0.9 * r && reach[1] < R + 0.5 * r,
    contour.Loops << " loops: no outer loop and interior contour");
  NPR_CHECK(worst <= tolerance, "a contour point's facing cosine is " << worst);
  NPR_CHECK(roots >= 720 && farthestMiss <= longest,
    "the analytic contour is " << farthestMiss << " from the smooth contour");
  NPR_CHECK(WorstZeroPoint(filter, torus, contour) <= 1e-12, "zero points off their edges");
  return nprTestResult();
}

// Without point normals the option changes nothing.
int SmoothNoNormals()
{
  vtkSmartPointer<vtkPolyData> sphere = Sphere(32, 32);
  sphere->GetPointData()->SetNormals(nullptr);
  auto off = MakeFilter(AllTypes);
  auto on = MakeFilter(AllTypes);
  on->SmoothContoursOn();
  for (auto* filter : { off.Get(), on.Get() })
  {
    filter->SetEyePosition(0.4, -0.3, 4.0);
    filter->SetInputData(sphere);
    filter->Update();
  }
  vtkPolyData* a = off->GetOutput();
  vtkPolyData* b = on->GetOutput();
  bool same = a->GetNumberOfPoints() == b->GetNumberOfPoints() &&
    a->GetNumberOfCells() == b->GetNumberOfCells() &&
    b->GetCellData()->GetNumberOfArrays() == a->GetCellData()->GetNumberOfArrays() &&
    !b->GetCellData()->GetArray("ContourTriangle");
  for (vtkIdType i = 0; same && i < a->GetNumberOfPoints(); ++i)
  {
    double p[3], q[3];
    a->GetPoint(i, p);
    b->GetPoint(i, q);
    same = p[0] == q[0] && p[1] == q[1] && p[2] == q[2];
  }
  for (const char* name : { "FeatureType", "InputPointIds" })
  {
    vtkDataArray* x = a->GetCellData()->GetArray(name);
    vtkDataArray* y = b->GetCellData()->GetArray(name);
    for (vtkIdType i = 0; same && x && y && i < x->GetNumberOfValues(); ++i)
    {
      same = x->GetVariantValue(i) == y->GetVariantValue(i);
    }
  }
  for (vtkIdType i = 0; same && i < a->GetNumberOfCells(); ++i)
  {
    vtkIdType n, m;
    const vtkIdType *p, *q;
    a->GetLines()->GetCellAtId(i, n, p);
    b->GetLines()->GetCellAtId(i, m, q);
    same = n == 2 && m == 2 && p[0] == q[0] && p[1] == q[1];
  }
  std::cout << "no normals: " << b->GetNumberOfCells() << " lines, "
            << CountCells(on, vtkNPRFeatureLines::SILHOUETTE) << " mesh silhouettes, "
            << (same ? "identical" : "different") << " with smooth contours on\n";
  NPR_CHECK(same, "without normals, SmoothContours changed the output");
  NPR_CHECK(CountCells(on, vtkNPRFeatureLines::SILHOUETTE) > 32, "no mesh silhouettes");
  return nprTestResult();
}

// Zero and NaN normals: those points' triangles are skipped and counted, the rest unchanged.
int SmoothBadNormals()
{
  vtkSmartPointer<vtkPolyData> good = Sphere(48, 48);
  vtkNew<vtkPolyData> bad;
  bad->DeepCopy(good);
  vtkDataArray* normals = bad->GetPointData()->GetNormals();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  // On two arcs of the contour of the view below (the circle x = 0 for a view along +x).
  std::set<vtkIdType> broken;
  for (vtkIdType i = 0; i < bad->GetNumberOfPoints(); ++i)
  {
    double p[3];
    bad->GetPoint(i, p);
    if (std::abs(p[0]) < 0.07 && (p[1] > 0.5 || p[1] < -0.9))
    {
      broken.insert(i);
      const int kind = static_cast<int>(broken.size() % 3);
      normals->SetTuple3(i, kind == 0 ? 0.0 : nan, kind == 2 ? inf : 0.0, 0.0);
    }
  }
  vtkCellArray* polys = bad->GetPolys();
  long long touching = 0;
  for (vtkIdType c = 0; c < polys->GetNumberOfCells(); ++c)
  {
    vtkIdType size;
    const vtkIdType* ids;
    polys->GetCellAtId(c, size, ids);
    bool hit = false;
    for (vtkIdType k = 0; k < size; ++k)
    {
      hit = hit || broken.count(ids[k]) > 0;
    }
    touching += hit ? size - 2 : 0;
  }
  std::set<std::vector<double>> expected, got;
  long long skipped = -1;
  for (vtkPolyData* mesh : { good.Get(), bad.Get() })
  {
    auto filter = MakeFilter(AllTypes);
    filter->SmoothContoursOn();
    filter->ParallelProjectionOn();
    filter->SetDirectionOfProjection(1, 0, 0);
    filter->SetInputData(mesh);
    filter->Update();
    const Contour contour = SmoothContour(filter);
    for (size_t s = 0; s < contour.Segments.size(); ++s)
    {
      const auto& t = contour.Triangles[s];
      if (mesh == good.Get() && (broken.count(t[0]) || broken.count(t[1]) || broken.count(t[2])))
      {
        continue;
      }
      double a[3], b[3];
      filter->GetOutput()->GetPoint(contour.Segments[s][0], a);
      filter->GetOutput()->GetPoint(contour.Segments[s][1], b);
      (mesh == good.Get() ? expected : got)
        .insert({ a[0], a[1], a[2], b[0], b[1], b[2], double(t[0]), double(t[1]), double(t[2]) });
    }
    if (mesh == bad.Get())
    {
      skipped = filter->GetNumberOfSkippedContourTriangles();
      NPR_CHECK(!contour.Closed && contour.Loops == 2,
        "the contour broken twice: " << contour.Loops << " pieces, closed " << contour.Closed);
    }
  }
  std::cout << broken.size() << " points with zero, NaN or infinite normals, " << touching
            << " triangles use them, " << skipped << " skipped; " << got.size() << " segments, "
            << expected.size() << " of the intact mesh's away from them\n";
  NPR_CHECK(
    broken.size() >= 6 && skipped == touching, skipped << " skipped, " << touching << " expected");
  NPR_CHECK(got == expected && !got.empty(), "the segments away from the broken normals changed");
  return nprTestResult();
}

// ---- The line settings: one vtkNPRLineSettings behind the setters of every class ----
// A holder (vtkNPRFeatureLines, vtkNPRReferenceMask, vtkNPRDrawingLines) starts with a fresh
// vtkNPRLineSettings's defaults, its setters and getters are GetLineSettings()'s, the angle is
// clamped as vtkNPRLineSettings clamps it, and a changed setting (through either) changes the
// holder's MTime while an unchanged one does not.
template <class Holder>
void CheckLineSettings(const std::string& name, const std::string& angleName,
  void (Holder::*setAngle)(double), double (Holder::*getAngle)())
{
  vtkNew<vtkNPRLineSettings> fresh;
  vtkNew<Holder> holder;
  vtkNPRLineSettings* settings = holder->GetLineSettings();
  NPR_CHECK(settings && settings->GetClassName() == std::string("vtkNPRLineSettings"),
    name << ": no line settings");
  if (!settings)
  {
    return;
  }
  NPR_CHECK(holder->GetSilhouettes() == fresh->GetSilhouettes() &&
      holder->GetCreases() == fresh->GetCreases() &&
      holder->GetBoundaries() == fresh->GetBoundaries() &&
      holder->GetNonManifoldEdges() == fresh->GetNonManifoldEdges() &&
      (holder.Get()->*getAngle)() == fresh->GetCreaseAngle() && fresh->GetCreaseAngle() == 30.0,
    name << ": defaults differ from vtkNPRLineSettings's");
  for (const double angle : { -5.0, 500.0, 45.0 })
  {
    (holder.Get()->*setAngle)(angle);
    fresh->SetCreaseAngle(angle);
    NPR_CHECK((holder.Get()->*getAngle)() == fresh->GetCreaseAngle() &&
        settings->GetCreaseAngle() == fresh->GetCreaseAngle(),
      name << ": " << angleName << " " << angle << " kept as " << (holder.Get()->*getAngle)()
           << ", vtkNPRLineSettings keeps " << fresh->GetCreaseAngle());
  }
  holder->SilhouettesOff();
  holder->SetNonManifoldEdges(false);
  settings->SetBoundaries(false);
  NPR_CHECK(!settings->GetSilhouettes() && !settings->GetNonManifoldEdges() &&
      !holder->GetBoundaries() && holder->GetCreases(),
    name << ": the setters and GetLineSettings() disagree");
  const vtkMTimeType before = holder->GetMTime();
  holder->SetCreases(true);
  NPR_CHECK(holder->GetMTime() == before, name << ": an unchanged setting changed the MTime");
  holder->CreasesOff();
  const vtkMTimeType changed = holder->GetMTime();
  settings->SetSilhouettes(true);
  NPR_CHECK(before < changed && changed < holder->GetMTime(),
    name << ": a changed setting left the MTime as it was");
  std::ostringstream printed;
  holder->Print(printed);
  NPR_CHECK(printed.str().find(angleName + ": 45\n") != std::string::npos &&
      printed.str().find("Silhouettes: 1\n") != std::string::npos,
    name << ": PrintSelf lacks the settings:\n"
         << printed.str());
}

int LineSettings()
{
  CheckLineSettings<vtkNPRFeatureLines>("vtkNPRFeatureLines", "FeatureAngle",
    &vtkNPRFeatureLines::SetFeatureAngle, &vtkNPRFeatureLines::GetFeatureAngle);
  CheckLineSettings<vtkNPRReferenceMask>("vtkNPRReferenceMask", "CreaseAngle",
    &vtkNPRReferenceMask::SetCreaseAngle, &vtkNPRReferenceMask::GetCreaseAngle);
  CheckLineSettings<vtkNPRDrawingLines>("vtkNPRDrawingLines", "CreaseAngle",
    &vtkNPRDrawingLines::SetCreaseAngle, &vtkNPRDrawingLines::GetCreaseAngle);
  // The pipeline sees a change made through GetLineSettings(): the creases go.
  auto filter = MakeFilter(AllTypes);
  filter->SetInputData(CubeSource());
  filter->Update();
  const size_t creases = EdgesOf(Lines(filter), vtkNPRFeatureLines::CREASE).size();
  filter->GetLineSettings()->CreasesOff();
  filter->Update();
  const size_t after = EdgesOf(Lines(filter), vtkNPRFeatureLines::CREASE).size();
  std::cout << creases << " crease edges of the cube, " << after
            << " after GetLineSettings()->CreasesOff()\n";
  NPR_CHECK(creases == 12 && after == 0, "the settings' change did not reach the output");
  return nprTestResult();
}
}

int main(int argc, char* argv[])
{
  const std::map<std::string, std::function<int()>> cases = {
    { "cube-creases", CubeCreases },
    { "cube-silhouettes", CubeSilhouettes },
    { "boundary-non-manifold", BoundaryAndNonManifold },
    { "reuse", Reuse },
    { "exact-sides", ExactSides },
    { "smooth-sphere-parallel", SmoothSphereParallel },
    { "smooth-sphere-perspective", SmoothSpherePerspective },
    { "smooth-torus", SmoothTorus },
    { "smooth-no-normals", SmoothNoNormals },
    { "smooth-bad-normals", SmoothBadNormals },
    { "line-settings", LineSettings },
  };
  return nprRunTestCase(argc, argv, cases);
}
