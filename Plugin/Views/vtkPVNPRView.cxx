// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkPVNPRView.h"

#include "vtkNPRDrawingExporter.h"
#include "vtkNPRDrawingPass.h"
#include "vtkNPREdgePass.h"
#include "vtkNPRInkPass.h"
#include "vtkNPRPass.h"
#include "vtkNPRSketchPass.h"
#include "vtkNPRToonPass.h"
#include "vtkNPRViewPass.h"
#include "vtkObjectFactory.h"
#include "vtkPVSynchronizedRenderer.h"

vtkStandardNewMacro(vtkPVNPRView);

vtkPVNPRView::vtkPVNPRView()
{
  // vtkPVSynchronizedRenderer::SetupPasses(): [FXAA ->] NPRViewPass -> camera -> default pass
  // in one process; under IceT the composite pass is the delegate.
  this->SynchronizedRenderers->SetImageProcessingPass(this->NPRViewPass);
  this->SynchronizedRenderers->SetUseDepthBuffer(true); // IceT pastes depth back too
}

vtkPVNPRView::~vtkPVNPRView() = default;

vtkNPRViewPass* vtkPVNPRView::GetNPRViewPass()
{
  return this->NPRViewPass;
}

// Forwarders: one property, one setter of a pass.
#define vtkPVNPRViewForward(name, type, pass, setter)                                              \
  void vtkPVNPRView::Set##name(type value)                                                         \
  {                                                                                                \
    this->NPRViewPass->GetNPRPass()->pass->setter(value);                                          \
  }
#define vtkPVNPRViewForwardColor(name, pass, setter)                                               \
  void vtkPVNPRView::Set##name(double r, double g, double b)                                       \
  {                                                                                                \
    this->NPRViewPass->GetNPRPass()->pass->setter(r, g, b);                                        \
  }

void vtkPVNPRView::SetStyle(int style)
{
  this->NPRViewPass->GetNPRPass()->SetStyle(style);
  this->UpdateSceneRenderPass();
}
void vtkPVNPRView::SetSketchToonShading(bool on)
{
  this->NPRViewPass->GetNPRPass()->SetSketchToonShading(on);
  this->UpdateSceneRenderPass();
}

void vtkPVNPRView::UpdateSceneRenderPass()
{
  // Under IceT this pass renders each rank's piece before compositing; in one process the view
  // pass renders the scene itself and uses it only with ForceDepthOnly.
  vtkRenderPass* pass = this->NPRViewPass->GetSceneRenderPass();
  if (this->SynchronizedRenderers->GetRenderPass() != pass)
  {
    this->SynchronizedRenderers->SetRenderPass(pass);
  }
}
vtkPVNPRViewForward(DepthFalloff, bool, GetEdgePass(), SetDepthFalloff) vtkPVNPRViewForward(
  NearLineScale, double, GetEdgePass(), SetNearLineScale) vtkPVNPRViewForward(FarLineScale, double,
  GetEdgePass(), SetFarLineScale) vtkPVNPRViewForward(DrawingTaperLength, double, GetDrawingPass(),
  SetTaperLength) vtkPVNPRViewForward(DrawingCurvatureWidth, double, GetDrawingPass(),
  SetCurvatureWidth) vtkPVNPRViewForward(FaceCreases, bool, GetEdgePass(),
  SetFaceCreases) vtkPVNPRViewForward(SmoothSilhouettes, bool, GetEdgePass(),
  SetSmoothSilhouettes) vtkPVNPRViewForward(SuggestiveContours, bool, GetEdgePass(),
  SetSuggestiveContours) vtkPVNPRViewForward(SuggestiveContourThreshold, double, GetEdgePass(),
  SetSuggestiveContourThreshold) vtkPVNPRViewForwardColor(SuggestiveContourColor, GetEdgePass(),
  SetSuggestiveContourColor) vtkPVNPRViewForward(Silhouettes, bool, GetEdgePass(),
  SetSilhouettes) vtkPVNPRViewForward(SilhouetteThreshold, double, GetEdgePass(),
  SetSilhouetteThreshold) vtkPVNPRViewForwardColor(SilhouetteColor, GetEdgePass(),
  SetSilhouetteColor) vtkPVNPRViewForward(Creases, bool, GetEdgePass(), SetCreases)
  vtkPVNPRViewForward(CreaseAngle, double, GetEdgePass(), SetCreaseAngle) vtkPVNPRViewForwardColor(
    CreaseColor, GetEdgePass(), SetCreaseColor) vtkPVNPRViewForward(Contours, bool, GetEdgePass(),
    SetContours) vtkPVNPRViewForward(ContourSide, int, GetEdgePass(), SetContourSide)
    vtkPVNPRViewForwardColor(ContourColor, GetEdgePass(), SetContourColor) vtkPVNPRViewForward(
      LineWidth, double, GetEdgePass(), SetLineWidth) vtkPVNPRViewForward(SilhouetteLineWidth,
      double, GetEdgePass(), SetSilhouetteLineWidth) vtkPVNPRViewForward(CreaseLineWidth, double,
      GetEdgePass(), SetCreaseLineWidth) vtkPVNPRViewForward(ContourLineWidth, double,
      GetEdgePass(), SetContourLineWidth) vtkPVNPRViewForward(SuggestiveContourLineWidth, double,
      GetEdgePass(), SetSuggestiveContourLineWidth) vtkPVNPRViewForward(MaximumLineFraction, double,
      GetEdgePass(), SetMaximumLineFraction) vtkPVNPRViewForward(SurfaceLineShade, double,
      GetEdgePass(), SetSurfaceLineShade) vtkPVNPRViewForward(LineAntiAliasing, bool, GetEdgePass(),
      SetAntiAliasing) vtkPVNPRViewForward(LineEncoding, int, GetEdgePass(), SetEncoding)
      vtkPVNPRViewForward(PackedThreshold, double, GetEdgePass(), SetPackedThreshold)
        vtkPVNPRViewForward(ToonBands, int, GetToonPass(), SetNumberOfBands)
          vtkPVNPRViewForward(ToonSpecular, bool, GetToonPass(), SetSpecular)
            vtkPVNPRViewForward(SketchUncertainty, double, GetSketchPass(), SetUncertainty)
              vtkPVNPRViewForward(SketchNoiseFrequency, double, GetSketchPass(), SetNoiseFrequency)
                vtkPVNPRViewForward(SketchNoiseSpace, int, GetSketchPass(), SetNoiseSpace)
                  vtkPVNPRViewForward(SketchPaper, bool, GetSketchPass(), SetPaper)
                    vtkPVNPRViewForwardColor(SketchPaperColor, GetSketchPass(), SetPaperColor)
                      vtkPVNPRViewForward(InkLineWidth, double, GetInkPass(), SetLineWidth)
                        vtkPVNPRViewForwardColor(InkColor, GetInkPass(), SetInkColor)

                          void vtkPVNPRView::SetSketchNoiseSeed(int seed)
{
  this->NPRViewPass->GetNPRPass()->GetSketchPass()->SetNoiseSeed(
    static_cast<unsigned int>(seed < 0 ? 0 : seed));
}

void vtkPVNPRView::SetDrawingHiddenLines(bool on)
{
  this->NPRViewPass->GetNPRPass()->SetHiddenLines(on);
}

void vtkPVNPRView::SetDrawingFaceColor(double r, double g, double b)
{
  this->NPRViewPass->GetNPRPass()->GetDrawingPass()->SetFaceColor(r, g, b);
}

void vtkPVNPRView::SetDrawingHiddenLineColor(double r, double g, double b)
{
  this->NPRViewPass->GetNPRPass()->GetDrawingPass()->SetHiddenLineColor(r, g, b);
}

void vtkPVNPRView::SetDrawingFileName(const char* path)
{
  this->DrawingFileName = path ? path : "";
}

void vtkPVNPRView::SetDrawingFillFaces(bool on)
{
  this->DrawingFillFaces = on;
}

void vtkPVNPRView::SetDrawingFillColors(int mode)
{
  this->DrawingFillColors = mode;
}

bool vtkPVNPRView::ExportDrawing()
{
  // The view's renderer is drawn by vtkNPRViewPass, not a vtkNPRPass: the style comes from ours.
  vtkNPRPass* pass = this->NPRViewPass->GetNPRPass();
  vtkNew<vtkNPRDrawingExporter> exporter;
  exporter->SetRenderer(this->GetRenderer());
  exporter->SetDrawingPass(pass->GetDrawingPass());
  exporter->SetEdgePass(pass->GetEdgePass());
  exporter->SetEmbedImage(
    pass->GetStyle() == vtkNPRPass::DRAWING || this->DrawingFillFaces ? 0 : 1);
  exporter->SetFillFaces(this->DrawingFillFaces);
  exporter->SetFillColors(this->DrawingFillColors);
  exporter->SetFileName(this->DrawingFileName.c_str());
  if (!exporter->Write())
  {
    vtkErrorMacro("the drawing was not written: " << exporter->GetErrorMessage());
    return false;
  }
  return true;
}

void vtkPVNPRView::SetForceDepthOnly(bool on)
{
  this->NPRViewPass->SetForceDepthOnly(on);
}

void vtkPVNPRView::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NPRViewPass:\n";
  this->NPRViewPass->PrintSelf(os, indent.GetNextIndent());
}
