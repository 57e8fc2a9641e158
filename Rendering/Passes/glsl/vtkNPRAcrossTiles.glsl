// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// Tiled renders (vtkWindowToImageFilter's Scale, ParaView's screenshots larger than the view):
// each tile draws its part of the renderer through G-buffer textures of its own size.
uniform int tileSides[4]; // 1 where a side (left, bottom, right, top) meets another tile

// A texel looked up past a side that meets another tile: that tile's texels are not here, the
// nearest of this one stands in (a stroke or a fill crossing the border keeps no gap).
ivec2 nprAcrossTiles(ivec2 texel, ivec2 size)
{
  ivec2 low = ivec2(tileSides[0] != 0 ? max(texel.x, 0) : texel.x,
    tileSides[1] != 0 ? max(texel.y, 0) : texel.y);
  return ivec2(tileSides[2] != 0 ? min(low.x, size.x - 1) : low.x,
    tileSides[3] != 0 ? min(low.y, size.y - 1) : low.y);
}
