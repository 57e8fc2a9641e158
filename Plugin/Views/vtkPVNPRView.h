// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkPVNPRView
 * @brief   ParaView render view with the vtkNPR styles ("Render View (NPR)").
 *
 * A vtkPVRenderView whose image-processing pass is a vtkNPRViewPass (the same slot as the
 * eye-dome-lighting view's), with the depth buffer kept through IceT compositing. The setters
 * below are the server-manager properties of NPRView.xml; they forward to the passes of the
 * vtkNPRPass façade (vtkNPRPass, vtkNPREdgePass, vtkNPRToonPass, vtkNPRSketchPass,
 * vtkNPRInkPass), whose documentation gives the details.
 *
 * In one process the view draws the full G-buffer; under MPI the lines come from the composited
 * depth, and the toon styles shade each rank's piece before compositing through the
 * synchronized renderers' render pass (see vtkNPRViewPass).
 *
 * @sa vtkNPRViewPass vtkNPRPass
 */
#ifndef vtkPVNPRView_h
#define vtkPVNPRView_h

#include "vtkNPRViewsModule.h" // for export macro
#include "vtkNew.h"            // for vtkNew
#include "vtkPVRenderView.h"

#include <string> // for the drawing's file name

class vtkNPRViewPass;

class VTKNPRVIEWS_EXPORT vtkPVNPRView : public vtkPVRenderView
{
public:
  static vtkPVNPRView* New();
  vtkTypeMacro(vtkPVNPRView, vtkPVRenderView);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * The pass in the image-processing slot.
   */
  vtkNPRViewPass* GetNPRViewPass();

  ///@{
  /**
   * Style: 0 shaded, 1 edges, 2 toon, 3 toon+edges, 4 sketch, 5 inked, 6 drawing
   * (vtkNPRPass::Styles);
   * SketchToonShading sketches the toon bands instead of flat colours.
   */
  void SetStyle(int style);
  void SetSketchToonShading(bool on);
  ///@}

  ///@{
  /**
   * Lines of the edges, toon+edges and sketch styles (vtkNPREdgePass).
   */
  void SetSilhouettes(bool on);
  void SetSilhouetteThreshold(double threshold);
  void SetSilhouetteColor(double r, double g, double b);
  void SetCreases(bool on);
  void SetCreaseAngle(double degrees);
  void SetCreaseColor(double r, double g, double b);
  void SetFaceCreases(bool on);
  void SetSmoothSilhouettes(bool on);
  void SetSuggestiveContours(bool on);
  void SetSuggestiveContourThreshold(double threshold);
  void SetSuggestiveContourColor(double r, double g, double b);
  void SetContours(bool on);
  void SetContourSide(int side);
  void SetContourColor(double r, double g, double b);
  void SetLineWidth(double width);
  void SetSilhouetteLineWidth(double width);
  void SetCreaseLineWidth(double width);
  void SetContourLineWidth(double width);
  void SetSuggestiveContourLineWidth(double width);
  void SetMaximumLineFraction(double fraction);
  void SetSurfaceLineShade(double shade);
  void SetDepthFalloff(bool on);
  void SetNearLineScale(double scale);
  void SetFarLineScale(double scale);
  void SetLineAntiAliasing(bool on);
  void SetLineEncoding(int encoding);
  void SetPackedThreshold(double threshold);
  ///@}

  ///@{
  /**
   * Toon shading (vtkNPRToonPass): number of bands, hard specular highlight.
   */
  void SetToonBands(int bands);
  void SetToonSpecular(bool on);
  ///@}

  ///@{
  /**
   * Drawing (vtkNPRDrawingPass).
   */
  void SetDrawingHiddenLines(bool on);
  void SetDrawingFaceColor(double r, double g, double b);
  void SetDrawingHiddenLineColor(double r, double g, double b);
  void SetDrawingTaperLength(double pixels);
  void SetDrawingCurvatureWidth(double factor);
  ///@}

  ///@{
  /**
   * Vector output of the view's lines (vtkNPRDrawingExporter): ExportDrawing() writes
   * DrawingFileName (.svg, .pdf, .ps or .eps) on the process that renders (the client in a builtin
   * session, the server's first rank otherwise), with the faces filled on request. False, with
   * an error, when it could not.
   */
  void SetDrawingFileName(const char* path);
  void SetDrawingFillFaces(bool on);   // vtkNPRDrawingExporter's FillFaces
  void SetDrawingFillColors(int mode); // and FillColors
  bool ExportDrawing();
  ///@}

  ///@{
  /**
   * Sketch (vtkNPRSketchPass).
   */
  void SetSketchUncertainty(double pixels);
  void SetSketchNoiseSeed(int seed);
  void SetSketchNoiseFrequency(double frequency);
  void SetSketchNoiseSpace(int space);
  void SetSketchPaper(bool on);
  void SetSketchPaperColor(double r, double g, double b);
  ///@}

  ///@{
  /**
   * Inked style (vtkNPRInkPass).
   */
  void SetInkLineWidth(double width);
  void SetInkColor(double r, double g, double b);
  ///@}

  /**
   * Lines from depth only, as under MPI, in one process too (vtkNPRViewPass).
   */
  void SetForceDepthOnly(bool on);

protected:
  vtkPVNPRView();
  ~vtkPVNPRView() override;

  // Gives the synchronized renderers the scene render pass the style needs.
  void UpdateSceneRenderPass();

  vtkNew<vtkNPRViewPass> NPRViewPass;
  std::string DrawingFileName;
  bool DrawingFillFaces = false;
  int DrawingFillColors = 0;

private:
  vtkPVNPRView(const vtkPVNPRView&) = delete;
  void operator=(const vtkPVNPRView&) = delete;
};

#endif
