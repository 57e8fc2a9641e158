// Object-space feature lines (vtkNPRFeatureLines) and the ground-truth mask of the visible ones
// (vtkNPRReferenceMask), checked against what can be stated analytically: a box's creases,
// silhouettes from chosen viewpoints, boundaries of an open box, a non-manifold fin, the reuse of
// the edge adjacency, degenerate input; the mask of a cube against an independent projection of
// its visible edges, occlusion by another object, reuse, and agreement with vtkNPREdgePass.
//
// usage: TestFeatureLines CASE [DATA_DIR]   (CASE: see the table at the end of this file)
#include "nprTesting.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkCleanPolyData.h"
#include "vtkCubeSource.h"
#include "vtkIdTypeArray.h"
#include "vtkImageData.h"
#include "vtkMatrix4x4.h"
#include "vtkNPREdgePass.h"
#include "vtkNPRFeatureLines.h"
#include "vtkNPRModelReader.h"
#include "vtkNPRPass.h"
#include "vtkNPRReferenceMask.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataNormals.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
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
#include <numeric>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace
{
using Point = std::array<double, 3>;
using Edge = std::pair<Point, Point>; // ends in lexicographic order

constexpr int AllTypes = vtkNPRFeatureLines::SILHOUETTE | vtkNPRFeatureLines::CREASE |
  vtkNPRFeatureLines::BOUNDARY | vtkNPRFeatureLines::NON_MANIFOLD;

Edge MakeEdge(Point a, Point b)
{
  return a < b ? Edge{ a, b } : Edge{ b, a };
}

std::string Describe(const Edge& edge)
{
  std::string text;
  for (const Point& p : { edge.first, edge.second })
  {
    text +=
      "(" + std::to_string(p[0]) + "," + std::to_string(p[1]) + "," + std::to_string(p[2]) + ")";
  }
  return text;
}

// The output lines of the filter: each edge with its FeatureType bits.
std::map<Edge, int> Lines(vtkNPRFeatureLines* filter)
{
  vtkPolyData* output = filter->GetOutput();
  auto* types = vtkUnsignedCharArray::SafeDownCast(output->GetCellData()->GetArray("FeatureType"));
  std::map<Edge, int> lines;
  auto iterator = vtk::TakeSmartPointer(output->GetLines()->NewIterator());
  vtkIdType cell = 0;
  for (iterator->GoToFirstCell(); !iterator->IsDoneWithTraversal();
       iterator->GoToNextCell(), ++cell)
  {
    vtkIdType size;
    const vtkIdType* ids;
    iterator->GetCurrentCell(size, ids);
    NPR_CHECK(size == 2, "a line of " << size << " points");
    Point a, b;
    output->GetPoint(ids[0], a.data());
    output->GetPoint(ids[1], b.data());
    const Edge edge = MakeEdge(a, b);
    NPR_CHECK(!lines.count(edge), "edge output twice: " << Describe(edge));
    lines[edge] = types ? types->GetValue(cell) : -1;
  }
  return lines;
}

std::set<Edge> EdgesOf(const std::map<Edge, int>& lines, int type)
{
  std::set<Edge> edges;
  for (const auto& line : lines)
  {
    if (line.second & type)
    {
      edges.insert(line.first);
    }
  }
  return edges;
}

// Output cells whose FeatureType is exactly `type` (edges with equal coordinates counted apart).
long long CountCells(vtkNPRFeatureLines* filter, int type)
{
  auto* types =
    vtkUnsignedCharArray::SafeDownCast(filter->GetOutput()->GetCellData()->GetArray("FeatureType"));
  long long count = 0;
  for (vtkIdType i = 0; types && i < types->GetNumberOfTuples(); ++i)
  {
    count += types->GetValue(i) == type ? 1 : 0;
  }
  return count;
}

vtkSmartPointer<vtkNPRFeatureLines> MakeFilter(int types)
{
  auto filter = vtkSmartPointer<vtkNPRFeatureLines>::New();
  filter->SetSilhouettes((types & vtkNPRFeatureLines::SILHOUETTE) != 0);
  filter->SetCreases((types & vtkNPRFeatureLines::CREASE) != 0);
  filter->SetBoundaries((types & vtkNPRFeatureLines::BOUNDARY) != 0);
  filter->SetNonManifoldEdges((types & vtkNPRFeatureLines::NON_MANIFOLD) != 0);
  return filter;
}

// ---- An axis-aligned box of half size h about the origin, analytically ----
// Corner c (bits 0..2: +x, +y, +z); face (axis, positive) has the outward normal +-e_axis.
Point Corner(int c, double h = 0.5)
{
  return { (c & 1) ? h : -h, (c & 2) ? h : -h, (c & 4) ? h : -h };
}

struct BoxEdge
{
  Edge Ends;
  int Faces[2][2]; // (axis, positive) of its two faces
};

std::vector<BoxEdge> BoxEdges(double h = 0.5)
{
  std::vector<BoxEdge> edges;
  for (int a = 0; a < 8; ++a)
  {
    for (int axis = 0; axis < 3; ++axis)
    {
      if (a & (1 << axis))
      {
        continue;
      }
      BoxEdge edge;
      edge.Ends = MakeEdge(Corner(a, h), Corner(a | (1 << axis), h));
      int k = 0;
      for (int other = 0; other < 3; ++other)
      {
        if (other != axis)
        {
          edge.Faces[k][0] = other;
          edge.Faces[k][1] = (a >> other) & 1;
          ++k;
        }
      }
      edges.push_back(edge);
    }
  }
  return edges;
}

// Whether a face of the box faces the viewer: the eye strictly on its outer side (perspective),
// or the direction of projection strictly against its normal (parallel).
bool BoxFaceFront(int axis, int positive, bool parallel, const double view[3], double h = 0.5)
{
  const double sign = positive ? 1.0 : -1.0;
  return parallel ? sign * view[axis] < 0.0 : sign * view[axis] > h;
}

std::set<Edge> BoxSilhouettes(bool parallel, const double view[3])
{
  std::set<Edge> edges;
  for (const BoxEdge& edge : BoxEdges())
  {
    if (BoxFaceFront(edge.Faces[0][0], edge.Faces[0][1], parallel, view) !=
      BoxFaceFront(edge.Faces[1][0], edge.Faces[1][1], parallel, view))
    {
      edges.insert(edge.Ends);
    }
  }
  return edges;
}

std::set<Edge> AllBoxEdges()
{
  std::set<Edge> edges;
  for (const BoxEdge& edge : BoxEdges())
  {
    edges.insert(edge.Ends);
  }
  return edges;
}

// A box of 8 shared points and 6 outward quads; `skip` leaves a face out, `flip` reverses one.
vtkSmartPointer<vtkPolyData> MakeBox(int skip = -1, int flip = -1)
{
  auto box = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  for (int c = 0; c < 8; ++c)
  {
    points->InsertNextPoint(Corner(c).data());
  }
  vtkNew<vtkCellArray> quads;
  for (int face = 0; face < 6; ++face)
  {
    const int axis = face / 2, positive = face % 2;
    const int j = (axis + 1) % 3, k = (axis + 2) % 3; // e_j x e_k = e_axis
    const int base = positive << axis;
    vtkIdType ids[4] = { base, base | (1 << j), base | (1 << j) | (1 << k), base | (1 << k) };
    if (!positive)
    {
      std::reverse(ids, ids + 4);
    }
    if (face == flip)
    {
      std::reverse(ids, ids + 4);
    }
    if (face != skip)
    {
      quads->InsertNextCell(4, ids);
    }
  }
  box->SetPoints(points);
  box->SetPolys(quads);
  return box;
}

vtkSmartPointer<vtkPolyData> Triangulated(vtkPolyData* input)
{
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputData(input);
  triangles->Update();
  return triangles->GetOutput();
}

vtkSmartPointer<vtkPolyData> CubeSource(double size = 1.0)
{
  vtkNew<vtkCubeSource> cube;
  cube->SetXLength(size);
  cube->SetYLength(size);
  cube->SetZLength(size);
  cube->Update();
  return cube->GetOutput();
}

void CheckEdges(const std::set<Edge>& got, const std::set<Edge>& expected, const std::string& what)
{
  NPR_CHECK(got == expected, what << ": " << got.size() << " edges, expected " << expected.size());
  for (const Edge& edge : got)
  {
    NPR_CHECK(expected.count(edge), what << ": unexpected " << Describe(edge));
  }
  for (const Edge& edge : expected)
  {
    NPR_CHECK(got.count(edge), what << ": missing " << Describe(edge));
  }
}

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
    auto ids = [](vtkNPRFeatureLines* filter) {
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

// ---- Degenerate input ----
int Degenerate()
{
  const std::set<Edge> twelve = AllBoxEdges();
  const double eye[3] = { 2.2, 1.7, 2.9 };
  const double direction[3] = { -1.0, -0.8, -1.3 };

  // Zero-area triangles: repeated points, one point three times, collinear points; a two-point
  // and a one-point polygon.
  {
    vtkSmartPointer<vtkPolyData> box = Triangulated(MakeBox());
    vtkNew<vtkPolyData> mesh;
    mesh->DeepCopy(box);
    const vtkIdType middle = mesh->GetPoints()->InsertNextPoint(0.0, -0.5, -0.5); // on edge 0-1
    const vtkIdType degenerate[][3] = { { 0, 0, 1 }, { 0, 1, 0 }, { 2, 2, 2 }, { 0, middle, 1 } };
    for (const auto& triangle : degenerate)
    {
      mesh->GetPolys()->InsertNextCell(3, triangle);
    }
    const vtkIdType two[2] = { 3, 5 }, one[1] = { 6 };
    mesh->GetPolys()->InsertNextCell(2, two);
    mesh->GetPolys()->InsertNextCell(1, one);
    auto filter = MakeFilter(AllTypes);
    filter->SetInputData(mesh);
    filter->SetEyePosition(eye[0], eye[1], eye[2]);
    filter->Update();
    const auto lines = Lines(filter);
    CheckEdges(EdgesOf(lines, vtkNPRFeatureLines::CREASE), twelve, "creases with zero-area faces");
    CheckEdges(EdgesOf(lines, vtkNPRFeatureLines::SILHOUETTE), BoxSilhouettes(false, eye),
      "silhouettes with zero-area faces");
    NPR_CHECK(
      EdgesOf(lines, vtkNPRFeatureLines::BOUNDARY | vtkNPRFeatureLines::NON_MANIFOLD).empty(),
      "zero-area faces made boundary or non-manifold edges");
    NPR_CHECK(filter->GetNumberOfDegenerateFaces() == 6,
      "degenerate faces counted: " << filter->GetNumberOfDegenerateFaces());
  }

  // Points split by vtkPolyDataNormals along the sharp edges: still 12 creases, no boundary.
  {
    vtkNew<vtkCleanPolyData> clean; // vtkCubeSource's 24 points -> 8
    clean->SetInputData(CubeSource());
    vtkNew<vtkPolyDataNormals> normals;
    normals->SetInputConnection(clean->GetOutputPort());
    normals->SetFeatureAngle(30.0);
    normals->SplittingOn();
    normals->Update();
    NPR_CHECK(clean->GetOutput()->GetNumberOfPoints() == 8 &&
        normals->GetOutput()->GetNumberOfPoints() == 24,
      "the split cube has " << normals->GetOutput()->GetNumberOfPoints() << " points");
    auto filter = MakeFilter(AllTypes);
    filter->SetInputConnection(normals->GetOutputPort());
    filter->SetEyePosition(eye[0], eye[1], eye[2]);
    filter->Update();
    const auto lines = Lines(filter);
    CheckEdges(EdgesOf(lines, AllTypes), twelve, "split cube");
    CheckEdges(EdgesOf(lines, vtkNPRFeatureLines::CREASE), twelve, "split cube creases");
    NPR_CHECK(EdgesOf(lines, vtkNPRFeatureLines::BOUNDARY).empty(), "split cube boundaries");
    // Unmerged, each sharp edge is two boundary edges (one per side's copy of its points).
    filter->MergeCoincidentPointsOff();
    filter->Update();
    NPR_CHECK(CountCells(filter, vtkNPRFeatureLines::BOUNDARY) == 24 &&
        filter->GetOutput()->GetNumberOfCells() == 24,
      "without merging, the split edges should be boundaries");
  }

  // One face wound the other way: the same creases and silhouettes.
  for (bool parallel : { false, true })
  {
    for (int flip = 0; flip < 6; ++flip)
    {
      for (bool triangulate : { false, true })
      {
        vtkSmartPointer<vtkPolyData> mesh = MakeBox(-1, flip);
        if (triangulate)
        {
          mesh = Triangulated(mesh);
        }
        auto filter = MakeFilter(AllTypes);
        filter->SetInputData(mesh);
        filter->SetParallelProjection(parallel);
        filter->SetEyePosition(eye[0], eye[1], eye[2]);
        filter->SetDirectionOfProjection(direction[0], direction[1], direction[2]);
        filter->Update();
        const auto lines = Lines(filter);
        const std::string name = "face " + std::to_string(flip) + " flipped" +
          (triangulate ? ", triangles" : "") + (parallel ? ", parallel" : "");
        CheckEdges(EdgesOf(lines, vtkNPRFeatureLines::CREASE), twelve, name + ": creases");
        CheckEdges(EdgesOf(lines, vtkNPRFeatureLines::SILHOUETTE),
          BoxSilhouettes(parallel, parallel ? direction : eye), name + ": silhouettes");
        NPR_CHECK(lines.size() == 12, name << ": " << lines.size() << " lines");
      }
    }
  }

  // NaN and infinite coordinates: their faces are skipped, with one warning per build.
  {
    vtkNew<vtkPolyData> mesh;
    mesh->DeepCopy(Triangulated(MakeBox()));
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const vtkIdType bad = mesh->GetPoints()->InsertNextPoint(nan, 0.0, 0.0);
    const vtkIdType far =
      mesh->GetPoints()->InsertNextPoint(0.0, std::numeric_limits<double>::infinity(), 0.0);
    const vtkIdType onEdge[3] = { 0, 1, bad }, other[3] = { far, 2, 3 };
    mesh->GetPolys()->InsertNextCell(3, onEdge);
    mesh->GetPolys()->InsertNextCell(3, other);
    auto* messages = nprCountingOutputWindow::SafeDownCast(vtkOutputWindow::GetInstance());
    const int warnings = messages ? messages->Warnings : 0;
    std::cout << "expected: one VTK warning about 2 faces with NaN or infinite coordinates\n";
    auto filter = MakeFilter(AllTypes);
    filter->SetInputData(mesh);
    filter->SetEyePosition(eye[0], eye[1], eye[2]);
    filter->Update();
    NPR_CHECK(messages && messages->Warnings == warnings + 1,
      "one warning expected, got " << (messages ? messages->Warnings - warnings : -1));
    NPR_CHECK(filter->GetNumberOfNonFiniteFaces() == 2,
      "non-finite faces counted: " << filter->GetNumberOfNonFiniteFaces());
    const auto lines = Lines(filter);
    CheckEdges(EdgesOf(lines, AllTypes), twelve, "cube with NaN faces");
    CheckEdges(EdgesOf(lines, vtkNPRFeatureLines::CREASE), twelve, "creases with NaN faces");
    filter->SetEyePosition(-2, 1, 3);
    filter->Update();
    NPR_CHECK(messages && messages->Warnings == warnings + 1, "warned again without a rebuild");
  }

  // Empty input, and points without faces: empty output, no error.
  {
    vtkNew<vtkPolyData> empty;
    auto filter = MakeFilter(AllTypes);
    filter->SetInputData(empty);
    filter->Update();
    NPR_CHECK(
      filter->GetOutput()->GetNumberOfCells() == 0 && filter->GetOutput()->GetNumberOfPoints() == 0,
      "empty input gave lines");
    vtkNew<vtkPolyData> cloud;
    vtkNew<vtkPoints> points;
    points->InsertNextPoint(0, 0, 0);
    points->InsertNextPoint(1, 0, 0);
    cloud->SetPoints(points);
    filter->SetInputData(cloud);
    filter->Update();
    NPR_CHECK(filter->GetOutput()->GetNumberOfCells() == 0, "points without faces gave lines");
  }
  return nprTestResult();
}

// ---- The reference mask ----
double SegmentDistance(const double p[2], const double a[2], const double b[2])
{
  const double abx = b[0] - a[0], aby = b[1] - a[1];
  const double length2 = abx * abx + aby * aby;
  double t = length2 > 0 ? ((p[0] - a[0]) * abx + (p[1] - a[1]) * aby) / length2 : 0.0;
  t = std::min(1.0, std::max(0.0, t));
  return std::hypot(p[0] - (a[0] + t * abx), p[1] - (a[1] + t * aby));
}

struct MaskScene
{
  vtkSmartPointer<vtkRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkNPRReferenceMask> Reference;
  int Width, Height;

  MaskScene(int width, int height)
    : Width(width)
    , Height(height)
  {
    this->Window = nprCreateTestWindow(width, height, nullptr);
    this->Window->AddRenderer(this->Renderer);
    this->Reference->SetRenderer(this->Renderer);
  }
  vtkCamera* Camera() { return this->Renderer->GetActiveCamera(); }
  vtkImageData* Mask()
  {
    NPR_CHECK(this->Reference->Update(), "the reference mask failed");
    return this->Reference->GetMask();
  }
  // Window coordinates of a world point through the renderer (not the mask's code).
  std::array<double, 2> Project(const Point& world)
  {
    this->Renderer->SetWorldPoint(world[0], world[1], world[2], 1.0);
    this->Renderer->WorldToDisplay();
    const double* display = this->Renderer->GetDisplayPoint();
    return { display[0], display[1] };
  }
};

vtkSmartPointer<vtkActor> AddCube(vtkRenderer* renderer, const double center[3], double size)
{
  vtkNew<vtkCubeSource> cube;
  cube->SetCenter(center[0], center[1], center[2]);
  cube->SetXLength(size);
  cube->SetYLength(size);
  cube->SetZLength(size);
  return nprAddActor(renderer, cube->GetOutputPort());
}

long long CountSet(vtkImageData* mask)
{
  const int* dims = mask->GetDimensions();
  long long count = 0;
  for (int y = 0; y < dims[1]; ++y)
  {
    for (int x = 0; x < dims[0]; ++x)
    {
      count += nprPixel(mask, x, y) ? 1 : 0;
    }
  }
  return count;
}

// A unit cube from a known camera: the mask against the analytic visible edges.
int MaskCube(bool parallel)
{
  MaskScene scene(400, 300);
  const double origin[3] = { 0, 0, 0 };
  AddCube(scene.Renderer, origin, 1.0);
  const double eye[3] = { 2.2, 1.7, 2.9 };
  vtkCamera* camera = scene.Camera();
  camera->SetPosition(eye[0], eye[1], eye[2]);
  camera->SetFocalPoint(0, 0, 0);
  camera->SetViewUp(0, 1, 0);
  camera->SetViewAngle(30);
  camera->SetParallelProjection(parallel);
  camera->SetParallelScale(1.0);
  camera->SetClippingRange(1.0, 10.0);
  vtkImageData* mask = scene.Mask();
  NPR_CHECK(mask->GetDimensions()[0] == 400 && mask->GetDimensions()[1] == 300 &&
      mask->GetNumberOfScalarComponents() == 1 && mask->GetScalarType() == VTK_UNSIGNED_CHAR,
    "the mask is not 400x300 unsigned char");

  // Visible edges of a convex box: at least one face towards the viewer.
  double toward[3];
  for (int i = 0; i < 3; ++i)
  {
    toward[i] = -eye[i]; // direction of projection (focal point at the origin)
  }
  std::vector<std::array<double, 4>> visible, hidden;
  for (const BoxEdge& edge : BoxEdges())
  {
    const bool seen =
      BoxFaceFront(edge.Faces[0][0], edge.Faces[0][1], parallel, parallel ? toward : eye) ||
      BoxFaceFront(edge.Faces[1][0], edge.Faces[1][1], parallel, parallel ? toward : eye);
    const auto a = scene.Project(edge.Ends.first), b = scene.Project(edge.Ends.second);
    (seen ? visible : hidden).push_back({ a[0], a[1], b[0], b[1] });
  }
  NPR_CHECK(visible.size() == 9 && hidden.size() == 3, "a cube seen from a corner shows 9 edges");
  auto nearest = [](const std::vector<std::array<double, 4>>& edges, const double p[2]) {
    double best = 1e300;
    for (const auto& e : edges)
    {
      best = std::min(best, SegmentDistance(p, &e[0], &e[2]));
    }
    return best;
  };

  // Precision: every mask pixel's centre lies within half a pixel diagonal of a visible edge.
  double worst = 0.0;
  long long pixels = 0, onHidden = 0;
  for (int y = 0; y < scene.Height; ++y)
  {
    for (int x = 0; x < scene.Width; ++x)
    {
      const double p[2] = { x + 0.5, y + 0.5 };
      const int value = nprPixel(mask, x, y);
      NPR_CHECK(value == 0 || value == 255, "mask value " << value);
      if (value)
      {
        ++pixels;
        worst = std::max(worst, nearest(visible, p));
      }
      if (value && nearest(hidden, p) <= 0.5 && nearest(visible, p) > 1.5)
      {
        ++onHidden;
      }
    }
  }
  // Recall: along every visible edge, a mask pixel in the 3x3 pixels around each point.
  long long samples = 0, found = 0;
  for (const auto& e : visible)
  {
    const double length = std::hypot(e[2] - e[0], e[3] - e[1]);
    const int steps = static_cast<int>(length / 0.1);
    for (int s = 0; s <= steps; ++s)
    {
      const double px = e[0] + (e[2] - e[0]) * s / steps, py = e[1] + (e[3] - e[1]) * s / steps;
      const int x = static_cast<int>(std::floor(px)), y = static_cast<int>(std::floor(py));
      if (x < 2 || y < 2 || x >= scene.Width - 2 || y >= scene.Height - 2)
      {
        continue;
      }
      bool hit = false;
      for (int oy = -1; oy <= 1 && !hit; ++oy)
      {
        for (int ox = -1; ox <= 1 && !hit; ++ox)
        {
          hit = nprPixel(mask, x + ox, y + oy) != 0;
        }
      }
      ++samples;
      found += hit ? 1 : 0;
    }
  }
  vtkNPRReferenceMask* reference = scene.Reference;
  std::cout << (parallel ? "parallel" : "perspective") << ": " << pixels
            << " mask pixels, farthest centre " << worst << " px from a visible edge, " << onHidden
            << " on hidden edges, " << found << "/" << samples << " edge points found; "
            << reference->GetNumberOfFeatureEdges() << " edges, " << reference->GetNumberOfSamples()
            << " samples, " << reference->GetNumberOfRayCasts() << " rays, "
            << reference->GetNumberOfVisibleSamples() << " visible\n";
  NPR_CHECK(pixels > 900, "too few mask pixels: " << pixels);
  NPR_CHECK(pixels == reference->GetNumberOfLinePixels(), "GetNumberOfLinePixels is wrong");
  NPR_CHECK(worst <= std::sqrt(0.5) + 1e-6, "a mask pixel lies " << worst << " px from the edges");
  NPR_CHECK(onHidden == 0, onHidden << " mask pixels on hidden edges");
  NPR_CHECK(found == samples,
    "visible edges missed at " << samples - found << " of " << samples << " points");
  NPR_CHECK(reference->GetNumberOfFeatureEdges() == 12, "the cube's 12 edges are feature lines");

  // The visible lines: the same mask with them on, and every visible point in a mask pixel.
  std::vector<unsigned char> first(static_cast<unsigned char*>(mask->GetScalarPointer()),
    static_cast<unsigned char*>(mask->GetScalarPointer()) + scene.Width * scene.Height);
  reference->GenerateVisibleLinesOn();
  mask = scene.Mask();
  const std::vector<unsigned char> second(static_cast<unsigned char*>(mask->GetScalarPointer()),
    static_cast<unsigned char*>(mask->GetScalarPointer()) + scene.Width * scene.Height);
  NPR_CHECK(first == second, "the mask changed with GenerateVisibleLines");
  vtkPolyData* lines = reference->GetVisibleLines();
  NPR_CHECK(lines->GetNumberOfCells() >= 9 && lines->GetCellData()->GetArray("FeatureType"),
    "visible lines: " << lines->GetNumberOfCells() << " polylines");
  NPR_CHECK(reference->GetNumberOfRayCasts() == reference->GetNumberOfSamples(),
    "with visible lines every sample needs a ray");
  long long outside = 0;
  for (vtkIdType i = 0; i < lines->GetNumberOfPoints(); ++i)
  {
    Point p;
    lines->GetPoint(i, p.data());
    const auto d = scene.Project(p);
    outside +=
      nprPixel(mask, static_cast<int>(std::floor(d[0])), static_cast<int>(std::floor(d[1]))) ? 0
                                                                                             : 1;
  }
  NPR_CHECK(outside <= 2, outside << " visible-line points outside the mask's pixels");
  return nprTestResult();
}

// Andrew's monotone chain: the convex hull of 2D points, counter-clockwise.
std::vector<std::array<double, 2>> ConvexHull(std::vector<std::array<double, 2>> points)
{
  std::sort(points.begin(), points.end());
  std::vector<std::array<double, 2>> hull(2 * points.size());
  size_t k = 0;
  auto cross = [](const std::array<double, 2>& o, const std::array<double, 2>& a,
                 const std::array<double, 2>& b) {
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
  };
  for (size_t i = 0; i < points.size(); ++i)
  {
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], points[i]) <= 0)
    {
      --k;
    }
    hull[k++] = points[i];
  }
  for (size_t i = points.size() - 1, t = k + 1; i > 0; --i)
  {
    while (k >= t && cross(hull[k - 2], hull[k - 1], points[i - 1]) <= 0)
    {
      --k;
    }
    hull[k++] = points[i - 1];
  }
  hull.resize(k - 1);
  return hull;
}

// ---- A small cube behind a big one: hidden entirely, then in part ----
int MaskOcclusion()
{
  MaskScene scene(400, 300);
  const double origin[3] = { 0, 0, 0 };
  vtkSmartPointer<vtkActor> big = AddCube(scene.Renderer, origin, 2.0);
  vtkCamera* camera = scene.Camera();
  camera->SetPosition(0.5, 0.4, 8.0);
  camera->SetFocalPoint(0, 0, 0);
  camera->SetViewUp(0, 1, 0);
  camera->SetClippingRange(1.0, 20.0);
  auto copy = [&](vtkImageData* mask) {
    const unsigned char* p = static_cast<unsigned char*>(mask->GetScalarPointer());
    return std::vector<unsigned char>(p, p + scene.Width * scene.Height);
  };
  const std::vector<unsigned char> bigOnly = copy(scene.Mask());

  const double behind[3] = { 0, 0, -3 };
  vtkSmartPointer<vtkActor> small = AddCube(scene.Renderer, behind, 0.5);
  const std::vector<unsigned char> both = copy(scene.Mask());
  big->VisibilityOff();
  const std::vector<unsigned char> smallOnly = copy(scene.Mask());
  big->VisibilityOn();
  long long smallPixels = 0;
  for (unsigned char v : smallOnly)
  {
    smallPixels += v ? 1 : 0;
  }
  std::cout << "small cube alone: " << smallPixels
            << " pixels; behind the big one: " << (both == bigOnly ? "hidden" : "visible in part")
            << "\n";
  NPR_CHECK(smallPixels > 100, "the small cube alone has no lines");
  NPR_CHECK(both == bigOnly, "the hidden cube changed the mask");

  // Moved half out from behind: new pixels appear, none inside the big cube's outline.
  small->SetPosition(1.45, 0.0, 0.0);
  const std::vector<unsigned char> partly = copy(scene.Mask());
  std::vector<std::array<double, 2>> corners;
  for (int c = 0; c < 8; ++c)
  {
    corners.push_back(scene.Project(Corner(c, 1.0)));
  }
  const auto hull = ConvexHull(corners);
  long long added = 0, inside = 0;
  for (int y = 0; y < scene.Height; ++y)
  {
    for (int x = 0; x < scene.Width; ++x)
    {
      const size_t i = static_cast<size_t>(y) * scene.Width + x;
      if (!partly[i] || bigOnly[i])
      {
        NPR_CHECK(partly[i] || !bigOnly[i], "the big cube's line pixel lost at " << x << "," << y);
        continue;
      }
      ++added;
      // Inside the hull by more than a pixel: hidden by the big cube.
      double depth = 1e300;
      for (size_t k = 0; k < hull.size(); ++k)
      {
        const auto& a = hull[k];
        const auto& b = hull[(k + 1) % hull.size()];
        const double length = std::hypot(b[0] - a[0], b[1] - a[1]);
        depth = std::min(
          depth, ((b[0] - a[0]) * (y + 0.5 - a[1]) - (b[1] - a[1]) * (x + 0.5 - a[0])) / length);
      }
      inside += depth > 1.0 ? 1 : 0;
    }
  }
  std::cout << "small cube half out: " << added << " new pixels, " << inside
            << " inside the big cube's outline\n";
  NPR_CHECK(added > 50, "the part of the small cube out from behind has no lines");
  NPR_CHECK(inside == 0, inside << " pixels of the hidden part in the mask");
  return nprTestResult();
}

// ---- What the mask reuses between updates ----
int MaskReuse()
{
  MaskScene scene(200, 150);
  vtkNew<vtkCubeSource> cube;
  vtkSmartPointer<vtkActor> actor = nprAddActor(scene.Renderer, cube->GetOutputPort());
  vtkCamera* camera = scene.Camera();
  camera->SetPosition(2.2, 1.7, 2.9);
  camera->SetFocalPoint(0, 0, 0);
  camera->SetClippingRange(1.0, 10.0);
  vtkNPRReferenceMask* reference = scene.Reference;
  const long long first = CountSet(scene.Mask());
  camera->Azimuth(20);
  const long long turned = CountSet(scene.Mask());
  NPR_CHECK(
    reference->GetNumberOfAdjacencyBuilds() == 1 && reference->GetNumberOfLocatorBuilds() == 1,
    "a camera move rebuilt: adjacency " << reference->GetNumberOfAdjacencyBuilds() << ", locator "
                                        << reference->GetNumberOfLocatorBuilds());
  NPR_CHECK(first > 100 && turned > 100, "no lines");
  actor->SetPosition(0.2, 0, 0);
  scene.Mask();
  NPR_CHECK(
    reference->GetNumberOfAdjacencyBuilds() == 1 && reference->GetNumberOfLocatorBuilds() == 2,
    "an actor move: adjacency " << reference->GetNumberOfAdjacencyBuilds() << ", locator "
                                << reference->GetNumberOfLocatorBuilds());
  cube->SetXLength(1.5);
  scene.Mask();
  NPR_CHECK(
    reference->GetNumberOfAdjacencyBuilds() == 2 && reference->GetNumberOfLocatorBuilds() == 3,
    "a new mesh: adjacency " << reference->GetNumberOfAdjacencyBuilds() << ", locator "
                             << reference->GetNumberOfLocatorBuilds());
  // Translucent actors neither draw lines nor hide them; the explicit size wins.
  actor->GetProperty()->SetOpacity(0.5);
  NPR_CHECK(CountSet(scene.Mask()) == 0, "a translucent actor has lines");
  actor->GetProperty()->SetOpacity(1.0);
  reference->SetSize(64, 48);
  NPR_CHECK(scene.Mask()->GetDimensions()[0] == 64 && CountSet(reference->GetMask()) > 20,
    "an explicit size");
  reference->CreasesOff();
  reference->SilhouettesOff();
  NPR_CHECK(CountSet(scene.Mask()) == 0, "no line types, still lines");
  return nprTestResult();
}

// ---- Far from the origin and at any scale: the same lines and the same mask ----
int Stability()
{
  // The filter on a double-precision box moved 1e7 away, the eye moved with it.
  const double eye[3] = { 2.2, 1.7, 2.9 };
  std::set<std::pair<vtkIdType, vtkIdType>> reference;
  for (double offset : { 0.0, 1e7 })
  {
    vtkSmartPointer<vtkPolyData> box = Triangulated(MakeBox());
    vtkNew<vtkPoints> moved;
    moved->SetDataTypeToDouble();
    for (vtkIdType i = 0; i < box->GetNumberOfPoints(); ++i)
    {
      double p[3];
      box->GetPoint(i, p);
      moved->InsertNextPoint(p[0] + offset, p[1] - offset, p[2] + offset);
    }
    box->SetPoints(moved);
    auto filter = MakeFilter(AllTypes);
    filter->SetInputData(box);
    filter->SetEyePosition(eye[0] + offset, eye[1] - offset, eye[2] + offset);
    filter->Update();
    std::set<std::pair<vtkIdType, vtkIdType>> lines;
    auto* ids = vtkIdTypeArray::SafeDownCast(
      filter->GetOutput()->GetCellData()->GetArray("InputPointIds"));
    auto* types = vtkUnsignedCharArray::SafeDownCast(
      filter->GetOutput()->GetCellData()->GetArray("FeatureType"));
    for (vtkIdType i = 0; ids && types && i < ids->GetNumberOfTuples(); ++i)
    {
      lines.insert({ ids->GetTypedComponent(i, 0) * 16 + types->GetValue(i),
        ids->GetTypedComponent(i, 1) });
    }
    if (offset == 0.0)
    {
      reference = lines;
    }
    NPR_CHECK(lines == reference && lines.size() == 12,
      "offset " << offset << ": " << lines.size() << " lines, not those at the origin");
  }

  // The mask of a cube moved by an actor position and scaled, the camera with it.
  std::vector<unsigned char> first;
  const double cases[][2] = { { 0.0, 1.0 }, { 1e5, 1.0 }, { 1e7, 1.0 }, { 0.0, 1e-6 },
    { 0.0, 1e6 }, { 1e7, 1e3 } };
  for (const auto& c : cases)
  {
    const double offset = c[0], scale = c[1];
    MaskScene scene(400, 300);
    const double origin[3] = { 0, 0, 0 };
    vtkSmartPointer<vtkActor> cube = AddCube(scene.Renderer, origin, scale);
    cube->SetPosition(offset, offset, offset);
    vtkCamera* camera = scene.Camera();
    camera->SetPosition(offset + 2.2 * scale, offset + 1.7 * scale, offset + 2.9 * scale);
    camera->SetFocalPoint(offset, offset, offset);
    camera->SetViewUp(0, 1, 0);
    camera->SetClippingRange(scale, 10 * scale);
    vtkImageData* mask = scene.Mask();
    const unsigned char* p = static_cast<unsigned char*>(mask->GetScalarPointer());
    const std::vector<unsigned char> pixels(p, p + scene.Width * scene.Height);
    if (first.empty())
    {
      first = pixels;
    }
    const long long differ = std::inner_product(pixels.begin(), pixels.end(), first.begin(), 0LL,
      std::plus<long long>(), [](unsigned char a, unsigned char b) { return a != b ? 1LL : 0LL; });
    std::cout << "offset " << offset << ", scale " << scale << ": "
              << scene.Reference->GetNumberOfLinePixels() << " pixels, " << differ
              << " differ from the unit cube at the origin\n";
    NPR_CHECK(differ == 0 && scene.Reference->GetNumberOfLinePixels() > 900,
      "offset " << offset << ", scale " << scale << ": " << differ << " pixels differ");
  }
  return nprTestResult();
}

// ---- The groups of triangles the occlusion structure is split into change nothing ----
int MaskLocatorGroups()
{
  MaskScene scene(640, 480);
  vtkNew<vtkNPRModelReader> reader;
  reader->SetFileName((nprTestDataDir() + "/bunny.ply").c_str());
  nprAddActor(scene.Renderer, reader->GetOutputPort());
  scene.Renderer->ResetCamera();
  scene.Camera()->Azimuth(30);
  scene.Camera()->Elevation(20);
  scene.Camera()->OrthogonalizeViewUp();
  scene.Renderer->ResetCameraClippingRange();
  vtkNPRReferenceMask* reference = scene.Reference;
  reference->GenerateVisibleLinesOn(); // every sample's visibility counts, not only the pixels'
  std::vector<unsigned char> first;
  vtkIdType visible = -1;
  for (int group : { VTK_INT_MAX, 16384, 1000, 7 })
  {
    reference->SetTrianglesPerLocator(group);
    vtkImageData* mask = scene.Mask();
    const unsigned char* p = static_cast<unsigned char*>(mask->GetScalarPointer());
    const std::vector<unsigned char> pixels(p, p + scene.Width * scene.Height);
    std::cout << "groups of " << group << " triangles: " << reference->GetNumberOfVisibleSamples()
              << " of " << reference->GetNumberOfRayCasts() << " samples visible, "
              << reference->GetNumberOfLinePixels() << " pixels, visibility "
              << reference->GetVisibilityTime() << " s\n";
    if (first.empty())
    {
      first = pixels;
      visible = reference->GetNumberOfVisibleSamples();
      NPR_CHECK(reference->GetNumberOfLinePixels() > 1000, "too few line pixels on the bunny");
    }
    NPR_CHECK(pixels == first && reference->GetNumberOfVisibleSamples() == visible,
      "groups of " << group << " triangles changed the result");
  }
  NPR_CHECK(
    reference->GetNumberOfLocatorBuilds() == 4 && reference->GetNumberOfAdjacencyBuilds() == 1,
    "builds: locator " << reference->GetNumberOfLocatorBuilds() << ", adjacency "
                       << reference->GetNumberOfAdjacencyBuilds());
  return nprTestResult();
}

// ---- The mask against vtkNPREdgePass's lines of the same camera: they line up ----
int MaskAgainstEdgePass(const char* model)
{
  MaskScene scene(400, 300);
  vtkNew<vtkNPRPass> pass;
  scene.Renderer->SetPass(pass);
  vtkNPREdgePass* edges = pass->GetEdgePass();
  edges->SetLineWidth(1.0);
  edges->AntiAliasingOff();
  edges->CoverageOnlyOn();
  vtkNew<vtkNPRModelReader> reader;
  vtkNew<vtkPolyDataNormals> normals;
  if (model)
  {
    reader->SetFileName((nprTestDataDir() + "/" + model).c_str());
    normals->SetInputConnection(reader->GetOutputPort());
    normals->SetFeatureAngle(30.0);
    normals->SplittingOn();
    nprAddActor(scene.Renderer, normals->GetOutputPort());
    scene.Renderer->ResetCamera();
    scene.Camera()->Azimuth(30);
    scene.Camera()->Elevation(20);
    scene.Camera()->OrthogonalizeViewUp();
    scene.Renderer->ResetCameraClippingRange();
  }
  else
  {
    const double origin[3] = { 0, 0, 0 };
    AddCube(scene.Renderer, origin, 1.0);
    scene.Camera()->SetPosition(2.2, 1.7, 2.9);
    scene.Camera()->SetFocalPoint(0, 0, 0);
    scene.Camera()->SetClippingRange(1.0, 10.0);
  }
  scene.Window->Render();
  vtkSmartPointer<vtkImageData> rendered = nprCaptureImage(scene.Window);
  vtkImageData* reference = scene.Mask();
  auto near = [](vtkImageData* image, int x, int y, int radius, int threshold) {
    for (int oy = -radius; oy <= radius; ++oy)
    {
      for (int ox = -radius; ox <= radius; ++ox)
      {
        if (nprPixel(image, x + ox, y + oy) > threshold)
        {
          return true;
        }
      }
    }
    return false;
  };
  long long truth = 0, truthFound = 0, drawn = 0, drawnTrue = 0;
  for (int y = 2; y < scene.Height - 2; ++y)
  {
    for (int x = 2; x < scene.Width - 2; ++x)
    {
      if (nprPixel(reference, x, y))
      {
        ++truth;
        truthFound += near(rendered, x, y, 1, 127) ? 1 : 0;
      }
      if (nprPixel(rendered, x, y) > 127)
      {
        ++drawn;
        drawnTrue += near(reference, x, y, 1, 0) ? 1 : 0;
      }
    }
  }
  const double recall = truth ? double(truthFound) / truth : 0.0;
  const double precision = drawn ? double(drawnTrue) / drawn : 0.0;
  std::cout << (model ? model : "cube") << ": " << truth << " reference pixels, " << drawn
            << " edge-pass pixels; within 1 px: recall " << recall << ", precision " << precision
            << "\n";
  NPR_CHECK(truth > 500 && drawn > 500, "too few line pixels");
  NPR_CHECK(recall >= (model ? 0.95 : 0.97), "the edge pass misses the reference: " << recall);
  NPR_CHECK(
    precision >= (model ? 0.85 : 0.97), "the edge pass is off the reference: " << precision);
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
    { "degenerate", Degenerate },
    { "mask-cube", [] { return MaskCube(false); } },
    { "mask-cube-parallel", [] { return MaskCube(true); } },
    { "mask-occlusion", MaskOcclusion },
    { "mask-reuse", MaskReuse },
    { "mask-stability", Stability },
    { "mask-locator-groups", MaskLocatorGroups },
    { "mask-edge-pass-cube", [] { return MaskAgainstEdgePass(nullptr); } },
    { "mask-edge-pass-bunny", [] { return MaskAgainstEdgePass("bunny.ply"); } },
  };
  return nprRunTestCase(argc, argv, cases);
}
