// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// The colours vtkNPRDrawingExporter fills vtkNPRDrawingLines' faces with in the toon bands of a
// renderer's lights (FillColors TOON_BANDS): what vtkNPRToonPass draws on a flat face. Private to
// NPR::Passes.
#ifndef vtkNPRFaceShading_h
#define vtkNPRFaceShading_h

#include "vtkSmartPointer.h" // for the colours

class vtkDataArray;
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

// The colours, one a face, that vtkNPRDrawingExporter::FillColors `mode` fills the faces with
// for the renderer: SURFACE_COLORS the faces' Colors, TOON_BANDS vtkNPRToonFaceColors with the
// renderer's vtkNPRPass's toon pass (else one of 3 bands); null for FACE_COLOR (one colour).
vtkSmartPointer<vtkDataArray> vtkNPRFillColors(vtkPolyData* faces, int mode, vtkRenderer* renderer);

#endif
// VTK-HeaderTest-Exclude: vtkNPRFaceShading.h
