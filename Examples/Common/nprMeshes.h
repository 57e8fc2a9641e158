// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// Meshes built in code, for npr-benchmark's scenes and stress variants and for the tests' meshes
// (Testing/Toolkit/nprTestMeshes.h): one implementation, so that both build the same cells.
#ifndef nprMeshes_h
#define nprMeshes_h

#include "vtkSmartPointer.h"
#include "vtkType.h"

#include <array>
#include <functional>
#include <vector>

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

// ---- Generated CAD parts and a scan-like surface (npr-benchmark's generated set, the tests) ----
// A closed surface of revolution about z: the profile's (r, z) points, from a point on the axis
// (r = 0) to another on it, each point between turned into a ring of `around` points. The rings
// share their points with the faces on both sides, so each corner of the profile is a circular
// crease whose angle (between the faces' normals) is the profile's turn there. Outward normals
// when the profile runs outwards along the bottom and back inwards along the top.
vtkSmartPointer<vtkPolyData> nprRevolvedProfile(
  const std::vector<std::array<double, 2>>& profile, int around);

// A truncated cone rising from a round flange: the cone's side makes coneAngle degrees (0..90)
// with the flange's top, a concave circular crease of that angle where they meet and a convex one
// of the same angle at the cone's flat top. Flange radius 1, 0.25 thick; cone radius 0.85 at its
// foot, 0.1 at its top.
vtkSmartPointer<vtkPolyData> nprConeOnFlange(double coneAngle, int around = 128);

// A cylinder (radius 1, 1.4 high) with a 45-degree chamfer round its foot (two convex creases of
// 45 degrees) and a quarter-round fillet (radius 0.25, six facets of 15 degrees: no crease) round
// its top, and on top a boss (radius 0.3, up to 2) joined to it by a concave fillet of the same
// kind, with a convex 90-degree crease round its top.
vtkSmartPointer<vtkPolyData> nprFilletedCylinder(int around = 128);

// A round plate (radius 1, 0.3 thick) with a boss (radius 0.55, concave 90-degree crease at its
// foot) whose top holds a pocket (radius 0.3, 0.3 deep: convex rim, concave floor).
vtkSmartPointer<vtkPolyData> nprBossAndPocket(int around = 128);

// A scan-like organic surface: a torus about z (ring radius 1, tube radius 0.4) whose tube radius
// is displaced by smooth bumps of several sizes (a sum of sines), along x around quads as
// triangles (nprTubeTriangles). No crease: its lines are its contours.
vtkSmartPointer<vtkPolyData> nprBumpyTorus(int along = 360, int around = 120);

#endif
