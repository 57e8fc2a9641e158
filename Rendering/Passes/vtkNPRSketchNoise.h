// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// The noise tiles of vtkNPRSketchPass, made on the CPU from a seed: periodic Perlin gradient noise
// of two components (a displacement vector). The raw 32-bit outputs of std::mt19937 give the
// gradients, so that a seed gives the same tiles on every platform. Private to the passes module.
#ifndef vtkNPRSketchNoise_h
#define vtkNPRSketchNoise_h

#include <memory> // for std::shared_ptr
#include <vector> // for std::vector

struct vtkNPRSketchNoise
{
  static constexpr int ScreenTileSize = 256; // texels of the screen tile on each side
  static constexpr int ScreenTexelsPerCell = 32;
  static constexpr int SurfaceTileSize = 64;  // texels of the surface tile on each side
  static constexpr int SurfaceTileCells = 16; // cells of its fine octave across the tile

  /**
   * The screen tile: ScreenTileSize^2 vectors (x, y), row by row, scaled so that the longest is
   * just under 1 (float storage cannot push a length above 1).
   */
  static std::vector<float> ScreenTile(unsigned int seed);

  /**
   * The surface tile: four bytes per texel, the fine and the coarse octave's vectors as v / 2 +
   * 1/2. Kept for the last seed asked, as every new pass of the same seed (a window per view)
   * would make it again.
   */
  static std::shared_ptr<const std::vector<unsigned char>> SurfaceTile(unsigned int seed);

  /**
   * The 2x2 matrix m (row major) scaled down to operator norm 1 when its norm is larger;
   * non-finite entries become 0.
   */
  static void NormalisedMatrix(const double m[4], double out[4]);
};

#endif
// VTK-HeaderTest-Exclude: vtkNPRSketchNoise.h
