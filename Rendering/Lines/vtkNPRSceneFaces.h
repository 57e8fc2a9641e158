// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// The faces of a renderer's scene as a vector drawing fills them: every triangle that can show,
// back to front and split where needed (vtkNPRFaceOrder), so that painting them in order gives
// the picture with nothing behind showing through; clipped to the near and far planes; each with
// its colour as the actor draws it without lighting. vtkNPRDrawingLines::UpdateFaces(). Private
// to NPR::Lines.
#ifndef vtkNPRSceneFaces_h
#define vtkNPRSceneFaces_h

#include "vtkNPROccluders.h" // for vtkNPRMeshInstance
#include "vtkSmartPointer.h" // for the mapped colours
#include "vtkType.h"         // for vtkIdType

#include <vector> // for the meshes

class vtkPolyData;
class vtkUnsignedCharArray;
struct vtkNPRSceneView;

// The colours the actor's mapper maps the mesh's scalars to (vtkMapper::MapScalars, RGB or RGBA,
// one a point or, with `perCell` set, one a cell in the mesh's cell order), as VTK draws them;
// null when it colours by its property (ScalarVisibility off, no scalars, field data scalars, or
// too few of them). Shared by the faces and the points of a vector drawing.
vtkSmartPointer<vtkUnsignedCharArray> vtkNPRMapScalars(
  vtkActor* actor, vtkPolyData* mesh, bool& perCell);

// What vtkNPRSceneFaces did: the scene's triangles, those left out (outside the frustum, the back
// faces of closed meshes, culled by their property, edge-on or degenerate), the pieces made by
// splitting, the polygons output.
struct vtkNPRSceneFacesCounts
{
  vtkIdType Triangles = 0, LeftOut = 0, Splits = 0, Polygons = 0;
};

// Fills `output` (emptied first) with the faces of `meshes` for `view`, in painting order:
// - points in world coordinates, polygons (convex), back to front;
// - point data "ImageCoordinates" (x, y in pixels, row 0 at the bottom, z the depth buffer's
//   value), as vtkNPRDrawingLines' strokes have them;
// - cell data "Colors" (unsigned char RGB): the actor's mapped scalar colour (a cell's, or the
//   mean of the corners' point colours) with ScalarVisibility on and scalars to map, else its
//   property's colour (vtkProperty::GetColor());
// - field data "ImageSize".
// A mesh that is closed and wound one way (each edge used twice, in opposite directions) loses
// its back faces, unless the near plane cuts it (the camera may be inside); the faces a
// property culls (BackfaceCulling, FrontfaceCulling) are left out; polygons wholly outside the
// image are not output.
vtkNPRSceneFacesCounts vtkNPRSceneFaces(
  const std::vector<vtkNPRMeshInstance>& meshes, const vtkNPRSceneView& view, vtkPolyData* output);

#endif
// VTK-HeaderTest-Exclude: vtkNPRSceneFaces.h
