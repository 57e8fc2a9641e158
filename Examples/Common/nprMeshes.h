// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// Meshes built in code, for npr-benchmark's scenes and stress variants and for the tests' meshes
// (Testing/Toolkit/nprTestMeshes.h): one implementation, so that both build the same cells.
#ifndef nprMeshes_h
#define nprMeshes_h

#include "vtkSmartPointer.h"
#include "vtkType.h"

#include <functional>

class vtkCellArray;
class vtkPoints;
class vtkPolyData;

// A mesh of these points and polygons.
vtkSmartPointer<vtkPolyData> nprMesh(vtkPoints* points, vtkCellArray* polygons);

// Calls visit for each cell of cells in order, with its index and point ids.
void nprForEachCell(vtkCellArray* cells,
  const std::function<void(vtkIdType cell, vtkIdType size, const vtkIdType* ids)>& visit);

// The mesh's polygons, each with its own points (a soup: no point shared, as in STL), the points
// of the mesh's data type.
vtkSmartPointer<vtkPolyData> nprPolygonSoup(vtkPolyData* mesh);

// The triangles of a closed tube of along rings of around points, point (i, j) being
// i * around + j: each quad (i, j)-(i + 1, j + 1) split into (i, j), (i + 1, j), (i + 1, j + 1)
// and (i, j), (i + 1, j + 1), (i, j + 1), the last ring joined to the first.
vtkSmartPointer<vtkCellArray> nprTubeTriangles(int along, int around);

#endif
