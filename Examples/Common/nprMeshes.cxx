// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nprMeshes.h"

#include "vtkCellArray.h"
#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

vtkSmartPointer<vtkPolyData> nprMesh(vtkPoints* points, vtkCellArray* polygons)
{
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->SetPoints(points);
  mesh->SetPolys(polygons);
  return mesh;
}

void nprForEachCell(vtkCellArray* cells,
  const std::function<void(vtkIdType cell, vtkIdType size, const vtkIdType* ids)>& visit)
{
  vtkNew<vtkIdList> ids; // a copy of each cell's ids, whatever the array's storage
  for (vtkIdType cell = 0; cell < cells->GetNumberOfCells(); ++cell)
  {
    cells->GetCellAtId(cell, ids);
    visit(cell, ids->GetNumberOfIds(), ids->begin());
  }
}

vtkSmartPointer<vtkPolyData> nprPolygonSoup(vtkPolyData* mesh)
{
  vtkNew<vtkPoints> points;
  points->SetDataType(mesh->GetPoints()->GetDataType());
  vtkNew<vtkCellArray> polygons;
  nprForEachCell(mesh->GetPolys(),
    [&](vtkIdType, vtkIdType size, const vtkIdType* ids)
    {
      polygons->InsertNextCell(size);
      for (vtkIdType k = 0; k < size; ++k)
      {
        polygons->InsertCellPoint(points->InsertNextPoint(mesh->GetPoint(ids[k])));
      }
    });
  return nprMesh(points, polygons);
}

vtkSmartPointer<vtkCellArray> nprTubeTriangles(int along, int around)
{
  auto triangles = vtkSmartPointer<vtkCellArray>::New();
  auto id = [&](int i, int j) { return static_cast<vtkIdType>((i % along) * around + j % around); };
  for (int i = 0; i < along; ++i)
  {
    for (int j = 0; j < around; ++j)
    {
      const vtkIdType first[3] = { id(i, j), id(i + 1, j), id(i + 1, j + 1) };
      const vtkIdType second[3] = { id(i, j), id(i + 1, j + 1), id(i, j + 1) };
      triangles->InsertNextCell(3, first);
      triangles->InsertNextCell(3, second);
    }
  }
  return triangles;
}
