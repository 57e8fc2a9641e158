// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNPRFeatureLines.h"

#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkNPRMeshAdjacency.h"
#include "vtkNPRVectors.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

namespace
{
// The typed mesh edges as lines, their points in the order the edges first use them.
void AddMeshEdges(const vtkNPRMeshAdjacency& adjacency,
  const std::vector<vtkNPRMeshAdjacency::TypedEdge>& typed, vtkPoints* points, vtkCellArray* lines,
  vtkUnsignedCharArray* types, vtkIdTypeArray* inputIds)
{
  std::unordered_map<std::uint32_t, vtkIdType> outputIds(2 * typed.size());
  auto outputPoint = [&](std::uint32_t id)
  {
    auto found = outputIds.emplace(id, points->GetNumberOfPoints());
    if (found.second)
    {
      double x[3];
      adjacency.GetMesh().GetPoint(id, x);
      points->InsertNextPoint(x);
    }
    return found.first->second;
  };
  const vtkIdType count = static_cast<vtkIdType>(typed.size());
  lines->AllocateExact(count, 2 * count);
  types->SetNumberOfValues(count);
  inputIds->SetNumberOfTuples(count);
  for (vtkIdType i = 0; i < count; ++i)
  {
    const vtkNPRMeshAdjacency::TypedEdge& edge = typed[i];
    const vtkIdType ends[2] = { outputPoint(edge.A), outputPoint(edge.B) };
    lines->InsertNextCell(2, ends);
    types->SetValue(i, edge.Type);
    inputIds->SetValue(2 * i, edge.A);
    inputIds->SetValue(2 * i + 1, edge.B);
  }
}

// The smooth contours after the mesh edges: one output point per crossed edge, so that the
// segments chain; each edge's zero point interpolated from its smaller id to its larger.
void AddContours(const vtkNPRMeshAdjacency& adjacency, vtkPoints* points, vtkCellArray* lines,
  vtkUnsignedCharArray* types, vtkIdTypeArray* inputIds, vtkIdTypeArray* contourTriangles)
{
  const vtkNPRSmoothContours& contours = adjacency.GetContours();
  std::unordered_map<std::uint64_t, vtkIdType> edgePoints;
  auto zeroPoint = [&](std::uint32_t a, std::uint32_t b)
  {
    if (b < a)
    {
      std::swap(a, b);
    }
    const std::uint64_t key = (static_cast<std::uint64_t>(a) << 32) | b;
    auto found = edgePoints.find(key);
    if (found != edgePoints.end())
    {
      return found->second;
    }
    const double ga = contours.GetFacing(a), gb = contours.GetFacing(b);
    const double t = ga / (ga - gb); // the signs differ: in [0, 1]
    double pa[3], pb[3], x[3];
    adjacency.GetMesh().GetPoint(a, pa);
    adjacency.GetMesh().GetPoint(b, pb);
    vtkNPRPointAt(pa, pb, t, x);
    const vtkIdType id = points->InsertNextPoint(x);
    edgePoints.emplace(key, id);
    return id;
  };
  const unsigned char type = vtkNPRFeatureLines::SILHOUETTE | vtkNPRFeatureLines::SMOOTH_CONTOUR;
  for (const auto& listed : contours.GetSegments())
  {
    for (const vtkNPRSmoothContours::Segment& segment : listed)
    {
      const std::uint32_t* ids = contours.GetTriangle(segment.Triangle);
      const std::uint32_t rise[2] = { ids[segment.Rise], ids[(segment.Rise + 1) % 3] };
      const std::uint32_t fall[2] = { ids[segment.Fall], ids[(segment.Fall + 1) % 3] };
      const vtkIdType ends[2] = { zeroPoint(rise[0], rise[1]), zeroPoint(fall[0], fall[1]) };
      lines->InsertNextCell(2, ends);
      types->InsertNextValue(type);
      const vtkIdType edge[2] = { std::min(rise[0], rise[1]), std::max(rise[0], rise[1]) };
      inputIds->InsertNextTypedTuple(edge);
      const vtkIdType corners[3] = { ids[0], ids[1], ids[2] };
      contourTriangles->InsertNextTypedTuple(corners);
    }
  }
}
}

vtkStandardNewMacro(vtkNPRFeatureLines);

vtkNPRFeatureLines::vtkNPRFeatureLines()
  : Adjacency(new vtkNPRMeshAdjacency)
{
}

vtkNPRFeatureLines::~vtkNPRFeatureLines() = default;

vtkIdType vtkNPRFeatureLines::GetNumberOfEdges() const
{
  return this->Adjacency->GetNumberOfEdges();
}

vtkIdType vtkNPRFeatureLines::GetNumberOfDegenerateFaces() const
{
  return this->Adjacency->GetNumberOfDegenerateFaces();
}

vtkIdType vtkNPRFeatureLines::GetNumberOfNonFiniteFaces() const
{
  return this->Adjacency->GetNumberOfNonFiniteFaces();
}

vtkIdType vtkNPRFeatureLines::GetNumberOfUnsureFaces() const
{
  return this->Adjacency->GetNumberOfUnsureFaces();
}

vtkIdType vtkNPRFeatureLines::GetNumberOfSkippedContourTriangles() const
{
  return this->Adjacency->GetNumberOfSkippedContourTriangles();
}

size_t vtkNPRFeatureLines::GetAdjacencyMemorySize() const
{
  return this->Adjacency->GetMemorySize();
}

void vtkNPRFeatureLines::SetCamera(vtkCamera* camera, vtkMatrix4x4* modelMatrix)
{
  if (!camera)
  {
    vtkErrorMacro("SetCamera: no camera");
    return;
  }
  double eye[4] = { 0.0, 0.0, 0.0, 1.0 };
  double direction[4] = { 0.0, 0.0, 0.0, 0.0 };
  camera->GetPosition(eye);
  camera->GetDirectionOfProjection(direction);
  if (modelMatrix)
  {
    const double determinant = modelMatrix->Determinant();
    if (determinant == 0.0 || !std::isfinite(determinant))
    {
      vtkErrorMacro("SetCamera: the model matrix is singular");
      return;
    }
    vtkNew<vtkMatrix4x4> inverse;
    vtkMatrix4x4::Invert(modelMatrix, inverse);
    inverse->MultiplyPoint(eye, eye);
    inverse->MultiplyPoint(direction, direction); // w = 0: a direction, no translation
    vtkNPRStore(vtkNPRVector(eye) / eye[3], eye);
  }
  this->SetEyePosition(eye);
  this->SetDirectionOfProjection(direction);
  this->SetParallelProjection(camera->GetParallelProjection() != 0);
}

int vtkNPRFeatureLines::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  if (!input || !output)
  {
    return 0;
  }
  vtkNPRMeshAdjacency& adjacency = *this->Adjacency;
  if (!adjacency.IsCurrent(input, this->MergeCoincidentPoints))
  {
    adjacency.Build(input, this->MergeCoincidentPoints, this);
    ++this->NumberOfAdjacencyBuilds;
  }
  adjacency.ClearViewCounts();

  // For this viewpoint, in parallel on packed arrays: the crease bits (when the angle changed),
  // the side of each face's plane the eye is on, then each edge's type; then the output from
  // the typed edges (few: the output is small).
  vtkNPRMeshAdjacency::View view;
  view.Parallel = this->ParallelProjection;
  std::copy_n(this->EyePosition, 3, view.Eye);
  std::copy_n(this->DirectionOfProjection, 3, view.Direction);
  vtkNPRLineSettings& settings = *this->LineSettings;
  view.Creases = settings.GetCreases();
  view.Boundaries = settings.GetBoundaries();
  view.NonManifoldEdges = settings.GetNonManifoldEdges();
  if (view.Creases)
  {
    adjacency.UpdateCreases(settings.GetCreaseAngle());
  }
  // Smooth contours replace the mesh silhouettes only where the input has point normals.
  vtkDataArray* contourNormals = settings.GetSilhouettes() && this->SmoothContours
    ? vtkNPRSmoothContours::PointNormals(input)
    : nullptr;
  const bool smooth = contourNormals && adjacency.GetNumberOfEdges() > 0;
  view.Silhouettes = settings.GetSilhouettes() && !smooth;
  view.SplitContours = smooth;
  const double* viewpoint = view.Parallel ? view.Direction : view.Eye;
  if (smooth)
  {
    adjacency.ComputeContours(contourNormals, view.Parallel, viewpoint);
  }
  if (view.Silhouettes || smooth)
  {
    adjacency.ComputeFaceSides(view.Parallel, viewpoint);
  }
  const std::vector<vtkNPRMeshAdjacency::TypedEdge> typed = adjacency.ClassifyEdges(view);

  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkCellArray> lines;
  vtkNew<vtkUnsignedCharArray> types;
  types->SetName("FeatureType");
  vtkNew<vtkIdTypeArray> inputIds;
  inputIds->SetName("InputPointIds");
  inputIds->SetNumberOfComponents(2);
  AddMeshEdges(adjacency, typed, points, lines, types, inputIds);
  output->SetPoints(points);
  output->SetLines(lines);
  output->GetCellData()->AddArray(types);
  output->GetCellData()->AddArray(inputIds);
  if (smooth)
  {
    vtkNew<vtkIdTypeArray> contourTriangles;
    contourTriangles->SetName("ContourTriangle");
    contourTriangles->SetNumberOfComponents(3);
    contourTriangles->SetNumberOfTuples(static_cast<vtkIdType>(typed.size()));
    contourTriangles->Fill(-1);
    AddContours(adjacency, points, lines, types, inputIds, contourTriangles);
    output->GetCellData()->AddArray(contourTriangles);
  }
  return 1;
}

void vtkNPRFeatureLines::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "EyePosition: " << this->EyePosition[0] << ", " << this->EyePosition[1] << ", "
     << this->EyePosition[2] << "\n";
  os << indent << "ParallelProjection: " << this->ParallelProjection << "\n";
  os << indent << "DirectionOfProjection: " << this->DirectionOfProjection[0] << ", "
     << this->DirectionOfProjection[1] << ", " << this->DirectionOfProjection[2] << "\n";
  this->LineSettings->PrintSettings(os, indent, "FeatureAngle");
  os << indent << "MergeCoincidentPoints: " << this->MergeCoincidentPoints << "\n";
  os << indent << "SmoothContours: " << this->SmoothContours << "\n";
  os << indent << "NumberOfAdjacencyBuilds: " << this->NumberOfAdjacencyBuilds << "\n";
  os << indent << "NumberOfEdges: " << this->GetNumberOfEdges() << "\n";
  os << indent << "AdjacencyMemorySize: " << this->GetAdjacencyMemorySize() << " bytes\n";
  os << indent << "NumberOfSkippedContourTriangles: " << this->GetNumberOfSkippedContourTriangles()
     << "\n";
}
