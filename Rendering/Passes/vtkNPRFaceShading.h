// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// The colours vtkNPRDrawingExporter fills vtkNPRDrawingLines' faces with in the toon bands of a
// renderer's lights (FillColors TOON_BANDS): what vtkNPRToonPass draws on a flat face. Private to
// NPR::Passes.
#ifndef vtkNPRFaceShading_h
#define vtkNPRFaceShading_h

#include "vtkSmartPointer.h" // for the colours

class vtkNPRToonPass;
class vtkPolyData;
class vtkRenderer;
class vtkUnsignedCharArray;

// Each face's colour (RGB): its AmbientColors plus its DiffuseColors times the toon table's
// factor (vtkNPRToonPass::GetShade) for the light reaching it, as the toon shader sums it over the
// renderer's first vtkNPRToonPass::MaximumNumberOfLights switched-on lights (intensity x
// luminance x attenuation x max(0, n.l), spot cones, clamped to 1) with the face's Normals at its
// centroid. Null when the faces lack those arrays. Specular highlights are not filled.
vtkSmartPointer<vtkUnsignedCharArray> vtkNPRToonFaceColors(
  vtkPolyData* faces, vtkRenderer* renderer, vtkNPRToonPass* toon);

#endif
// VTK-HeaderTest-Exclude: vtkNPRFaceShading.h
