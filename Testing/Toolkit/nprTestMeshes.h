// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// The test toolkit's meshes and scenes: actors of sources, spheres, a torus with exact normals,
// copies with broken normals, the test models and the cameras the tests share. The meshes the tests
// share with npr-benchmark (a polygon soup, a walk over cells, a tube's triangles) are nprMeshes'
// (Examples/Common).
#ifndef nprTestMeshes_h
#define nprTestMeshes_h

#include "nprMeshes.h"

#include "vtkSmartPointer.h"
#include "vtkType.h"

#include <string>
#include <vector>

class vtkActor;
class vtkAlgorithmOutput;
class vtkCamera;
class vtkCellArray;
class vtkNPRModelReader;
class vtkPolyData;
class vtkRenderer;
class vtkSphereSource;
class vtkVolume;

// An actor of the port's polygons (through a vtkPolyDataMapper) added to the renderer.
vtkSmartPointer<vtkActor> nprAddActor(
  vtkRenderer* renderer, vtkAlgorithmOutput* port, const double color[3] = nullptr);

// The tests' neutral object colour.
constexpr double nprGrey[3] = { 0.8, 0.8, 0.8 };

// An actor of the mesh in one colour (the mapper ignores its scalars) added to the renderer.
vtkSmartPointer<vtkActor> nprAddMesh(
  vtkRenderer* renderer, vtkPolyData* mesh, const double color[3] = nprGrey);

// A cube of edge length size about center (vtkCubeSource), added as by nprAddActor.
vtkSmartPointer<vtkActor> nprAddCube(
  vtkRenderer* renderer, const double center[3], double size, const double color[3] = nullptr);

// A vtkSphereSource of theta x phi facets (not updated: a caller may change it), about center
// (the origin when nullptr).
vtkSmartPointer<vtkSphereSource> nprSphereSource(
  double radius, int theta, int phi, const double center[3] = nullptr);
// nprSphereSource's output about the origin.
vtkSmartPointer<vtkPolyData> nprSphere(double radius, int theta, int phi);

// A sphere of resolution x resolution / 2 facets (theta x phi), added as by nprAddActor.
vtkSmartPointer<vtkActor> nprAddSphere(vtkRenderer* renderer, const double center[3], double radius,
  const double color[3], int resolution = 128);

// The camera at eye, looking at the origin, y up, clipping range 1..far.
void nprLookAtOrigin(vtkCamera* camera, const double eye[3], double far);
// A parallel camera on +z at (0, 0, 10) looking at the origin, y up, `scale` the half height it
// sees, its clipping planes `nearPlane` and `farPlane` from the eye.
void nprParallelFromFront(vtkCamera* camera, double scale, double nearPlane, double farPlane);
// An actor of a mesh of two triangles, one with a NaN corner (bad input).
vtkSmartPointer<vtkActor> nprNaNTriangleActor();

// The cube tests' camera: at eye, looking at the origin, y up, a view angle of 30 degrees or a
// parallel scale of 1, clipping range 1..10.
void nprViewFromCorner(vtkCamera* camera, const double eye[3], bool parallel);

// An opaque, unshaded volume of one colour (a GPU ray-cast 16 x 16 x 16 block at origin with the
// given spacing) added to the renderer; the program needs VTK::RenderingVolumeOpenGL2's factory.
vtkSmartPointer<vtkVolume> nprAddBlockVolume(
  vtkRenderer* renderer, const double origin[3], const double spacing[3], const double color[3]);

// The cube tests' eye, and their scene: a unit cube at the origin (nprAddCube) seen from it
// (nprViewFromCorner).
constexpr double nprCornerEye[3] = { 2.2, 1.7, 2.9 };
vtkSmartPointer<vtkActor> nprAddCornerCube(
  vtkRenderer* renderer, bool parallel, const double color[3] = nullptr);

// Testing/Data/<model> read by vtkNPRModelReader (updated); a failed check when it reports one.
vtkSmartPointer<vtkNPRModelReader> nprReadTestModel(const std::string& model);

// The same cells with the same point ids in the same order, whatever the storage (VTK 9.6's
// readers and filters keep 32-bit ids where they fit, this project's cell arrays vtkIdType).
bool nprSameCells(vtkCellArray* a, vtkCellArray* b);

// A torus about z (ring radius R, tube radius r) of along x around quads, each split into two
// triangles (nprTubeTriangles), with its exact unit normals (point data "Normals"); point (i, j)
// is i * around + j.
vtkSmartPointer<vtkPolyData> nprMakeTorus(double R, double r, int along, int around);

// A deep copy of the mesh whose point normals at ids are broken, in turn a zero vector, a NaN and a
// NaN with an infinity: the input of the checks that a filter survives invalid normals.
vtkSmartPointer<vtkPolyData> nprBreakNormals(vtkPolyData* mesh, const std::vector<vtkIdType>& ids);

// The baseline scenes' view: the camera reset, then turned 30 degrees in azimuth and elevation.
void nprTurnBaselineCamera(vtkRenderer* renderer);

// The baseline scenes' model: nprReadTestModel, prepared by vtkNPRShadingNormals as npr-render
// prepares it, in a warm grey with a little specular, added to the renderer; then
// nprTurnBaselineCamera.
vtkSmartPointer<vtkActor> nprAddBaselineModel(vtkRenderer* renderer, const std::string& model);

#endif
