// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// What vtkNPRReferenceMask and vtkNPRDrawingLines share: a renderer's actors as drawn, the
// feature lines of each (one vtkNPRFeatureLines per actor, kept), those lines in world
// coordinates, the occlusion structure of all their triangles (rebuilt only when the scene
// changed), and the camera's view: projection into the image, clipping, the ray of a point.
// Private to NPR::Lines.
#ifndef vtkNPRSceneLines_h
#define vtkNPRSceneLines_h

#include "vtkNPROccluders.h" // for vtkNPROccluders, vtkNPRMeshInstance
#include "vtkSmartPointer.h" // for the actors' lines
#include "vtkWeakPointer.h"  // for the actors' lines

#include <cstddef> // for size_t
#include <map>     // for the actors' lines
#include <string>  // for the props' descriptions
#include <utility> // for std::pair
#include <vector>  // for the segments

class vtkCamera;
class vtkNPRFeatureLines;
class vtkPolyData;
class vtkRenderer;

// The image size of a renderer: `size` when both are positive, else the renderer's size in its
// window. False when there is none.
bool vtkNPRImageSize(vtkRenderer* renderer, const int size[2], int& width, int& height);

// How the actors vtkNPRDrawnMeshes() lists draw their meshes: as surfaces (the Surface
// representation), as point clouds (the Points representation) or as the edges of their polygons
// (the Wireframe representation).
enum class vtkNPRDrawnAs
{
  Surfaces,
  Points,
  Wireframe
};

// The meshes of the renderer's visible, opaque vtkActors drawn by a vtkPolyDataMapper (or a
// vtkDataSetMapper of a vtkPolyData) as surfaces (or as points, or as wireframes: vtkNPRDrawnAs),
// those inside assemblies included (vtkNPRPropParts), each polygonal leaf of a composite input a
// mesh of its actor; their inputs brought up to date.
std::vector<vtkNPRMeshInstance> vtkNPRDrawnMeshes(
  vtkRenderer* renderer, vtkNPRDrawnAs drawnAs = vtkNPRDrawnAs::Surfaces);

// The parts of the renderer's visible 3D props (vtkProp3D, assemblies' parts included) that
// vtkNPRDrawnMeshes() lists in no representation: what the scene's lines, faces and points leave
// out (volumes, image slices, translucent actors, other mappers' and non-polygonal data), each
// described by its class ("translucent vtkActor", "vtkActor of a vtkUnstructuredGrid",
// "vtkActor drawn by vtkGlyph3DMapper", "vtkVolume"), in drawing order.
std::vector<std::string> vtkNPRPropsNotDrawn(vtkRenderer* renderer);

// The camera of a frame as the image sees it.
struct vtkNPRSceneView
{
  int Width = 0, Height = 0;
  double Projection[16]; // world to clip coordinates (VTK's composite projection, near -1)
  double Eye[3], Direction[3], Range[2];
  bool Parallel = false;

  void Set(vtkCamera* camera, int width, int height);
  void Clip(const double x[3], double clip[4]) const;
  // Window coordinates of a world point: x, y in pixels (row 0 at the bottom), z the depth
  // buffer's [0, 1]. False behind the eye.
  bool ToImage(const double x[3], double image[3]) const;
  // The part [t0, t1] of the segment a-b inside the frustum, the image widened by `margin`
  // pixels on each side. False when nothing is left.
  bool ClipSegment(
    const double a[3], const double b[3], double margin, double& t0, double& t1) const;
  // The segment parameter at image fraction s of the clipped piece [t0, t1] (equal steps in
  // the image are unequal along the segment under perspective).
  double ParameterAt(const double a[3], const double b[3], double t0, double t1, double s) const;
  // The length in pixels of the image of a-b between parameters t0 and t1.
  double ImageLength(const double a[3], const double b[3], double t0, double t1) const;
  // The ray a visibility test casts for point p: from the near plane to p, short of p by
  // `epsilon` of its length.
  void Ray(const double p[3], double epsilon, double from[3], double to[3]) const;
};

class vtkNPRSceneLines
{
public:
  struct Settings
  {
    bool Silhouettes = true, Creases = true, Boundaries = true, NonManifoldEdges = true;
    bool SmoothContours = false;
    bool Intersections = false; // crossing surfaces at more than CreaseAngle, as creases
    // The meshes' line cells as LINE segments, and the polygon edges of the wireframe meshes and
    // of the surfaces with EdgeVisibility as MESH_EDGE segments.
    bool LinePrimitives = false;
    double CreaseAngle = 30.0;
  };
  // A feature edge in world coordinates; Nodes identify its end points across the scene (the
  // same mesh vertex of the same actor, or the same crossed edge of a smooth contour: the same
  // node). Triangle: for a smooth contour, the scene point ids (vtkNPROccluders's numbering)
  // of the triangle it lies on; -1 otherwise. Mesh: the index of its mesh in GetLineMeshes(), -1
  // for a crossing of two.
  struct Segment
  {
    double A[3], B[3];
    unsigned char Type;
    vtkIdType NodeA, NodeB;
    vtkIdType Triangle[3];
    int Mesh;
  };

  vtkNPRSceneLines();
  ~vtkNPRSceneLines();

  // The visible, opaque vtkActors of the renderer drawn by a vtkPolyDataMapper or vtkDataSetMapper
  // (their inputs brought up to date; each polygonal leaf of a composite input), their feature
  // lines for the renderer's camera in world coordinates, and the occlusion structure (built again
  // only when the actors, meshes or matrices changed).
  void Update(vtkRenderer* renderer, const Settings& settings, int trianglesPerLocator);

  const std::vector<Segment>& GetSegments() const { return this->Segments; }
  // The meshes of the last Update() (the actors' meshes as drawn).
  const std::vector<vtkNPRMeshInstance>& GetMeshes() const { return this->LocatorState; }
  // The meshes the segments' Mesh indices refer to: GetMeshes(), then (with LinePrimitives) the
  // meshes drawn as wireframes.
  const std::vector<vtkNPRMeshInstance>& GetLineMeshes() const { return this->LineMeshes; }
  const vtkNPROccluders& GetOccluders() const { return this->Occluders; }
  vtkIdType GetNumberOfLocatorBuilds() const { return this->LocatorBuilds; }
  vtkIdType GetNumberOfAdjacencyBuilds() const;
  double GetLinesTime() const { return this->LinesTime; }
  // Bytes held between updates: each mesh's edge table, the occlusion structure, the segments.
  size_t GetMemorySize() const;
  double GetLocatorTime() const { return this->LocatorTime; }

private:
  vtkNPRSceneLines(const vtkNPRSceneLines&) = delete;
  void operator=(const vtkNPRSceneLines&) = delete;

  // The steps of Update(): each mesh's feature lines as segments (returns the number of line
  // nodes), one mesh's output appended, the occluders (built again only when the scene changed)
  // and the crossings' segments.
  vtkIdType UpdateLines(
    const std::vector<vtkNPRMeshInstance>& actors, vtkCamera* camera, const Settings& settings);
  void AppendSegments(vtkPolyData* output, const vtkNPRMeshInstance& state, int mesh,
    vtkIdType nodeOffset, vtkIdType pointOffset);
  // The meshes' line cells as LINE segments, their nodes from firstNode on; returns the next
  // free node.
  vtkIdType AppendLinePrimitives(
    const std::vector<vtkNPRMeshInstance>& actors, vtkIdType firstNode);
  // Each polygon edge of the wireframe meshes (those from firstWireframe on) and of the surfaces
  // with EdgeVisibility, once, as a MESH_EDGE segment; nodes from firstNode on.
  void AppendMeshEdges(
    const std::vector<vtkNPRMeshInstance>& meshes, size_t firstWireframe, vtkIdType firstNode);
  void UpdateOccluders(const std::vector<vtkNPRMeshInstance>& actors, const Settings& settings,
    int trianglesPerLocator, vtkIdType nodeOffset);
  // The crossings at more than the crease angle as segments, their ends chained (nodes from
  // nodeOffset on).
  void AppendCrossings(double creaseAngle, vtkIdType nodeOffset);

  // Each mesh of each actor (a composite input has several) keeps its feature lines.
  using MeshKey = std::pair<vtkActor*, vtkPolyData*>;
  struct LinesEntry
  {
    vtkWeakPointer<vtkActor> Actor; // to tell a new actor or mesh at a freed address
    vtkWeakPointer<vtkPolyData> Mesh;
    vtkSmartPointer<vtkNPRFeatureLines> Lines;
  };
  std::map<MeshKey, LinesEntry> Lines;
  std::vector<Segment> Segments;
  std::vector<vtkNPRMeshInstance> LocatorState; // what the occluders were built from
  std::vector<vtkNPRMeshInstance> LineMeshes;   // LocatorState, then the wireframe meshes
  int LocatorTrianglesPerLocator = 0;
  vtkNPROccluders Occluders;
  vtkIdType LocatorBuilds = 0;
  double LinesTime = 0.0, LocatorTime = 0.0;
};

#endif
// VTK-HeaderTest-Exclude: vtkNPRSceneLines.h
