// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// What the sources of the TestSceneMatrix program share: its actors and spheres, and the checks
// each style's case runs (TestSceneMatrix.cxx calls them in turn).
#ifndef TestSceneMatrix_h
#define TestSceneMatrix_h

#include "nprTesting.h"

class vtkActor;
class vtkImageData;
class vtkPolyData;
class vtkRenderer;

namespace nprSceneMatrix
{
// An actor of data in tan, at (x, y, 0), added to the renderer.
vtkSmartPointer<vtkActor> ActorFor(vtkRenderer* renderer, vtkPolyData* data, double x, double y);
// An unlit actor of data in one colour at the origin (ActorFor), for the scenes' flat props.
vtkSmartPointer<vtkActor> UnlitActor(
  vtkRenderer* renderer, vtkPolyData* data, double red, double green, double blue);
// A sphere of radius 0.4 with no normals (0), point normals (1) or cell normals (2).
vtkSmartPointer<vtkPolyData> Sphere(int normals);
// Renders twice (the second frame may reuse the G-buffer) and returns the last image.
vtkSmartPointer<vtkImageData> RenderTwice(nprPassScene& scene);

// The checks of a style's case (TestSceneMatrixProps.cxx, TestSceneMatrixLooks.cxx,
// TestSceneMatrixComposite.cxx).
void EveryKind(int style);
void LineLooks(int style);
long long CubeAxesPixels(int style, bool labels);
void CompositedKinds(int style);
long long SphereLinePixels(int style, bool dataSetMapper);
}

#endif
