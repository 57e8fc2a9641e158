// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// vtkNPREdgePass and vtkNPRDrawingPass: the depth a line pixel off the surfaces is drawn at. Lines
// reaching past a surface onto the background belong to the nearest surface within NPR_RADIUS
// pixels (the includer defines it and depthTexture).
float nprNearestDepth(ivec2 p)
{
  ivec2 size = textureSize(depthTexture, 0);
  float nearest = 1.0;
  for (int r = 1; r <= NPR_RADIUS; ++r)
  {
    nearest = min(nearest, texelFetch(depthTexture, clamp(p + ivec2(r, 0), ivec2(0), size - 1), 0).r);
    nearest = min(nearest, texelFetch(depthTexture, clamp(p - ivec2(r, 0), ivec2(0), size - 1), 0).r);
    nearest = min(nearest, texelFetch(depthTexture, clamp(p + ivec2(0, r), ivec2(0), size - 1), 0).r);
    nearest = min(nearest, texelFetch(depthTexture, clamp(p - ivec2(0, r), ivec2(0), size - 1), 0).r);
  }
  return nearest;
}
