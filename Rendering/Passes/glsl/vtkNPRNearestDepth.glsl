// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// vtkNPREdgePass and vtkNPRDrawingPass: the surface a line pixel off the surfaces belongs to. Lines
// reaching past a surface onto the background belong to the nearest surface within NPR_RADIUS
// pixels along the axes (the includer defines it and depthTexture).

// The texel of that surface; p itself (a background texel) where there is none.
ivec2 nprNearestSurface(ivec2 p)
{
  ivec2 size = textureSize(depthTexture, 0);
  const ivec2 axes[4] = ivec2[4](ivec2(1, 0), ivec2(-1, 0), ivec2(0, 1), ivec2(0, -1));
  float nearest = 1.0;
  ivec2 found = p;
  for (int r = 1; r <= NPR_RADIUS; ++r)
  {
    for (int k = 0; k < 4; ++k)
    {
      ivec2 q = clamp(p + r * axes[k], ivec2(0), size - 1);
      float depth = texelFetch(depthTexture, q, 0).r;
      found = depth < nearest ? q : found;
      nearest = min(nearest, depth);
    }
  }
  return found;
}

// The depth a background pixel p of a line is drawn at: that surface's (1.0 where there is none).
float nprNearestDepth(ivec2 p)
{
  return texelFetch(depthTexture, nprNearestSurface(p), 0).r;
}
