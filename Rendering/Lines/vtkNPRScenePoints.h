// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// The point primitives of a renderer's scene as a vector drawing draws them: the vertex cells of
// the meshes drawn as surfaces and each point a cell uses of the meshes drawn as points (a point
// cloud), those the camera sees (inside the view frustum, and not behind a surface of any actor:
// vtkNPROccluders' ray, as the lines' samples are tested). vtkNPRDrawingLines' PointPrimitives.
// Private to NPR::Lines.
#ifndef vtkNPRScenePoints_h
#define vtkNPRScenePoints_h

#include "vtkNPROccluders.h" // for vtkNPRMeshInstance
#include "vtkType.h"         // for vtkIdType

#include <vector> // for the meshes

class vtkPolyData;
struct vtkNPRSceneView;

// Fills `output` (emptied first) with one vertex cell a visible point, in the meshes' order
// (`surfaces`' vertex cells, then `clouds`' points):
// - points in world coordinates; point data "ImageCoordinates" (x, y in pixels, row 0 at the
//   bottom, z the depth buffer's value), as vtkNPRDrawingLines' strokes have them;
// - cell data "Colors" (unsigned char RGB: the point's mapped scalar colour, or its cell's, with
//   ScalarVisibility on, else the actor's colour), "PointSizes" (float: the property's PointSize,
//   pixels at 72 DPI) and "RoundPoints" (unsigned char: 1 where the property renders points as
//   spheres, which a drawing shows as discs; 0 for OpenGL's squares).
// Points that are not finite are left out. Returns the number of points tested.
vtkIdType vtkNPRScenePoints(const std::vector<vtkNPRMeshInstance>& surfaces,
  const std::vector<vtkNPRMeshInstance>& clouds, const vtkNPRSceneView& view,
  const vtkNPROccluders& occluders, double epsilon, vtkPolyData* output);

#endif
// VTK-HeaderTest-Exclude: vtkNPRScenePoints.h
