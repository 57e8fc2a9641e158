// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// The edge table of vtkNPRFeatureLines against a plain one built here from the documented rules
// (a map from each edge's two points to the faces that use it, all in double): the same lines,
// types, input ids and order, edge for edge, on meshes with creases (some exactly at the crease
// angle), boundaries, a non-manifold fin, faces wound the other way, points split along creases,
// faces in a random order, quads and a pentagon, strips, degenerate faces and a NaN point; with
// the cells in 64- and 32-bit storage and float and double points. And the memory the table and
// the drawing's occlusion structure hold, in bytes per triangle.
//
// usage: TestFeatureLinesTable CASE [DATA_DIR]   (CASE: the NPR_TEST_CASE names below)
#include "nprFeatureLineTesting.h"

#include "vtkActor.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkCylinderSource.h"
#include "vtkIdTypeArray.h"
#include "vtkMath.h"
#include "vtkNPRDrawingLines.h"
#include "vtkNPRModelReader.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkPolyDataNormals.h"
#include "vtkSphereSource.h"
#include "vtkStripper.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <numeric>
#include <random>
#include <string>
#include <vector>

namespace
{
using namespace nprFeatureLineTesting;

// ---- The plain table ----
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

double Dot3(const double a[3], const double b[3])
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

class PlainTable
{
public:
  PlainTable(vtkPolyData* mesh, bool merge)
  {
    this->ReadPoints(mesh, merge);
    vtkIdType size;
    const vtkIdType* ids;
    vtkCellArray* polys = mesh->GetPolys();
    for (polys->InitTraversal(); polys->GetNextCell(size, ids);)
    {
      this->AddFace(std::vector<vtkIdType>(ids, ids + size));
    }
    vtkCellArray* strips = mesh->GetStrips();
    for (strips->InitTraversal(); strips->GetNextCell(size, ids);)
    {
      for (vtkIdType k = 0; k + 2 < size; ++k)
      {
        this->AddFace({ ids[k + (k & 1)], ids[k + 1 - (k & 1)], ids[k + 2] });
      }
    }
  }

  // The angles between the faces' normals at the two-face edges, degrees.
  std::vector<double> Angles() const
  {
    std::vector<double> angles;
    for (const Edge& edge : this->Edges)
    {
      if (edge.Uses.size() == 2)
      {
        angles.push_back(this->Angle(edge));
      }
    }
    return angles;
  }

  // The lines for a viewpoint, in the order the faces first use their edges.
  std::vector<Line> Lines(const Viewpoint& viewpoint) const
  {
    std::vector<Line> lines;
    for (const Edge& edge : this->Edges)
    {
      const int type = this->Type(edge, viewpoint);
      if (type)
      {
        lines.push_back({ edge.A, edge.B, type });
      }
    }
    return lines;
  }

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

  void ReadPoints(vtkPolyData* mesh, bool merge)
  {
    std::map<Point, vtkIdType> first;
    for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
    {
      Point p;
      mesh->GetPoint(i, p.data());
      this->Points.push_back(p);
      const bool finite = std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
      const Point key = { p[0] + 0.0, p[1] + 0.0, p[2] + 0.0 }; // -0 as +0
      this->Representatives.push_back(merge && finite ? first.emplace(key, i).first->second : i);
    }
  }

  // Newell's normal from the first point, unit length; none where the face has no orientation.
  bool Normal(const std::vector<vtkIdType>& ids, std::array<double, 3>& unit) const
  {
    double normal[3] = { 0.0, 0.0, 0.0 }, size2 = 0.0;
    const Point& o = this->Points[ids[0]];
    for (size_t i = 1; i + 1 < ids.size(); ++i)
    {
      const Point& p = this->Points[ids[i]];
      const Point& q = this->Points[ids[i + 1]];
      const double a[3] = { p[0] - o[0], p[1] - o[1], p[2] - o[2] };
      const double b[3] = { q[0] - o[0], q[1] - o[1], q[2] - o[2] };
      normal[0] += a[1] * b[2] - a[2] * b[1];
      normal[1] += a[2] * b[0] - a[0] * b[2];
      normal[2] += a[0] * b[1] - a[1] * b[0];
      size2 = std::max(size2, std::max(Dot3(a, a), Dot3(b, b)));
    }
    const double length = std::sqrt(Dot3(normal, normal));
    if (!(length > 1e-12 * size2) || !std::isfinite(length))
    {
      return false;
    }
    unit = { normal[0] / length, normal[1] / length, normal[2] / length };
    return true;
  }

  void AddFace(const std::vector<vtkIdType>& ids)
  {
    const size_t size = ids.size();
    bool usable = size >= 3;
    for (vtkIdType id : ids)
    {
      usable = usable && id >= 0 && id < static_cast<vtkIdType>(this->Points.size());
    }
    for (size_t i = 0; usable && i < size; ++i)
    {
      const Point& p = this->Points[ids[i]];
      usable = std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
    }
    std::array<double, 3> normal;
    if (!usable || !this->Normal(ids, normal))
    {
      return;
    }
    this->Normals.push_back(normal);
    for (size_t i = 0; i < size; ++i)
    {
      vtkIdType a = this->Representatives[ids[i]], b = this->Representatives[ids[(i + 1) % size]];
      if (a == b || this->Points[a] == this->Points[b])
      {
        continue;
      }
      const bool forward = a < b;
      const auto key = std::make_pair(std::min(a, b), std::max(a, b));
      auto found = this->Index.emplace(key, this->Edges.size());
      if (found.second)
      {
        this->Edges.push_back({ key.first, key.second, {} });
      }
      this->Edges[found.first->second].Uses.push_back({ this->Normals.size() - 1, forward,
        std::make_pair(
          std::min(ids[i], ids[(i + 1) % size]), std::max(ids[i], ids[(i + 1) % size])) });
    }
  }

  // The angle between a two-face edge's normals (the second flipped where the windings
  // disagree), degrees.
  double Angle(const Edge& edge) const
  {
    const bool same = edge.Uses[0].Forward == edge.Uses[1].Forward;
    const auto& n0 = this->Normals[edge.Uses[0].Face];
    const auto& n1 = this->Normals[edge.Uses[1].Face];
    double flipped[3], cross[3];
    for (int k = 0; k < 3; ++k)
    {
      flipped[k] = same ? -n1[k] : n1[k];
    }
    vtkMath::Cross(n0.data(), flipped, cross);
    return vtkMath::DegreesFromRadians(std::atan2(vtkMath::Norm(cross), Dot3(n0.data(), flipped)));
  }

  int Type(const Edge& edge, const Viewpoint& viewpoint) const
  {
    if (edge.Uses.size() != 2)
    {
      return edge.Uses.size() == 1 ? vtkNPRFeatureLines::BOUNDARY
                                   : vtkNPRFeatureLines::NON_MANIFOLD;
    }
    const bool same = edge.Uses[0].Forward == edge.Uses[1].Forward;
    const auto& n0 = this->Normals[edge.Uses[0].Face];
    const auto& n1 = this->Normals[edge.Uses[1].Face];
    int type = this->Angle(edge) > viewpoint.Angle ? vtkNPRFeatureLines::CREASE : 0;
    double f0, f1;
    if (viewpoint.Parallel)
    {
      f0 = Dot3(n0.data(), viewpoint.View);
      f1 = Dot3(n1.data(), viewpoint.View);
    }
    else
    {
      const Point& p = this->Points[edge.A];
      const double toPoint[3] = { p[0] - viewpoint.View[0], p[1] - viewpoint.View[1],
        p[2] - viewpoint.View[2] };
      f0 = Dot3(n0.data(), toPoint);
      f1 = Dot3(n1.data(), toPoint);
    }
    // With smooth contours, a mesh edge is a silhouette only where its faces reach it through
    // different points (split normals).
    const bool split = edge.Uses[0].InputIds != edge.Uses[1].InputIds;
    if ((f0 < 0.0) != ((same ? -f1 : f1) < 0.0) && (!viewpoint.Smooth || split))
    {
      type |= vtkNPRFeatureLines::SILHOUETTE;
    }
    return type;
  }

  std::vector<Point> Points;
  std::vector<vtkIdType> Representatives;
  std::vector<std::array<double, 3>> Normals;
  std::vector<Edge> Edges;
  std::map<std::pair<vtkIdType, vtkIdType>, size_t> Index;
};

// ---- The meshes ----
// Creases, a non-manifold fin, a face wound the other way, a quad and a pentagon, a point
// coincident with another, strips (with a repeated point and a two-point strip), zero-area and
// two-point faces, an out-of-range id and a NaN point.
vtkSmartPointer<vtkPolyData> MixedMesh()
{
  const double p[][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 }, { 0.5, 0.5, 1 },
    { 0.5, 0.5, -1 }, { 0.5, 1.5, 0.3 }, { 1, 0, 0 }, { 2, 0, 0 }, { 2, 1, 0.2 }, { 1.5, 1.8, 0.1 },
    { std::nan(""), 0, 0 }, { 3, 0, 0 }, { 3, 1, 0 }, { 4, 0, 0.5 }, { 4, 1, 0 },
    { 0.25, 0.25, 0 } };
  vtkNew<vtkPoints> points;
  for (const auto& x : p)
  {
    points->InsertNextPoint(x);
  }
  vtkNew<vtkCellArray> polys;
  const std::vector<std::vector<vtkIdType>> faces = { { 0, 1, 4 }, { 1, 2, 4 }, { 2, 3, 4 },
    { 3, 0, 4 }, { 0, 5, 1 }, { 1, 5, 2 }, { 2, 5, 3 }, { 0, 3, 5 }, { 3, 2, 6 }, { 2, 3, 6 },
    { 0, 1, 16 }, { 0, 0, 1 }, { 0, 16, 16 }, { 11, 1, 2 }, { 1, 2, 99 }, { 7, 8, 9, 2 },
    { 8, 12, 13, 10, 9 }, { 0, 1 } };
  for (const auto& face : faces)
  {
    polys->InsertNextCell(static_cast<vtkIdType>(face.size()), face.data());
  }
  vtkNew<vtkCellArray> strips;
  const std::vector<std::vector<vtkIdType>> stripCells = { { 12, 14, 13, 15, 15, 14, 12 },
    { 12, 14 }, { 8, 12, 9, 13 } };
  for (const auto& strip : stripCells)
  {
    strips->InsertNextCell(static_cast<vtkIdType>(strip.size()), strip.data());
  }
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->SetPoints(points);
  mesh->SetPolys(polys);
  mesh->SetStrips(strips);
  return mesh;
}

std::vector<std::pair<std::string, vtkSmartPointer<vtkPolyData>>> Meshes()
{
  std::vector<std::pair<std::string, vtkSmartPointer<vtkPolyData>>> meshes;
  meshes.emplace_back("mixed", MixedMesh());
  // The bunny with its points split along creases (its normals' feature edges).
  vtkNew<vtkNPRModelReader> reader;
  reader->SetFileName((nprTestDataDir() + "/bunny.ply").c_str());
  vtkNew<vtkPolyDataNormals> split;
  split->SetInputConnection(reader->GetOutputPort());
  split->SetFeatureAngle(20.0);
  split->Update();
  meshes.emplace_back("bunny, split", split->GetOutput());
  // The bunny with its faces in a random order (the table numbers them in space instead).
  vtkPolyData* bunny = split->GetOutput();
  std::vector<vtkIdType> order(bunny->GetNumberOfPolys());
  std::iota(order.begin(), order.end(), 0);
  std::shuffle(order.begin(), order.end(), std::mt19937(5));
  vtkNew<vtkCellArray> shuffled;
  for (vtkIdType cell : order)
  {
    vtkIdType size;
    const vtkIdType* ids;
    bunny->GetPolys()->GetCellAtId(cell, size, ids);
    shuffled->InsertNextCell(size, ids);
  }
  auto shuffledBunny = vtkSmartPointer<vtkPolyData>::New();
  shuffledBunny->SetPoints(bunny->GetPoints());
  shuffledBunny->SetPolys(shuffled);
  meshes.emplace_back("bunny, shuffled", shuffledBunny);
  // A 12-sided cylinder: its sides meet at exactly 30 degrees, the default crease angle; one of
  // 300 sides, whose caps are polygons of 300 points.
  for (int sides : { 12, 300 })
  {
    vtkNew<vtkCylinderSource> cylinder;
    cylinder->SetResolution(sides);
    cylinder->Update();
    meshes.emplace_back("cylinder of " + std::to_string(sides), cylinder->GetOutput());
  }
  auto sphere = nprSphereSource(0.5, 24, 13);
  vtkNew<vtkStripper> strips;
  strips->SetInputConnection(sphere->GetOutputPort());
  strips->Update();
  meshes.emplace_back("sphere strips", strips->GetOutput());
  return meshes;
}

// The same mesh with its cells in 32-bit storage and its points in double.
vtkSmartPointer<vtkPolyData> OtherStorage(vtkPolyData* mesh)
{
  auto copy = vtkSmartPointer<vtkPolyData>::New();
  copy->DeepCopy(mesh);
  copy->GetPolys()->ConvertTo32BitStorage();
  copy->GetStrips()->ConvertTo32BitStorage();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->DeepCopy(mesh->GetPoints());
  copy->SetPoints(points);
  return copy;
}

// Views from all sides; some with the crease angle at an edge's exact angle, or the double just
// below it, which only the exact angle decides.
std::vector<Viewpoint> Viewpoints(vtkPolyData* mesh, const std::vector<double>& angles)
{
  double bounds[6];
  mesh->GetPoints()->GetBounds(bounds);
  const double centre[3] = { 0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]),
    0.5 * (bounds[4] + bounds[5]) };
  std::mt19937 random(11);
  std::normal_distribution<double> gaussian;
  std::vector<Viewpoint> views;
  for (int v = 0; v < 16; ++v)
  {
    const bool smooth = v % 7 == 3 && mesh->GetPointData()->GetNormals();
    Viewpoint view{ v % 3 == 1, {}, v % 4 == 2 ? 10.0 : (v % 4 == 3 ? 89.99 : 30.0), v % 5 != 4,
      smooth };
    double d[3] = { gaussian(random), gaussian(random), gaussian(random) };
    vtkMath::Normalize(d);
    for (int k = 0; k < 3; ++k)
    {
      view.View[k] = view.Parallel ? d[k] : centre[k] + 4.0 * d[k];
    }
    if (v % 6 == 5) // the eye at a mesh point: its faces seen edge-on
    {
      mesh->GetPoint(v % mesh->GetNumberOfPoints(), view.View);
      view.Parallel = false;
    }
    if (v % 4 == 1 && !angles.empty())
    {
      const double angle = angles[random() % angles.size()];
      view.Angle = v % 8 == 1 ? angle : std::nextafter(angle, 0.0);
    }
    views.push_back(view);
  }
  return views;
}

// ---- The filter's table against the plain one ----
// The output's mesh edges: its cells before the smooth contours.
vtkIdType MeshEdges(vtkPolyData* output)
{
  auto* types = vtkUnsignedCharArray::SafeDownCast(output->GetCellData()->GetArray("FeatureType"));
  vtkIdType count = 0;
  while (types && count < types->GetNumberOfValues() &&
    !(types->GetValue(count) & vtkNPRFeatureLines::SMOOTH_CONTOUR))
  {
    ++count;
  }
  return count;
}

// Whether the output's first lines are the expected ones: input ids, type and coordinates.
bool SameLines(vtkPolyData* output, vtkPolyData* mesh, const std::vector<Line>& expected)
{
  auto* ids = vtkIdTypeArray::SafeDownCast(output->GetCellData()->GetArray("InputPointIds"));
  auto* types = vtkUnsignedCharArray::SafeDownCast(output->GetCellData()->GetArray("FeatureType"));
  auto cells = vtk::TakeSmartPointer(output->GetLines()->NewIterator());
  cells->GoToFirstCell();
  bool same = ids && types;
  for (size_t i = 0; same && i < expected.size(); ++i, cells->GoToNextCell())
  {
    vtkIdType size;
    const vtkIdType* ends;
    cells->GetCurrentCell(size, ends);
    Point got, wanted;
    output->GetPoint(ends[0], got.data());
    mesh->GetPoint(expected[i].A, wanted.data());
    same = ids->GetValue(2 * i) == expected[i].A && ids->GetValue(2 * i + 1) == expected[i].B &&
      types->GetValue(i) == expected[i].Type && got == wanted;
  }
  return same;
}

int TableReference()
{
  vtkObject::GlobalWarningDisplayOff(); // the NaN point's warning
  long long compared = 0;
  for (const auto& named : Meshes())
  {
    for (const bool other : { false, true })
    {
      vtkSmartPointer<vtkPolyData> mesh = other ? OtherStorage(named.second) : named.second;
      const std::string name = named.first + (other ? " (32-bit cells, double points)" : "");
      auto filter = MakeFilter(AllTypes);
      filter->SetInputData(mesh);
      const PlainTable merged(mesh, true), separate(mesh, false);
      for (const Viewpoint& view : Viewpoints(mesh, merged.Angles()))
      {
        filter->SetParallelProjection(view.Parallel);
        if (view.Parallel)
        {
          filter->SetDirectionOfProjection(view.View);
        }
        else
        {
          filter->SetEyePosition(view.View);
        }
        filter->SetFeatureAngle(view.Angle);
        filter->SetMergeCoincidentPoints(view.Merge);
        filter->SetSmoothContours(view.Smooth);
        filter->Update();
        const std::vector<Line> expected = (view.Merge ? merged : separate).Lines(view);
        const vtkIdType got = MeshEdges(filter->GetOutput());
        NPR_CHECK(got == static_cast<vtkIdType>(expected.size()) &&
            SameLines(filter->GetOutput(), mesh, expected),
          name << ": " << got << " mesh edges, the plain table has " << expected.size()
               << " (or they differ)");
        compared += static_cast<long long>(expected.size());
      }
    }
  }
  vtkObject::GlobalWarningDisplayOn();
  std::cout << compared << " lines identical to the plain table, in order\n";
  NPR_CHECK(compared > 10000, "too few lines compared: " << compared);
  return nprTestResult();
}
NPR_TEST_CASE("table-reference", TableReference);

// ---- What the tables hold, per triangle ----
int TableMemory()
{
  auto sphere = nprSphereSource(0.5, 400, 400);
  sphere->Update();
  vtkPolyData* mesh = sphere->GetOutput();
  const double triangles = static_cast<double>(mesh->GetNumberOfPolys());
  auto filter = MakeFilter(AllTypes);
  filter->SetInputData(mesh);
  filter->SetEyePosition(0.0, 0.0, 5.0);
  filter->Update();
  const double table = static_cast<double>(filter->GetAdjacencyMemorySize()) / triangles;

  MaskScene scene(400, 300);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(mesh);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  scene.Renderer->AddActor(actor);
  scene.Renderer->ResetCamera();
  vtkNew<vtkNPRDrawingLines> drawing;
  drawing->SetRenderer(scene.Renderer);
  drawing->SetSize(400, 300);
  drawing->Update();
  const double drawn = static_cast<double>(drawing->GetMemorySize()) / triangles;
  std::cout << triangles << " triangles: the edge table holds " << table
            << " bytes a triangle, the drawing's tables and occlusion structure " << drawn << "\n";
  // About 40 and 75 (Documentation/drawing.md); the tables before them held over 290.
  NPR_CHECK(table > 20.0 && table <= 44.0, table << " bytes a triangle in the edge table");
  NPR_CHECK(drawn > table && drawn <= 84.0, drawn << " bytes a triangle for the drawing");
  NPR_CHECK(drawing->GetNumberOfStrokes() > 0, "no strokes");
  return nprTestResult();
}
NPR_TEST_CASE("table-memory", TableMemory);
}
