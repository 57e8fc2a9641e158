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

// x' = M x for a point (w = 1), divided by the result's w.
void TransformPoint(const double m[16], const double x[3], double out[3])
{
  double h[4];
  for (int r = 0; r < 4; ++r)
  {
    h[r] = m[4 * r] * x[0] + m[4 * r + 1] * x[1] + m[4 * r + 2] * x[2] + m[4 * r + 3];
  }
  for (int r = 0; r < 3; ++r)
  {
    out[r] = h[r] / h[3];
  }
}

// Homogeneous clip coordinates of a world point.
void Clip(const double m[16], const double x[3], double clip[4])
{
  for (int r = 0; r < 4; ++r)
  {
    clip[r] = m[4 * r] * x[0] + m[4 * r + 1] * x[1] + m[4 * r + 2] * x[2] + m[4 * r + 3];
  }
}

// d . ((p - o) x (q - p)): on which side of the edge p q the line o + t d passes. Computed from
// the edge's ends in one order whichever way a triangle runs along it, so that triangles that
// share an edge get the same value up to its sign: a line through the edge meets one of them.
// (It equals d . ((p - o) x (q - o)), with less rounding: q - p is short.)
double EdgeSide(const double o[3], const double d[3], const double* p, const double* q)
{
  if (std::lexicographical_compare(q, q + 3, p, p + 3))
  {
    return -EdgeSide(o, d, q, p);
  }
  const double op[3] = { p[0] - o[0], p[1] - o[1], p[2] - o[2] };
  const double pq[3] = { q[0] - p[0], q[1] - p[1], q[2] - p[2] };
  return d[0] * (op[1] * pq[2] - op[2] * pq[1]) + d[1] * (op[2] * pq[0] - op[0] * pq[2]) +
    d[2] * (op[0] * pq[1] - op[1] * pq[0]);
}

// Whether the segment o + t d, t in [0, 1], meets the triangle (a, b, c), its edges included
// (from either side). t from the triangle's normal, not from the sum of the sides: that loses
// digits when the segment grazes the plane, as a sample's does on the faces of its line, where
// t must be right to well below OcclusionEpsilon.
bool SegmentMeetsTriangle(
  const double o[3], const double d[3], const double* a, const double* b, const double* c)
{
  const double u = EdgeSide(o, d, b, c), v = EdgeSide(o, d, c, a), w = EdgeSide(o, d, a, b);
  if (!((u >= 0.0 && v >= 0.0 && w >= 0.0) || (u <= 0.0 && v <= 0.0 && w <= 0.0)))
  {
    return false;
  }
  const double ab[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
  const double ac[3] = { c[0] - a[0], c[1] - a[1], c[2] - a[2] };
  double n[3];
  vtkMath::Cross(ab, ac, n);
  const double along = vtkMath::Dot(n, d); // 0: parallel to the plane, or degenerate
  if (along == 0.0)
  {
    return false;
  }
  const double oa[3] = { a[0] - o[0], a[1] - o[1], a[2] - o[2] };
  const double t = vtkMath::Dot(n, oa) / along;
  return t >= 0.0 && t <= 1.0;
}

// What an actor contributes: its mesh, as drawn now.
struct ActorState
{
  vtkActor* Actor;
  vtkPolyData* Mesh;
  vtkMTimeType MeshTime;
  std::array<double, 16> Matrix;
  bool operator==(const ActorState& other) const
  {
    return this->Actor == other.Actor && this->Mesh == other.Mesh &&
      this->MeshTime == other.MeshTime && this->Matrix == other.Matrix;
  }
};
}

struct vtkNPRReferenceMask::Internals
{
  struct LinesEntry
  {
    vtkWeakPointer<vtkActor> Actor;
    vtkSmartPointer<vtkNPRFeatureLines> Lines;
  };
  std::map<vtkActor*, LinesEntry> Lines;

  std::vector<ActorState> LocatorState; // what the locators were built from
  double FrameCenter[3] = { 0.0, 0.0, 0.0 }; // the locators' frame: (world - centre) x scale
  double FrameScale = 1.0;
  int LocatorTrianglesPerLocator = 0;
  // vtkStaticCellLocator, not vtkCellLocator: VTK 9.1's vtkCellLocator::IntersectWithLine
  // misses some triangles (rays through a cube's faces at 2 of 297 points in a test). The
  // static locator clears a flag per cell on every ray (O(cells) per ray), hence the groups.
  // Only its candidates along a ray are used (FindCellsAlongLine), not its IntersectWithLine:
  // since VTK 9.2 that keeps a hit only within the given tolerance of the bin being walked, and
  // with none it loses hits on faces that lie on a bin's side (a cube's) rounded just outside.
  struct Group
  {
    vtkSmartPointer<vtkPolyData> Triangles;
    vtkSmartPointer<vtkStaticCellLocator> Locator;
    vtkSmartPointer<vtkIdTypeArray> Corners; // the triangles' point ids, 3 each
    const double* Coordinates;               // Triangles' points, x y z each
    double Bounds[6];
  };
  std::vector<Group> Groups;
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

  void BuildLocator(const std::vector<ActorState>& actors, int trianglesPerLocator);
  // Whether a triangle crosses the segment.
  bool Hidden(const double from[3], const double to[3], vtkIdList* candidates);
};

void vtkNPRReferenceMask::Internals::BuildLocator(
  const std::vector<ActorState>& actors, int trianglesPerLocator)
{
  // All triangles in world coordinates, double; points with a NaN or infinite coordinate are
  // left out with their triangles (they would spoil the locators' bounds).
  std::vector<double> points;
  std::vector<vtkIdType> triangles;
  for (const ActorState& state : actors)
  {
    vtkPoints* meshPoints = state.Mesh->GetPoints();
    if (!meshPoints)
    {
      continue;
    }
    const vtkIdType count = meshPoints->GetNumberOfPoints();
    const vtkIdType offset = static_cast<vtkIdType>(points.size() / 3);
    points.resize(points.size() + 3 * count);
    std::vector<char> finite(count);
    for (vtkIdType i = 0; i < count; ++i)
    {
      double x[3];
      meshPoints->GetPoint(i, x);
      double* world = &points[3 * (offset + i)];
      TransformPoint(state.Matrix.data(), x, world);
      finite[i] = std::isfinite(world[0]) && std::isfinite(world[1]) && std::isfinite(world[2]);
    }
    auto addTriangle = [&](vtkIdType a, vtkIdType b, vtkIdType c) {
      for (vtkIdType corner : { a, b, c })
      {
        if (corner < 0 || corner >= count || !finite[corner])
        {
          return;
        }
      }
      triangles.insert(triangles.end(), { offset + a, offset + b, offset + c });
    };
    // Polygons as fans, as the OpenGL mapper draws convex polygons; strips as their triangles.
    auto iterator = vtk::TakeSmartPointer(state.Mesh->GetPolys()->NewIterator());
    for (iterator->GoToFirstCell(); !iterator->IsDoneWithTraversal(); iterator->GoToNextCell())
    {
      vtkIdType size;
      const vtkIdType* ids;
      iterator->GetCurrentCell(size, ids);
      for (vtkIdType k = 1; k + 1 < size; ++k)
      {
        addTriangle(ids[0], ids[k], ids[k + 1]);
      }
    }
    iterator = vtk::TakeSmartPointer(state.Mesh->GetStrips()->NewIterator());
    for (iterator->GoToFirstCell(); !iterator->IsDoneWithTraversal(); iterator->GoToNextCell())
    {
      vtkIdType size;
      const vtkIdType* ids;
      iterator->GetCurrentCell(size, ids);
      for (vtkIdType k = 0; k + 2 < size; ++k)
      {
        addTriangle(ids[k], ids[k + 1], ids[k + 2]);
      }
    }
  }

  // The locators work in a frame centred on the scene and scaled to its size: VTK's static
  // locator bins with absolute tolerances, so a scene at 1e-6 took 300 times longer to bin than
  // the same scene at 1 (the rays are moved into that frame too; intersections do not change).
  double sceneLow[3] = { VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, VTK_DOUBLE_MAX };
  double sceneHigh[3] = { -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
  for (vtkIdType id : triangles)
  {
    for (int k = 0; k < 3; ++k)
    {
      sceneLow[k] = std::min(sceneLow[k], points[3 * id + k]);
      sceneHigh[k] = std::max(sceneHigh[k], points[3 * id + k]);
    }
  }
  this->FrameScale = 1.0;
  for (int k = 0; k < 3; ++k)
  {
    this->FrameCenter[k] = triangles.empty() ? 0.0 : 0.5 * (sceneLow[k] + sceneHigh[k]);
  }
  if (!triangles.empty())
  {
    const double extent = std::max(
      { sceneHigh[0] - sceneLow[0], sceneHigh[1] - sceneLow[1], sceneHigh[2] - sceneLow[2] });
    this->FrameScale = extent > 0.0 ? 1.0 / extent : 1.0;
  }
  for (size_t i = 0; i < points.size(); ++i)
  {
    points[i] = (points[i] - this->FrameCenter[i % 3]) * this->FrameScale;
  }

  // Large scenes: groups of nearby triangles (in Morton order of their centroids), one locator
  // each, so that a ray pays only for the groups whose box it crosses.
  const size_t count = triangles.size() / 3;
  std::vector<size_t> order(count);
  for (size_t i = 0; i < count; ++i)
  {
    order[i] = i;
  }
  if (count > static_cast<size_t>(trianglesPerLocator))
  {
    double low[3] = { VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, VTK_DOUBLE_MAX };
    double high[3] = { VTK_DOUBLE_MIN, VTK_DOUBLE_MIN, VTK_DOUBLE_MIN };
    for (vtkIdType id : triangles)
    {
      for (int k = 0; k < 3; ++k)
      {
        low[k] = std::min(low[k], points[3 * id + k]);
        high[k] = std::max(high[k], points[3 * id + k]);
      }
    }
    std::vector<std::uint32_t> code(count);
    for (size_t i = 0; i < count; ++i)
    {
      std::uint32_t key = 0;
      for (int k = 0; k < 3; ++k)
      {
        const double centroid =
          (points[3 * triangles[3 * i] + k] + points[3 * triangles[3 * i + 1] + k] +
            points[3 * triangles[3 * i + 2] + k]) /
          3.0;
        const double extent = high[k] - low[k];
        const std::uint32_t cell = extent > 0.0
          ? static_cast<std::uint32_t>(std::min(1023.0, 1024.0 * (centroid - low[k]) / extent))
          : 0u;
        for (int bit = 0; bit < 10; ++bit)
        {
          key |= ((cell >> bit) & 1u) << (3 * bit + k);
        }
      }
      code[i] = key;
    }
    std::stable_sort(
      order.begin(), order.end(), [&](size_t a, size_t b) { return code[a] < code[b]; });
  }

  this->Groups.clear();
  std::vector<vtkIdType> local(points.size() / 3, -1);
  for (size_t first = 0; first < count; first += trianglesPerLocator)
  {
    const size_t last = std::min(count, first + static_cast<size_t>(trianglesPerLocator));
    Group group;
    vtkNew<vtkPoints> groupPoints;
    groupPoints->SetDataTypeToDouble();
    group.Corners = vtkSmartPointer<vtkIdTypeArray>::New();
    group.Corners->SetNumberOfValues(3 * static_cast<vtkIdType>(last - first));
    vtkIdType* corners = group.Corners->GetPointer(0);
    std::vector<vtkIdType> used;
    for (size_t i = first; i < last; ++i)
    {
      for (int k = 0; k < 3; ++k)
      {
        const vtkIdType id = triangles[3 * order[i] + k];
        if (local[id] < 0)
        {
          local[id] = groupPoints->InsertNextPoint(&points[3 * id]);
          used.push_back(id);
        }
        *corners++ = local[id];
      }
    }
    for (vtkIdType id : used)
    {
      local[id] = -1;
    }
    vtkNew<vtkCellArray> cells;
    cells->SetData(3, group.Corners);
    group.Triangles = vtkSmartPointer<vtkPolyData>::New();
    group.Triangles->SetPoints(groupPoints);
    group.Triangles->SetPolys(cells);
    group.Coordinates = vtkDoubleArray::FastDownCast(groupPoints->GetData())->GetPointer(0);
    group.Triangles->GetBounds(group.Bounds);
    // A margin, so that the box test can only let through more rays, never fewer.
    const double margin = 1e-9 * std::max(1.0, group.Triangles->GetLength());
    for (int k = 0; k < 3; ++k)
    {
      group.Bounds[2 * k] -= margin;
      group.Bounds[2 * k + 1] += margin;
    }
    group.Locator = vtkSmartPointer<vtkStaticCellLocator>::New();
    group.Locator->SetDataSet(group.Triangles);
    // One triangle per bin on average: rays near a surface (every silhouette sample's) then
    // test fewest triangles (measured: 1.7x faster than VTK's default of 10 at 1.2M).
    group.Locator->SetNumberOfCellsPerNode(1);
    group.Locator->BuildLocator();
    this->Groups.push_back(group);
  }
  this->LocatorState = actors;
  this->LocatorTrianglesPerLocator = trianglesPerLocator;
  ++this->LocatorBuilds;
}

bool vtkNPRReferenceMask::Internals::Hidden(
  const double fromWorld[3], const double toWorld[3], vtkIdList* candidates)
{
  double from[3], to[3], direction[3];
  for (int k = 0; k < 3; ++k)
  {
    from[k] = (fromWorld[k] - this->FrameCenter[k]) * this->FrameScale;
    to[k] = (toWorld[k] - this->FrameCenter[k]) * this->FrameScale;
    direction[k] = to[k] - from[k];
  }
  for (const Group& group : this->Groups)
  {
    // Slab test of the segment against the group's box.
    double t0 = 0.0, t1 = 1.0;
    for (int k = 0; k < 3 && t0 <= t1; ++k)
    {
      const double d = to[k] - from[k];
      const double low = group.Bounds[2 * k], high = group.Bounds[2 * k + 1];
      if (d == 0.0)
      {
        if (from[k] < low || from[k] > high)
        {
          t1 = -1.0;
        }
        continue;
      }
      double a = (low - from[k]) / d, b = (high - from[k]) / d;
      if (a > b)
      {
        std::swap(a, b);
      }
      t0 = std::max(t0, a);
      t1 = std::min(t1, b);
    }
    if (t0 > t1)
    {
      continue;
    }
    group.Locator->FindCellsAlongLine(from, to, 0.0, candidates);
    const vtkIdType* corners = group.Corners->GetPointer(0);
    const double* x = group.Coordinates;
    for (vtkIdType i = 0, n = candidates->GetNumberOfIds(); i < n; ++i)
    {
      const vtkIdType* ids = corners + 3 * candidates->GetId(i);
      if (SegmentMeetsTriangle(from, direction, x + 3 * ids[0], x + 3 * ids[1], x + 3 * ids[2]))
      {
        return true;
      }
    }
  }
  return false;
}

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
  std::vector<ActorState> actors;
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
    ActorState state{ actor, mesh, mesh->GetMTime(), {} };
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
  for (const ActorState& state : actors)
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
      TransformPoint(state.Matrix.data(), a, segment.A);
      TransformPoint(state.Matrix.data(), b, segment.B);
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
    internal.BuildLocator(actors, this->TrianglesPerLocator);
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
  auto endRun = [&](unsigned char type) {
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
      if (internal.Hidden(from, to, candidates))
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
