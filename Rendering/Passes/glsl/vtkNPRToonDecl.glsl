// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// vtkNPRToonPass: fragment shader declarations. The pass defines NPR_TOON_PER_VERTEX,
// NPR_TOON_SPECULAR and NPR_TOON_HAVE_VERTEX_VC and adds vtkNPRToonLighting before this text.
uniform sampler2D nprToonTable; // width x 1, RGB factor for the intensity range [0, 1]
uniform int nprToonTableSize;
#if NPR_TOON_PER_VERTEX
in vec2 nprToonIntensityVSOutput; // front and back face
#endif
