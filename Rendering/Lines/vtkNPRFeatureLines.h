// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkNPRFeatureLines
 * @brief   Silhouette, crease, boundary and non-manifold edges of a mesh, for a viewpoint.
 *
 * Takes the polygons and triangle strips of the input (vertices and lines are ignored) and
 * outputs the mesh edges that are feature lines, as two-point line cells, with a cell-data
 * array "FeatureType" (vtkUnsignedCharArray) of bit flags; an edge may carry several:
 * - SILHOUETTE (1): of the edge's two faces, one faces the eye and the other faces away. Each
 *   face's signed facing term is n . (p - eye) for a perspective view, with n the face's normal
 *   and p the edge's first point (the same point for both faces, so the test is exact: it is
 *   the side of each face's plane the eye lies on), or n . d for a parallel view, with d the
 *   direction of projection. A face faces the eye where the term is negative; a face seen
 *   exactly edge-on (term 0) counts as facing away, so an axis-aligned box seen along an axis
 *   has the four edges of its front face as silhouettes.
 * - CREASE (2): the angle between the two faces' normals exceeds FeatureAngle (degrees).
 * - BOUNDARY (4): the edge belongs to one face only.
 * - NON_MANIFOLD (8): the edge belongs to more than two faces. Such edges get no silhouette or
 *   crease test (which pair of faces would it be?).
 * - SMOOTH_CONTOUR (16): with SmoothContours on, a piece of the smooth contour inside a
 *   triangle, not a mesh edge; always with SILHOUETTE (17), so that code selecting silhouettes
 *   by their bit keeps them (see below).
 * The output points are those used by the edges, in double precision, at the input's
 * coordinates; a second cell-data array "InputPointIds" (vtkIdTypeArray, 2 components) holds the
 * input ids of each edge's two points (with MergeCoincidentPoints, the first input point at
 * those coordinates), smaller id first. Edges come in the order the faces first use them.
 *
 * The viewpoint is given in the input's coordinates: SetEyePosition(), SetParallelProjection()
 * and SetDirectionOfProjection(), or SetCamera() with the camera and the actor's matrix, which
 * takes the camera into the input's coordinates with the inverse of that matrix. The facing
 * test is a side-of-plane test, which any invertible affine map preserves, so silhouettes are
 * exact under any actor matrix. The angle between normals is not preserved by non-uniform
 * scaling or shear: creases are measured in the input's coordinates, not in the world's.
 *
 * Cost: the edge-adjacency table (each edge's faces: the faces' uses of their edges bucketed by
 * their smaller point, in parallel with vtkSMPTools; coincident points found by sorting a hash
 * of their coordinates) and a single-precision copy of the faces' planes are built once per mesh
 * and reused while the input, its points and its cells are unchanged (their modification times
 * and identities). The input's points and cells are read where they are, never copied: the table
 * holds about 33 bytes a triangle (GetAdjacencyMemorySize(); 16 bytes a face, 10 an edge, 4 a
 * point where points were merged and 4 a face where the faces were renumbered), and its build
 * peaks at about 60. Changing the viewpoint, the switches or FeatureAngle costs one linear pass
 * over the faces and one over the edges (both in parallel, vtkSMPTools), then the output's few
 * edges. GetNumberOfAdjacencyBuilds() counts the builds. (19.3M triangles on 2 cores: a build in
 * about 4 s, a new camera in about 0.3 s; Documentation/drawing.md.)
 *
 * The side of each face's plane the eye is on is decided first from that single-precision copy
 * (the unit normal, the offset from the mesh's centre and a power of two bounding the error),
 * wherever the value is farther from zero than a bound of its rounding error; only the edges of
 * the faces it leaves undecided (edge-on to within about 1e-6 of the scene's size,
 * GetNumberOfUnsureFaces()) take the double-precision test, which computes the two faces'
 * normals again from their points. The output is that of the double-precision test alone, edge
 * for edge, and so are the creases: the angle from the single-precision normals decides where it
 * is more than 1e-4 degrees from FeatureAngle, the exact one elsewhere. The faces keep the
 * input's order where it is local (consecutive faces mostly near each other), else are numbered
 * by the cell of their first point in a 32 x 32 x 32 grid over the mesh (the input's order
 * within a cell), and the edges are ordered by their first faces, so that an edge's two faces
 * are near each other in memory whatever the input's order.
 *
 * Points with exactly equal coordinates are one point for the adjacency when
 * MergeCoincidentPoints is on (the default): vtkPolyDataNormals with splitting duplicates the
 * points along sharp edges, and those edges must stay creases, not become boundaries.
 *
 * Degenerate input never stops the filter:
 * - a face with fewer than three points, a point id out of range, or a zero Newell normal
 *   (zero area: all points collinear or coincident; "zero" is below 1e-12 of the face's squared
 *   size, where rounding decides the direction) has no orientation: it is left out of the
 *   adjacency altogether,
 *   so its edges count only through the other faces that use them (a zero-area sliver filling
 *   a T-junction therefore leaves boundary edges: the mesh is open there);
 * - an edge whose two points are the same point (same id, or equal coordinates) is skipped;
 * - two faces that traverse their shared edge in the same direction (inconsistent winding):
 *   one normal is flipped for that edge's crease and silhouette tests, so the result is that
 *   of a consistently oriented mesh;
 * - a face with a NaN or infinite coordinate is skipped, with one warning per build giving
 *   the count (GetNumberOfNonFiniteFaces());
 * - an empty input gives an empty output, without error.
 * GetNumberOfDegenerateFaces() counts the faces left out for having no orientation.
 *
 * Every result is that of a computation in double precision, whatever the input points' type.
 *
 * Smooth contours (SmoothContours, off by default; Hertzmann & Zorin 2000): when on, with
 * Silhouettes on and point normals in the input (GetPointData()->GetNormals(), 3 components),
 * the silhouettes are not mesh edges but the zero set of the facing function interpolated
 * linearly over each triangle (polygons split into fans, strips into their triangles), the
 * contour of the smooth surface the shaded normals show. Per point, once per update, in double:
 * g = n . (p - eye) for a perspective view, g = n . d for a parallel one, with n the point's
 * normal made unit length (the sign is all the test needs, but the interpolation of g is that
 * of unit normals, as the mapper shades with normalised interpolated normals). A triangle whose
 * g changes sign gives one segment between the zero points of its two sign-changing edges; g
 * == 0 counts as positive, so every edge is decided one way for all its triangles. An edge's
 * zero point is interpolated from its smaller point id to its larger, and there is one output
 * point per crossed edge (raw input ids, not merged), so the segments share their ends and
 * chain into polylines: a closed contour is a closed loop. Each segment runs from the edge
 * where g turns from negative to positive to the edge where it turns back, in the triangle's
 * winding, so the loops of a consistently wound mesh are oriented. The facing function lives
 * in the input's coordinates, as the face test does: its sign is kept by any invertible affine
 * actor matrix when normals are mapped by the inverse transpose, as VTK's are. Smooth-contour
 * cells come after the mesh edges, with InputPointIds the (smaller id first) ids of the edge
 * of their first point, and a third cell array, "ContourTriangle" (vtkIdTypeArray, 3
 * components), the input ids of the triangle each lies on (-1 for mesh edges), present only
 * when smooth contours were computed. Creases, boundaries and non-manifold edges stay mesh
 * edges, and no mesh edge then carries SILHOUETTE. A triangle with a point whose normal is
 * zero, NaN or infinite (or whose coordinates are not finite) gives no contour:
 * GetNumberOfSkippedContourTriangles() counts them; triangles with a repeated point are left
 * out. Without point normals the option changes nothing: the mapper then shades facets, whose
 * outline is the mesh silhouette. Cost: one parallel pass over the points and one over the
 * triangles per update (the triangles and unit normals are kept per mesh): on 1.2M triangles
 * and 2 cores about 35 ms per camera against about 21 ms for the mesh silhouettes
 * (Documentation/feature-lines.md).
 *
 * @sa vtkNPRReferenceMask vtkFeatureEdges
 */
#ifndef vtkNPRFeatureLines_h
#define vtkNPRFeatureLines_h

#include "vtkNPRLineSettings.h" // for vtkNPRLineSettingsMacro
#include "vtkNPRLinesModule.h"  // for export macro
#include "vtkNew.h"             // for LineSettings
#include "vtkPolyDataAlgorithm.h"

#include <cstddef> // for size_t
#include <memory>  // for std::unique_ptr

class vtkCamera;
class vtkMatrix4x4;
class vtkNPRMeshAdjacency;

class VTKNPRLINES_EXPORT vtkNPRFeatureLines : public vtkPolyDataAlgorithm
{
public:
  static vtkNPRFeatureLines* New();
  vtkTypeMacro(vtkNPRFeatureLines, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Bits of the "FeatureType" cell array.
   */
  enum FeatureTypes
  {
    SILHOUETTE = 1,
    CREASE = 2,
    BOUNDARY = 4,
    NON_MANIFOLD = 8,
    SMOOTH_CONTOUR = 16,
    INTERSECTION = 32, // not made here: vtkNPRReferenceMask's curves where surfaces cross
    LINE = 64, // not made here: a line cell of the scene (vtkNPRDrawingLines' LinePrimitives)
    MESH_EDGE =
      128 // not made here: a polygon edge a Wireframe representation or EdgeVisibility draws
  };

  ///@{
  /**
   * The eye of a perspective view, in the input's coordinates (default 0, 0, 0).
   */
  vtkSetVector3Macro(EyePosition, double);
  vtkGetVector3Macro(EyePosition, double);
  ///@}

  ///@{
  /**
   * Parallel projection (off by default): silhouettes use DirectionOfProjection, not the eye.
   */
  vtkSetMacro(ParallelProjection, bool);
  vtkGetMacro(ParallelProjection, bool);
  vtkBooleanMacro(ParallelProjection, bool);
  ///@}

  ///@{
  /**
   * The direction of projection of a parallel view, in the input's coordinates (default
   * 0, 0, -1: VTK's default camera). Its length does not matter.
   */
  vtkSetVector3Macro(DirectionOfProjection, double);
  vtkGetVector3Macro(DirectionOfProjection, double);
  ///@}

  /**
   * Sets EyePosition, ParallelProjection and DirectionOfProjection from the camera, taken into
   * the input's coordinates by the inverse of modelMatrix (an actor's GetMatrix(); none: the
   * identity). The values are copied: call again after the camera moves. A singular matrix
   * leaves the viewpoint unchanged, with an error.
   */
  void SetCamera(vtkCamera* camera, vtkMatrix4x4* modelMatrix = nullptr);

  ///@{
  /**
   * The line types output (all on by default) and FeatureAngle, the angle between face normals
   * in degrees above which an edge is a crease (default 30, clamped to [0, 180]):
   * GetLineSettings()'s, forwarded (vtkNPRLineSettings, where FeatureAngle is CreaseAngle).
   */
  vtkNPRLineSettingsMacro(FeatureAngle);
  ///@}

  ///@{
  /**
   * Silhouettes as the smooth contour of the point normals' facing function, inside the
   * triangles, instead of mesh edges (off by default). Needs point normals; without them the
   * silhouettes stay mesh edges.
   */
  vtkSetMacro(SmoothContours, bool);
  vtkGetMacro(SmoothContours, bool);
  vtkBooleanMacro(SmoothContours, bool);
  ///@}

  ///@{
  /**
   * Treat points with exactly equal coordinates as one point when finding the faces of each
   * edge (on by default). Changing it rebuilds the adjacency.
   */
  vtkSetMacro(MergeCoincidentPoints, bool);
  vtkGetMacro(MergeCoincidentPoints, bool);
  vtkBooleanMacro(MergeCoincidentPoints, bool);
  ///@}

  /**
   * How many times the edge-adjacency table has been built (once per mesh while it does not
   * change).
   */
  vtkIdType GetNumberOfAdjacencyBuilds() const { return this->NumberOfAdjacencyBuilds; }

  ///@{
  /**
   * What the last adjacency build found: the mesh's distinct edges (after merging), the faces
   * left out for having no orientation (zero area, fewer than three points), and the faces
   * skipped for a NaN or infinite coordinate.
   */
  vtkIdType GetNumberOfEdges() const;
  vtkIdType GetNumberOfDegenerateFaces() const;
  vtkIdType GetNumberOfNonFiniteFaces() const;
  ///@}

  /**
   * How many faces of the last update the single-precision side-of-plane test left undecided
   * (edge-on to the eye, to within its error bound, or not finite), so that their edges took
   * the double-precision test. Zero when silhouettes are off.
   */
  vtkIdType GetNumberOfUnsureFaces() const;

  /**
   * How many triangles of the last update gave no smooth contour because one of their points
   * has a zero, NaN or infinite normal or a non-finite coordinate. Zero when no smooth
   * contours were computed.
   */
  vtkIdType GetNumberOfSkippedContourTriangles() const;

  /**
   * Bytes the edge-adjacency table holds between updates (the input's own points and cells,
   * which it reads in place, not counted): about 43 a triangle for a closed triangle mesh.
   */
  size_t GetAdjacencyMemorySize() const;

protected:
  vtkNPRFeatureLines();
  ~vtkNPRFeatureLines() override;

  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  double EyePosition[3] = { 0.0, 0.0, 0.0 };
  bool ParallelProjection = false;
  double DirectionOfProjection[3] = { 0.0, 0.0, -1.0 };
  vtkNew<vtkNPRLineSettings> LineSettings;
  bool MergeCoincidentPoints = true;
  bool SmoothContours = false;
  vtkIdType NumberOfAdjacencyBuilds = 0;

private:
  vtkNPRFeatureLines(const vtkNPRFeatureLines&) = delete;
  void operator=(const vtkNPRFeatureLines&) = delete;

  std::unique_ptr<vtkNPRMeshAdjacency> Adjacency;
};

#endif
