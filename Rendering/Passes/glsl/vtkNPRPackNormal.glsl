// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// The G-buffer's normal packing, put in place of //NPR::PackNormal by vtkNPRGBufferPass: one
// source for the mappers' G-buffer output (vtkNPRGBufferDecl) and the depth-only geometry
// (vtkNPRDepthGeometryFS), which must store the same values.

// Octahedral encoding of a unit vector: two coordinates in [-1, 1].
vec2 nprOctahedral(vec3 n)
{
  n /= abs(n.x) + abs(n.y) + abs(n.z);
  vec2 e = n.xy;
  if (n.z < 0.0)
  {
    e = (1.0 - abs(n.yx)) * vec2(n.x >= 0.0 ? 1.0 : -1.0, n.y >= 0.0 ? 1.0 : -1.0);
  }
  return e;
}

// Both octahedral coordinates quantised to 12 bits and packed into one float (an integer below
// 2^24, exact in 32-bit float): about 0.05 degree resolution.
float nprPackNormal(vec3 n)
{
  vec2 e = floor((nprOctahedral(n) * 0.5 + 0.5) * 4095.0 + 0.5);
  return e.x * 4096.0 + e.y;
}
