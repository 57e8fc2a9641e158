// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// vtkNPRToonPass, per-vertex lighting: vertex shader declarations (after vtkNPRToonLighting).
out vec2 nprToonIntensityVSOutput; // front and back face
