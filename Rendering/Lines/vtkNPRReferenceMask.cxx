// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNPRReferenceMask.h"

#include "vtkActor.h"
#include "vtkActorCollection.h"
#include "vtkAlgorithm.h"
#include "vtkAlgorithmOutput.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkNPRFeatureLines.h"
#include "vtkNPROccluders.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkStaticCellLocator.h"
#include "vtkUnsignedCharArray.h"
#include "vtkWeakPointer.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <map>
#include <vector>

namespace
{
using Clock = std::chrono::steady_clock;

double Seconds(Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Homogeneous clip coordinates of a world point.
void Clip(const double m[16], const double x[3], double clip[4])
{
  for (int r = 0; r < 4; ++r)
  {
    clip[r] = m[4 * r] * x[0] + m[4 * r + 1] * x[1] + m[4 * r + 2] * x[2] + m[4 * r + 3];
  }
}

}

struct vtkNPRReferenceMask::Internals
{
  struct LinesEntry
  {
    vtkWeakPointer<vtkActor> Actor;
    vtkSmartPointer<vtkNPRFeatureLines> Lines;
  };
  std::map<vtkActor*, LinesEntry> Lines;

  std::vector<vtkNPRMeshInstance> LocatorState; // what the locators were built from
  int LocatorTrianglesPerLocator = 0;
  vtkNPROccluders Occluders;
  vtkIdType LocatorBuilds = 0;

  vtkNew<vtkImageData> Mask;
  vtkNew<vtkPolyData> VisibleLines;

  vtkIdType FeatureEdges = 0, Samples = 0, RayCasts = 0, VisibleSamples = 0, LinePixels = 0;
  double LinesTime = 0.0, LocatorTime = 0.0, VisibilityTime = 0.0;

  vtkNPRFeatureLines* LinesFor(vtkActor* actor)
  {
    LinesEntry& entry = this->Lines[actor];
    if (!entry.Lines || entry.Actor != actor) // new, or another actor at a freed address
    {
      entry.Actor = actor;
      entry.Lines = vtkSmartPointer<vtkNPRFeatureLines>::New();
    }
    return entry.Lines;
  }
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
  return this->Internal->LocatorBuilds;
}

vtkIdType vtkNPRReferenceMask::GetNumberOfAdjacencyBuilds() const
{
  vtkIdType builds = 0;
  for (const auto& entry : this->Internal->Lines)
  {
    builds += entry.second.Lines ? entry.second.Lines->GetNumberOfAdjacencyBuilds() : 0;
  }
  return builds;
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
  int width = this->Size[0], height = this->Size[1];
  if (width <= 0 || height <= 0)
  {
    const int* size = this->Renderer->GetRenderWindow() ? this->Renderer->GetSize() : nullptr;
    width = size ? size[0] : 0;
    height = size ? size[1] : 0;
  }
  if (width <= 0 || height <= 0)
  {
    vtkErrorMacro("no size: set Size or put the renderer in a window with a size");
    return false;
  }
  vtkImageData* mask = internal.Mask;
  mask->SetDimensions(width, height, 1);
  mask->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
  unsigned char* pixels = static_cast<unsigned char*>(mask->GetScalarPointer());
  std::fill(pixels, pixels + static_cast<size_t>(width) * height, 0);

  // The actors as they are drawn: visible, opaque, polygonal through a vtkPolyDataMapper.
  vtkCamera* camera = this->Renderer->GetActiveCamera();
  std::vector<vtkNPRMeshInstance> actors;
  vtkActorCollection* collection = this->Renderer->GetActors();
  vtkCollectionSimpleIterator it;
  collection->InitTraversal(it);
  while (vtkActor* actor = collection->GetNextActor(it))
  {
    auto* mapper = vtkPolyDataMapper::SafeDownCast(actor->GetMapper());
    if (!actor->GetVisibility() || !mapper)
    {
      continue;
    }
    if (vtkAlgorithm* producer = mapper->GetInputAlgorithm())
    {
      producer->Update(mapper->GetInputConnection(0, 0)->GetIndex());
    }
    vtkPolyData* mesh = mapper->GetInput();
    if (!mesh || !actor->HasOpaqueGeometry())
    {
      continue;
    }
    vtkNPRMeshInstance state{ actor, mesh, mesh->GetMTime(), {} };
    vtkMatrix4x4* matrix = actor->GetMatrix();
    std::copy_n(&matrix->Element[0][0], 16, state.Matrix.data());
    actors.push_back(state);
  }

  // Feature lines of each actor, in world coordinates.
  Clock::time_point start = Clock::now();
  struct Segment
  {
    double A[3], B[3];
    unsigned char Type;
  };
  std::vector<Segment> segments;
  std::map<vtkActor*, Internals::LinesEntry> used;
  for (const vtkNPRMeshInstance& state : actors)
  {
    vtkNPRFeatureLines* lines = internal.LinesFor(state.Actor);
    used[state.Actor] = internal.Lines[state.Actor];
    lines->SetInputData(state.Mesh);
    lines->SetCamera(camera, state.Actor->GetMatrix());
    lines->SetSilhouettes(this->Silhouettes);
    lines->SetCreases(this->Creases);
    lines->SetBoundaries(this->Boundaries);
    lines->SetNonManifoldEdges(this->NonManifoldEdges);
    lines->SetFeatureAngle(this->CreaseAngle);
    lines->Update();
    vtkPolyData* output = lines->GetOutput();
    auto* types =
      vtkUnsignedCharArray::SafeDownCast(output->GetCellData()->GetArray("FeatureType"));
    auto iterator = vtk::TakeSmartPointer(output->GetLines()->NewIterator());
    vtkIdType cell = 0;
    for (iterator->GoToFirstCell(); !iterator->IsDoneWithTraversal();
         iterator->GoToNextCell(), ++cell)
    {
      vtkIdType size;
      const vtkIdType* ids;
      iterator->GetCurrentCell(size, ids);
      Segment segment;
      double a[3], b[3];
      output->GetPoint(ids[0], a);
      output->GetPoint(ids[1], b);
      vtkNPRTransformPoint(state.Matrix.data(), a, segment.A);
      vtkNPRTransformPoint(state.Matrix.data(), b, segment.B);
      segment.Type = types ? types->GetValue(cell) : 0;
      segments.push_back(segment);
    }
  }
  internal.Lines.swap(used); // forget the actors that are gone
  internal.FeatureEdges = static_cast<vtkIdType>(segments.size());
  internal.LinesTime = Seconds(start);

  start = Clock::now();
  if (!(actors == internal.LocatorState) || internal.LocatorBuilds == 0 ||
    internal.LocatorTrianglesPerLocator != this->TrianglesPerLocator)
  {
    internal.Occluders.Build(actors, this->TrianglesPerLocator);
    internal.LocatorState = actors;
    internal.LocatorTrianglesPerLocator = this->TrianglesPerLocator;
    ++internal.LocatorBuilds;
  }
  internal.LocatorTime = Seconds(start);

  // Visibility: samples along each segment's image, a ray for each.
  start = Clock::now();
  const double aspect = static_cast<double>(width) / height;
  double projection[16];
  std::copy_n(
    &camera->GetCompositeProjectionTransformMatrix(aspect, -1, 1)->Element[0][0], 16, projection);
  double eye[3], direction[3], range[2];
  camera->GetPosition(eye);
  camera->GetDirectionOfProjection(direction);
  camera->GetClippingRange(range);
  const bool parallel = camera->GetParallelProjection() != 0;
  // Segments are clipped one pixel beyond the image; samples outside it are then skipped.
  const double marginX = 1.0 + 2.0 / width, marginY = 1.0 + 2.0 / height;

  vtkNew<vtkIdList> candidates;
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

  for (const Segment& segment : segments)
  {
    double ca[4], cb[4];
    Clip(projection, segment.A, ca);
    Clip(projection, segment.B, cb);
    // Clip t in [0, 1] against -w <= z <= w and the image (with its margin), homogeneously.
    double t0 = 0.0, t1 = 1.0;
    const double distances[6][2] = { { ca[3] + ca[2], cb[3] + cb[2] },
      { ca[3] - ca[2], cb[3] - cb[2] }, { marginX * ca[3] + ca[0], marginX * cb[3] + cb[0] },
      { marginX * ca[3] - ca[0], marginX * cb[3] - cb[0] },
      { marginY * ca[3] + ca[1], marginY * cb[3] + cb[1] },
      { marginY * ca[3] - ca[1], marginY * cb[3] - cb[1] } };
    for (const auto& d : distances)
    {
      if (d[0] < 0.0 && d[1] < 0.0)
      {
        t0 = 1.0;
        t1 = 0.0;
        break;
      }
      if (d[0] < 0.0)
      {
        t0 = std::max(t0, d[0] / (d[0] - d[1]));
      }
      else if (d[1] < 0.0)
      {
        t1 = std::min(t1, d[0] / (d[0] - d[1]));
      }
    }
    if (!(t0 <= t1))
    {
      continue;
    }
    // The clipped ends in the image, and how many samples keep them SampleSpacing apart.
    double h0[4], h1[4];
    for (int k = 0; k < 4; ++k)
    {
      h0[k] = ca[k] + t0 * (cb[k] - ca[k]);
      h1[k] = ca[k] + t1 * (cb[k] - ca[k]);
    }
    if (!(h0[3] > 0.0 && h1[3] > 0.0))
    {
      continue;
    }
    const double dx = 0.5 * width * (h1[0] / h1[3] - h0[0] / h0[3]);
    const double dy = 0.5 * height * (h1[1] / h1[3] - h0[1] / h0[3]);
    const double length = std::sqrt(dx * dx + dy * dy);
    const vtkIdType steps =
      std::max<vtkIdType>(1, static_cast<vtkIdType>(std::ceil(length / this->SampleSpacing)));

    for (vtkIdType k = 0; k <= steps; ++k)
    {
      // Equal steps in the image are unequal along the segment under perspective: the
      // parameter of image fraction s is s w0 / ((1 - s) w1 + s w0).
      const double s = static_cast<double>(k) / steps;
      const double tau = s * h0[3] / ((1.0 - s) * h1[3] + s * h0[3]);
      const double t = t0 + (t1 - t0) * tau;
      double p[3];
      for (int i = 0; i < 3; ++i)
      {
        p[i] = segment.A[i] + t * (segment.B[i] - segment.A[i]);
      }
      double c[4];
      Clip(projection, p, c);
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
      // From the near plane to the sample, short of it by the epsilon.
      const double toPoint[3] = { p[0] - eye[0], p[1] - eye[1], p[2] - eye[2] };
      const double depth =
        toPoint[0] * direction[0] + toPoint[1] * direction[1] + toPoint[2] * direction[2];
      double from[3], to[3];
      for (int i = 0; i < 3; ++i)
      {
        from[i] = parallel ? p[i] - (depth - range[0]) * direction[i]
                           : eye[i] + toPoint[i] * (range[0] / depth);
        to[i] = from[i] + (1.0 - this->OcclusionEpsilon) * (p[i] - from[i]);
      }
      ++internal.RayCasts;
      if (internal.Occluders.Hidden(from, to, candidates))
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
  os << indent << "Boundaries: " << this->Boundaries << "\n";
  os << indent << "NonManifoldEdges: " << this->NonManifoldEdges << "\n";
  os << indent << "CreaseAngle: " << this->CreaseAngle << "\n";
  os << indent << "SampleSpacing: " << this->SampleSpacing << "\n";
  os << indent << "OcclusionEpsilon: " << this->OcclusionEpsilon << "\n";
  os << indent << "GenerateVisibleLines: " << this->GenerateVisibleLines << "\n";
  os << indent << "TrianglesPerLocator: " << this->TrianglesPerLocator << "\n";
  os << indent << "NumberOfLocatorBuilds: " << this->GetNumberOfLocatorBuilds() << "\n";
}
