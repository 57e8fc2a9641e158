// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNPRScenePoints.h"

#include "vtkActor.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkNPRSceneFaces.h"
#include "vtkNPRSceneLines.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>

namespace
{
// A point a mesh draws: its mesh (in the order surfaces, then clouds), its id and the cell that
// draws it (for cell colours).
struct Candidate
{
  double World[3];
  size_t Mesh;
  vtkIdType Point, Cell;
};

// The points of `cells` (whose first cell has id `firstCell` in the mesh's cell numbering), each
// with the first cell that uses it; `seen` marks the points already listed when not null.
void AddCellPoints(vtkCellArray* cells, vtkIdType firstCell, const vtkNPRMeshInstance& mesh,
  size_t meshIndex, std::vector<char>* seen, std::vector<Candidate>& candidates)
{
  vtkPoints* points = mesh.Mesh->GetPoints();
  if (!cells || !points)
  {
    return;
  }
  const vtkIdType count = points->GetNumberOfPoints();
  auto iterator = vtk::TakeSmartPointer(cells->NewIterator());
  vtkIdType cell = firstCell;
  for (iterator->GoToFirstCell(); !iterator->IsDoneWithTraversal();
       iterator->GoToNextCell(), ++cell)
  {
    vtkIdType size;
    const vtkIdType* ids;
    iterator->GetCurrentCell(size, ids);
    for (vtkIdType k = 0; k < size; ++k)
    {
      if (ids[k] < 0 || ids[k] >= count || (seen && (*seen)[ids[k]]))
      {
        continue;
      }
      if (seen)
      {
        (*seen)[ids[k]] = 1;
      }
      Candidate candidate{ {}, meshIndex, ids[k], cell };
      double x[3];
      points->GetPoint(ids[k], x);
      vtkNPRTransformPoint(mesh.Matrix.data(), x, candidate.World);
      if (std::all_of(
            candidate.World, candidate.World + 3, [](double v) { return std::isfinite(v); }))
      {
        candidates.push_back(candidate);
      }
    }
  }
}

// Every point the meshes draw: the surfaces' vertex cells, every point a cloud's cells use.
std::vector<Candidate> DrawnPoints(
  const std::vector<const vtkNPRMeshInstance*>& meshes, size_t firstCloud)
{
  std::vector<Candidate> candidates;
  for (size_t m = 0; m < meshes.size(); ++m)
  {
    vtkPolyData* mesh = meshes[m]->Mesh;
    if (m < firstCloud)
    {
      AddCellPoints(mesh->GetVerts(), 0, *meshes[m], m, nullptr, candidates);
      continue;
    }
    std::vector<char> seen(static_cast<size_t>(mesh->GetNumberOfPoints()), 0);
    vtkIdType firstCell = 0;
    for (vtkCellArray* cells :
      { mesh->GetVerts(), mesh->GetLines(), mesh->GetPolys(), mesh->GetStrips() })
    {
      AddCellPoints(cells, firstCell, *meshes[m], m, &seen, candidates);
      firstCell += cells ? cells->GetNumberOfCells() : 0;
    }
  }
  return candidates;
}

// Whether the camera sees the point: inside the frustum, and no surface on its ray.
bool Seen(const Candidate& candidate, const vtkNPRSceneView& view, const vtkNPROccluders& occluders,
  double epsilon, double image[3])
{
  double clip[4];
  view.Clip(candidate.World, clip);
  const double w = clip[3];
  if (!(w > 0.0) || std::abs(clip[0]) > w || std::abs(clip[1]) > w || std::abs(clip[2]) > w ||
    !view.ToImage(candidate.World, image))
  {
    return false;
  }
  double from[3], to[3];
  view.Ray(candidate.World, epsilon, from, to);
  return !occluders.Hidden(from, to);
}

// Each mesh's look: its colours (mapped scalars, else the actor's), point size and shape.
struct PointLook
{
  vtkSmartPointer<vtkUnsignedCharArray> Mapped;
  bool PerCell = false;
  unsigned char Color[3];
  float Size;
  unsigned char Round;

  explicit PointLook(const vtkNPRMeshInstance& mesh)
  {
    vtkProperty* property = mesh.Actor->GetProperty();
    const double* color = property->GetColor();
    for (int c = 0; c < 3; ++c)
    {
      this->Color[c] =
        static_cast<unsigned char>(std::lround(255.0 * std::clamp(color[c], 0.0, 1.0)));
    }
    this->Size = static_cast<float>(property->GetPointSize());
    this->Round = property->GetRenderPointsAsSpheres() ? 1 : 0;
    this->Mapped = vtkNPRMapScalars(mesh.Actor, mesh.Mesh, this->PerCell);
  }

  void ColorOf(const Candidate& candidate, unsigned char rgb[3]) const
  {
    if (!this->Mapped)
    {
      std::copy_n(this->Color, 3, rgb);
      return;
    }
    const vtkIdType tuple = this->PerCell ? candidate.Cell : candidate.Point;
    for (int c = 0; c < 3; ++c)
    {
      rgb[c] = this->Mapped->GetValue(tuple * this->Mapped->GetNumberOfComponents() + c);
    }
  }
};
}

vtkIdType vtkNPRScenePoints(const std::vector<vtkNPRMeshInstance>& surfaces,
  const std::vector<vtkNPRMeshInstance>& clouds, const vtkNPRSceneView& view,
  const vtkNPROccluders& occluders, double epsilon, vtkPolyData* output)
{
  output->Initialize();
  std::vector<const vtkNPRMeshInstance*> meshes;
  for (const auto* list : { &surfaces, &clouds })
  {
    for (const vtkNPRMeshInstance& mesh : *list)
    {
      meshes.push_back(&mesh);
    }
  }
  const std::vector<Candidate> candidates = DrawnPoints(meshes, surfaces.size());

  // The rays on all cores: each point's image position, or NaN when it is not seen.
  const vtkIdType count = static_cast<vtkIdType>(candidates.size());
  std::vector<double> images(3 * candidates.size());
  vtkSMPTools::For(0, count,
    [&](vtkIdType first, vtkIdType last)
    {
      for (vtkIdType i = first; i < last; ++i)
      {
        double* image = images.data() + 3 * i;
        if (!Seen(candidates[i], view, occluders, epsilon, image))
        {
          image[0] = std::nan("");
        }
      }
    });

  std::vector<PointLook> looks;
  for (const vtkNPRMeshInstance* mesh : meshes)
  {
    looks.emplace_back(*mesh);
  }
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> coordinates;
  coordinates->SetName("ImageCoordinates");
  coordinates->SetNumberOfComponents(3);
  vtkNew<vtkCellArray> verts;
  vtkNew<vtkUnsignedCharArray> colors;
  colors->SetName("Colors");
  colors->SetNumberOfComponents(3);
  vtkNew<vtkFloatArray> sizes;
  sizes->SetName("PointSizes");
  vtkNew<vtkUnsignedCharArray> round;
  round->SetName("RoundPoints");
  for (vtkIdType i = 0; i < count; ++i)
  {
    const double* image = images.data() + 3 * i;
    if (std::isnan(image[0]))
    {
      continue;
    }
    const Candidate& candidate = candidates[i];
    const PointLook& look = looks[candidate.Mesh];
    const vtkIdType id = points->InsertNextPoint(candidate.World);
    coordinates->InsertNextTuple(image);
    verts->InsertNextCell(1, &id);
    unsigned char rgb[3];
    look.ColorOf(candidate, rgb);
    colors->InsertNextTypedTuple(rgb);
    sizes->InsertNextValue(look.Size);
    round->InsertNextValue(look.Round);
  }
  output->SetPoints(points);
  output->SetVerts(verts);
  output->GetPointData()->AddArray(coordinates);
  output->GetCellData()->AddArray(colors);
  output->GetCellData()->AddArray(sizes);
  output->GetCellData()->AddArray(round);
  return count;
}
