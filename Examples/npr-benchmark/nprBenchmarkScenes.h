// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// The benchmark's scenes, cameras and the stress variants of a mesh (npr-benchmark).
#ifndef nprBenchmarkScenes_h
#define nprBenchmarkScenes_h

#include "vtkSmartPointer.h"

#include <string>
#include <vector>

struct nprBenchmarkOptions;
class vtkCamera;
class vtkPolyData;
class vtkRenderer;

struct nprBenchmarkScene
{
  std::string Name;
  std::string Description;
  vtkSmartPointer<vtkPolyData> Raw;  // as loaded (or generated), double-precision points
  vtkSmartPointer<vtkPolyData> Mesh; // what is drawn: Raw prepared by nprPrepareMesh()
  long long Triangles = 0;
};

// The scene names, in the default order: cad, rotor, bunny, isosurface, blobs, knot, bunny1m. The
// scene "box" (108 triangles, for --speed) loads too but is not among them.
const std::vector<std::string>& nprBenchmarkSceneNames();

// The generated set (nprMeshes): CAD parts with circular creases, concave and convex, above the
// crease angle (cone-flange, steep-cone, filleted-cylinder, boss-pocket) and a scan-like bumpy
// surface (bumpy-torus). --contours measures it after the default scenes and reports it apart.
const std::vector<std::string>& nprBenchmarkGeneratedSceneNames();
bool nprIsGeneratedScene(const std::string& name);

// Loads or generates a scene. dataDir holds cad_part.vtp, rotor.ply and bunny.ply; denseMesh is
// the 1M-triangle bunny (bunny_1m.ply). Throws std::runtime_error on failure.
nprBenchmarkScene nprLoadBenchmarkScene(
  const std::string& name, const std::string& dataDir, const std::string& denseMesh);

// Loads the named scenes in turn, telling each on stderr. The dense mesh is made by the build
// (target `benchmark`): without it, the scene bunny1m is left out with a warning unless the
// names were given.
std::vector<nprBenchmarkScene> nprLoadBenchmarkScenes(const std::vector<std::string>& names,
  const std::string& dataDir, const std::string& denseMesh, bool namesGiven);

// What every mode does first: makes the output folders of options and loads its scenes.
std::vector<nprBenchmarkScene> nprStartBenchmarkRun(const nprBenchmarkOptions& options);

// One line per scene for the report: "- name: description, N triangles".
std::string nprBenchmarkSceneLines(const std::vector<nprBenchmarkScene>& scenes);

// The benchmark's cameras: after ResetCamera, an azimuth and an elevation (degrees), perspective.
struct nprBenchmarkCamera
{
  std::string Name; // "a30e20"
  double Azimuth;
  double Elevation;
};
const std::vector<nprBenchmarkCamera>& nprBenchmarkCameras();
// A turn around the model: azimuth -180 up to 180 (excluded) every step degrees, at each
// elevation of nprBenchmarkCameras(); elevation by elevation.
std::vector<nprBenchmarkCamera> nprBenchmarkOrbitCameras(int step);
void nprApplyBenchmarkCamera(vtkRenderer* renderer, const nprBenchmarkCamera& camera);
// The first count cameras for the report: "a30e20 (azimuth 30, elevation 20), ...".
std::string nprBenchmarkCameraLine(int count);

// ---- Stress variants of a scene's raw mesh (npr-benchmark --stress) ----
// The points scaled by a factor about the origin (units changed, as a user's file would be).
vtkSmartPointer<vtkPolyData> nprScaledMesh(vtkPolyData* raw, double factor);
// The points moved by a distance along a fixed oblique direction.
vtkSmartPointer<vtkPolyData> nprTranslatedMesh(vtkPolyData* raw, double distance);
// Near-degenerate needle triangles in a manifold mesh: every fifth triangle is split in three at
// a point 1e-6 of its first edge's length off that edge's midpoint (one needle, two ordinary).
vtkSmartPointer<vtkPolyData> nprSliverMesh(vtkPolyData* raw);
// NaN points added to the mesh, each used by a triangle with two real points.
vtkSmartPointer<vtkPolyData> nprNaNPointsMesh(vtkPolyData* raw);
// A prepared mesh with every seventh point normal set to (0, 0, 0).
vtkSmartPointer<vtkPolyData> nprZeroNormalsMesh(vtkPolyData* prepared);

// The length of the diagonal of a mesh's bounding box.
double nprModelSize(vtkPolyData* mesh);

#endif
