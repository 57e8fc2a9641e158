// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNPRSceneLines.h"

#include "vtkActor.h"
#include "vtkAlgorithm.h"
#include "vtkAlgorithmOutput.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataSetMapper.h"
#include "vtkIdTypeArray.h"
#include "vtkMatrix4x4.h"
#include "vtkNPRFeatureLines.h"
#include "vtkNPRPropParts.h"
#include "vtkNPRVectors.h"
#include "vtkNew.h"
#include "vtkPointGaussianMapper.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProp3D.h"
#include "vtkPropCollection.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numeric>

namespace
{
using Clock = std::chrono::steady_clock;

double Seconds(Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// The ends of the crossings (2 i: A of crossing i, 2 i + 1: its B) numbered as nodes: ends within
// a billionth of the scene's size of each other are one node, since two neighbouring pairs of
// triangles compute the end they share each with its own rounding; so the curves chain.
std::vector<vtkIdType> NumberCrossingEnds(const std::vector<const vtkNPROccluders::Crossing*>& kept)
{
  const size_t count = 2 * kept.size();
  auto end = [&](size_t i) { return vtkNPRVector(i % 2 ? kept[i / 2]->B : kept[i / 2]->A); };
  double size = 0.0; // the largest coordinate or extent, which bounds the rounding
  glm::dvec3 low(std::numeric_limits<double>::max()), high(-low);
  for (size_t i = 0; i < count; ++i)
  {
    low = glm::min(low, end(i));
    high = glm::max(high, end(i));
  }
  for (int k = 0; count > 0 && k < 3; ++k)
  {
    size = std::max({ size, high[k] - low[k], std::abs(low[k]), std::abs(high[k]) });
  }
  const double tolerance = 1e-9 * size;
  // The ends sorted by x; those within the tolerance joined (union-find).
  std::vector<size_t> order(count), root(count);
  std::iota(order.begin(), order.end(), size_t{ 0 });
  std::iota(root.begin(), root.end(), size_t{ 0 });
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return end(a).x < end(b).x; });
  auto find = [&](size_t i)
  {
    while (root[i] != i)
    {
      i = root[i] = root[root[i]];
    }
    return i;
  };
  for (size_t a = 0; a < count; ++a)
  {
    for (size_t b = a + 1; b < count && end(order[b]).x - end(order[a]).x <= tolerance; ++b)
    {
      if (glm::distance(end(order[a]), end(order[b])) <= tolerance)
      {
        const size_t ra = find(order[a]), rb = find(order[b]);
        root[std::max(ra, rb)] = std::min(ra, rb);
      }
    }
  }
  // Nodes numbered in the order of their first end.
  std::vector<vtkIdType> nodes(count, -1);
  vtkIdType next = 0;
  for (size_t i = 0; i < count; ++i)
  {
    const size_t r = find(i);
    nodes[i] = nodes[r] >= 0 ? nodes[r] : (nodes[r] = next++);
  }
  return nodes;
}

// Calls edge(a, b) for each side of each polygon of the mesh (its closing side too) and each
// side of each triangle of its strips, as a wireframe draws them; shared sides come once a face.
template <typename Edge>
void ForEachPolygonEdge(vtkPolyData* mesh, Edge&& edge)
{
  vtkIdType size;
  const vtkIdType* ids;
  auto polygons = vtk::TakeSmartPointer(mesh->GetPolys()->NewIterator());
  for (polygons->GoToFirstCell(); !polygons->IsDoneWithTraversal(); polygons->GoToNextCell())
  {
    polygons->GetCurrentCell(size, ids);
    for (vtkIdType k = 0; size > 1 && k < size; ++k)
    {
      edge(ids[k], ids[(k + 1) % size]);
    }
  }
  auto strips = vtk::TakeSmartPointer(mesh->GetStrips()->NewIterator());
  for (strips->GoToFirstCell(); !strips->IsDoneWithTraversal(); strips->GoToNextCell())
  {
    strips->GetCurrentCell(size, ids);
    for (vtkIdType k = 0; k + 1 < size; ++k)
    {
      edge(ids[k], ids[k + 1]);
      if (k + 2 < size)
      {
        edge(ids[k], ids[k + 2]);
      }
    }
  }
}

// Appends the segment between points a and b of a mesh, in world coordinates, as a line of the
// scene (`type` LINE or MESH_EDGE; nodes the mesh's point ids from firstNode on); nothing where a
// point is not finite.
void AppendPrimitive(const vtkNPRMeshInstance& state, int mesh, vtkIdType a, vtkIdType b,
  unsigned char type, vtkIdType firstNode, std::vector<vtkNPRSceneLines::Segment>& segments)
{
  vtkNPRSceneLines::Segment segment;
  double x[3];
  state.Mesh->GetPoints()->GetPoint(a, x);
  vtkNPRTransformPoint(state.Matrix.data(), x, segment.A);
  state.Mesh->GetPoints()->GetPoint(b, x);
  vtkNPRTransformPoint(state.Matrix.data(), x, segment.B);
  auto finite = [](const double p[3])
  { return std::all_of(p, p + 3, [](double v) { return std::isfinite(v); }); };
  if (!finite(segment.A) || !finite(segment.B))
  {
    return;
  }
  segment.Type = type;
  segment.NodeA = firstNode + a;
  segment.NodeB = firstNode + b;
  std::fill_n(segment.Triangle, 3, -1);
  segment.Mesh = mesh;
  segments.push_back(segment);
}

// Whether the actor shows surfaces: not a point cloud or a wireframe (the Points and Wireframe
// representations, vtkPointGaussianMapper splats), which has no outline or creases of its own.
bool ShowsSurfaces(vtkActor* actor)
{
  return actor->GetProperty()->GetRepresentation() == VTK_SURFACE &&
    !vtkPointGaussianMapper::SafeDownCast(actor->GetMapper());
}

// Whether the actor draws its meshes' points as its points (the Points representation), not
// splats.
bool ShowsPoints(vtkActor* actor)
{
  return actor->GetProperty()->GetRepresentation() == VTK_POINTS &&
    !vtkPointGaussianMapper::SafeDownCast(actor->GetMapper());
}

// Whether the actor draws its meshes as the representation asks.
bool DrawnAs(vtkActor* actor, vtkNPRDrawnAs drawnAs)
{
  switch (drawnAs)
  {
    case vtkNPRDrawnAs::Surfaces:
      return ShowsSurfaces(actor);
    case vtkNPRDrawnAs::Points:
      return ShowsPoints(actor);
    default:
      return actor->GetProperty()->GetRepresentation() == VTK_WIREFRAME &&
        !vtkPointGaussianMapper::SafeDownCast(actor->GetMapper());
  }
}

// One actor as it is drawn, with the matrix it is drawn with: visible, opaque, surfaces
// (ShowsSurfaces; or points or wireframes: DrawnAs) through a vtkPolyDataMapper, or a
// vtkDataSetMapper of a vtkPolyData (PyVista's meshes); each polygonal leaf of a composite input
// (ParaView's representations, vtkCompositePolyDataMapper2) is a mesh of its actor.
void AddDrawnMeshes(vtkActor* actor, vtkMatrix4x4* matrix, vtkNPRDrawnAs drawnAs,
  std::vector<vtkNPRMeshInstance>& meshes)
{
  vtkMapper* mapper = actor->GetMapper();
  if ((!vtkPolyDataMapper::SafeDownCast(mapper) && !vtkDataSetMapper::SafeDownCast(mapper)) ||
    !DrawnAs(actor, drawnAs))
  {
    return;
  }
  if (vtkAlgorithm* producer = mapper->GetInputAlgorithm())
  {
    producer->Update(mapper->GetInputConnection(0, 0)->GetIndex());
  }
  if (!actor->HasOpaqueGeometry())
  {
    return;
  }
  vtkNPRMeshInstance state{ actor, nullptr, 0, {} };
  std::copy_n(&matrix->Element[0][0], 16, state.Matrix.data());
  vtkDataObject* input = mapper->GetInputDataObject(0, 0);
  if (auto* composite = vtkCompositeDataSet::SafeDownCast(input))
  {
    auto iterator = vtk::TakeSmartPointer(composite->NewIterator());
    for (iterator->InitTraversal(); !iterator->IsDoneWithTraversal(); iterator->GoToNextItem())
    {
      if (auto* leaf = vtkPolyData::SafeDownCast(iterator->GetCurrentDataObject()))
      {
        state.Mesh = leaf;
        state.MeshTime = leaf->GetMTime();
        meshes.push_back(state);
      }
    }
  }
  else if (auto* mesh = vtkPolyData::SafeDownCast(input))
  {
    state.Mesh = mesh;
    state.MeshTime = mesh->GetMTime();
    meshes.push_back(state);
  }
}
}

std::vector<vtkNPRMeshInstance> vtkNPRDrawnMeshes(vtkRenderer* renderer, vtkNPRDrawnAs drawnAs)
{
  std::vector<vtkNPRMeshInstance> meshes;
  vtkPropCollection* props = renderer->GetViewProps();
  vtkCollectionSimpleIterator it;
  props->InitTraversal(it);
  while (vtkProp* prop = props->GetNextProp(it))
  {
    if (!prop->GetVisibility())
    {
      continue;
    }
    for (const vtkNPRPropPart& part : vtkNPRPropParts(prop))
    {
      auto* actor = vtkActor::SafeDownCast(part.Prop);
      if (actor && part.Matrix)
      {
        AddDrawnMeshes(actor, part.Matrix, drawnAs, meshes);
      }
    }
  }
  return meshes;
}

namespace
{
// A class's name as the user made it: VTK's object factory makes vtkOpenGLActor of vtkActor.
std::string UserClassName(vtkObject* object)
{
  std::string name = object->GetClassName();
  return name.rfind("vtkOpenGL", 0) == 0 ? "vtk" + name.substr(9) : name;
}

// What a part that no drawn mesh comes from is, for a message.
std::string DescribeNotDrawn(vtkProp* part)
{
  const std::string name = UserClassName(part);
  auto* actor = vtkActor::SafeDownCast(part);
  vtkMapper* mapper = actor ? actor->GetMapper() : nullptr;
  if (!mapper)
  {
    return name;
  }
  if (!vtkPolyDataMapper::SafeDownCast(mapper) && !vtkDataSetMapper::SafeDownCast(mapper))
  {
    return name + " drawn by " + UserClassName(mapper);
  }
  vtkDataObject* input = mapper->GetInputDataObject(0, 0);
  if (input && !vtkPolyData::SafeDownCast(input) && !vtkCompositeDataSet::SafeDownCast(input))
  {
    return name + " of a " + input->GetClassName();
  }
  return actor->HasTranslucentPolygonalGeometry() ? "translucent " + name : name;
}
}

std::vector<std::string> vtkNPRPropsNotDrawn(vtkRenderer* renderer)
{
  std::vector<std::string> notDrawn;
  vtkPropCollection* props = renderer->GetViewProps();
  vtkCollectionSimpleIterator it;
  props->InitTraversal(it);
  while (vtkProp* prop = props->GetNextProp(it))
  {
    if (!prop->GetVisibility() || !vtkProp3D::SafeDownCast(prop))
    {
      continue; // 2D props are the overlays'
    }
    for (const vtkNPRPropPart& part : vtkNPRPropParts(prop))
    {
      std::vector<vtkNPRMeshInstance> meshes;
      auto* actor = vtkActor::SafeDownCast(part.Prop);
      for (const vtkNPRDrawnAs drawnAs :
        { vtkNPRDrawnAs::Surfaces, vtkNPRDrawnAs::Points, vtkNPRDrawnAs::Wireframe })
      {
        if (actor && part.Matrix)
        {
          AddDrawnMeshes(actor, part.Matrix, drawnAs, meshes);
        }
      }
      if (meshes.empty())
      {
        notDrawn.push_back(DescribeNotDrawn(part.Prop));
      }
    }
  }
  return notDrawn;
}

bool vtkNPRImageSize(vtkRenderer* renderer, const int size[2], int& width, int& height)
{
  width = size[0];
  height = size[1];
  if (width <= 0 || height <= 0)
  {
    const int* own = renderer->GetRenderWindow() ? renderer->GetSize() : nullptr;
    width = own ? own[0] : 0;
    height = own ? own[1] : 0;
  }
  return width > 0 && height > 0;
}

void vtkNPRSceneView::Set(vtkCamera* camera, int width, int height)
{
  this->Width = width;
  this->Height = height;
  const double aspect = static_cast<double>(width) / height;
  std::copy_n(&camera->GetCompositeProjectionTransformMatrix(aspect, -1, 1)->Element[0][0], 16,
    this->Projection);
  camera->GetPosition(this->Eye);
  camera->GetDirectionOfProjection(this->Direction);
  camera->GetClippingRange(this->Range);
  this->Parallel = camera->GetParallelProjection() != 0;
}

void vtkNPRSceneView::Clip(const double x[3], double clip[4]) const
{
  const double* m = this->Projection;
  for (int r = 0; r < 4; ++r)
  {
    clip[r] = m[4 * r] * x[0] + m[4 * r + 1] * x[1] + m[4 * r + 2] * x[2] + m[4 * r + 3];
  }
}

bool vtkNPRSceneView::ToImage(const double x[3], double image[3]) const
{
  double c[4];
  this->Clip(x, c);
  image[0] = 0.5 * this->Width * (c[0] / c[3] + 1.0);
  image[1] = 0.5 * this->Height * (c[1] / c[3] + 1.0);
  image[2] = 0.5 * (c[2] / c[3] + 1.0);
  return c[3] > 0.0;
}

bool vtkNPRSceneView::ClipSegment(
  const double a[3], const double b[3], double margin, double& t0, double& t1) const
{
  double ca[4], cb[4];
  this->Clip(a, ca);
  this->Clip(b, cb);
  const double marginX = 1.0 + 2.0 * margin / this->Width;
  const double marginY = 1.0 + 2.0 * margin / this->Height;
  // t in [0, 1] against -w <= z <= w and the widened image, homogeneously.
  t0 = 0.0;
  t1 = 1.0;
  const double distances[6][2] = { { ca[3] + ca[2], cb[3] + cb[2] },
    { ca[3] - ca[2], cb[3] - cb[2] }, { marginX * ca[3] + ca[0], marginX * cb[3] + cb[0] },
    { marginX * ca[3] - ca[0], marginX * cb[3] - cb[0] },
    { marginY * ca[3] + ca[1], marginY * cb[3] + cb[1] },
    { marginY * ca[3] - ca[1], marginY * cb[3] - cb[1] } };
  for (const auto& d : distances)
  {
    if (d[0] < 0.0 && d[1] < 0.0)
    {
      return false;
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
    return false;
  }
  const double w0 = ca[3] + t0 * (cb[3] - ca[3]), w1 = ca[3] + t1 * (cb[3] - ca[3]);
  return w0 > 0.0 && w1 > 0.0;
}

double vtkNPRSceneView::ParameterAt(
  const double a[3], const double b[3], double t0, double t1, double s) const
{
  double ca[4], cb[4];
  this->Clip(a, ca);
  this->Clip(b, cb);
  const double w0 = ca[3] + t0 * (cb[3] - ca[3]), w1 = ca[3] + t1 * (cb[3] - ca[3]);
  // Image fraction s is parameter fraction s w0 / ((1 - s) w1 + s w0).
  const double tau = s * w0 / ((1.0 - s) * w1 + s * w0);
  return t0 + (t1 - t0) * tau;
}

double vtkNPRSceneView::ImageLength(
  const double a[3], const double b[3], double t0, double t1) const
{
  double p0[3], p1[3], i0[3], i1[3];
  vtkNPRPointAt(a, b, t0, p0);
  vtkNPRPointAt(a, b, t1, p1);
  this->ToImage(p0, i0);
  this->ToImage(p1, i1);
  return std::hypot(i1[0] - i0[0], i1[1] - i0[1]);
}

void vtkNPRSceneView::Ray(const double p[3], double epsilon, double from[3], double to[3]) const
{
  const glm::dvec3 point = vtkNPRVector(p), eye = vtkNPRVector(this->Eye);
  const glm::dvec3 direction = vtkNPRVector(this->Direction), toPoint = point - eye;
  const double depth = glm::dot(toPoint, direction);
  const glm::dvec3 start = this->Parallel ? point - (depth - this->Range[0]) * direction
                                          : eye + toPoint * (this->Range[0] / depth);
  vtkNPRStore(start, from);
  vtkNPRStore(vtkNPRPointAlong(start, point, 1.0 - epsilon), to);
}

vtkNPRSceneLines::vtkNPRSceneLines() = default;
vtkNPRSceneLines::~vtkNPRSceneLines() = default;

vtkIdType vtkNPRSceneLines::GetNumberOfAdjacencyBuilds() const
{
  vtkIdType builds = 0;
  for (const auto& entry : this->Lines)
  {
    builds += entry.second.Lines ? entry.second.Lines->GetNumberOfAdjacencyBuilds() : 0;
  }
  return builds;
}

size_t vtkNPRSceneLines::GetMemorySize() const
{
  size_t bytes = this->Occluders.GetMemorySize() + sizeof(Segment) * this->Segments.capacity();
  for (const auto& entry : this->Lines)
  {
    bytes += entry.second.Lines ? entry.second.Lines->GetAdjacencyMemorySize() : 0;
  }
  return bytes;
}

void vtkNPRSceneLines::Update(
  vtkRenderer* renderer, const Settings& settings, int trianglesPerLocator)
{
  const std::vector<vtkNPRMeshInstance> actors = vtkNPRDrawnMeshes(renderer);
  Clock::time_point start = Clock::now();
  const vtkIdType nodes = this->UpdateLines(actors, renderer->GetActiveCamera(), settings);
  this->LinesTime = Seconds(start);
  start = Clock::now();
  this->UpdateOccluders(actors, settings, trianglesPerLocator, nodes);
  this->LocatorTime = Seconds(start);
  this->LineMeshes = actors;
  if (settings.LinePrimitives)
  {
    const std::vector<vtkNPRMeshInstance> wireframes =
      vtkNPRDrawnMeshes(renderer, vtkNPRDrawnAs::Wireframe);
    this->LineMeshes.insert(this->LineMeshes.end(), wireframes.begin(), wireframes.end());
    vtkIdType firstNode = 0;
    for (const Segment& segment : this->Segments)
    {
      firstNode = std::max({ firstNode, segment.NodeA + 1, segment.NodeB + 1 });
    }
    firstNode = this->AppendLinePrimitives(this->LineMeshes, firstNode);
    this->AppendMeshEdges(this->LineMeshes, actors.size(), firstNode);
  }
}

vtkIdType vtkNPRSceneLines::UpdateLines(
  const std::vector<vtkNPRMeshInstance>& actors, vtkCamera* camera, const Settings& settings)
{
  // Feature lines of each actor, in world coordinates.
  this->Segments.clear();
  std::map<MeshKey, LinesEntry> used;
  vtkIdType nodeOffset = 0;
  vtkIdType pointOffset = 0; // of the mesh's points in the occluders' numbering
  for (const vtkNPRMeshInstance& state : actors)
  {
    const MeshKey key{ state.Actor, state.Mesh };
    LinesEntry& entry = this->Lines[key];
    // New, or another actor or mesh at a freed address.
    if (!entry.Lines || entry.Actor != state.Actor || entry.Mesh != state.Mesh)
    {
      entry.Actor = state.Actor;
      entry.Mesh = state.Mesh;
      entry.Lines = vtkSmartPointer<vtkNPRFeatureLines>::New();
    }
    used[key] = entry;
    vtkNPRFeatureLines* lines = entry.Lines;
    lines->SetInputData(state.Mesh);
    vtkNew<vtkMatrix4x4> model; // the matrix it is drawn with (an assembly's part: its path's)
    model->DeepCopy(state.Matrix.data());
    lines->SetCamera(camera, model);
    lines->SetSilhouettes(settings.Silhouettes);
    lines->SetCreases(settings.Creases);
    lines->SetBoundaries(settings.Boundaries);
    lines->SetNonManifoldEdges(settings.NonManifoldEdges);
    lines->SetFeatureAngle(settings.CreaseAngle);
    lines->SetSmoothContours(settings.SmoothContours);
    lines->Update();
    this->AppendSegments(
      lines->GetOutput(), state, static_cast<int>(&state - actors.data()), nodeOffset, pointOffset);
    nodeOffset += lines->GetOutput()->GetNumberOfPoints();
    pointOffset += state.Mesh->GetPoints() ? state.Mesh->GetNumberOfPoints() : 0;
  }
  this->Lines.swap(used); // forget the actors that are gone
  return nodeOffset;
}

void vtkNPRSceneLines::AppendSegments(vtkPolyData* output, const vtkNPRMeshInstance& state,
  int mesh, vtkIdType nodeOffset, vtkIdType pointOffset)
{
  auto* types = vtkUnsignedCharArray::SafeDownCast(output->GetCellData()->GetArray("FeatureType"));
  auto* triangles =
    vtkIdTypeArray::SafeDownCast(output->GetCellData()->GetArray("ContourTriangle"));
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
    segment.NodeA = nodeOffset + ids[0];
    segment.NodeB = nodeOffset + ids[1];
    for (int k = 0; k < 3; ++k)
    {
      const vtkIdType corner = triangles ? triangles->GetTypedComponent(cell, k) : -1;
      segment.Triangle[k] = corner >= 0 ? pointOffset + corner : -1;
    }
    segment.Mesh = mesh;
    this->Segments.push_back(segment);
  }
}

vtkIdType vtkNPRSceneLines::AppendLinePrimitives(
  const std::vector<vtkNPRMeshInstance>& actors, vtkIdType firstNode)
{
  for (size_t mesh = 0; mesh < actors.size(); ++mesh)
  {
    const vtkNPRMeshInstance& state = actors[mesh];
    vtkCellArray* cells = state.Mesh->GetLines();
    vtkPoints* points = state.Mesh->GetPoints();
    if (cells && points && cells->GetNumberOfCells() > 0)
    {
      auto iterator = vtk::TakeSmartPointer(cells->NewIterator());
      for (iterator->GoToFirstCell(); !iterator->IsDoneWithTraversal(); iterator->GoToNextCell())
      {
        vtkIdType size;
        const vtkIdType* ids;
        iterator->GetCurrentCell(size, ids);
        for (vtkIdType k = 0; k + 1 < size; ++k) // a polyline's segments
        {
          AppendPrimitive(state, static_cast<int>(mesh), ids[k], ids[k + 1],
            vtkNPRFeatureLines::LINE, firstNode, this->Segments);
        }
      }
    }
    firstNode += state.Mesh->GetNumberOfPoints();
  }
  return firstNode;
}

void vtkNPRSceneLines::AppendMeshEdges(
  const std::vector<vtkNPRMeshInstance>& meshes, size_t firstWireframe, vtkIdType firstNode)
{
  for (size_t mesh = 0; mesh < meshes.size(); ++mesh)
  {
    const vtkNPRMeshInstance& state = meshes[mesh];
    vtkPoints* points = state.Mesh->GetPoints();
    const vtkIdType count = points ? points->GetNumberOfPoints() : 0;
    if (points && (mesh >= firstWireframe || state.Actor->GetProperty()->GetEdgeVisibility()))
    {
      // Each edge once: its two point ids, the smaller first, sorted.
      std::vector<std::pair<vtkIdType, vtkIdType>> edges;
      ForEachPolygonEdge(state.Mesh,
        [&](vtkIdType a, vtkIdType b)
        {
          if (a != b && a >= 0 && b >= 0 && a < count && b < count)
          {
            edges.emplace_back(std::min(a, b), std::max(a, b));
          }
        });
      std::sort(edges.begin(), edges.end());
      edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
      for (const auto& edge : edges)
      {
        AppendPrimitive(state, static_cast<int>(mesh), edge.first, edge.second,
          vtkNPRFeatureLines::MESH_EDGE, firstNode, this->Segments);
      }
    }
    firstNode += count;
  }
}

void vtkNPRSceneLines::UpdateOccluders(const std::vector<vtkNPRMeshInstance>& actors,
  const Settings& settings, int trianglesPerLocator, vtkIdType nodeOffset)
{
  if (!(actors == this->LocatorState) || this->LocatorBuilds == 0 ||
    this->LocatorTrianglesPerLocator != trianglesPerLocator)
  {
    this->Occluders.Build(actors, trianglesPerLocator);
    this->LocatorState = actors;
    this->LocatorTrianglesPerLocator = trianglesPerLocator;
    ++this->LocatorBuilds;
  }
  // Where surfaces cross (parts of one mesh, or two actors), a crease of no mesh.
  if (settings.Intersections)
  {
    this->AppendCrossings(settings.CreaseAngle, nodeOffset);
  }
}

void vtkNPRSceneLines::AppendCrossings(double creaseAngle, vtkIdType nodeOffset)
{
  std::vector<const vtkNPROccluders::Crossing*> kept;
  for (const vtkNPROccluders::Crossing& crossing : this->Occluders.GetCrossings())
  {
    if (crossing.Angle > creaseAngle)
    {
      kept.push_back(&crossing);
    }
  }
  const std::vector<vtkIdType> nodes = NumberCrossingEnds(kept);
  for (size_t i = 0; i < kept.size(); ++i)
  {
    if (nodes[2 * i] == nodes[2 * i + 1])
    {
      continue; // a crossing that touches at a point: no line
    }
    Segment segment;
    std::copy_n(kept[i]->A, 3, segment.A);
    std::copy_n(kept[i]->B, 3, segment.B);
    segment.Type = vtkNPRFeatureLines::CREASE | vtkNPRFeatureLines::INTERSECTION;
    segment.NodeA = nodeOffset + nodes[2 * i];
    segment.NodeB = nodeOffset + nodes[2 * i + 1];
    std::fill_n(segment.Triangle, 3, -1);
    segment.Mesh = -1;
    this->Segments.push_back(segment);
  }
}
