// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// What the sources of the TestInkEncodings program share: its cube, pixel masks and the colours
// of ink and object.
#ifndef TestInkEncodings_h
#define TestInkEncodings_h

#include "nprEdgeMetrics.h"
#include "nprTesting.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCubeSource.h"
#include "vtkImageData.h"
#include "vtkNew.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

namespace nprInkEncodingsTesting
{
using Scene = nprPassScene;

// A unit cube seen from a corner direction: a hexagonal outline and three visible creases.
inline vtkSmartPointer<vtkActor> AddCubeSeenFromCorner(Scene& scene, bool parallel)
{
  vtkNew<vtkCubeSource> cube;
  const double color[3] = { 0.6, 0.7, 0.9 };
  vtkSmartPointer<vtkActor> actor = nprAddActor(scene.Renderer, cube->GetOutputPort(), color);
  scene.Camera()->SetFocalPoint(0, 0, 0);
  scene.Camera()->SetPosition(2.2, 1.7, 2.6);
  scene.Camera()->SetViewUp(0, 1, 0);
  scene.Camera()->SetParallelProjection(parallel);
  scene.Camera()->SetParallelScale(0.9);
  scene.Renderer->ResetCameraClippingRange();
  return actor;
}

// Pixel masks as flat vectors, row 0 at the bottom.
using Mask = std::vector<unsigned char>;

inline Mask Threshold(vtkImageData* image, const std::function<bool(int, int, int)>& test)
{
  const int* dims = image->GetDimensions();
  Mask mask(static_cast<size_t>(dims[0]) * dims[1], 0);
  for (int y = 0; y < dims[1]; ++y)
  {
    for (int x = 0; x < dims[0]; ++x)
    {
      mask[static_cast<size_t>(y) * dims[0] + x] =
        test(nprPixel(image, x, y, 0), nprPixel(image, x, y, 1), nprPixel(image, x, y, 2));
    }
  }
  return mask;
}

// Distance from every pixel to the nearest set pixel of a mask (nprDistanceTransform).
inline std::vector<double> DistanceTo(const Mask& mask, int width, int height)
{
  std::vector<double> distance = nprDistanceTransform::Compute(mask.data(), width, height);
  for (double& d : distance)
  {
    d = std::sqrt(d);
  }
  return distance;
}

// The pixels of a mask with a pixel not in it among their 4 neighbours.
inline Mask Boundary(const Mask& mask, int width, int height)
{
  Mask boundary(mask.size(), 0);
  for (int y = 1; y < height - 1; ++y)
  {
    for (int x = 1; x < width - 1; ++x)
    {
      const size_t i = static_cast<size_t>(y) * width + x;
      boundary[i] =
        mask[i] && (!mask[i - 1] || !mask[i + 1] || !mask[i - width] || !mask[i + width]);
    }
  }
  return boundary;
}

inline long long Count(const Mask& mask)
{
  return std::count(mask.begin(), mask.end(), 1);
}

// F1 of mask a against mask b at a tolerance in pixels (nprEdgeMetrics).
inline double F1(const Mask& a, const Mask& b, int width, int height, double tolerance)
{
  nprEdgeMetrics metrics;
  metrics.Compute(a.data(), b.data(), width, height);
  return metrics.F1(tolerance);
}

inline bool IsInk(int r, int g, int b)
{
  return r < 60 && g < 60 && b < 60;
}

inline bool IsObject(int r, int g, int b)
{
  return r < 225 || g < 225 || b < 225;
}
}

#endif
