// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNPRSceneFaces.h"

#include "vtkActor.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkIntArray.h"
#include "vtkMapper.h"
#include "vtkNPRFaceOrder.h"
#include "vtkNPRImageOverlaps.h"
#include "vtkNPRMeshFaces.h"
#include "vtkNPRSceneLines.h"
#include "vtkNPRVectors.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkScalarsToColors.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

vtkSmartPointer<vtkUnsignedCharArray> vtkNPRMapScalars(
  vtkActor* actor, vtkPolyData* mesh, bool& perCell)
{
  perCell = false;
  vtkMapper* mapper = actor->GetMapper();
  if (!mapper || !mapper->GetScalarVisibility())
  {
    return nullptr;
  }
  int cellFlag = 0;
  vtkDataArray* scalars = vtkAbstractMapper::GetScalars(mesh, mapper->GetScalarMode(),
    mapper->GetArrayAccessMode(), mapper->GetArrayId(), mapper->GetArrayName(), cellFlag);
  if (!scalars || cellFlag > 1) // field data colours are left to the property's colour
  {
    return nullptr;
  }
  vtkScalarsToColors* table = mapper->GetLookupTable();
  if (!mapper->GetUseLookupTableScalarRange())
  {
    table->SetRange(mapper->GetScalarRange()); // as the mapper does before it draws
  }
  auto colors = vtk::TakeSmartPointer(
    table->MapScalars(scalars, mapper->GetColorMode(), mapper->GetArrayComponent(), VTK_RGBA));
  perCell = cellFlag == 1;
  const vtkIdType needed = perCell ? mesh->GetNumberOfCells() : mesh->GetNumberOfPoints();
  if (colors && (colors->GetNumberOfTuples() < needed || colors->GetNumberOfComponents() < 3))
  {
    return nullptr; // scalars not one a point or a cell: the property's colour
  }
  return colors;
}

namespace
{
using Color = std::array<unsigned char, 3>;

// A face's colours: as drawn without lighting, and the ambient and diffuse terms of VTK's lighting
// (coefficient times colour) that a renderer lights it with.
struct Shades
{
  Color Unlit, Ambient, Diffuse;
};

Color ToColor(const double rgb[3], double scale = 1.0)
{
  Color color;
  for (int c = 0; c < 3; ++c)
  {
    color[c] =
      static_cast<unsigned char>(std::lround(255.0 * std::clamp(scale * rgb[c], 0.0, 1.0)));
  }
  return color;
}

// A mesh's faces' colours as its actor draws them: the mapper's scalar colours (as
// vtkMapper::MapScalars makes them; they are the ambient and diffuse colours too, as VTK's default
// material mode has them), else the property's colours.
class FaceColors
{
public:
  FaceColors(vtkActor* actor, vtkPolyData* mesh);
  Shades Of(const vtkNPRMeshFaces& faces, vtkIdType triangle, const vtkIdType ids[3]) const;

private:
  vtkSmartPointer<vtkUnsignedCharArray> Colors; // RGB or RGBA, a point's or a cell's
  int Stride = 4;
  bool PerCell = false;
  vtkIdType FirstFaceCell = 0; // the cell id of the first polygon: after vertices and lines
  Shades Uniform;
  double Ambient, Diffuse; // the property's coefficients
};

FaceColors::FaceColors(vtkActor* actor, vtkPolyData* mesh)
{
  vtkProperty* property = actor->GetProperty();
  this->Ambient = property->GetAmbient();
  this->Diffuse = property->GetDiffuse();
  this->Uniform = { ToColor(property->GetColor()),
    ToColor(property->GetAmbientColor(), this->Ambient),
    ToColor(property->GetDiffuseColor(), this->Diffuse) };
  this->FirstFaceCell = mesh->GetNumberOfVerts() + mesh->GetNumberOfLines();
  this->Colors = vtkNPRMapScalars(actor, mesh, this->PerCell);
  // Direct colours keep their own components (VTK 9.1 returns RGB scalars as RGBA or RGB).
  this->Stride = this->Colors ? this->Colors->GetNumberOfComponents() : 4;
}

Shades FaceColors::Of(
  const vtkNPRMeshFaces& faces, vtkIdType triangle, const vtkIdType ids[3]) const
{
  if (!this->Colors)
  {
    return this->Uniform;
  }
  const unsigned char* rgb = this->Colors->GetPointer(0);
  double mean[3];
  const int s = this->Stride;
  for (int c = 0; c < 3; ++c)
  {
    mean[c] = this->PerCell
      ? rgb[s * (this->FirstFaceCell + faces.GetCellOfTriangle(triangle)) + c] / 255.0
      : (rgb[s * ids[0] + c] + rgb[s * ids[1] + c] + rgb[s * ids[2] + c]) / (3.0 * 255.0);
  }
  return { ToColor(mean), ToColor(mean, this->Ambient), ToColor(mean, this->Diffuse) };
}

// +1 when the mesh is closed and wound one way with its faces outwards (each edge used twice, in
// opposite directions, and a positive volume), -1 wound inwards, 0 otherwise: then a back face is
// behind a front face of its own mesh.
int ClosedWinding(const vtkNPRMeshFaces& faces)
{
  const vtkIdType triangles = faces.GetNumberOfTriangles();
  if (triangles < 4)
  {
    return 0;
  }
  struct Use
  {
    vtkIdType Low, High;
    bool Forward;
  };
  std::vector<Use> uses;
  uses.reserve(3 * triangles);
  double volume = 0.0, origin[3], x[3][3];
  faces.GetPoint(0, origin);
  for (vtkIdType t = 0; t < triangles; ++t)
  {
    vtkIdType ids[3];
    faces.GetTriangle(t, ids);
    for (int k = 0; k < 3; ++k)
    {
      const vtkIdType a = ids[k], b = ids[(k + 1) % 3];
      uses.push_back({ std::min(a, b), std::max(a, b), a < b });
      faces.GetPoint(ids[k], x[k]);
    }
    const glm::dvec3 o = vtkNPRVector(origin);
    volume +=
      glm::dot(vtkNPRVector(x[0]) - o, glm::cross(vtkNPRVector(x[1]) - o, vtkNPRVector(x[2]) - o));
  }
  std::sort(uses.begin(), uses.end(),
    [](const Use& u, const Use& v)
    { return u.Low < v.Low || (u.Low == v.Low && u.High < v.High); });
  const auto sameEdge = [](const Use& u, const Use& v)
  { return u.Low == v.Low && u.High == v.High; };
  for (size_t i = 0; i < uses.size(); i += 2)
  {
    if (i + 1 >= uses.size() || !sameEdge(uses[i], uses[i + 1]) ||
      uses[i].Forward == uses[i + 1].Forward ||
      (i + 2 < uses.size() && sameEdge(uses[i], uses[i + 2])))
    {
      return 0;
    }
  }
  return volume > 0.0 ? 1 : (volume < 0.0 ? -1 : 0);
}

// The determinant of the matrix's linear part: negative for a mirror.
double LinearDeterminant(const std::array<double, 16>& m)
{
  return m[0] * (m[5] * m[10] - m[6] * m[9]) - m[1] * (m[4] * m[10] - m[6] * m[8]) +
    m[2] * (m[4] * m[9] - m[5] * m[8]);
}

// Whether the world points of the mesh reach behind the near plane.
bool CutByNearPlane(const std::vector<double>& world, const vtkNPRSceneView& view)
{
  for (size_t i = 0; i < world.size(); i += 3)
  {
    double c[4];
    view.Clip(&world[i], c);
    if (c[2] + c[3] < 0.0)
    {
      return true;
    }
  }
  return false;
}

// Whether a triangle lies wholly outside one plane of the view frustum.
bool OutsideFrustum(const double* corners[3], const vtkNPRSceneView& view)
{
  double c[3][4];
  for (int k = 0; k < 3; ++k)
  {
    view.Clip(corners[k], c[k]);
  }
  for (int axis = 0; axis < 3; ++axis)
  {
    for (double sign : { -1.0, 1.0 })
    {
      bool outside = true;
      for (int k = 0; k < 3 && outside; ++k)
      {
        outside = c[k][3] + sign * c[k][axis] < 0.0;
      }
      if (outside)
      {
        return true;
      }
    }
  }
  return false;
}

// A triangle that can show: its world corners and its colour.
struct Candidate
{
  std::array<double, 9> Corners;
  Shades Fill;
};

// Appends the triangles of one mesh that can show to `candidates`.
void CollectMesh(const vtkNPRMeshInstance& instance, const vtkNPRSceneView& view,
  std::vector<Candidate>& candidates, vtkNPRSceneFacesCounts& counts)
{
  vtkNPRMeshFaces faces;
  faces.Set(instance.Mesh);
  std::vector<double> world(3 * faces.GetNumberOfPoints());
  for (vtkIdType i = 0; i < faces.GetNumberOfPoints(); ++i)
  {
    double local[3];
    faces.GetPoint(i, local);
    vtkNPRTransformPoint(instance.Matrix.data(), local, &world[3 * i]);
  }
  const bool cut = CutByNearPlane(world, view);
  const int winding = cut ? 0 : ClosedWinding(faces);
  const double outwards = winding * (LinearDeterminant(instance.Matrix) < 0.0 ? -1.0 : 1.0);
  vtkProperty* property = instance.Actor->GetProperty();
  const bool cullBack = property->GetBackfaceCulling() != 0;
  const bool cullFront = property->GetFrontfaceCulling() != 0;
  const FaceColors palette(instance.Actor, instance.Mesh);
  const glm::dvec3 eye = vtkNPRVector(view.Eye), towardsEye = -vtkNPRVector(view.Direction);
  for (vtkIdType t = 0; t < faces.GetNumberOfTriangles(); ++t)
  {
    ++counts.Triangles;
    vtkIdType ids[3];
    faces.GetTriangle(t, ids);
    const double* corners[3] = { &world[3 * ids[0]], &world[3 * ids[1]], &world[3 * ids[2]] };
    const glm::dvec3 a = vtkNPRVector(corners[0]);
    const glm::dvec3 normal =
      glm::cross(vtkNPRVector(corners[1]) - a, vtkNPRVector(corners[2]) - a);
    const double facing = glm::dot(normal, view.Parallel ? towardsEye : eye - a);
    const bool front = facing > 0.0;
    if (facing == 0.0 || !std::isfinite(facing) || (cullBack && !front) || (cullFront && front) ||
      (outwards != 0.0 && front != (outwards > 0.0)) || OutsideFrustum(corners, view))
    {
      ++counts.LeftOut;
      continue;
    }
    candidates.push_back(
      { { corners[0][0], corners[0][1], corners[0][2], corners[1][0], corners[1][1], corners[1][2],
          corners[2][0], corners[2][1], corners[2][2] },
        palette.Of(faces, t, ids) });
  }
}

// The candidates' images for vtkNPRMarkImageOverlaps.
std::vector<vtkNPRImageTriangle> ProjectCandidates(
  const std::vector<Candidate>& candidates, const vtkNPRSceneView& view)
{
  std::vector<vtkNPRImageTriangle> images(candidates.size());
  for (size_t i = 0; i < candidates.size(); ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      double c[4], image[3];
      view.Clip(&candidates[i].Corners[3 * k], c);
      images[i].Unprojected = images[i].Unprojected || !(c[2] + c[3] > 0.0 && c[3] > 0.0);
      view.ToImage(&candidates[i].Corners[3 * k], image);
      images[i].X[k] = image[0];
      images[i].Y[k] = image[1];
    }
  }
  return images;
}

// The unit normal of a triangle (world corners) on the side the camera sees, as VTK's two-sided
// lighting turns it.
std::array<float, 3> FacingNormal(const double* corners, const vtkNPRSceneView& view)
{
  const glm::dvec3 a = vtkNPRVector(corners);
  glm::dvec3 n = glm::cross(vtkNPRVector(corners + 3) - a, vtkNPRVector(corners + 6) - a);
  const glm::dvec3 towardsEye =
    view.Parallel ? -vtkNPRVector(view.Direction) : vtkNPRVector(view.Eye) - a;
  const double length = glm::length(n);
  n = (glm::dot(n, towardsEye) < 0.0 ? -1.0 : 1.0) * n / (length > 0.0 ? length : 1.0);
  return { static_cast<float>(n.x), static_cast<float>(n.y), static_cast<float>(n.z) };
}

// The part of a convex polygon (world corners) between the near and far planes.
std::vector<glm::dvec3> ClipToDepthRange(
  std::vector<glm::dvec3> polygon, const vtkNPRSceneView& view)
{
  for (double sign : { 1.0, -1.0 }) // near: z + w >= 0, far: w - z >= 0
  {
    std::vector<glm::dvec3> kept;
    const size_t n = polygon.size();
    for (size_t k = 0; k < n; ++k)
    {
      const glm::dvec3& a = polygon[k];
      const glm::dvec3& b = polygon[(k + 1) % n];
      double ca[4], cb[4];
      view.Clip(glm::value_ptr(a), ca);
      view.Clip(glm::value_ptr(b), cb);
      const double da = ca[3] + sign * ca[2], db = cb[3] + sign * cb[2];
      if (da >= 0.0)
      {
        kept.push_back(a);
      }
      if ((da >= 0.0) != (db >= 0.0))
      {
        kept.push_back(vtkNPRPointAlong(a, b, da / (da - db)));
      }
    }
    polygon.swap(kept);
  }
  return polygon;
}

// Appends one ordered polygon to the output arrays; false when nothing of it is in the image or
// it has no area (under a millionth of a square pixel).
bool AppendPolygon(const std::vector<glm::dvec3>& polygon, const vtkNPRSceneView& view,
  vtkPoints* points, vtkDoubleArray* image, vtkCellArray* polys)
{
  if (polygon.size() < 3)
  {
    return false;
  }
  std::vector<std::array<double, 3>> projected(polygon.size());
  double low[2] = { 1e300, 1e300 }, high[2] = { -1e300, -1e300 };
  for (size_t k = 0; k < polygon.size(); ++k)
  {
    view.ToImage(glm::value_ptr(polygon[k]), projected[k].data());
    for (int axis = 0; axis < 2; ++axis)
    {
      low[axis] = std::min(low[axis], projected[k][axis]);
      high[axis] = std::max(high[axis], projected[k][axis]);
    }
  }
  double area = 0.0;
  for (size_t k = 0; k < projected.size(); ++k)
  {
    const auto& a = projected[k];
    const auto& b = projected[(k + 1) % projected.size()];
    area += a[0] * b[1] - b[0] * a[1];
  }
  // Outside the image, or a sliver that covers nothing (its seam stroke would still paint).
  if (high[0] < 0.0 || high[1] < 0.0 || low[0] > view.Width || low[1] > view.Height ||
    !(std::abs(area) > 2e-6))
  {
    return false;
  }
  polys->InsertNextCell(static_cast<vtkIdType>(polygon.size()));
  for (size_t k = 0; k < polygon.size(); ++k)
  {
    polys->InsertCellPoint(points->InsertNextPoint(glm::value_ptr(polygon[k])));
    image->InsertNextTypedTuple(projected[k].data());
  }
  return true;
}
}

namespace
{
// The output's arrays, a polygon appended at a time.
class FaceArrays
{
public:
  FaceArrays()
  {
    this->Points->SetDataTypeToDouble();
    this->Image->SetName("ImageCoordinates");
    this->Image->SetNumberOfComponents(3);
    for (auto* colors : { this->Unlit.Get(), this->Ambient.Get(), this->Diffuse.Get() })
    {
      colors->SetNumberOfComponents(3);
    }
    this->Unlit->SetName("Colors");
    this->Ambient->SetName("AmbientColors");
    this->Diffuse->SetName("DiffuseColors");
    this->Normals->SetName("Normals");
    this->Normals->SetNumberOfComponents(3);
  }

  // A piece of a candidate, clipped to the depth range; nothing if none of it shows.
  void Append(std::vector<glm::dvec3> corners, const Candidate& from, const vtkNPRSceneView& view)
  {
    if (AppendPolygon(
          ClipToDepthRange(std::move(corners), view), view, this->Points, this->Image, this->Polys))
    {
      this->Unlit->InsertNextTypedTuple(from.Fill.Unlit.data());
      this->Ambient->InsertNextTypedTuple(from.Fill.Ambient.data());
      this->Diffuse->InsertNextTypedTuple(from.Fill.Diffuse.data());
      const std::array<float, 3> normal = FacingNormal(from.Corners.data(), view);
      this->Normals->InsertNextTypedTuple(normal.data());
    }
  }

  vtkIdType Store(vtkPolyData* output, const vtkNPRSceneView& view)
  {
    output->Initialize();
    output->SetPoints(this->Points);
    output->SetPolys(this->Polys);
    output->GetPointData()->AddArray(this->Image);
    output->GetCellData()->AddArray(this->Unlit);
    output->GetCellData()->AddArray(this->Ambient);
    output->GetCellData()->AddArray(this->Diffuse);
    output->GetCellData()->SetNormals(this->Normals);
    vtkNew<vtkIntArray> imageSize;
    imageSize->SetName("ImageSize");
    imageSize->SetNumberOfComponents(2);
    const int size[2] = { view.Width, view.Height };
    imageSize->InsertNextTypedTuple(size);
    output->GetFieldData()->AddArray(imageSize);
    return this->Polys->GetNumberOfCells();
  }

private:
  vtkNew<vtkPoints> Points;
  vtkNew<vtkCellArray> Polys;
  vtkNew<vtkDoubleArray> Image;
  vtkNew<vtkUnsignedCharArray> Unlit, Ambient, Diffuse;
  vtkNew<vtkFloatArray> Normals;
};
}

vtkNPRSceneFacesCounts vtkNPRSceneFaces(
  const std::vector<vtkNPRMeshInstance>& meshes, const vtkNPRSceneView& view, vtkPolyData* output)
{
  vtkNPRSceneFacesCounts counts;
  std::vector<Candidate> candidates;
  for (const vtkNPRMeshInstance& instance : meshes)
  {
    CollectMesh(instance, view, candidates, counts);
  }
  // Only the triangles whose images overlap need the partition; the others are painted first.
  const std::vector<char> overlapping =
    vtkNPRMarkImageOverlaps(ProjectCandidates(candidates, view));
  vtkNPRFaceOrder order;
  std::vector<std::uint32_t> free;
  for (std::uint32_t i = 0; i < candidates.size(); ++i)
  {
    if (!overlapping[i])
    {
      free.push_back(i);
    }
    else if (!order.Add(candidates[i].Corners.data(), 3, i))
    {
      ++counts.LeftOut;
    }
  }
  order.Build();
  counts.Splits = order.GetNumberOfSplits();

  FaceArrays arrays;
  for (std::uint32_t i : free)
  {
    const double* x = candidates[i].Corners.data();
    arrays.Append(
      { vtkNPRVector(x), vtkNPRVector(x + 3), vtkNPRVector(x + 6) }, candidates[i], view);
  }
  for (std::uint32_t polygon : order.BackToFront(view.Eye, view.Direction, view.Parallel))
  {
    std::vector<glm::dvec3> corners(order.GetNumberOfCorners(polygon));
    for (size_t k = 0; k < corners.size(); ++k)
    {
      order.GetCorner(polygon, static_cast<int>(k), glm::value_ptr(corners[k]));
    }
    arrays.Append(std::move(corners), candidates[order.GetTag(polygon)], view);
  }
  counts.Polygons = arrays.Store(output, view);
  return counts;
}
