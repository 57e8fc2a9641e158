// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// The faces a vector drawing fills (vtkNPRDrawingLines::UpdateFaces), part of the TestDrawingLines
// program: painted in their order, the faces give at every sample the triangle a ray meets first,
// among random triangles that pass through each other and a sphere through them (perspective and
// parallel), and on a closed torus over itself beside a sphere; a closed sphere loses its back
// faces, wound either way; colours; bad input.
//
// usage: TestDrawingLines CASE [DATA_DIR]   (CASE: the NPR_TEST_CASE names below)
#include "nprTestMeshes.h"
#include "nprTesting.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkMatrix4x4.h"
#include "vtkNPRDrawingLines.h"
#include "vtkNew.h"
#include "vtkOutputWindow.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkReverseSense.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

namespace
{
constexpr int Width = 240, Height = 180;
using Vec = std::array<double, 3>;
using Color = std::array<unsigned char, 3>;

Vec Sub(const Vec& a, const Vec& b)
{
  return { a[0] - b[0], a[1] - b[1], a[2] - b[2] };
}
Vec Cross(const Vec& a, const Vec& b)
{
  return { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] };
}
double Dot(const Vec& a, const Vec& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

// A triangle of the reference scene, with the colour that tells it apart.
struct Triangle
{
  Vec A, B, C;
  Color Id;
};

// The ray parameter where from + t d meets the triangle, well inside it (barycentric
// coordinates above `margin`); -1 where it does not.
double Hit(const Triangle& tri, const Vec& from, const Vec& d, double margin)
{
  const Vec e1 = Sub(tri.B, tri.A), e2 = Sub(tri.C, tri.A), p = Cross(d, e2);
  const double det = Dot(e1, p);
  if (std::abs(det) < 1e-14)
  {
    return -1.0;
  }
  const Vec s = Sub(from, tri.A), q = Cross(s, e1);
  const double u = Dot(s, p) / det, v = Dot(d, q) / det, t = Dot(e2, q) / det;
  return u > margin && v > margin && u + v < 1.0 - margin && t > 0.0 ? t : -1.0;
}

// An actor of the mesh coloured by the cell colours `ids` (direct RGB scalars).
vtkSmartPointer<vtkActor> AddCellColored(
  vtkRenderer* renderer, vtkPolyData* mesh, vtkUnsignedCharArray* ids)
{
  mesh->GetCellData()->SetScalars(ids);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(mesh);
  mapper->SetScalarModeToUseCellData();
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  renderer->AddActor(actor);
  return actor;
}

// A mesh of separate triangles, each cell coloured with its id (direct RGB scalars).
vtkSmartPointer<vtkActor> AddTriangles(vtkRenderer* renderer, const std::vector<Triangle>& tris)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkCellArray> cells;
  vtkNew<vtkUnsignedCharArray> ids;
  ids->SetNumberOfComponents(3);
  for (const Triangle& t : tris)
  {
    const vtkIdType cell[3] = { points->InsertNextPoint(t.A.data()),
      points->InsertNextPoint(t.B.data()), points->InsertNextPoint(t.C.data()) };
    cells->InsertNextCell(3, cell);
    ids->InsertNextTypedTuple(t.Id.data());
  }
  vtkNew<vtkPolyData> mesh;
  mesh->SetPoints(points);
  mesh->SetPolys(cells);
  return AddCellColored(renderer, mesh, ids);
}

// The faces' polygons in painting order: image corners and colour.
struct Painted
{
  std::vector<std::array<double, 2>> Corners;
  Color Id;
};
std::vector<Painted> ReadFaces(vtkPolyData* faces)
{
  std::vector<Painted> out;
  vtkDataArray* image = faces->GetPointData()->GetArray("ImageCoordinates");
  vtkDataArray* colors = faces->GetCellData()->GetArray("Colors");
  if (!image || !colors)
  {
    return out;
  }
  auto it = vtk::TakeSmartPointer(faces->GetPolys()->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    vtkIdType size;
    const vtkIdType* ids;
    it->GetCurrentCell(size, ids);
    Painted p;
    for (vtkIdType k = 0; k < size; ++k)
    {
      p.Corners.push_back({ image->GetComponent(ids[k], 0), image->GetComponent(ids[k], 1) });
    }
    const vtkIdType cell = it->GetCurrentCellId();
    for (int c = 0; c < 3; ++c)
    {
      p.Id[c] = static_cast<unsigned char>(colors->GetComponent(cell, c));
    }
    out.push_back(p);
  }
  return out;
}

// Whether the point is inside the convex polygon (either winding), `margin` pixels in.
bool Inside(const Painted& p, double x, double y, double margin)
{
  double area = 0.0;
  const size_t n = p.Corners.size();
  for (size_t k = 0; k < n; ++k)
  {
    const auto& a = p.Corners[k];
    const auto& b = p.Corners[(k + 1) % n];
    area += a[0] * b[1] - b[0] * a[1];
  }
  const double sign = area > 0.0 ? 1.0 : -1.0;
  for (size_t k = 0; k < n; ++k)
  {
    const auto& a = p.Corners[k];
    const auto& b = p.Corners[(k + 1) % n];
    const double length = std::hypot(b[0] - a[0], b[1] - a[1]);
    const double side = sign * ((b[0] - a[0]) * (y - a[1]) - (b[1] - a[1]) * (x - a[0]));
    if (length > 0.0 && side / length < margin)
    {
      return false;
    }
  }
  return true;
}

// The world ray through window point (x, y) of the renderer's camera.
void PixelRay(vtkRenderer* renderer, double x, double y, Vec& from, Vec& direction)
{
  vtkMatrix4x4* m = renderer->GetActiveCamera()->GetCompositeProjectionTransformMatrix(
    static_cast<double>(Width) / Height, -1, 1);
  vtkNew<vtkMatrix4x4> inverse;
  vtkMatrix4x4::Invert(m, inverse);
  Vec ends[2];
  for (int e = 0; e < 2; ++e)
  {
    const double ndc[4] = { 2.0 * x / Width - 1.0, 2.0 * y / Height - 1.0, e ? 1.0 : -1.0, 1.0 };
    double w[4];
    inverse->MultiplyPoint(ndc, w);
    ends[e] = { w[0] / w[3], w[1] / w[3], w[2] / w[3] };
  }
  from = ends[0];
  direction = Sub(ends[1], ends[0]);
}

// Samples where the painted faces show another triangle than the first the ray meets (samples
// within a hair of an edge, or where two surfaces meet, are skipped as undecided).
int CompareWithRays(vtkRenderer* renderer, const std::vector<Triangle>& tris,
  const std::vector<Painted>& painted, int& decided)
{
  int wrong = 0;
  decided = 0;
  for (int j = 1; j < Height; j += 3)
  {
    for (int i = 1; i < Width; i += 3)
    {
      const double x = i + 0.5, y = j + 0.5;
      Vec from, d;
      PixelRay(renderer, x, y, from, d);
      double first = -1.0, second = -1.0;
      const Triangle* nearest = nullptr;
      bool nearEdge = false;
      for (const Triangle& t : tris)
      {
        const double hit = Hit(t, from, d, 0.0);
        if (hit < 0.0)
        {
          continue;
        }
        nearEdge = nearEdge || Hit(t, from, d, 1e-3) < 0.0;
        if (first < 0.0 || hit < first)
        {
          second = first;
          first = hit;
          nearest = &t;
        }
        else if (second < 0.0 || hit < second)
        {
          second = hit;
        }
      }
      const Painted* top = nullptr;
      for (const Painted& p : painted)
      {
        nearEdge = nearEdge || (Inside(p, x, y, -0.01) && !Inside(p, x, y, 0.01));
        top = Inside(p, x, y, 0.0) ? &p : top;
      }
      if (nearEdge || (second >= 0.0 && second - first < 1e-4 * first))
      {
        continue;
      }
      ++decided;
      const bool same = (!nearest && !top) || (nearest && top && nearest->Id == top->Id);
      if (!same && ++wrong <= 5)
      {
        std::cerr << "sample " << x << ", " << y << ": painted "
                  << (top ? static_cast<int>(top->Id[0]) : -1) << ", first hit "
                  << (nearest ? static_cast<int>(nearest->Id[0]) : -1) << "\n";
      }
    }
  }
  return wrong;
}

// The faces of the renderer's scene (UpdateFaces) against the rays (CompareWithRays), printed.
struct RayComparison
{
  size_t Polygons;
  vtkIdType Splits;
  int Decided, Wrong;
};
RayComparison PaintAndCompare(
  vtkRenderer* renderer, const std::vector<Triangle>& tris, const char* name)
{
  vtkNew<vtkNPRDrawingLines> lines;
  lines->SetRenderer(renderer);
  lines->SetSize(Width, Height);
  NPR_CHECK(lines->UpdateFaces(), "UpdateFaces failed");
  const std::vector<Painted> painted = ReadFaces(lines->GetFaces());
  RayComparison found{ painted.size(), lines->GetNumberOfFaceSplits(), 0, 0 };
  found.Wrong = CompareWithRays(renderer, tris, painted, found.Decided);
  std::cout << name << ": " << tris.size() << " triangles, " << found.Polygons << " polygons ("
            << found.Splits << " splits); " << found.Decided << " samples decided, " << found.Wrong
            << " wrong\n";
  return found;
}

// Random big triangles in [-1, 1]^3 that pass through each other (cycles included), and a
// sphere's triangles through them.
std::vector<Triangle> RandomScene()
{
  std::mt19937 random(20261202);
  std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
  std::vector<Triangle> tris;
  for (int k = 0; k < 40; ++k)
  {
    Triangle t;
    for (Vec* corner : { &t.A, &t.B, &t.C })
    {
      *corner = { coordinate(random), coordinate(random), coordinate(random) };
    }
    t.Id = { static_cast<unsigned char>(k + 1), 0, 0 };
    tris.push_back(t);
  }
  vtkNew<vtkSphereSource> sphere;
  sphere->SetRadius(0.5);
  sphere->SetCenter(0.2, -0.1, 0.1);
  sphere->SetThetaResolution(16);
  sphere->SetPhiResolution(8);
  sphere->Update();
  vtkPolyData* s = sphere->GetOutput();
  auto it = vtk::TakeSmartPointer(s->GetPolys()->NewIterator());
  int k = 0;
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell(), ++k)
  {
    vtkIdType size;
    const vtkIdType* ids;
    it->GetCurrentCell(size, ids);
    Triangle t;
    s->GetPoint(ids[0], t.A.data());
    s->GetPoint(ids[1], t.B.data());
    s->GetPoint(ids[2], t.C.data());
    t.Id = { 0, static_cast<unsigned char>(k % 256), static_cast<unsigned char>(1 + k / 256) };
    tris.push_back(t);
  }
  return tris;
}

int FacesOrder(bool parallel)
{
  const std::vector<Triangle> tris = RandomScene();
  vtkNew<vtkRenderer> renderer;
  AddTriangles(renderer, tris);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(2.6, 1.7, 3.4);
  camera->SetFocalPoint(0, 0, 0);
  camera->SetViewUp(0, 1, 0);
  camera->SetParallelProjection(parallel);
  camera->SetParallelScale(1.5);
  camera->SetClippingRange(0.5, 10.0);
  const RayComparison found =
    PaintAndCompare(renderer, tris, parallel ? "parallel" : "perspective");
  NPR_CHECK(found.Decided > Width * Height / 9 / 2, "too few samples decided: " << found.Decided);
  NPR_CHECK(found.Wrong == 0, found.Wrong << " samples show a triangle behind the first one hit");
  NPR_CHECK(found.Splits > 0, "triangles that cross were not split");
  return nprTestResult();
}
NPR_TEST_CASE("drawing-faces-order", [] { return FacesOrder(false); });
NPR_TEST_CASE("drawing-faces-order-parallel", [] { return FacesOrder(true); });

// A closed torus (its faces in a random order) seen at a slant, its near side over its far side
// (faces whose images overlap, ordered), its back faces left out, and a sphere beside it that
// overlaps nothing (faces painted first, unordered): the same comparison with the rays.
int FacesOrderTorus()
{
  vtkNew<vtkPolyData> torus; // closed: each point shared, quads as two outward triangles
  {
    constexpr int U = 48, V = 24;
    vtkNew<vtkPoints> points;
    std::vector<std::array<vtkIdType, 3>> triangles;
    for (int u = 0; u < U; ++u)
    {
      for (int v = 0; v < V; ++v)
      {
        const double a = 2.0 * M_PI * u / U, b = 2.0 * M_PI * v / V;
        const double r = 1.0 + 0.35 * std::cos(b);
        points->InsertNextPoint(r * std::cos(a), r * std::sin(a), 0.35 * std::sin(b));
        const vtkIdType p00 = u * V + v, p10 = ((u + 1) % U) * V + v;
        const vtkIdType p01 = u * V + (v + 1) % V, p11 = ((u + 1) % U) * V + (v + 1) % V;
        triangles.push_back({ p00, p10, p11 });
        triangles.push_back({ p00, p11, p01 });
      }
    }
    // In a random order: painting the faces in the mesh's order would not be right by chance.
    std::shuffle(triangles.begin(), triangles.end(), std::mt19937(7));
    vtkNew<vtkCellArray> cells;
    for (const auto& t : triangles)
    {
      cells->InsertNextCell(3, t.data());
    }
    torus->SetPoints(points);
    torus->SetPolys(cells);
  }
  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(2.2, 0.0, 0.0);
  sphere->SetRadius(0.5);
  sphere->Update();
  vtkNew<vtkRenderer> renderer;
  std::vector<Triangle> tris;
  int next = 0;
  for (vtkPolyData* source : { static_cast<vtkPolyData*>(torus), sphere->GetOutput() })
  {
    vtkNew<vtkPolyData> mesh;
    mesh->ShallowCopy(source);
    mesh->GetPointData()->Initialize(); // no normals or scalars: the cell ids colour it
    vtkNew<vtkUnsignedCharArray> ids;
    ids->SetNumberOfComponents(3);
    auto it = vtk::TakeSmartPointer(mesh->GetPolys()->NewIterator());
    for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell(), ++next)
    {
      vtkIdType size;
      const vtkIdType* cell;
      it->GetCurrentCell(size, cell);
      const Color id = { static_cast<unsigned char>(next % 256),
        static_cast<unsigned char>(next / 256), 1 };
      ids->InsertNextTypedTuple(id.data());
      for (vtkIdType k = 1; k + 1 < size; ++k) // the polygon's fan, as drawn
      {
        Triangle t;
        mesh->GetPoint(cell[0], t.A.data());
        mesh->GetPoint(cell[k], t.B.data());
        mesh->GetPoint(cell[k + 1], t.C.data());
        t.Id = id;
        tris.push_back(t);
      }
    }
    AddCellColored(renderer, mesh, ids);
  }
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(0.5, -3.5, 1.0);
  camera->SetFocalPoint(0.6, 0.0, 0.0);
  camera->SetViewUp(0, 0, 1);
  renderer->ResetCameraClippingRange();
  const RayComparison found = PaintAndCompare(renderer, tris, "torus and sphere");
  NPR_CHECK(found.Decided > 2000, "too few samples decided: " << found.Decided);
  NPR_CHECK(found.Wrong == 0, found.Wrong << " samples show a face behind the first one hit");
  NPR_CHECK(found.Polygons < 0.75 * tris.size(),
    found.Polygons << " polygons of " << tris.size() << " triangles: back faces not left out");
  return nprTestResult();
}
NPR_TEST_CASE("drawing-faces-order-torus", FacesOrderTorus);

// The signed image area of a polygon: positive when it winds counter-clockwise (front facing).
double ImageArea(const Painted& p)
{
  double area = 0.0;
  for (size_t k = 0; k < p.Corners.size(); ++k)
  {
    const auto& a = p.Corners[k];
    const auto& b = p.Corners[(k + 1) % p.Corners.size()];
    area += 0.5 * (a[0] * b[1] - b[0] * a[1]);
  }
  return area;
}

int FacesCulling()
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(32);
  sphere->SetPhiResolution(16);
  vtkNew<vtkReverseSense> inwards;
  inwards->SetInputConnection(sphere->GetOutputPort());
  inwards->ReverseCellsOn();
  for (int reversed = 0; reversed < 2; ++reversed)
  {
    vtkNew<vtkRenderer> renderer;
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputConnection(reversed ? inwards->GetOutputPort() : sphere->GetOutputPort());
    mapper->ScalarVisibilityOff();
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    actor->GetProperty()->SetColor(0.2, 0.4, 0.6);
    renderer->AddActor(actor);
    renderer->ResetCamera();
    vtkNew<vtkNPRDrawingLines> lines;
    lines->SetRenderer(renderer);
    lines->SetSize(Width, Height);
    NPR_CHECK(lines->UpdateFaces(), "UpdateFaces failed");
    const std::vector<Painted> painted = ReadFaces(lines->GetFaces());
    sphere->Update();
    const auto triangles = static_cast<size_t>(sphere->GetOutput()->GetNumberOfPolys());
    const double sign = reversed ? -1.0 : 1.0;
    const auto facing = std::count_if(
      painted.begin(), painted.end(), [&](const Painted& p) { return sign * ImageArea(p) > 0.0; });
    const bool colored = std::all_of(painted.begin(), painted.end(),
      [](const Painted& p) {
        return p.Id == Color{ 51, 102, 153 };
      });
    std::cout << (reversed ? "inward" : "outward") << " winding: " << painted.size() << " of "
              << triangles << " triangles painted\n";
    NPR_CHECK(!painted.empty() && painted.size() < 0.6 * triangles,
      painted.size() << " polygons: the back faces were not left out");
    NPR_CHECK(facing == static_cast<long>(painted.size()),
      painted.size() - facing << " polygons face away from the camera");
    NPR_CHECK(colored, "a polygon is not the actor's colour (51, 102, 153)");
  }
  return nprTestResult();
}
NPR_TEST_CASE("drawing-faces-culling", FacesCulling);

int FacesErrors()
{
  auto* messages = nprCountingOutputWindow::SafeDownCast(vtkOutputWindow::GetInstance());
  vtkNew<vtkNPRDrawingLines> lines;
  vtkNew<vtkRenderer> alone;
  for (int step = 0; step < 2; ++step)
  {
    const int errors = messages ? messages->Errors : 0;
    NPR_CHECK(
      !lines->UpdateFaces(), (step ? "no size" : "no renderer") << ": UpdateFaces succeeded");
    NPR_CHECK(messages && messages->Errors == errors + 1, "no error reported");
    if (messages)
    {
      messages->Errors = errors;
    }
    lines->SetRenderer(alone);
  }
  // An empty scene: no faces, and no error. A NaN corner: its triangle left out.
  lines->SetSize(Width, Height);
  NPR_CHECK(
    lines->UpdateFaces() && lines->GetFaces()->GetNumberOfCells() == 0, "an empty scene has faces");
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(nprNaNTriangleActor());
  renderer->ResetCamera(0, 1, 0, 1, -0.5, 0.5);
  lines->SetRenderer(renderer);
  NPR_CHECK(lines->UpdateFaces() && lines->GetFaces()->GetNumberOfCells() == 1,
    "the NaN triangle was not left out: " << lines->GetFaces()->GetNumberOfCells() << " faces");
  return nprTestResult();
}
NPR_TEST_CASE("drawing-faces-errors", FacesErrors);
}
