// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
  // vtkNPRToonPass: the light intensity at this vertex for both faces, interpolated before the
  // table lookup.
  {
    vec3 nprNormal = normalVCVSOutput;
    nprNormal = dot(nprNormal, nprNormal) > 0.0 ? normalize(nprNormal) : vec3(0.0, 0.0, 1.0);
    vec3 nprPosition = vertexVCVSOutput.xyz / vertexVCVSOutput.w;
    nprToonIntensityVSOutput = vec2(nprToonLight(nprNormal, nprPosition, 1.0).x,
      nprToonLight(-nprNormal, nprPosition, 1.0).x);
  }
