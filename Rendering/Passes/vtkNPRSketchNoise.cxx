// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNPRSketchNoise.h"

#include "vtkMath.h"

#include <algorithm>
#include <cmath>
#include <mutex>
#include <random>

namespace
{
constexpr int ScreenCells =
  vtkNPRSketchNoise::ScreenTileSize / vtkNPRSketchNoise::ScreenTexelsPerCell;

double Fade(double t)
{
  return t * t * t * (t * (t * 6.0 - 15.0) + 10.0);
}

// Periodic 2D Perlin gradient noise over a ScreenCells x ScreenCells lattice.
struct GradientNoise
{
  double Gradients[ScreenCells][ScreenCells][2];

  explicit GradientNoise(std::mt19937& random)
  {
    for (auto& row : this->Gradients)
    {
      for (auto& gradient : row)
      {
        // The raw 32-bit output, so that a seed gives the same angles on every platform.
        const double angle = random() * (2.0 * vtkMath::Pi() / 4294967296.0);
        gradient[0] = std::cos(angle);
        gradient[1] = std::sin(angle);
      }
    }
  }

  double Corner(int i, int j, double dx, double dy) const
  {
    const double* g = this->Gradients[i % ScreenCells][j % ScreenCells];
    return g[0] * dx + g[1] * dy;
  }

  // x, y in lattice cells, in [0, ScreenCells).
  double operator()(double x, double y) const
  {
    const int i = static_cast<int>(std::floor(x));
    const int j = static_cast<int>(std::floor(y));
    const double fx = x - i, fy = y - j;
    const double u = Fade(fx), v = Fade(fy);
    const double n00 = this->Corner(i, j, fx, fy);
    const double n10 = this->Corner(i + 1, j, fx - 1.0, fy);
    const double n01 = this->Corner(i, j + 1, fx, fy - 1.0);
    const double n11 = this->Corner(i + 1, j + 1, fx - 1.0, fy - 1.0);
    return (n00 + u * (n10 - n00)) + v * ((n01 + u * (n11 - n01)) - (n00 + u * (n10 - n00)));
  }
};

// The surface tile's rg components are a 3D Perlin gradient noise of 4 texels a cell and a period
// of 8 cells (twice over the tile), and its ba components the same noise at half the frequency
// (8 texels a cell), so that one fetch gives both octaves the shader blends, and the coarse octave
// at one level is the fine one at the next. At 4 texels a cell the trilinear interpolation departs
// from the noise by under 5 % of its range.
constexpr int SurfaceCells = 8;         // of the fine octave, in its period
constexpr int SurfaceTexelsPerCell = 4; // of the fine octave
static_assert(vtkNPRSketchNoise::SurfaceTileSize == 2 * SurfaceCells * SurfaceTexelsPerCell,
  "the tile holds the fine octave's period twice");
static_assert(
  vtkNPRSketchNoise::SurfaceTileCells == 2 * SurfaceCells, "fine cells across the tile");

struct GradientNoise3D
{
  std::vector<double> Gradients; // 3 per lattice point

  explicit GradientNoise3D(std::mt19937& random)
    : Gradients(3 * SurfaceCells * SurfaceCells * SurfaceCells)
  {
    for (size_t i = 0; i < this->Gradients.size(); i += 3)
    {
      // Uniform on the sphere, from the raw 32-bit outputs (the same on every platform).
      const double z = random() * (2.0 / 4294967296.0) - 1.0;
      const double angle = random() * (2.0 * vtkMath::Pi() / 4294967296.0);
      const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
      this->Gradients[i] = r * std::cos(angle);
      this->Gradients[i + 1] = r * std::sin(angle);
      this->Gradients[i + 2] = z;
    }
  }

  double Corner(int i, int j, int k, double dx, double dy, double dz) const
  {
    constexpr int n = SurfaceCells;
    const double* g = &this->Gradients[3 * (((k % n) * n + (j % n)) * n + (i % n))];
    return g[0] * dx + g[1] * dy + g[2] * dz;
  }

  // x, y, z in lattice cells, >= 0.
  double operator()(double x, double y, double z) const
  {
    const int i = static_cast<int>(std::floor(x));
    const int j = static_cast<int>(std::floor(y));
    const int k = static_cast<int>(std::floor(z));
    const double fx = x - i, fy = y - j, fz = z - k;
    const double u = Fade(fx), v = Fade(fy), w = Fade(fz);
    double planes[2];
    for (int dk = 0; dk < 2; ++dk)
    {
      const double cz = fz - dk;
      const double n00 = this->Corner(i, j, k + dk, fx, fy, cz);
      const double n10 = this->Corner(i + 1, j, k + dk, fx - 1.0, fy, cz);
      const double n01 = this->Corner(i, j + 1, k + dk, fx, fy - 1.0, cz);
      const double n11 = this->Corner(i + 1, j + 1, k + dk, fx - 1.0, fy - 1.0, cz);
      const double bottom = n00 + u * (n10 - n00);
      const double top = n01 + u * (n11 - n01);
      planes[dk] = bottom + v * (top - bottom);
    }
    return planes[0] + w * (planes[1] - planes[0]);
  }
};
}

std::vector<float> vtkNPRSketchNoise::ScreenTile(unsigned int seed)
{
  std::mt19937 random(seed);
  const GradientNoise noiseX(random);
  const GradientNoise noiseY(random);
  constexpr int size = ScreenTileSize;
  std::vector<double> vectors(2 * size * size);
  double largest = 0.0;
  for (int y = 0; y < size; ++y)
  {
    for (int x = 0; x < size; ++x)
    {
      const double u = static_cast<double>(x) / ScreenTexelsPerCell;
      const double v = static_cast<double>(y) / ScreenTexelsPerCell;
      double* n = &vectors[2 * (y * size + x)];
      n[0] = noiseX(u, v);
      n[1] = noiseY(u, v);
      largest = std::max(largest, std::hypot(n[0], n[1]));
    }
  }
  // Vectors of length up to 1: bilinear mixes of them stay within 1. Rounded towards zero so that
  // float storage cannot push a length above 1.
  const double scale = largest > 0.0 ? 1.0 / largest : 0.0;
  std::vector<float> tile(vectors.size());
  for (size_t i = 0; i < vectors.size(); ++i)
  {
    tile[i] = static_cast<float>(vectors[i] * scale * (1.0 - 1e-6));
  }
  return tile;
}

// The surface noise tile of a seed (four bytes per texel: two noise vectors, |vector| <= 1, as v /
// 2 + 1/2). Kept for the last seed asked, as every new pass of the same seed (a window per view)
// would make it again.
std::shared_ptr<const std::vector<unsigned char>> vtkNPRSketchNoise::SurfaceTile(unsigned int seed)
{
  static std::mutex mutex;
  static unsigned int lastSeed = 0;
  static std::shared_ptr<const std::vector<unsigned char>> last;
  std::lock_guard<std::mutex> lock(mutex);
  if (last && lastSeed == seed)
  {
    return last;
  }
  std::mt19937 random(seed);
  const GradientNoise3D noiseX(random);
  const GradientNoise3D noiseY(random);
  constexpr size_t texels = static_cast<size_t>(vtkNPRSketchNoise::SurfaceTileSize) *
    vtkNPRSketchNoise::SurfaceTileSize * vtkNPRSketchNoise::SurfaceTileSize;
  std::vector<double> vectors(4 * texels);
  double largest = 0.0;
  size_t index = 0;
  for (int z = 0; z < vtkNPRSketchNoise::SurfaceTileSize; ++z)
  {
    for (int y = 0; y < vtkNPRSketchNoise::SurfaceTileSize; ++y)
    {
      for (int x = 0; x < vtkNPRSketchNoise::SurfaceTileSize; ++x, index += 4)
      {
        const double at[3] = { static_cast<double>(x) / SurfaceTexelsPerCell,
          static_cast<double>(y) / SurfaceTexelsPerCell,
          static_cast<double>(z) / SurfaceTexelsPerCell };
        vectors[index] = noiseX(at[0], at[1], at[2]);
        vectors[index + 1] = noiseY(at[0], at[1], at[2]);
        // Half the frequency: the same noise, read at half the lattice coordinates.
        vectors[index + 2] = noiseX(0.5 * at[0], 0.5 * at[1], 0.5 * at[2]);
        vectors[index + 3] = noiseY(0.5 * at[0], 0.5 * at[1], 0.5 * at[2]);
        largest = std::max(largest, std::hypot(vectors[index], vectors[index + 1]));
      }
    }
  }
  // 8-bit unsigned normalised storage, v / 2 + 1/2 (the shader undoes it): llvmpipe filters
  // 8-bit textures much faster than float ones, and 1/255 of the noise's range is 0.01 px of
  // a 3 px uncertainty.
  const double scale = largest > 0.0 ? 1.0 / largest : 0.0;
  auto tile = std::make_shared<std::vector<unsigned char>>(4 * texels);
  for (size_t i = 0; i < vectors.size(); ++i)
  {
    const double value = 127.5 + 127.5 * vectors[i] * scale;
    (*tile)[i] = static_cast<unsigned char>(std::min(255.0, std::max(0.0, std::round(value))));
  }
  lastSeed = seed;
  last = tile;
  return last;
}

// The matrix scaled down to operator norm 1 when its norm is larger.
void vtkNPRSketchNoise::NormalisedMatrix(const double m[4], double out[4])
{
  const double t = m[0] * m[0] + m[1] * m[1] + m[2] * m[2] + m[3] * m[3];
  const double d = m[0] * m[3] - m[1] * m[2];
  const double norm = std::sqrt(0.5 * (t + std::sqrt(std::max(0.0, t * t - 4.0 * d * d))));
  const double scale = norm > 1.0 ? 1.0 / norm : 1.0;
  for (int i = 0; i < 4; ++i)
  {
    out[i] = std::isfinite(m[i]) ? m[i] * scale : 0.0;
  }
}
