// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNPRReferenceMask.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkImageData.h"
#include "vtkNPRFeatureLines.h"
#include "vtkNPRSceneLines.h"
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
}

struct vtkNPRReferenceMask::Internals
{
  vtkNPRSceneLines Scene;
  vtkNew<vtkImageData> Mask;
  vtkNew<vtkPolyData> VisibleLines;

  vtkIdType FeatureEdges = 0, Samples = 0, RayCasts = 0, VisibleSamples = 0, LinePixels = 0;
  double LinesTime = 0.0, LocatorTime = 0.0, VisibilityTime = 0.0;
};

vtkStandardNewMacro(vtkNPRReferenceMask);
vtkCxxSetObjectMacro(vtkNPRReferenceMask, Renderer, vtkRenderer);

vtkNPRReferenceMask::vtkNPRReferenceMask()
  : Internal(new Internals)
{
}

vtkNPRReferenceMask::~vtkNPRReferenceMask()
{
  this->SetRenderer(nullptr);
}

vtkImageData* vtkNPRReferenceMask::GetMask()
{
  return this->Internal->Mask;
}

vtkPolyData* vtkNPRReferenceMask::GetVisibleLines()
{
  return this->Internal->VisibleLines;
}

vtkIdType vtkNPRReferenceMask::GetNumberOfFeatureEdges() const
{
  return this->Internal->FeatureEdges;
}

vtkIdType vtkNPRReferenceMask::GetNumberOfSamples() const
{
  return this->Internal->Samples;
}

vtkIdType vtkNPRReferenceMask::GetNumberOfRayCasts() const
{
  return this->Internal->RayCasts;
}

vtkIdType vtkNPRReferenceMask::GetNumberOfVisibleSamples() const
{
  return this->Internal->VisibleSamples;
}

vtkIdType vtkNPRReferenceMask::GetNumberOfLinePixels() const
{
  return this->Internal->LinePixels;
}

double vtkNPRReferenceMask::GetLinesTime() const
{
  return this->Internal->LinesTime;
}

double vtkNPRReferenceMask::GetLocatorTime() const
{
  return this->Internal->LocatorTime;
}

double vtkNPRReferenceMask::GetVisibilityTime() const
{
  return this->Internal->VisibilityTime;
}

vtkIdType vtkNPRReferenceMask::GetNumberOfLocatorBuilds() const
{
  return this->Internal->Scene.GetNumberOfLocatorBuilds();
}

vtkIdType vtkNPRReferenceMask::GetNumberOfAdjacencyBuilds() const
{
  return this->Internal->Scene.GetNumberOfAdjacencyBuilds();
}

bool vtkNPRReferenceMask::Update()
{
  Internals& internal = *this->Internal;
  internal.FeatureEdges = internal.Samples = internal.RayCasts = internal.VisibleSamples =
    internal.LinePixels = 0;
  internal.LinesTime = internal.LocatorTime = internal.VisibilityTime = 0.0;
  internal.VisibleLines->Initialize();
  if (!this->Renderer)
  {
    vtkErrorMacro("no renderer");
    return false;
  }
  int width, height;
  if (!vtkNPRImageSize(this->Renderer, this->Size, width, height))
  {
    vtkErrorMacro("no size: set Size or put the renderer in a window with a size");
    return false;
  }
  vtkImageData* mask = internal.Mask;
  mask->SetDimensions(width, height, 1);
  mask->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
  unsigned char* pixels = static_cast<unsigned char*>(mask->GetScalarPointer());
  std::fill(pixels, pixels + static_cast<size_t>(width) * height, 0);

  vtkNPRSceneLines::Settings settings;
  settings.Silhouettes = this->Silhouettes;
  settings.Creases = this->Creases;
  settings.Boundaries = this->Boundaries;
  settings.NonManifoldEdges = this->NonManifoldEdges;
  settings.CreaseAngle = this->CreaseAngle;
  settings.SmoothContours = this->SmoothContours;
  settings.Intersections = this->Creases && this->IntersectionCurves;
  internal.Scene.Update(this->Renderer, settings, this->TrianglesPerLocator);
  const std::vector<vtkNPRSceneLines::Segment>& segments = internal.Scene.GetSegments();
  internal.FeatureEdges = static_cast<vtkIdType>(segments.size());
  internal.LinesTime = internal.Scene.GetLinesTime();
  internal.LocatorTime = internal.Scene.GetLocatorTime();
  const vtkNPROccluders& occluders = internal.Scene.GetOccluders();

  // Visibility: samples along each segment's image, a ray for each.
  Clock::time_point start = Clock::now();
  vtkNPRSceneView view;
  view.Set(this->Renderer->GetActiveCamera(), width, height);

  vtkNew<vtkPoints> visiblePoints;
  visiblePoints->SetDataTypeToDouble();
  vtkNew<vtkCellArray> visibleCells;
  vtkNew<vtkUnsignedCharArray> visibleTypes;
  visibleTypes->SetName("FeatureType");
  std::vector<vtkIdType> run;
  auto endRun = [&](unsigned char type)
  {
    if (run.size() >= 2)
    {
      visibleCells->InsertNextCell(static_cast<vtkIdType>(run.size()), run.data());
      visibleTypes->InsertNextValue(type);
    }
    run.clear();
  };

  for (const vtkNPRSceneLines::Segment& segment : segments)
  {
    // Clipped one pixel beyond the image; samples outside it are then skipped.
    double t0, t1;
    if (!view.ClipSegment(segment.A, segment.B, 1.0, t0, t1))
    {
      continue;
    }
    // How many samples keep them SampleSpacing apart.
    const double length = view.ImageLength(segment.A, segment.B, t0, t1);
    const vtkIdType steps =
      std::max<vtkIdType>(1, static_cast<vtkIdType>(std::ceil(length / this->SampleSpacing)));

    for (vtkIdType k = 0; k <= steps; ++k)
    {
      const double t =
        view.ParameterAt(segment.A, segment.B, t0, t1, static_cast<double>(k) / steps);
      double p[3];
      for (int i = 0; i < 3; ++i)
      {
        p[i] = segment.A[i] + t * (segment.B[i] - segment.A[i]);
      }
      double c[4];
      view.Clip(p, c);
      const double x = 0.5 * width * (c[0] / c[3] + 1.0);
      const double y = 0.5 * height * (c[1] / c[3] + 1.0);
      if (!(c[3] > 0.0 && c[2] >= -c[3] && c[2] <= c[3] && x >= 0.0 && x < width && y >= 0.0 &&
            y < height))
      {
        endRun(segment.Type);
        continue;
      }
      ++internal.Samples;
      unsigned char& pixel =
        pixels[static_cast<size_t>(static_cast<int>(y)) * width + static_cast<int>(x)];
      if (pixel && !this->GenerateVisibleLines)
      {
        continue; // marked already: the mask cannot change
      }
      double from[3], to[3];
      view.Ray(p, this->OcclusionEpsilon, from, to);
      ++internal.RayCasts;
      // A smooth contour lies inside a triangle, often a back-facing one just behind the front
      // faces next to it: the faces sharing a point with its triangle do not hide it.
      const bool smooth = (segment.Type & vtkNPRFeatureLines::SMOOTH_CONTOUR) != 0;
      if (occluders.Hidden(from, to, smooth ? segment.Triangle : nullptr, smooth ? 3 : 0))
      {
        endRun(segment.Type);
        continue;
      }
      ++internal.VisibleSamples;
      pixel = 255;
      if (this->GenerateVisibleLines)
      {
        run.push_back(visiblePoints->InsertNextPoint(p));
      }
    }
    endRun(segment.Type);
  }
  for (size_t i = 0, n = static_cast<size_t>(width) * height; i < n; ++i)
  {
    internal.LinePixels += pixels[i] ? 1 : 0;
  }
  mask->Modified();
  if (this->GenerateVisibleLines)
  {
    internal.VisibleLines->SetPoints(visiblePoints);
    internal.VisibleLines->SetLines(visibleCells);
    internal.VisibleLines->GetCellData()->AddArray(visibleTypes);
  }
  internal.VisibilityTime = Seconds(start);
  return true;
}

void vtkNPRReferenceMask::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Renderer: " << this->Renderer << "\n";
  os << indent << "Size: " << this->Size[0] << " x " << this->Size[1] << "\n";
  os << indent << "Silhouettes: " << this->Silhouettes << "\n";
  os << indent << "Creases: " << this->Creases << "\n";
  os << indent << "IntersectionCurves: " << this->IntersectionCurves << "\n";
  os << indent << "Boundaries: " << this->Boundaries << "\n";
  os << indent << "NonManifoldEdges: " << this->NonManifoldEdges << "\n";
  os << indent << "CreaseAngle: " << this->CreaseAngle << "\n";
  os << indent << "SmoothContours: " << this->SmoothContours << "\n";
  os << indent << "SampleSpacing: " << this->SampleSpacing << "\n";
  os << indent << "OcclusionEpsilon: " << this->OcclusionEpsilon << "\n";
  os << indent << "GenerateVisibleLines: " << this->GenerateVisibleLines << "\n";
  os << indent << "TrianglesPerLocator: " << this->TrianglesPerLocator << "\n";
  os << indent << "NumberOfLocatorBuilds: " << this->GetNumberOfLocatorBuilds() << "\n";
}
