// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkNPRDrawingLines
 * @brief   A renderer's feature lines as strokes, each piece visible or hidden: the geometry of a
 *          technical drawing (hidden-line removal).
 *
 * For a renderer (its active camera and its visible, opaque vtkActors drawn by a
 * vtkPolyDataMapper, or a vtkDataSetMapper of a vtkPolyData as PyVista's meshes are, with their
 * actor matrices: the scene vtkNPRReferenceMask sees) and an image
 * size, Update() computes on the CPU, in double precision:
 * - the silhouette, crease, boundary and non-manifold edges of every actor (vtkNPRFeatureLines,
 *   one per actor, kept between updates), in world coordinates, clipped to the view frustum;
 *   with SmoothContours on, the silhouettes of a mesh with point normals are its smooth contour
 *   (pieces inside its triangles, which chain through the edges they cross into one stroke: a
 *   sphere's outline is one smooth loop, a saddle's does not zigzag), and with
 *   IntersectionCurves on (the default) the curves where surfaces cross are lines too, their
 *   pieces chained through the ends they share (vtkNPRRendererLines);
 * - where each one passes behind a surface of any actor: each edge is sampled at most
 *   SampleSpacing pixels apart in the image (at least its two ends), each sample tested by the
 *   reference mask's ray cast (vtkNPROccluders: from the near plane to the sample, short of it by
 *   OcclusionEpsilon of the distance), and between two samples that differ the change is found by
 *   bisection to within 1/1000 of a pixel. Pieces shorter than 1/100 of a pixel are dropped (an
 *   edge that ends on a silhouette touches it only at its end);
 * - strokes: the pieces of one kind (the same line type and the same visibility) chained into
 *   polylines through the mesh vertices where exactly two pieces of that kind meet; a stroke ends
 *   where one, three or more meet, and at a change of visibility. A closed loop (the rim of a
 *   cylinder) is one polyline whose last point id is its first.
 *
 * Output, GetStrokes(): a vtkPolyData of polylines,
 * - points in world coordinates (double);
 * - point data "ImageCoordinates" (vtkDoubleArray, 3 components): x and y in pixels of the image
 *   (window coordinates: pixel (i, j) covers [i, i+1) x [j, j+1), row 0 at the bottom, as
 *   vtkNPRReferenceMask and vtkWindowToImageFilter have it) and z the depth as the depth buffer
 *   holds it ([0, 1], from the camera's projection);
 * - cell data "FeatureType" (vtkUnsignedCharArray): the stroke's kind, a single bit of
 *   vtkNPRFeatureLines::FeatureTypes: SILHOUETTE (also a smooth contour), BOUNDARY, INTERSECTION,
 *   CREASE, NON_MANIFOLD or (with LinePrimitives) LINE or MESH_EDGE, the first of these an edge
 *   carries (an
 *   edge that is both silhouette and crease is a silhouette);
 * - cell data "Hidden" (vtkUnsignedCharArray): 1 for a hidden stroke, 0 for a visible one;
 * - cell data "Colors" (vtkUnsignedCharArray, RGB) and "LineWidths" (vtkFloatArray, pixels at
 *   72 DPI): a LINE stroke's actor's colour and line width (a MESH_EDGE stroke's: the edge colour
 *   of a surface's, the colour of a wireframe's); black and 0 for the others (whose look is the
 *   style's);
 * - field data "ImageSize" (vtkIntArray, 2 components): the image's width and height.
 * Hidden pieces are output only with HiddenLines on.
 *
 * Accuracy: a piece of an edge hidden or uncovered between two samples (an occluder or a gap
 * narrower than SampleSpacing in the image, seen between them) can be missed; everything else is
 * exact to the bisection's 1/1000 pixel, OcclusionEpsilon and double rounding; a smooth contour's
 * samples ignore the faces about its triangle, so a fold of the mesh within an edge length of
 * it does not hide it (vtkNPRReferenceMask). Not included, as in vtkNPRReferenceMask:
 * translucent actors, props that are not vtkActors with those mappers, mapper clipping
 * planes. The actors inside assemblies and the drawn level of a vtkLODProp3D are included
 * (vtkNPRPropParts).
 *
 * Cost: the adjacency of each mesh and the occlusion structure are built once and reused while
 * the meshes and actor matrices do not change, both reading the meshes' points and cells in
 * place (GetMemorySize(): about 65 bytes a triangle in all); a camera change costs the lines (one
 * pass over each mesh's faces and edges) and the rays, each edge's on one of all the cores
 * (vtkSMPTools), the pieces then numbered and chained in the edges' order as on one core. On
 * 19.3M triangles and 2 cores: about 8 s for the first update, 0.7 to 1 s a camera change
 * (Documentation/drawing.md). Times of the last update: GetLinesTime(), GetLocatorTime(),
 * GetVisibilityTime(), GetChainTime().
 *
 * @sa vtkNPRReferenceMask vtkNPRFeatureLines
 */
#ifndef vtkNPRDrawingLines_h
#define vtkNPRDrawingLines_h

#include "vtkNPRLinesModule.h" // for export macro
#include "vtkNPRRendererLines.h"

#include <cstddef> // for size_t
#include <memory>  // for std::unique_ptr

class vtkPolyData;

class VTKNPRLINES_EXPORT vtkNPRDrawingLines : public vtkNPRRendererLines
{
public:
  static vtkNPRDrawingLines* New();
  vtkTypeMacro(vtkNPRDrawingLines, vtkNPRRendererLines);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Also output the hidden pieces of the lines (off by default).
   */
  vtkSetMacro(HiddenLines, bool);
  vtkGetMacro(HiddenLines, bool);
  vtkBooleanMacro(HiddenLines, bool);
  ///@}

  ///@{
  /**
   * Also output the line cells of the scene's meshes (an outline box, axes, streamlines drawn as
   * lines; off by default): each segment of each polyline split where it passes behind a surface
   * like the feature lines, chained through the mesh's points, as strokes of FeatureType LINE
   * with their actor's colour and line width (cell data "Colors" and "LineWidths"); and the
   * polygon edges that actors drawn with the Wireframe representation, or with EdgeVisibility
   * on, draw: each edge once, as strokes of FeatureType MESH_EDGE in the wireframe's colour or
   * the surface's EdgeColor (a wireframe hides nothing; a surface's own edges are not hidden by
   * it). Vector
   * files without the window's image take them so (vtkNPRDrawingExporter); the drawing style's
   * image leaves them to VTK, which draws them over it.
   */
  vtkSetMacro(LinePrimitives, bool);
  vtkGetMacro(LinePrimitives, bool);
  vtkBooleanMacro(LinePrimitives, bool);
  ///@}

  ///@{
  /**
   * Also compute the scene's point primitives the camera sees (off by default), as
   * GetVisiblePoints(): the vertex cells of the meshes drawn as surfaces, and the points of
   * the meshes drawn with the Points representation (a point cloud), each inside the view and
   * not behind a surface (the lines' ray test, at the point); a hidden point is left out. Vector
   * files without the window's image draw them so (vtkNPRDrawingExporter).
   */
  vtkSetMacro(PointPrimitives, bool);
  vtkGetMacro(PointPrimitives, bool);
  vtkBooleanMacro(PointPrimitives, bool);
  ///@}

  ///@{
  /**
   * The largest distance in pixels between the visibility samples of an edge (default 1,
   * clamped to [0.05, 16]).
   */
  vtkSetClampMacro(SampleSpacing, double, 0.05, 16.0);
  vtkGetMacro(SampleSpacing, double);
  ///@}

  /**
   * Computes the strokes. False, with an error, when there is no renderer or no size.
   */
  bool Update() override;

  /**
   * The strokes of the last Update() (see the class description).
   */
  vtkPolyData* GetStrokes();

  /**
   * The visible point primitives of the last Update() with PointPrimitives on (else empty): a
   * vtkPolyData of one vertex cell a point, points in world coordinates, point data
   * "ImageCoordinates" (as the strokes'), cell data "Colors" (unsigned char RGB: the point's
   * mapped scalar colour or its actor's colour), "PointSizes" (float: the actor's PointSize,
   * pixels at 72 DPI) and "RoundPoints" (unsigned char: 1 where the actor renders points as
   * spheres).
   */
  vtkPolyData* GetVisiblePoints();

  /**
   * Computes the faces a vector drawing fills (vtkNPRDrawingExporter's FillFaces), for the
   * renderer's scene and camera as they are now: every triangle that can show, back to front
   * and split where needed (a binary space partition of the faces' planes), so that painting
   * them in order gives the picture, surfaces that pass through each other included, with
   * nothing behind showing through; clipped to the near and far planes. The back faces of a
   * closed mesh wound one way (unless the near plane cuts it) and the faces its property culls
   * are left out, and so are polygons wholly outside the image. False, with an error, when there
   * is no renderer or no size.
   */
  bool UpdateFaces();

  /**
   * The faces of the last UpdateFaces(), in painting order: a vtkPolyData of convex polygons,
   * points in world coordinates, point data "ImageCoordinates" (as the strokes'), cell data
   * "Colors" (unsigned char RGB: the actor's colour without lighting, its mapped scalar colour
   * where it colours by scalars, a cell's or the mean of the corners'), field data "ImageSize".
   */
  vtkPolyData* GetFaces();

  ///@{
  /**
   * What the last UpdateFaces() did: the pieces made by splitting faces, and the seconds it took.
   */
  vtkIdType GetNumberOfFaceSplits() const;
  double GetFacesTime() const;
  ///@}

  ///@{
  /**
   * What the last Update() did besides vtkNPRRendererLines's counts (whose rays include the
   * bisection's and whose visibility time includes the splitting).
   */
  vtkIdType GetNumberOfStrokes() const;
  double GetChainTime() const; // seconds chaining the pieces into strokes
  ///@}

  ///@{
  /**
   * The parts of the renderer's visible 3D props (assemblies' parts included) that the last
   * Update() drew nothing of, neither lines nor faces nor points: volumes, image slices,
   * translucent actors, actors of other mappers or of non-polygonal data. How many, and each
   * one's description in drawing order ("vtkVolume", "translucent vtkActor", "vtkActor of a
   * vtkUnstructuredGrid", "vtkActor drawn by vtkGlyph3DMapper"); null past the last.
   */
  vtkIdType GetNumberOfPropsLeftOut() const;
  const char* GetPropLeftOut(vtkIdType index) const;
  ///@}

  /**
   * Bytes held between updates: each mesh's edge table (vtkNPRFeatureLines::
   * GetAdjacencyMemorySize()) and the occlusion structure; the meshes' own points and cells,
   * which both read in place, not counted. About 75 a triangle.
   */
  size_t GetMemorySize() const;

protected:
  vtkNPRDrawingLines();
  ~vtkNPRDrawingLines() override;

  bool HiddenLines = false;
  bool PointPrimitives = false;
  double SampleSpacing = 1.0;

private:
  vtkNPRDrawingLines(const vtkNPRDrawingLines&) = delete;
  void operator=(const vtkNPRDrawingLines&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
