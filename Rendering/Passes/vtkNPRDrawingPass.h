// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkNPRDrawingPass
 * @brief   A technical drawing: faces in one colour, visible lines solid, hidden lines dashed,
 *          from exact object-space lines, written as a depth sprite.
 *
 * Reads the G-buffer of the edge pass's vtkNPRGBufferPass (drawn earlier in the frame: its
 * colour for the background, its depth) and draws over it:
 * - the faces (every pixel the G-buffer covers) in FaceColor;
 * - the strokes of a vtkNPRDrawingLines for the renderer (object space, double precision, props
 *   hiding each other's lines), rasterised with anti-aliasing:
 *   - visible lines solid, in the edge pass's colours (silhouettes and boundaries in its
 *     SilhouetteColor, creases and non-manifold edges in its CreaseColor), its effective line
 *     width (LineWidth x DPI / 72 x tile scale), with round caps and joins;
 *   - with HiddenLines on, hidden lines under them, HiddenLineWidth times as wide, in
 *     HiddenLineColor, dashed in screen space: DashLength on, GapLength off (pixels, scaled like
 *     the line width), the pattern running on along each stroke.
 * The line types and the crease angle are the edge pass's (Silhouettes: silhouettes and
 * boundaries; Creases: creases and non-manifold edges; CreaseAngle).
 *
 * Depth sprite: a face pixel keeps its depth; a line pixel off the faces (a silhouette drawn
 * over the background) takes the nearest depth within the line's reach, so translucent props,
 * volumes and layers drawn later are depth-tested against the drawing as drawn.
 *
 * The strokes are computed again only when the camera, the size, the scene (actors, their
 * meshes and matrices) or a setting changed; GetNumberOfStrokeUpdates() counts the updates.
 * Their cost is the CPU's (see vtkNPRDrawingLines): fractions of a second for CAD parts,
 * seconds for million-triangle meshes, so this style suits figures more than interaction.
 *
 * @sa vtkNPRPass vtkNPRDrawingLines vtkNPRDrawingExporter
 */
#ifndef vtkNPRDrawingPass_h
#define vtkNPRDrawingPass_h

#include "vtkNPREdgeEffectPass.h"
#include "vtkNPRPassesModule.h" // for export macro

#include <memory> // for std::unique_ptr
#include <string> // for std::string

class vtkNPRDrawingLines;
class vtkRenderer;
class vtkPolyData;

class VTKNPRPASSES_EXPORT vtkNPRDrawingPass : public vtkNPREdgeEffectPass
{
public:
  static vtkNPRDrawingPass* New();
  vtkTypeMacro(vtkNPRDrawingPass, vtkNPREdgeEffectPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;
  void ReleaseGraphicsResources(vtkWindow* window) override;

  ///@{
  /**
   * Draw the hidden lines, dashed (off by default).
   */
  vtkSetMacro(HiddenLines, bool);
  vtkGetMacro(HiddenLines, bool);
  vtkBooleanMacro(HiddenLines, bool);
  ///@}

  ///@{
  /**
   * The colour of the faces (default white).
   */
  vtkSetVector3Macro(FaceColor, double);
  vtkGetVector3Macro(FaceColor, double);
  ///@}

  ///@{
  /**
   * The colour of the hidden lines (default 0.45 grey).
   */
  vtkSetVector3Macro(HiddenLineColor, double);
  vtkGetVector3Macro(HiddenLineColor, double);
  ///@}

  ///@{
  /**
   * The width of the hidden lines relative to the visible ones (default 0.6, clamped to
   * [0.1, 1]).
   */
  vtkSetClampMacro(HiddenLineWidth, double, 0.1, 1.0);
  vtkGetMacro(HiddenLineWidth, double);
  ///@}

  ///@{
  /**
   * The dash pattern of the hidden lines in pixels at 72 DPI (default 6 on, 4 off; each clamped
   * to [0.5, 100]).
   */
  vtkSetClampMacro(DashLength, double, 0.5, 100.0);
  vtkGetMacro(DashLength, double);
  vtkSetClampMacro(GapLength, double, 0.5, 100.0);
  vtkGetMacro(GapLength, double);
  ///@}

  ///@{
  /**
   * Tapered ends: the visible strokes' width grows from nothing at an open end to its full width
   * over TaperLength pixels at 72 DPI (default 0: no taper; clamped to [0, 200]). A closed
   * stroke has no end. In the image and in vector files (each stroke then one filled outline).
   */
  vtkSetClampMacro(TaperLength, double, 0.0, 200.0);
  vtkGetMacro(TaperLength, double);
  ///@}

  ///@{
  /**
   * Width from curvature: a visible stroke is up to 1 + CurvatureWidth times as wide where it
   * bends (fully where its radius of curvature is 8 pixels or less; default 0: off; clamped to
   * [0, 4]).
   */
  vtkSetClampMacro(CurvatureWidth, double, 0.0, 4.0);
  vtkGetMacro(CurvatureWidth, double);
  ///@}

  /**
   * The vtkNPRDrawingLines this pass computes its strokes with (its settings other than the
   * renderer, size, line types, crease angle and hidden lines can be tuned). Its renderer is set
   * only while the pass updates the strokes: the renderer holds the pass.
   */
  vtkNPRDrawingLines* GetDrawingLines();

  /**
   * The strokes of the last frame drawn (see vtkNPRDrawingLines::GetStrokes()).
   */
  vtkPolyData* GetStrokes();

  /**
   * How many times the strokes were computed.
   */
  vtkIdType GetNumberOfStrokeUpdates() const;

protected:
  vtkNPRDrawingPass();
  ~vtkNPRDrawingPass() override;

  // The steps of the frame (vtkNPRImageEffectPass) beside the G-buffer (vtkNPREdgeEffectPass).
  bool UpdateImages(const vtkRenderState* state) override;
  std::string GetCompositeKey(vtkRenderer* renderer) override;
  void GetCompositeRectangle(vtkRenderer* renderer, int rect[4]) override;
  bool DrawComposite(const vtkRenderState* state, const int origin[2]) override;

  bool HiddenLines = false;
  double FaceColor[3] = { 1.0, 1.0, 1.0 };
  double HiddenLineColor[3] = { 0.45, 0.45, 0.45 };
  double HiddenLineWidth = 0.6;
  double DashLength = 6.0;
  double GapLength = 4.0;
  double TaperLength = 0.0;
  double CurvatureWidth = 0.0;

private:
  vtkNPRDrawingPass(const vtkNPRDrawingPass&) = delete;
  void operator=(const vtkNPRDrawingPass&) = delete;

  // The strokes of the meshes for this renderer, rasterised at width x height; false on error.
  bool UpdateStrokes(vtkRenderer* renderer, int width, int height);
  std::string GetDrawingDefines(vtkRenderer* renderer) const;

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
