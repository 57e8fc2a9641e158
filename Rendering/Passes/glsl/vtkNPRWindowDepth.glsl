// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// The window depth of a G-buffer depth, for the depth sprites. With NPR_REMAPPED_DEPTH the
// G-buffer holds log(z / near) / log(far / near) of the view depth z (vtkNPRGBufferPass does so
// for perspective near/far ratios above 1e4, where the usual depth loses the order of nearby
// surfaces); the sprite is written in the usual perspective depth the rest of VTK expects.
uniform vec2 nprDepthRemap; // near, log(far / near)

float nprWindowDepth(float stored)
{
#if NPR_REMAPPED_DEPTH
  if (stored >= 1.0)
  {
    return 1.0;
  }
  float near = nprDepthRemap.x;
  float nearOverZ = exp(-stored * nprDepthRemap.y);
  float far = near * exp(nprDepthRemap.y);
  return far / (far - near) * (1.0 - nearOverZ);
#else
  return stored;
#endif
}
