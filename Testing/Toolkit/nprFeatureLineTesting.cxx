// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nprFeatureLineTesting.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkCubeSource.h"
#include "vtkDataArray.h"
#include "vtkIdTypeArray.h"
#include "vtkMath.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkTriangleFilter.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <functional>

namespace
{
using nprFeatureLineTesting::Edge;
using nprFeatureLineTesting::Point;

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
}

namespace nprFeatureLineTesting
{

Edge MakeEdge(Point a, Point b)
{
  return a < b ? Edge{ a, b } : Edge{ b, a };
}

std::map<Edge, int> Lines(vtkNPRFeatureLines* filter)
{
  vtkPolyData* output = filter->GetOutput();
  auto* types = vtkUnsignedCharArray::SafeDownCast(output->GetCellData()->GetArray("FeatureType"));
  std::map<Edge, int> lines;
  nprForEachCell(output->GetLines(),
    [&](vtkIdType cell, vtkIdType size, const vtkIdType* ids)
    {
      NPR_CHECK(size == 2, "a line of " << size << " points");
      Point a, b;
      output->GetPoint(ids[0], a.data());
      output->GetPoint(ids[1], b.data());
      const Edge edge = MakeEdge(a, b);
      NPR_CHECK(!lines.count(edge), "edge output twice: " << Describe(edge));
      lines[edge] = types ? types->GetValue(cell) : -1;
    });
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

Point Corner(int c, double h)
{
  return { (c & 1) ? h : -h, (c & 2) ? h : -h, (c & 4) ? h : -h };
}

std::vector<BoxEdge> BoxEdges(double h)
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

bool BoxFaceFront(int axis, int positive, bool parallel, const double view[3], double h)
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

vtkSmartPointer<vtkPolyData> MakeBox(int skip, int flip)
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

vtkSmartPointer<vtkPolyData> CubeSource(double size)
{
  vtkNew<vtkCubeSource> cube;
  cube->SetXLength(size);
  cube->SetYLength(size);
  cube->SetZLength(size);
  cube->Update();
  return cube->GetOutput();
}

std::vector<std::array<double, 2>> ConvexHull(std::vector<std::array<double, 2>> points)
{
  std::sort(points.begin(), points.end());
  std::vector<std::array<double, 2>> hull(2 * points.size());
  size_t k = 0;
  auto cross = [](const std::array<double, 2>& o, const std::array<double, 2>& a,
                 const std::array<double, 2>& b)
  { return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]); };
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

std::vector<Stroke> ReadStrokes(vtkNPRDrawingLines* lines)
{
  vtkPolyData* strokes = lines->GetStrokes();
  vtkDataArray* image = strokes->GetPointData()->GetArray("ImageCoordinates");
  auto* types = vtkUnsignedCharArray::SafeDownCast(strokes->GetCellData()->GetArray("FeatureType"));
  auto* hidden = vtkUnsignedCharArray::SafeDownCast(strokes->GetCellData()->GetArray("Hidden"));
  std::vector<Stroke> result;
  NPR_CHECK(image && image->GetNumberOfComponents() == 3 && types && hidden,
    "the strokes lack ImageCoordinates, FeatureType or Hidden");
  if (!image || !types || !hidden)
  {
    return result;
  }
  nprForEachCell(strokes->GetLines(),
    [&](vtkIdType cell, vtkIdType size, const vtkIdType* ids)
    {
      Stroke stroke;
      for (vtkIdType i = 0; i < size; ++i)
      {
        stroke.Ids.push_back(ids[i]);
        stroke.Points.push_back({ image->GetComponent(ids[i], 0), image->GetComponent(ids[i], 1) });
        const double z = image->GetComponent(ids[i], 2);
        NPR_CHECK(z >= 0.0 && z <= 1.0, "a stroke point's depth is " << z);
      }
      stroke.Type = types->GetValue(cell);
      stroke.Hidden = hidden->GetValue(cell) != 0;
      NPR_CHECK(size >= 2, "a stroke of " << size << " points");
      result.push_back(stroke);
    });
  return result;
}
}
