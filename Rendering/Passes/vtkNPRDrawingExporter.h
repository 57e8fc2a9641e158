// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkNPRDrawingExporter
 * @brief   Writes a renderer's lines as a vector drawing: SVG, PDF, PostScript or EPS.
 *
 * Write() computes the strokes of the renderer's scene (visible lines, and hidden ones when the
 * style asks for them) with the drawing pass's vtkNPRDrawingLines, so that the edge table and
 * occluders its frames built are used again, or with its own when there is no drawing pass (no
 * vtkNPRPass and none given with SetDrawingPass()), and paints them with Cairo, the same
 * painting as the drawing style's (vtkNPRStrokePainter): one path a stroke, round caps and joins,
 * hidden strokes dashed under the visible ones.
 *
 * - Format: from the file name's extension, `.svg`, `.pdf`, `.ps` or `.eps` (any case). Any
 *   other extension is an error naming these (GetSupportedExtensions()).
 * - Page: the image size (Size, or the renderer's size in its window), 1 image pixel = 1 point
 *   (1/72 inch; the 72 DPI at which VTK's line widths are given), so line widths are in points.
 *   The SVG's width and height are in `pt` with a viewBox of the image in pixels.
 * - Style: the renderer's vtkNPRPass (its drawing pass's HiddenLines, HiddenLineColor,
 *   HiddenLineWidth, DashLength, GapLength; its edge pass's line types, colours, width and crease
 *   angle), or the passes given with SetDrawingPass() and SetEdgePass(), or the defaults.
 * - Background: a rectangle of the renderer's background colour. When the renderer's style is
 *   not "drawing" (or it has no vtkNPRPass), the window's image (rendered again) is embedded as a
 *   raster under the lines (EmbedImage: -1, the default, decides so; 0 never; 1 always).
 * - Faces (FillFaces): the visible faces as filled polygons, in the drawing style's FaceColor
 *   or each actor's own colours (FillColors), painted back to front over the background.
 * - Order and structure: background, raster or faces, hidden strokes, then the visible silhouettes,
 *   boundaries, creases, non-manifold edges, intersection curves and, where no image is embedded,
 *   the scene's own line cells (an outline box, axes: vtkNPRDrawingLines' LinePrimitives, hidden
 *   where behind a surface, each in its actor's colour and line width) and the polygon edges of
 *   its wireframes and of its surfaces with EdgeVisibility (in their EdgeColor), its point
 * primitives (vertex cells and point clouds: PointPrimitives; squares of the actor's PointSize,
 * discs where it renders points as spheres, in the point's colour; a hidden point is left out) and,
 *   with Overlays on, its 2D props over everything: text (vtkTextActor, or a vtkActor2D of a
 *   vtkTextMapper) as the glyph outlines VTK's text renderer gives, and every other 2D prop (a
 *   scalar bar, a corner annotation, a logo) as one embedded image of its own pixels, with
 *   their coverage, so that faces and lines stay vector under it. In an SVG file each of
 *   these classes is a `<g class="npr-hidden">`, `npr-silhouette`, `npr-boundary`,
 *   `npr-crease`, `npr-non-manifold`, `npr-intersection`, `npr-line`, `npr-point`, `npr-text`
 *   group of `<path>` elements, one per stroke, point or text (hidden strokes with a
 *   `stroke-dasharray`; a text's background box and frame are paths of its group too), so a
 *   style sheet or an editor can restyle a class; the image of the other 2D props is last. Cairo
 * writes no classes itself: the groups are added to its output afterwards (if its output has not
 * the expected form, the file is written without them and a warning says so). PDF and PostScript
 *   files have the same painting order, without groups.
 *
 * Errors (Write() returns false, GetErrorCode() is a vtkErrorCode and GetErrorMessage() says
 * why): no renderer, no file name, an unknown extension, no size, a path that cannot be written
 * (a missing folder, a folder); no file is left behind. An empty scene gives a valid empty
 * drawing (the background, and the raster if any).
 *
 * @sa vtkNPRDrawingLines vtkNPRDrawingPass vtkNPRPass
 */
#ifndef vtkNPRDrawingExporter_h
#define vtkNPRDrawingExporter_h

#include "vtkNPRPassesModule.h" // for export macro
#include "vtkObject.h"

#include <memory> // for std::unique_ptr
#include <string> // for the error message

typedef struct _cairo cairo_t;
class vtkImageData;
class vtkNPRDrawingLines;
class vtkNPRDrawingPass;
class vtkNPREdgePass;
class vtkRenderWindow;
class vtkRenderer;

class VTKNPRPASSES_EXPORT vtkNPRDrawingExporter : public vtkObject
{
public:
  static vtkNPRDrawingExporter* New();
  vtkTypeMacro(vtkNPRDrawingExporter, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Formats
  {
    SVG = 0,
    PDF = 1,
    PS = 2,
    EPS = 3
  };

  ///@{
  /**
   * The renderer to draw; without one, the first renderer of RenderWindow.
   */
  virtual void SetRenderer(vtkRenderer* renderer);
  vtkGetObjectMacro(Renderer, vtkRenderer);
  virtual void SetRenderWindow(vtkRenderWindow* window);
  vtkGetObjectMacro(RenderWindow, vtkRenderWindow);
  ///@}

  ///@{
  /**
   * The file to write; its extension gives the format.
   */
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

  ///@{
  /**
   * The image size in pixels, which is the page size in points; 0, 0 (the default): the
   * renderer's size in its window.
   */
  vtkSetVector2Macro(Size, int);
  vtkGetVector2Macro(Size, int);
  ///@}

  ///@{
  /**
   * The passes whose settings style the lines; without them, those of the renderer's
   * vtkNPRPass, else the defaults.
   */
  virtual void SetDrawingPass(vtkNPRDrawingPass* pass);
  vtkGetObjectMacro(DrawingPass, vtkNPRDrawingPass);
  virtual void SetEdgePass(vtkNPREdgePass* pass);
  vtkGetObjectMacro(EdgePass, vtkNPREdgePass);
  ///@}

  enum FillColorModes
  {
    FACE_COLOR = 0,     ///< the drawing pass's FaceColor (white without one): as the style draws
    SURFACE_COLORS = 1, ///< each face's actor colour or mapped scalar colour, without lighting
    TOON_BANDS = 2      ///< those colours in the toon bands of the renderer's lights
  };

  ///@{
  /**
   * Fill the visible faces under the lines (off by default): vtkNPRDrawingLines::UpdateFaces()'s
   * polygons, back to front, so that the file shows the faces as the render does, nothing
   * behind showing through, as regions an editor can select and recolour. In FillColors:
   * FACE_COLOR (the default; the drawing style's picture), SURFACE_COLORS (each actor's
   * colour, or its scalar colours, flat and unlit: a coloured figure) or TOON_BANDS (those
   * colours lit in the toon bands of the renderer's lights, flat per face: the toon styles'
   * picture on flat faces; the vtkNPRPass's toon pass's bands or table, else 3 bands;
   * highlights are not filled). Each polygon is also
   * stroked with FillSeam pixels (default 1, clamped to [0, 2]) in its own colour, which
   * closes the hairline gaps anti-aliasing viewers leave between neighbouring polygons.
   */
  vtkSetMacro(FillFaces, bool);
  vtkGetMacro(FillFaces, bool);
  vtkBooleanMacro(FillFaces, bool);
  vtkSetClampMacro(FillColors, int, FACE_COLOR, TOON_BANDS);
  vtkGetMacro(FillColors, int);
  vtkSetClampMacro(FillSeam, double, 0.0, 2.0);
  vtkGetMacro(FillSeam, double);
  ///@}

  ///@{
  /**
   * Paint the renderer's 2D props (text, scalar bars, legends) over the drawing when no image
   * is embedded (on by default; with an embedded image they are part of it): text as vector
   * outlines, the other props as an image of their pixels (the window is rendered twice more
   * with only those props, and once again to show its picture).
   */
  vtkSetMacro(Overlays, bool);
  vtkGetMacro(Overlays, bool);
  vtkBooleanMacro(Overlays, bool);
  ///@}

  ///@{
  /**
   * Embed the window's image under the lines: -1 (the default) when the renderer's style is
   * not "drawing"
   * and FillFaces is off, 0 never, 1 always.
   */
  vtkSetClampMacro(EmbedImage, int, -1, 1);
  vtkGetMacro(EmbedImage, int);
  ///@}

  /**
   * Writes the file. False, with GetErrorCode() and GetErrorMessage(), on an error.
   */
  bool Write();

  /**
   * The format of a file name from its extension (Formats), -1 for an unsupported one.
   */
  static int GetFormatFromFileName(const char* fileName);

  /**
   * ".svg, .pdf, .ps, .eps".
   */
  static const char* GetSupportedExtensions();

  ///@{
  /**
   * The outcome of the last Write(): a vtkErrorCode value (0: none) and the message.
   */
  vtkGetMacro(ErrorCode, unsigned long);
  const char* GetErrorMessage() const;
  ///@}

  /**
   * The vtkNPRDrawingLines that computed the strokes of the last Write() (the drawing pass's,
   * else the exporter's own; the size, line types, crease angle and hidden lines are set by
   * Write(), and the drawing pass's lines are given back their renderer-free state after it).
   */
  vtkNPRDrawingLines* GetDrawingLines();

  ///@{
  /**
   * What the last Write() painted: the paths of a class (0 hidden, 1 silhouette, 2 boundary,
   * 3 crease, 4 non-manifold, 5 intersection strokes, 6 the scene's line cells, 7 its points,
   * 8 the texts' paths) and in all; the texts and the 2D props in the embedded image
   * (Overlays); whether the SVG's groups were labelled; whether a raster was embedded; the
   * polygons filled (FillFaces); the 3D props (or assembly parts) left out of a figure without
   * the window's image, which Write() names in a warning (volumes, image slices, translucent
   * actors, other mappers than polygonal data's: EmbedImage 1 shows them as pixels); the seconds
   * computing the strokes (and the faces) and painting and writing the file.
   */
  vtkIdType GetNumberOfStrokes(int strokeClass) const;
  vtkIdType GetNumberOfStrokes() const;
  vtkIdType GetNumberOfTexts() const;
  vtkIdType GetNumberOfImagedOverlays() const;
  vtkIdType GetNumberOfFilledFaces() const;
  vtkIdType GetNumberOfPropsLeftOut() const;
  bool GetClassesLabelled() const;
  bool GetImageEmbedded() const;
  double GetStrokesTime() const;
  double GetWriteTime() const;
  ///@}

protected:
  vtkNPRDrawingExporter();
  ~vtkNPRDrawingExporter() override;

  vtkRenderer* Renderer = nullptr;
  vtkRenderWindow* RenderWindow = nullptr;
  char* FileName = nullptr;
  int Size[2] = { 0, 0 };
  vtkNPRDrawingPass* DrawingPass = nullptr;
  vtkNPREdgePass* EdgePass = nullptr;
  int EmbedImage = -1;
  bool FillFaces = false;
  int FillColors = FACE_COLOR;
  double FillSeam = 1.0;
  bool Overlays = true;
  unsigned long ErrorCode = 0;

private:
  vtkNPRDrawingExporter(const vtkNPRDrawingExporter&) = delete;
  void operator=(const vtkNPRDrawingExporter&) = delete;

  bool Fail(unsigned long code, const std::string& message);

  // The steps of Write(); each but ResolveStyle() returns false after Fail().
  struct Target;
  bool CheckPath(Target& target);
  bool FindRenderer(Target& target);
  void ResolveStyle(Target& target);
  bool ComputeStrokes(const Target& target, bool linePrimitives);
  // Counts and names in a warning the 3D props a figure without the window's image leaves out.
  void ReportPropsLeftOut(const Target& target);
  bool Paint(const Target& target, vtkImageData* raster, std::string& bytes);
  bool PaintFaces(cairo_t* cr, const Target& target, std::string& error);
  bool WriteFile(const std::string& path, const std::string& bytes);

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
