// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNPRReferenceMask.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkImageData.h"
#include "vtkNPRFeatureLines.h"
#include "vtkNPRSceneLines.h"
#include "vtkNPRVectors.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkRenderer.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <vector>

namespace
{
using Clock = std::chrono::steady_clock;

double Seconds(Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// The visible samples as polylines: each run of visible samples along a segment is one line.
class VisibleRuns
{
public:
  VisibleRuns()
  {
    this->Points->SetDataTypeToDouble();
    this->Types->SetName("FeatureType");
  }
  void Add(const double p[3]) { this->Run.push_back(this->Points->InsertNextPoint(p)); }
  // Ends the current run: a line of `type` where it has two samples or more.
  void End(unsigned char type)
  {
    if (this->Run.size() >= 2)
    {
      this->Cells->InsertNextCell(static_cast<vtkIdType>(this->Run.size()), this->Run.data());
      this->Types->InsertNextValue(type);
    }
    this->Run.clear();
  }
  void CopyTo(vtkPolyData* lines)
  {
    lines->SetPoints(this->Points);
    lines->SetLines(this->Cells);
    lines->GetCellData()->AddArray(this->Types);
  }

private:
  vtkNew<vtkPoints> Points;
  vtkNew<vtkCellArray> Cells;
  vtkNew<vtkUnsignedCharArray> Types;
  std::vector<vtkIdType> Run;
};

// Samples along each segment's image, a ray for each: marks the pixels of the visible ones, and
// (where asked) keeps their runs as lines.
class Sampler
{
public:
  Sampler(const vtkNPRSceneView& view, const vtkNPROccluders& occluders, unsigned char* pixels,
    double spacing, double epsilon, bool keepRuns)
    : View(view)
    , Occluders(occluders)
    , Pixels(pixels)
    , Spacing(spacing)
    , Epsilon(epsilon)
    , KeepRuns(keepRuns)
  {
  }

  void Sample(const vtkNPRSceneLines::Segment& segment)
  {
    // Clipped one pixel beyond the image; samples outside it are then skipped.
    double t0, t1;
    if (!this->View.ClipSegment(segment.A, segment.B, 1.0, t0, t1))
    {
      return;
    }
    // How many samples keep them SampleSpacing apart.
    const double length = this->View.ImageLength(segment.A, segment.B, t0, t1);
    const vtkIdType steps =
      std::max<vtkIdType>(1, static_cast<vtkIdType>(std::ceil(length / this->Spacing)));
    for (vtkIdType k = 0; k <= steps; ++k)
    {
      const double t =
        this->View.ParameterAt(segment.A, segment.B, t0, t1, static_cast<double>(k) / steps);
      double p[3];
      vtkNPRPointAt(segment.A, segment.B, t, p);
      if (!this->SampleAt(p, segment))
      {
        this->Runs.End(segment.Type);
      }
    }
    this->Runs.End(segment.Type);
  }

  VisibleRuns Runs;
  vtkIdType Samples = 0, RayCasts = 0, VisibleSamples = 0;

private:
  // The pixel of point p, or null where it lies outside the image or the depth range.
  unsigned char* PixelOf(const double p[3]) const
  {
    const int width = this->View.Width, height = this->View.Height;
    double c[4];
    this->View.Clip(p, c);
    const double x = 0.5 * width * (c[0] / c[3] + 1.0);
    const double y = 0.5 * height * (c[1] / c[3] + 1.0);
    if (!(c[3] > 0.0 && c[2] >= -c[3] && c[2] <= c[3] && x >= 0.0 && x < width && y >= 0.0 &&
          y < height))
    {
      return nullptr;
    }
    return &this->Pixels[static_cast<size_t>(static_cast<int>(y)) * width + static_cast<int>(x)];
  }

  // Marks the sample at p where it is visible; false where it ends a run of visible samples
  // (outside the image, or hidden).
  bool SampleAt(const double p[3], const vtkNPRSceneLines::Segment& segment)
  {
    unsigned char* pixel = this->PixelOf(p);
    if (!pixel)
    {
      return false;
    }
    ++this->Samples;
    if (*pixel && !this->KeepRuns)
    {
      return true; // marked already: the mask cannot change
    }
    double from[3], to[3];
    this->View.Ray(p, this->Epsilon, from, to);
    ++this->RayCasts;
    // A smooth contour lies inside a triangle, often a back-facing one just behind the front
    // faces next to it: the faces sharing a point with its triangle do not hide it.
    const bool smooth = (segment.Type & vtkNPRFeatureLines::SMOOTH_CONTOUR) != 0;
    if (this->Occluders.Hidden(from, to, smooth ? segment.Triangle : nullptr, smooth ? 3 : 0))
    {
      return false;
    }
    ++this->VisibleSamples;
    *pixel = 255;
    if (this->KeepRuns)
    {
      this->Runs.Add(p);
    }
    return true;
  }

  const vtkNPRSceneView& View;
  const vtkNPROccluders& Occluders;
  unsigned char* Pixels;
  double Spacing, Epsilon;
  bool KeepRuns;
};
}

struct vtkNPRReferenceMask::Internals
{
  vtkNew<vtkImageData> Mask;
  vtkNew<vtkPolyData> VisibleLines;

  vtkIdType Samples = 0, VisibleSamples = 0, LinePixels = 0;

  // Zeroes what the last update counted and empties its lines.
  void Clear()
  {
    this->Samples = this->VisibleSamples = this->LinePixels = 0;
    this->VisibleLines->Initialize();
  }

  // The mask at this size, every pixel 0: its pixels.
  unsigned char* ClearMask(int width, int height)
  {
    this->Mask->SetDimensions(width, height, 1);
    this->Mask->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
    unsigned char* pixels = static_cast<unsigned char*>(this->Mask->GetScalarPointer());
    std::fill(pixels, pixels + static_cast<size_t>(width) * height, 0);
    return pixels;
  }

  // The sampler's counts and lines, and the marked pixels counted.
  void Collect(Sampler& sampler, bool keepLines)
  {
    this->Samples = sampler.Samples;
    this->VisibleSamples = sampler.VisibleSamples;
    const unsigned char* pixels = static_cast<unsigned char*>(this->Mask->GetScalarPointer());
    const int* size = this->Mask->GetDimensions();
    for (size_t i = 0, n = static_cast<size_t>(size[0]) * size[1]; i < n; ++i)
    {
      this->LinePixels += pixels[i] ? 1 : 0;
    }
    this->Mask->Modified();
    if (keepLines)
    {
      sampler.Runs.CopyTo(this->VisibleLines);
    }
  }
};

vtkStandardNewMacro(vtkNPRReferenceMask);

vtkNPRReferenceMask::vtkNPRReferenceMask()
  : Internal(new Internals)
{
}

vtkNPRReferenceMask::~vtkNPRReferenceMask() = default;

vtkImageData* vtkNPRReferenceMask::GetMask()
{
  return this->Internal->Mask;
}

vtkPolyData* vtkNPRReferenceMask::GetVisibleLines()
{
  return this->Internal->VisibleLines;
}

vtkIdType vtkNPRReferenceMask::GetNumberOfSamples() const
{
  return this->Internal->Samples;
}

vtkIdType vtkNPRReferenceMask::GetNumberOfVisibleSamples() const
{
  return this->Internal->VisibleSamples;
}

vtkIdType vtkNPRReferenceMask::GetNumberOfLinePixels() const
{
  return this->Internal->LinePixels;
}

vtkIdType vtkNPRReferenceMask::GetNumberOfAdjacencyBuilds() const
{
  return this->GetScene().GetNumberOfAdjacencyBuilds();
}

bool vtkNPRReferenceMask::Update()
{
  Internals& internal = *this->Internal;
  internal.Clear();
  int width, height;
  if (!this->StartUpdate(width, height))
  {
    return false;
  }
  unsigned char* pixels = internal.ClearMask(width, height);
  this->UpdateScene(this->TrianglesPerLocator);
  const vtkNPRSceneLines& scene = this->GetScene();

  // Visibility: samples along each segment's image, a ray for each.
  Clock::time_point start = Clock::now();
  vtkNPRSceneView view;
  view.Set(this->Renderer->GetActiveCamera(), width, height);
  Sampler sampler(view, scene.GetOccluders(), pixels, this->SampleSpacing, this->OcclusionEpsilon,
    this->GenerateVisibleLines);
  for (const vtkNPRSceneLines::Segment& segment : scene.GetSegments())
  {
    sampler.Sample(segment);
  }
  internal.Collect(sampler, this->GenerateVisibleLines);
  this->RayCasts = sampler.RayCasts;
  this->VisibilityTime = Seconds(start);
  return true;
}

void vtkNPRReferenceMask::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SampleSpacing: " << this->SampleSpacing << "\n";
  os << indent << "GenerateVisibleLines: " << this->GenerateVisibleLines << "\n";
  os << indent << "TrianglesPerLocator: " << this->TrianglesPerLocator << "\n";
}
