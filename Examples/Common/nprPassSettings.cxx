// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nprPassSettings.h"

#include "vtkNPRDrawingPass.h"
#include "vtkNPRInkPass.h"
#include "vtkNPRPass.h"
#include "vtkNPRSketchPass.h"
#include "vtkNPRToonPass.h"

vtkSmartPointer<vtkNPRPass> nprMakePass(const nprPassSettings& settings)
{
  auto pass = vtkSmartPointer<vtkNPRPass>::New();
  nprApplyPassSettings(pass, settings);
  return pass;
}

void nprApplyPassSettings(vtkNPRPass* pass, const nprPassSettings& settings)
{
  pass->SetStyle(vtkNPRPass::GetStyleFromName(settings.Style.c_str()));
  vtkNPREdgePass* edges = pass->GetEdgePass();
  edges->SetSilhouettes(settings.Silhouettes);
  edges->SetSmoothSilhouettes(settings.SmoothSilhouettes);
  edges->SetSuggestiveContours(settings.SuggestiveContours);
  edges->SetSuggestiveContourThreshold(settings.SuggestiveContourThreshold);
  edges->SetCreases(settings.Creases);
  edges->SetContours(settings.Contours);
  edges->SetSilhouetteThreshold(settings.SilhouetteThreshold);
  edges->SetCreaseAngle(settings.CreaseAngle);
  edges->SetContourSide(settings.ContourSide);
  edges->SetLineWidth(settings.LineWidth);
  edges->SetSilhouetteLineWidth(settings.SilhouetteLineWidth);
  edges->SetCreaseLineWidth(settings.CreaseLineWidth);
  edges->SetContourLineWidth(settings.ContourLineWidth);
  edges->SetSuggestiveContourLineWidth(settings.SuggestiveContourLineWidth);
  edges->SetMaximumLineFraction(settings.MaximumLineFraction);
  edges->SetSurfaceLineShade(settings.SurfaceLineShade);
  edges->SetDepthFalloff(settings.DepthFalloff);
  edges->SetNearLineScale(settings.NearLineScale);
  edges->SetFarLineScale(settings.FarLineScale);
  edges->SetSilhouetteColor(settings.SilhouetteColor);
  edges->SetCreaseColor(settings.CreaseColor);
  edges->SetContourColor(settings.ContourColor);
  edges->SetSuggestiveContourColor(settings.SuggestiveContourColor);
  edges->SetFaceCreases(settings.FaceCreases);
  edges->SetAntiAliasing(settings.AntiAliasing);
  edges->SetEncoding(settings.Encoding);
  edges->SetPackedThreshold(settings.PackedThreshold);
  edges->SetPackedBlur(settings.PackedBlur);
  vtkNPRToonPass* toon = pass->GetToonPass();
  toon->SetNumberOfBands(settings.ToonBands);
  toon->SetPerVertex(settings.ToonPerVertex);
  vtkNPRSketchPass* sketch = pass->GetSketchPass();
  sketch->SetUncertainty(settings.Uncertainty);
  sketch->SetNoiseSeed(static_cast<unsigned int>(settings.NoiseSeed));
  sketch->SetNoiseFrequency(settings.NoiseFrequency);
  sketch->SetNoiseSpace(settings.NoiseSpace);
  sketch->SetPaper(settings.Paper);
  sketch->SetPaperColor(settings.PaperColor);
  pass->SetSketchToonShading(settings.SketchToon);
  pass->SetHiddenLines(settings.HiddenLines);
  vtkNPRDrawingPass* drawing = pass->GetDrawingPass();
  drawing->SetTaperLength(settings.TaperLength);
  drawing->SetCurvatureWidth(settings.CurvatureWidth);
  vtkNPRInkPass* ink = pass->GetInkPass();
  ink->SetLineWidth(settings.LineWidth);
  ink->SetInkColor(settings.SilhouetteColor);
}
