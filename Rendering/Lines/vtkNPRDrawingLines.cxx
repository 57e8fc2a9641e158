// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// STAND-IN, to be replaced by main's vtkNPRDrawingLines.cxx (branch npr-vector needs strokes to
// export before the real class is merged). It samples each feature edge as vtkNPRReferenceMask
// does (SampleSpacing pixels apart, one ray each) and makes a stroke of every run of samples of
// the same visibility along one edge: no bisection, no chaining, no closed loops.
#include "vtkNPRDrawingLines.h"

#include "vtkActor.h"
#include "vtkActorCollection.h"
#include "vtkAlgorithm.h"
#include "vtkAlgorithmOutput.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdList.h"
#include "vtkIntArray.h"
#include "vtkMatrix4x4.h"
#include "vtkNPRFeatureLines.h"
#include "vtkNPROccluders.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <vector>

namespace
{
using Clock = std::chrono::steady_clock;
double Seconds(Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}
void Clip(const double m[16], const double x[3], double clip[4])
{
  for (int r = 0; r < 4; ++r)
  {
    clip[r] = m[4 * r] * x[0] + m[4 * r + 1] * x[1] + m[4 * r + 2] * x[2] + m[4 * r + 3];
  }
}
unsigned char OneType(unsigned char type)
{
  for (unsigned char bit : { 1, 4, 2, 8 })
  {
    if (type & bit)
    {
      return bit;
    }
  }
  return 0;
}
}

struct vtkNPRDrawingLines::Internals
{
  std::map<vtkActor*, vtkSmartPointer<vtkNPRFeatureLines>> Lines;
  vtkNPROccluders Occluders;
  std::vector<vtkNPRMeshInstance> LocatorState;
  vtkIdType LocatorBuilds = 0;
  vtkNew<vtkPolyData> Strokes;
  vtkIdType FeatureEdges = 0, RayCasts = 0;
  double LinesTime = 0.0, LocatorTime = 0.0, VisibilityTime = 0.0, ChainTime = 0.0;
};

vtkStandardNewMacro(vtkNPRDrawingLines);
vtkCxxSetObjectMacro(vtkNPRDrawingLines, Renderer, vtkRenderer);

vtkNPRDrawingLines::vtkNPRDrawingLines()
  : Internal(new Internals)
{
}

vtkNPRDrawingLines::~vtkNPRDrawingLines()
{
  this->SetRenderer(nullptr);
}

vtkPolyData* vtkNPRDrawingLines::GetStrokes()
{
  return this->Internal->Strokes;
}

vtkIdType vtkNPRDrawingLines::GetNumberOfFeatureEdges() const
{
  return this->Internal->FeatureEdges;
}
vtkIdType vtkNPRDrawingLines::GetNumberOfRayCasts() const
{
  return this->Internal->RayCasts;
}
vtkIdType vtkNPRDrawingLines::GetNumberOfStrokes() const
{
  return this->Internal->Strokes->GetNumberOfLines();
}
double vtkNPRDrawingLines::GetLinesTime() const
{
  return this->Internal->LinesTime;
}
double vtkNPRDrawingLines::GetLocatorTime() const
{
  return this->Internal->LocatorTime;
}
double vtkNPRDrawingLines::GetVisibilityTime() const
{
  return this->Internal->VisibilityTime;
}
double vtkNPRDrawingLines::GetChainTime() const
{
  return this->Internal->ChainTime;
}
vtkIdType vtkNPRDrawingLines::GetNumberOfLocatorBuilds() const
{
  return this->Internal->LocatorBuilds;
}

bool vtkNPRDrawingLines::Update()
{
  Internals& internal = *this->Internal;
  internal.Strokes->Initialize();
  internal.FeatureEdges = internal.RayCasts = 0;
  internal.LinesTime = internal.LocatorTime = internal.VisibilityTime = internal.ChainTime = 0.0;
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
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkCellArray> cells;
  vtkNew<vtkDoubleArray> image;
  image->SetName("ImageCoordinates");
  image->SetNumberOfComponents(3);
  vtkNew<vtkUnsignedCharArray> typesOut;
  typesOut->SetName("FeatureType");
  vtkNew<vtkUnsignedCharArray> hiddenOut;
  hiddenOut->SetName("Hidden");
  vtkNew<vtkIntArray> sizeArray;
  sizeArray->SetName("ImageSize");
  sizeArray->SetNumberOfComponents(2);
  sizeArray->InsertNextTuple2(width, height);

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
    std::copy_n(&actor->GetMatrix()->Element[0][0], 16, state.Matrix.data());
    actors.push_back(state);
  }

  Clock::time_point start = Clock::now();
  struct Segment
  {
    double A[3], B[3];
    unsigned char Type;
  };
  std::vector<Segment> segments;
  std::map<vtkActor*, vtkSmartPointer<vtkNPRFeatureLines>> used;
  for (const vtkNPRMeshInstance& state : actors)
  {
    vtkSmartPointer<vtkNPRFeatureLines>& lines = internal.Lines[state.Actor];
    if (!lines)
    {
      lines = vtkSmartPointer<vtkNPRFeatureLines>::New();
    }
    used[state.Actor] = lines;
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
      segment.Type = OneType(types ? types->GetValue(cell) : 0);
      segments.push_back(segment);
    }
  }
  internal.Lines.swap(used);
  internal.FeatureEdges = static_cast<vtkIdType>(segments.size());
  internal.LinesTime = Seconds(start);

  start = Clock::now();
  if (!(actors == internal.LocatorState) || internal.LocatorBuilds == 0)
  {
    internal.Occluders.Build(actors, 4096);
    internal.LocatorState = actors;
    ++internal.LocatorBuilds;
  }
  internal.LocatorTime = Seconds(start);

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
  vtkNew<vtkIdList> candidates;
  std::vector<vtkIdType> run;
  bool runHidden = false;
  auto endRun = [&](unsigned char type)
  {
    if (run.size() >= 2 && (!runHidden || this->HiddenLines))
    {
      cells->InsertNextCell(static_cast<vtkIdType>(run.size()), run.data());
      typesOut->InsertNextValue(type);
      hiddenOut->InsertNextValue(runHidden ? 1 : 0);
    }
    run.clear();
  };
  for (const Segment& segment : segments)
  {
    double ca[4], cb[4];
    Clip(projection, segment.A, ca);
    Clip(projection, segment.B, cb);
    if (!(ca[3] > 0.0 && cb[3] > 0.0))
    {
      continue; // the stand-in does not clip at the eye
    }
    const double dx = 0.5 * width * (cb[0] / cb[3] - ca[0] / ca[3]);
    const double dy = 0.5 * height * (cb[1] / cb[3] - ca[1] / ca[3]);
    const vtkIdType steps = std::max<vtkIdType>(
      1, static_cast<vtkIdType>(std::ceil(std::sqrt(dx * dx + dy * dy) / this->SampleSpacing)));
    for (vtkIdType k = 0; k <= steps; ++k)
    {
      const double s = static_cast<double>(k) / steps;
      const double t = s * ca[3] / ((1.0 - s) * cb[3] + s * ca[3]);
      double p[3], c[4];
      for (int i = 0; i < 3; ++i)
      {
        p[i] = segment.A[i] + t * (segment.B[i] - segment.A[i]);
      }
      Clip(projection, p, c);
      const double x = 0.5 * width * (c[0] / c[3] + 1.0);
      const double y = 0.5 * height * (c[1] / c[3] + 1.0);
      if (!(c[3] > 0.0 && c[2] >= -c[3] && c[2] <= c[3] && x >= -1.0 && x <= width + 1.0 &&
            y >= -1.0 && y <= height + 1.0))
      {
        endRun(segment.Type);
        continue;
      }
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
      const bool hidden = internal.Occluders.Hidden(from, to, candidates);
      if (!run.empty() && hidden != runHidden)
      {
        endRun(segment.Type);
      }
      runHidden = hidden;
      run.push_back(points->InsertNextPoint(p));
      image->InsertNextTuple3(x, y, 0.5 * (c[2] / c[3] + 1.0));
    }
    endRun(segment.Type);
  }
  internal.VisibilityTime = Seconds(start);
  internal.Strokes->SetPoints(points);
  internal.Strokes->SetLines(cells);
  internal.Strokes->GetPointData()->AddArray(image);
  internal.Strokes->GetCellData()->AddArray(typesOut);
  internal.Strokes->GetCellData()->AddArray(hiddenOut);
  internal.Strokes->GetFieldData()->AddArray(sizeArray);
  return true;
}

void vtkNPRDrawingLines::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Renderer: " << this->Renderer << "\n";
  os << indent << "Size: " << this->Size[0] << " x " << this->Size[1] << "\n";
  os << indent << "HiddenLines: " << this->HiddenLines << "\n";
}
