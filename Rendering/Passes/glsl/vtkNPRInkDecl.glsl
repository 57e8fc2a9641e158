// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// Declarations injected into a vtkOpenGLPolyDataMapper fragment shader while vtkNPRInkPass
// draws.
uniform int nprInkMode; // 0 shaded as usual, 1 ink (back faces only), 2 mask fill (black),
                        // 3 no ink (the ink image's faces, alpha a half)
uniform vec3 nprInkColor;
