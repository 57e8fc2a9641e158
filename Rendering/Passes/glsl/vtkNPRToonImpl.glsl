// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
  // vtkNPRToonPass: the diffuse lighting replaced by the table's band for the light intensity.
  {
#if NPR_TOON_HAVE_VERTEX_VC
    vec3 nprPosition = vertexVC.xyz;
#else
    vec3 nprPosition = vec3(0.0, 0.0, 1.0); // no position: as seen along the view direction
#endif
#if NPR_TOON_PER_VERTEX
    float nprIntensity = gl_FrontFacing ? nprToonIntensityVSOutput.x : nprToonIntensityVSOutput.y;
#if NPR_TOON_SPECULAR
    vec2 nprLight = nprToonLight(normalVCVSOutput, nprPosition, specularPower);
#endif
#else
    vec2 nprLight = nprToonLight(normalVCVSOutput, nprPosition, specularPower);
    float nprIntensity = nprLight.x;
#endif
    nprIntensity = nprIntensity >= 0.0 ? nprIntensity : 0.0; // NaN from a zero-length normal
    int nprBand = min(int(clamp(nprIntensity, 0.0, 1.0) * float(nprToonTableSize)), nprToonTableSize - 1);
    vec3 nprColor = ambientColor + diffuseColor * texelFetch(nprToonTable, ivec2(nprBand, 0), 0).rgb;
#if NPR_TOON_SPECULAR
    nprColor += specularColor * step(0.5, nprLight.y);
#endif
    gl_FragData[0].rgb = nprColor;
  }
