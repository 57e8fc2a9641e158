// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkNPRDrawingSheet
 * @brief   The standard views of a scene on one page, as a vector file: a drawing sheet.
 *
 * Write() computes the technical drawing's strokes (vtkNPRDrawingLines: the visible, opaque
 * vtkActors of the renderer, hidden lines on request) once per view, each view a parallel
 * projection of the scene's bounding box along its axis, and paints them on one page:
 * - Views (default "iso,front,top,right"; any of iso, front, top, right, left, back, bottom,
 *   comma separated, each once): front looks along -z with y up (VTK's default camera), top down
 *   -y with the front (+z) at the bottom, right along -x, left along +x, back along +z, bottom
 *   up +y, iso along (-1, -1, -1) with y up. The renderer's own camera is not changed.
 * - Arrangement: FIRST_ANGLE (the default, ISO 128's first-angle projection: the top view under
 *   the front view, the right view to its left) or THIRD_ANGLE (ASME's: the top view above the
 *   front view, the right view to its right); the back view at the far end of the row, the iso
 *   view in the free corner above the side views. Views in one column share their x axis and
 *   views in one row their y axis, as projection lines would join them.
 * - Scale: one for every view (iso included), the largest that fits the grid of views, the gaps
 *   between them (Gap, millimetres) and a line under each for its name, inside the margins. The
 *   page's bottom right corner names it: "scale 1 : N", N the model units one millimetre of
 *   paper stands for (GetScale(): points per model unit).
 * - Page: A4 (the default), A3 or LETTER, landscape by default, Margin millimetres (default 10)
 *   on each side, white. 1 point = 1/72 inch.
 * - Style: the renderer's vtkNPRPass (its drawing pass's HiddenLines and dashes, its edge pass's
 *   line types, colours, widths in points and crease angle, and SmoothSilhouettes), else the
 *   defaults, as vtkNPRDrawingExporter has it.
 * - Format: from FileName's extension: .svg, .pdf, .ps, .eps.
 *
 * Errors (Write() returns false, GetErrorCode() is a vtkErrorCode and GetErrorMessage() says
 * why; no file is left behind): no renderer, no file name, an unknown extension, a path that
 * cannot be written, an unknown or repeated view name, no view, nothing visible to draw.
 *
 * Cost: the strokes of each view (see vtkNPRDrawingLines; the occlusion structure is built once
 * for all the views) and the painting: the CAD part's four views in about 0.1 s on llvmpipe's
 * 2-core machine (Documentation/drawing.md).
 *
 * @sa vtkNPRDrawingExporter vtkNPRDrawingLines vtkNPRPass
 */
#ifndef vtkNPRDrawingSheet_h
#define vtkNPRDrawingSheet_h

#include "vtkNPRPassesModule.h" // for export macro
#include "vtkObject.h"

#include <memory> // for std::unique_ptr
#include <string> // for the error message

typedef struct _cairo cairo_t;
class vtkRenderer;

class VTKNPRPASSES_EXPORT vtkNPRDrawingSheet : public vtkObject
{
public:
  static vtkNPRDrawingSheet* New();
  vtkTypeMacro(vtkNPRDrawingSheet, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Arrangements
  {
    FIRST_ANGLE = 0,
    THIRD_ANGLE = 1
  };

  enum PaperSizes
  {
    A4 = 0,
    A3 = 1,
    LETTER = 2
  };

  ///@{
  /**
   * The renderer whose actors are drawn (its camera is left as it is).
   */
  virtual void SetRenderer(vtkRenderer* renderer);
  vtkGetObjectMacro(Renderer, vtkRenderer);
  ///@}

  ///@{
  /**
   * The file to write; its extension gives the format (.svg, .pdf, .ps, .eps).
   */
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

  ///@{
  /**
   * The views, comma separated (default "iso,front,top,right").
   */
  vtkSetStringMacro(Views);
  vtkGetStringMacro(Views);
  ///@}

  ///@{
  /**
   * FIRST_ANGLE (the default) or THIRD_ANGLE.
   */
  vtkSetClampMacro(Arrangement, int, FIRST_ANGLE, THIRD_ANGLE);
  vtkGetMacro(Arrangement, int);
  ///@}

  ///@{
  /**
   * The paper: A4 (the default), A3 or LETTER, landscape (the default) or portrait; the margin
   * on each side in millimetres (default 10, clamped to [0, 50]) and the gap between views
   * (default 10, clamped to [0, 50]).
   */
  vtkSetClampMacro(PaperSize, int, A4, LETTER);
  vtkGetMacro(PaperSize, int);
  vtkSetMacro(Landscape, bool);
  vtkGetMacro(Landscape, bool);
  vtkBooleanMacro(Landscape, bool);
  ///@{
  /**
   * Fill each view's visible faces under its lines (off by default), in FillColors:
   * vtkNPRDrawingExporter's FillColorModes, FACE_COLOR (the default; the drawing pass's
   * FaceColor), SURFACE_COLORS or TOON_BANDS (the renderer's lights as they are: a headlight
   * stays where the last render put it), as vtkNPRDrawingExporter's FillFaces.
   */
  vtkSetMacro(FillFaces, bool);
  vtkGetMacro(FillFaces, bool);
  vtkBooleanMacro(FillFaces, bool);
  vtkSetClampMacro(FillColors, int, 0, 2);
  vtkGetMacro(FillColors, int);
  ///@}

  vtkSetClampMacro(Margin, double, 0.0, 50.0);
  vtkGetMacro(Margin, double);
  vtkSetClampMacro(Gap, double, 0.0, 50.0);
  vtkGetMacro(Gap, double);
  ///@}

  /**
   * The paper size of a name ("A4", "A3", "letter", any case), -1 for another.
   */
  static int GetPaperSizeFromName(const char* name);

  /**
   * Whether a name is a view's (any case, spaces around it ignored); the names, "iso, front,
   * top, right, left, back, bottom".
   */
  static bool IsViewName(const char* name);
  static const char* GetViewNames();

  /**
   * Writes the sheet. False, with GetErrorCode() and GetErrorMessage(), on an error.
   */
  bool Write();

  ///@{
  /**
   * The outcome of the last Write(): a vtkErrorCode value (0: none) and the message.
   */
  vtkGetMacro(ErrorCode, unsigned long);
  const char* GetErrorMessage() const;
  ///@}

  ///@{
  /**
   * What the last successful Write() drew: the page's size in points, the scale (points per
   * model unit, the same in every view), the views in the order given, each one's name and its
   * box on the page in points, x0, y0, x1, y1 from the page's top left corner (the bounding
   * box's image, lines may reach a little beyond), its stroke count, and the seconds it took.
   */
  void GetPageSize(double size[2]) const;
  double GetScale() const;
  int GetNumberOfViews() const;
  const char* GetViewName(int view) const;
  void GetViewBox(int view, double box[4]) const;
  vtkIdType GetNumberOfStrokes(int view) const;
  double GetTime() const;
  ///@}

protected:
  vtkNPRDrawingSheet();
  ~vtkNPRDrawingSheet() override;

  vtkRenderer* Renderer = nullptr;
  char* FileName = nullptr;
  char* Views = nullptr;
  int Arrangement = FIRST_ANGLE;
  int PaperSize = A4;
  bool Landscape = true;
  double Margin = 10.0;
  double Gap = 10.0;
  bool FillFaces = false;
  int FillColors = 0;
  unsigned long ErrorCode = 0;

private:
  vtkNPRDrawingSheet(const vtkNPRDrawingSheet&) = delete;
  void operator=(const vtkNPRDrawingSheet&) = delete;

  bool Fail(unsigned long code, const std::string& message);

  // The steps of Write(); each returns false after Fail().
  bool ParseViews();
  bool LayOut();
  bool Paint(int format, std::string& bytes);
  bool PaintFaces(cairo_t* cr, double height, std::string& error);

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
