// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkNPRReferenceMask
 * @brief   The ground truth of a line drawing: a renderer's visible feature lines, as a pixel mask.
 *
 * For a renderer (its active camera and its visible, opaque vtkActors drawn by a
 * vtkPolyDataMapper, or a vtkDataSetMapper of a vtkPolyData, with their actor matrices) and an
 * image size, Update() computes on the CPU,
 * in double precision and without OpenGL:
 * - the feature lines of each actor's mesh, with a vtkNPRFeatureLines per actor (kept between
 *   updates, so each mesh's adjacency is built once): silhouettes for the camera taken into the
 *   actor's coordinates, creases above CreaseAngle, boundaries and non-manifold edges, each
 *   switched on its own; then put into world coordinates with the actor's matrix;
 * - which parts of them are visible: each line segment is clipped to the view frustum (near
 *   and far planes, the image) in homogeneous coordinates and sampled in the image at most
 *   SampleSpacing pixels apart (at least its two ends). Each sample is tested by casting a
 *   segment through a bounding volume hierarchy of all the actors' triangles in world
 *   coordinates, from the near plane (towards the eye for a perspective camera, along the direction
 * of projection for a parallel one: what lies before the near plane is clipped when rendering) to
 * the sample, stopped short of the sample by OcclusionEpsilon times its length, so that the faces
 * that contain the line do not hide it. A sample that nothing hides marks the pixel that contains
 * it.
 *
 * The projection is the camera's composite projection matrix
 * (vtkCamera::GetCompositeProjectionTransformMatrix with the image's aspect ratio, near -1, far
 * 1), as VTK renders with it, and pixel (i, j) covers [i, i+1) x [j, j+1) of the window
 * coordinates ((ndc + 1) / 2 x size), so the mask lines up with an image rendered from the same
 * camera at the same size.
 *
 * Output: GetMask(), a vtkImageData of Size, one unsigned char component, 255 on line pixels and
 * 0 elsewhere, row 0 at the bottom (as vtkWindowToImageFilter gives a window's image); with
 * GenerateVisibleLines on, GetVisibleLines(): the visible runs of samples as polylines in world
 * coordinates, with the cell array "FeatureType" of their edges (vtkNPRFeatureLines's bits).
 * The counts of the last update tell what was done: feature edges, samples in the view, rays
 * cast (a sample whose pixel is already marked needs none unless visible lines are asked for),
 * visible samples, line pixels; and the seconds spent on lines, locator and visibility.
 *
 * Accuracy: visibility is exact up to OcclusionEpsilon (default 1e-6 of the distance from the
 * near plane: an occluder closer than that to the line does not count) and the rounding of
 * double precision; positions are rounded to the pixel that contains the sample (a line pixel
 * lies within half a pixel diagonal, 0.71 px, of the exact visible line); a visible piece
 * shorter than SampleSpacing between two samples can be missed, and a line crossing a pixel's
 * corner by less than that can be missed in that pixel. Not included: lines of translucent actors
 * (and translucent actors do not hide lines, as they do not in vtkNPREdgePass's G-buffer), props
 * that are not vtkActors with those mappers (volumes, images, glyph mappers) and mapper
 * clipping planes; the parts of assemblies and a vtkLODProp3D's drawn level are included
 * (vtkNPRPropParts). Polygons are split into triangle fans
 * for the visibility test (exact for convex planar polygons).
 *
 * Smooth contours (SmoothContours, off by default; vtkNPRFeatureLines's SMOOTH_CONTOUR): such
 * a line lies inside a triangle, and on a coarse mesh often on a back-facing triangle just
 * behind the front-facing triangles next to the mesh's silhouette edge, so the ray above would
 * hide it along much of an outline. Its samples use another rule: the triangles that share a
 * point with the contour's triangle (by id or by equal coordinates, so also across points split
 * by vtkPolyDataNormals), and those with a corner closer to the sample than that triangle's
 * longest edge, do not count as occluders, as if the ray went on past them; every other
 * triangle, of the same mesh or another actor, hides as before. The contour lies about a
 * sagitta inside the smooth surface, so a grazing ray enters the surface up to about an edge
 * length from it, often beyond the triangles next to its own (with those alone, the drawing of
 * drawing.md's isosurfaces had 278 strokes, 149 hidden, many of them short pieces that broke
 * visible outlines; with the corners within reach too, 139 and 78, the outlines whole). Chosen
 * over a ray stopped short by twice the triangle's
 * longest edge, which would also let through large occluders crossing the ray there (a face of
 * a touching object); the cost is three exact point comparisons and three distances per
 * triangle hit, and a copy of the scene's points, 24 bytes a point. The accuracy limit: a fold
 * of the mesh, or another object's corner, within one edge length of the contour does not hide
 * it.
 *
 * The occlusion structure is rebuilt only when an actor's geometry, its matrix or the set of
 * actors changed (GetNumberOfLocatorBuilds()). Cost, measured on a 2-core machine (see
 * Documentation/feature-lines.md): a fraction of a second for a 75k-triangle mesh at
 * 1920x1080, a few seconds for 1.2M triangles.
 *
 * Call Update() after the camera is final (after a Render() if the renderer resets its
 * clipping range): the camera is read as it is.
 *
 * @sa vtkNPRFeatureLines vtkNPREdgePass
 */
#ifndef vtkNPRReferenceMask_h
#define vtkNPRReferenceMask_h

#include "vtkNPRLinesModule.h" // for export macro
#include "vtkNPRRendererLines.h"

#include <memory> // for std::unique_ptr

class vtkImageData;
class vtkPolyData;

class VTKNPRLINES_EXPORT vtkNPRReferenceMask : public vtkNPRRendererLines
{
public:
  static vtkNPRReferenceMask* New();
  vtkTypeMacro(vtkNPRReferenceMask, vtkNPRRendererLines);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The largest distance in pixels between the samples of a line (default 0.25, clamped to
   * [0.01, 0.25]).
   */
  vtkSetClampMacro(SampleSpacing, double, 0.01, 0.25);
  vtkGetMacro(SampleSpacing, double);
  ///@}

  ///@{
  /**
   * Also output the visible parts of the lines as polylines (off by default; costs a ray for
   * every sample).
   */
  vtkSetMacro(GenerateVisibleLines, bool);
  vtkGetMacro(GenerateVisibleLines, bool);
  vtkBooleanMacro(GenerateVisibleLines, bool);
  ///@}

  ///@{
  /**
   * The occlusion structure, a bounding volume hierarchy over the triangles in Morton order of
   * their centroids, splits them first into groups of at most this many (default 16384, at
   * least 1), each a subtree, then halves each group down to leaves of at most 8. This changes
   * the shape of the tree, never the result.
   */
  vtkSetClampMacro(TrianglesPerLocator, int, 1, VTK_INT_MAX);
  vtkGetMacro(TrianglesPerLocator, int);
  ///@}

  /**
   * Computes the mask (and the visible lines). False, with an error, when there is no renderer
   * or no size.
   */
  bool Update() override;

  /**
   * The mask of the last Update(): Size, unsigned char, 255 on lines, row 0 at the bottom.
   */
  vtkImageData* GetMask();

  /**
   * The visible lines of the last Update() in world coordinates (empty unless
   * GenerateVisibleLines is on).
   */
  vtkPolyData* GetVisibleLines();

  ///@{
  /**
   * What the last Update() did besides vtkNPRRendererLines's counts (whose rays are the
   * samples tested by a ray).
   */
  vtkIdType GetNumberOfSamples() const;        // samples inside the view
  vtkIdType GetNumberOfVisibleSamples() const; // tested samples that nothing hides
  vtkIdType GetNumberOfLinePixels() const;     // pixels set in the mask
  ///@}

  /**
   * The sum of the adjacency builds of the actors' vtkNPRFeatureLines (each mesh once while it
   * does not change).
   */
  vtkIdType GetNumberOfAdjacencyBuilds() const;

protected:
  vtkNPRReferenceMask();
  ~vtkNPRReferenceMask() override;

  double SampleSpacing = 0.25;
  bool GenerateVisibleLines = false;
  int TrianglesPerLocator = 16384;

private:
  vtkNPRReferenceMask(const vtkNPRReferenceMask&) = delete;
  void operator=(const vtkNPRReferenceMask&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
