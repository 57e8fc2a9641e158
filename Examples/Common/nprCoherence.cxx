// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nprCoherence.h"

#include "vtkCamera.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>

namespace
{
bool Inside(const nprCoherenceFrame& frame, int x, int y, int margin)
{
  return x >= margin && y >= margin && x < frame.Width - margin && y < frame.Height - margin;
}

bool LineNear(const nprCoherenceFrame& frame, int x, int y)
{
  for (int dy = -1; dy <= 1; ++dy)
  {
    for (int dx = -1; dx <= 1; ++dx)
    {
      const int u = x + dx, v = y + dy;
      if (Inside(frame, u, v, 0) && frame.Lines[static_cast<size_t>(v) * frame.Width + u])
      {
        return true;
      }
    }
  }
  return false;
}

void Transform(const double m[16], const double in[4], double out[4])
{
  for (int i = 0; i < 4; ++i)
  {
    out[i] = m[4 * i] * in[0] + m[4 * i + 1] * in[1] + m[4 * i + 2] * in[2] + m[4 * i + 3] * in[3];
  }
}
}

nprCoherenceFrame nprCaptureCoherenceFrame(vtkRenderWindow* window, vtkRenderer* renderer)
{
  nprCoherenceFrame frame;
  const int* size = window->GetSize();
  frame.Width = size[0];
  frame.Height = size[1];
  const size_t pixels = static_cast<size_t>(frame.Width) * frame.Height;
  frame.Lines.resize(pixels);
  vtkNew<vtkUnsignedCharArray> colors;
  window->GetPixelData(0, 0, frame.Width - 1, frame.Height - 1, 0, colors);
  const unsigned char* rgb = colors->GetPointer(0);
  for (size_t i = 0; i < pixels; ++i)
  {
    const double luminance = 0.299 * rgb[3 * i] + 0.587 * rgb[3 * i + 1] + 0.114 * rgb[3 * i + 2];
    frame.Lines[i] = luminance < 60.0 ? 1 : 0;
  }
  frame.Depth.resize(pixels);
  window->GetZbufferData(0, 0, frame.Width - 1, frame.Height - 1, frame.Depth.data());
  vtkMatrix4x4* worldToDevice = renderer->GetActiveCamera()->GetCompositeProjectionTransformMatrix(
    renderer->GetTiledAspectRatio(), -1.0, 1.0);
  for (int i = 0; i < 16; ++i)
  {
    frame.WorldToDevice[i] = worldToDevice->GetElement(i / 4, i % 4);
  }
  return frame;
}

nprCoherenceStep nprCompareCoherenceFrames(
  const nprCoherenceFrame& first, const nprCoherenceFrame& second, int margin)
{
  nprCoherenceStep step;
  margin = std::max(margin, 1); // the 3 x 3 neighbourhoods stay inside
  double deviceToWorld[16];
  vtkMatrix4x4::Invert(first.WorldToDevice, deviceToWorld);
  std::vector<unsigned char> reached(second.Lines.size(), 0);
  for (int y = 0; y < first.Height; ++y)
  {
    for (int x = 0; x < first.Width; ++x)
    {
      const size_t i = static_cast<size_t>(y) * first.Width + x;
      if (!first.Lines[i] || !Inside(first, x, y, margin))
      {
        continue;
      }
      ++step.Lines;
      const double depth = first.Depth[i];
      if (depth >= 1.0)
      {
        continue; // a line pixel with no depth cannot be carried
      }
      const double device[4] = { (x + 0.5) / first.Width * 2.0 - 1.0,
        (y + 0.5) / first.Height * 2.0 - 1.0, depth * 2.0 - 1.0, 1.0 };
      double world[4], next[4];
      Transform(deviceToWorld, device, world);
      Transform(second.WorldToDevice, world, next);
      if (next[3] == 0.0)
      {
        continue;
      }
      const int u = static_cast<int>(std::floor((next[0] / next[3] + 1.0) * 0.5 * second.Width));
      const int v = static_cast<int>(std::floor((next[1] / next[3] + 1.0) * 0.5 * second.Height));
      if (!Inside(second, u, v, margin))
      {
        continue;
      }
      ++step.Carried;
      if (LineNear(second, u, v))
      {
        ++step.Landed;
      }
      if (second.Lines[static_cast<size_t>(v) * second.Width + u])
      {
        ++step.LandedExactly;
      }
      for (int dy = -1; dy <= 1; ++dy)
      {
        for (int dx = -1; dx <= 1; ++dx)
        {
          reached[static_cast<size_t>(v + dy) * second.Width + u + dx] = 1;
        }
      }
    }
  }
  for (int y = margin; y < second.Height - margin; ++y)
  {
    for (int x = margin; x < second.Width - margin; ++x)
    {
      const size_t i = static_cast<size_t>(y) * second.Width + x;
      if (second.Lines[i])
      {
        ++step.NextLines;
        step.Appeared += reached[i] ? 0 : 1;
      }
    }
  }
  step.LandedFraction = step.Carried ? static_cast<double>(step.Landed) / step.Carried : 0.0;
  step.LandedExactlyFraction =
    step.Carried ? static_cast<double>(step.LandedExactly) / step.Carried : 0.0;
  step.VanishedFraction = step.Carried ? 1.0 - step.LandedFraction : 0.0;
  step.AppearedFraction =
    step.NextLines ? static_cast<double>(step.Appeared) / step.NextLines : 0.0;
  return step;
}

void nprPanParallelCamera(vtkCamera* camera, double pixels, int height)
{
  double right[3], position[3], focus[3];
  vtkMath::Cross(camera->GetDirectionOfProjection(), camera->GetViewUp(), right);
  vtkMath::Normalize(right);
  const double step = pixels * 2.0 * camera->GetParallelScale() / height;
  camera->GetPosition(position);
  camera->GetFocalPoint(focus);
  for (int i = 0; i < 3; ++i)
  {
    position[i] += step * right[i];
    focus[i] += step * right[i];
  }
  camera->SetPosition(position);
  camera->SetFocalPoint(focus);
}

double nprShiftedLineIoU(
  const nprCoherenceFrame& first, const nprCoherenceFrame& second, int dx, int dy, int margin)
{
  long long both = 0, either = 0;
  for (int y = 0; y < first.Height; ++y)
  {
    for (int x = 0; x < first.Width; ++x)
    {
      if (!Inside(first, x, y, margin) || !Inside(second, x + dx, y + dy, margin))
      {
        continue;
      }
      const bool a = first.Lines[static_cast<size_t>(y) * first.Width + x] != 0;
      const bool b = second.Lines[static_cast<size_t>(y + dy) * second.Width + x + dx] != 0;
      both += a && b ? 1 : 0;
      either += a || b ? 1 : 0;
    }
  }
  return either ? static_cast<double>(both) / either : 0.0;
}
