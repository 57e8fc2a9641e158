// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// Declarations injected into a vtkOpenGLPolyDataMapper fragment shader while vtkNPRInkPass
// draws.
uniform int nprInkMode;     // 0 shaded as usual, 1 ink (back faces only), 2 mask fill (black)
uniform vec3 nprInkColor;
