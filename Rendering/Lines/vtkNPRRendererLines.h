// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkNPRRendererLines
 * @brief   The base of vtkNPRReferenceMask and vtkNPRDrawingLines: a renderer's feature lines
 *          and what hides them, for an image size.
 *
 * Holds what both take as input (the renderer, the image size, the line settings, the
 * occlusion epsilon of their rays) and what both report of an update (the feature edges, the
 * rays cast, the seconds spent on the lines, the occlusion structure and the visibility, the
 * builds of the occlusion structure); the scene itself (each actor's vtkNPRFeatureLines, kept
 * between updates, and the occlusion structure of all their triangles) is shared by the
 * subclass's Update() through the protected StartUpdate() and UpdateScene().
 *
 * @sa vtkNPRReferenceMask vtkNPRDrawingLines vtkNPRLineSettings
 */
#ifndef vtkNPRRendererLines_h
#define vtkNPRRendererLines_h

#include "vtkNPRLineSettings.h" // for vtkNPRLineSettingsMacro
#include "vtkNPRLinesModule.h"  // for export macro
#include "vtkNew.h"             // for LineSettings
#include "vtkObject.h"

#include <memory> // for std::unique_ptr

class vtkNPRSceneLines;
class vtkRenderer;

class VTKNPRLINES_EXPORT vtkNPRRendererLines : public vtkObject
{
public:
  vtkTypeMacro(vtkNPRRendererLines, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The renderer whose camera and actors are used.
   */
  virtual void SetRenderer(vtkRenderer* renderer);
  vtkGetObjectMacro(Renderer, vtkRenderer);
  ///@}

  ///@{
  /**
   * The image size in pixels; 0, 0 (the default): the renderer's size in its window.
   */
  vtkSetVector2Macro(Size, int);
  vtkGetVector2Macro(Size, int);
  ///@}

  ///@{
  /**
   * The line types (all on by default, as in vtkNPRFeatureLines) and CreaseAngle, the angle
   * between face normals in degrees above which an edge is a crease (default 30, vtkNPREdgePass's
   * default; clamped to [0, 180]): GetLineSettings()'s, forwarded (vtkNPRLineSettings).
   */
  vtkNPRLineSettingsMacro(CreaseAngle);
  ///@}

  ///@{
  /**
   * With creases on, also the curves where two surfaces cross at more than CreaseAngle (on by
   * default): parts of one mesh that pass through each other (a boss through a housing, a pin
   * through a block) or two actors. They are edges of no mesh, but the image shows a crease
   * there and the edge pass draws one. Found once per occlusion structure: every pair of
   * triangles that share no corner and whose boxes overlap is intersected (the crossings' cost is
   * part of GetLocatorTime()); their FeatureType is CREASE | INTERSECTION.
   */
  vtkSetMacro(IntersectionCurves, bool);
  vtkGetMacro(IntersectionCurves, bool);
  vtkBooleanMacro(IntersectionCurves, bool);
  ///@}

  ///@{
  /**
   * Silhouettes as smooth contours (off by default): passed to each actor's
   * vtkNPRFeatureLines, so a mesh with point normals gets the contour of its interpolated
   * normals (the outline its shading shows; where the normals are split, the mesh edges that
   * are silhouettes), one without keeps its mesh silhouettes. A smooth contour lies inside a
   * triangle, often a back-facing one just behind the front faces next to it: its visibility
   * tests ignore the faces about its triangle (vtkNPRReferenceMask has the rule).
   */
  vtkSetMacro(SmoothContours, bool);
  vtkGetMacro(SmoothContours, bool);
  vtkBooleanMacro(SmoothContours, bool);
  ///@}

  ///@{
  /**
   * How much of the segment from the near plane to a sample is left untested at the sample's
   * end, relative to its length, so that the faces that contain the line do not hide it
   * (default 1e-6, clamped to [0, 0.01]).
   */
  vtkSetClampMacro(OcclusionEpsilon, double, 0.0, 0.01);
  vtkGetMacro(OcclusionEpsilon, double);
  ///@}

  /**
   * Computes the subclass's result. False, with an error, when there is no renderer or no size.
   */
  virtual bool Update() = 0;

  ///@{
  /**
   * What the last Update() did.
   */
  vtkIdType GetNumberOfFeatureEdges() const { return this->FeatureEdges; } // of all actors
  vtkIdType GetNumberOfRayCasts() const { return this->RayCasts; }         // visibility tests
  double GetLinesTime() const { return this->LinesTime; }           // seconds finding the lines
  double GetLocatorTime() const { return this->LocatorTime; }       // seconds building occluders
  double GetVisibilityTime() const { return this->VisibilityTime; } // seconds casting rays
  ///@}

  /**
   * How many times the occlusion structure (all actors' triangles, located) has been built:
   * again only when an actor's mesh or matrix, the set of actors or the structure's shape
   * (vtkNPRReferenceMask's TrianglesPerLocator) changed.
   */
  vtkIdType GetNumberOfLocatorBuilds() const;

protected:
  vtkNPRRendererLines();
  ~vtkNPRRendererLines() override;

  // The start of Update(): the counts and times zeroed, the image size; false, with an error,
  // when there is no renderer or no size.
  bool StartUpdate(int& width, int& height);
  // The actors' feature lines for the camera and the occlusion structure, with smooth contours
  // and intersection curves as asked; FeatureEdges, LinesTime and LocatorTime set.
  void UpdateScene(int trianglesPerLocator);
  vtkNPRSceneLines& GetScene() const { return *this->Scene; }

  vtkRenderer* Renderer = nullptr;
  int Size[2] = { 0, 0 };
  vtkNew<vtkNPRLineSettings> LineSettings;
  double OcclusionEpsilon = 1e-6;
  bool IntersectionCurves = true;
  bool SmoothContours = false;
  bool LinePrimitives = false; // vtkNPRDrawingLines': the scene's line cells as strokes

  vtkIdType FeatureEdges = 0;
  vtkIdType RayCasts = 0;
  double LinesTime = 0.0;
  double LocatorTime = 0.0;
  double VisibilityTime = 0.0;

private:
  vtkNPRRendererLines(const vtkNPRRendererLines&) = delete;
  void operator=(const vtkNPRRendererLines&) = delete;

  std::unique_ptr<vtkNPRSceneLines> Scene;
};

#endif
