// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNPRDrawingLines.h"

#include "vtkActor.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkIntArray.h"
#include "vtkNPRFeatureLines.h"
#include "vtkNPRSceneFaces.h"
#include "vtkNPRSceneLines.h"
#include "vtkNPRScenePoints.h"
#include "vtkNPRVectors.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <string>
#include <vector>

namespace
{
using Clock = std::chrono::steady_clock;

double Seconds(Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Where visibility changes is found to this many pixels; shorter pieces are dropped.
constexpr double BisectionPixels = 1e-3;
constexpr double ShortestPiecePixels = 1e-2;
// Lines are kept this many pixels beyond the image, so wide strokes reach its border.
constexpr double ClipMarginPixels = 2.0;

// The one line type a stroke is drawn as.
unsigned char StrokeType(unsigned char bits)
{
  if (bits & vtkNPRFeatureLines::SILHOUETTE)
  {
    return vtkNPRFeatureLines::SILHOUETTE;
  }
  if (bits & vtkNPRFeatureLines::BOUNDARY)
  {
    return vtkNPRFeatureLines::BOUNDARY;
  }
  if (bits & vtkNPRFeatureLines::INTERSECTION)
  {
    return vtkNPRFeatureLines::INTERSECTION;
  }
  if (bits & vtkNPRFeatureLines::CREASE)
  {
    return vtkNPRFeatureLines::CREASE;
  }
  if (bits & (vtkNPRFeatureLines::LINE | vtkNPRFeatureLines::MESH_EDGE))
  {
    return bits & vtkNPRFeatureLines::LINE ? vtkNPRFeatureLines::LINE
                                           : vtkNPRFeatureLines::MESH_EDGE;
  }
  return vtkNPRFeatureLines::NON_MANIFOLD;
}

// A piece of an edge of one visibility, between two nodes (mesh vertices, or points where the
// edge was split or clipped).
struct Piece
{
  double A[3], B[3];
  vtkIdType NodeA, NodeB;
  unsigned char Type;
  bool Hidden;
  int Mesh; // its segment's
};

// A stretch of one visibility along an edge's clipped part, in image fractions of it.
struct Span
{
  double S0, S1;
  bool Hidden;
};

// An edge's part inside the view, [T0, T1] of it (Length pixels long in the image), and its spans:
// Spans[First, First + Count) of its block's list; none where it is clipped away.
struct ClippedEdge
{
  double T0, T1, Length;
  size_t First;
  size_t Count;
};

// The point at image fraction s of an edge's clipped part.
void PointAt(const vtkNPRSceneView& view, const vtkNPRSceneLines::Segment& segment,
  const ClippedEdge& clipped, double s, double p[3])
{
  const double t = view.ParameterAt(segment.A, segment.B, clipped.T0, clipped.T1, s);
  vtkNPRPointAt(segment.A, segment.B, t, p);
}

// A span too short to see goes to its neighbours (an edge ending on a silhouette is visible only
// at its end); neighbours of the same visibility then join.
void DropShortSpans(std::vector<Span>& spans, size_t first, double length)
{
  for (size_t i = first; spans.size() - first > 1 && i < spans.size();)
  {
    if ((spans[i].S1 - spans[i].S0) * length >= ShortestPiecePixels)
    {
      ++i;
      continue;
    }
    if (i == first)
    {
      spans[first + 1].S0 = 0.0;
    }
    else if (i + 1 == spans.size())
    {
      spans[i - 1].S1 = 1.0;
    }
    else
    {
      spans[i - 1].S1 = spans[i + 1].S0 = 0.5 * (spans[i].S0 + spans[i].S1);
    }
    spans.erase(spans.begin() + static_cast<std::ptrdiff_t>(i));
    if (i > first && i < spans.size() && spans[i - 1].Hidden == spans[i].Hidden)
    {
      spans[i - 1].S1 = spans[i].S1;
      spans.erase(spans.begin() + static_cast<std::ptrdiff_t>(i));
    }
    i = i > first ? i - 1 : first;
  }
}
}

namespace
{
// Each edge's clipped part and spans (in blocks of SegmentsPerBlock edges), found in parallel.
constexpr size_t SegmentsPerBlock = 64;
struct Visibility
{
  std::vector<ClippedEdge> Edges;
  std::vector<std::vector<Span>> Blocks;
  vtkIdType RayCasts = 0;
};

// The ray tests of one edge: samples at most `spacing` pixels apart in the image (at least its
// two ends), each tested by a ray; between two samples that differ, the change found by
// bisection to within BisectionPixels. Appends its spans to `spans`.
void FindSpans(const vtkNPRSceneLines::Segment& segment, const vtkNPRSceneView& view,
  const vtkNPROccluders& occluders, double spacing, double epsilon, ClippedEdge& clipped,
  std::vector<Span>& spans, vtkIdType& rays)
{
  clipped = ClippedEdge{ 0.0, 0.0, 0.0, spans.size(), 0 };
  if (!view.ClipSegment(segment.A, segment.B, ClipMarginPixels, clipped.T0, clipped.T1))
  {
    return;
  }
  const double length = view.ImageLength(segment.A, segment.B, clipped.T0, clipped.T1);
  clipped.Length = length;
  // A smooth contour's own triangle and its neighbours do not hide it (vtkNPRReferenceMask).
  const bool smooth = (segment.Type & vtkNPRFeatureLines::SMOOTH_CONTOUR) != 0;
  auto hiddenAt = [&](double s)
  {
    double p[3], from[3], to[3];
    PointAt(view, segment, clipped, s, p);
    view.Ray(p, epsilon, from, to);
    ++rays;
    return occluders.Hidden(from, to, smooth ? segment.Triangle : nullptr, smooth ? 3 : 0);
  };
  const vtkIdType steps =
    std::max<vtkIdType>(1, static_cast<vtkIdType>(std::ceil(length / spacing)));
  double spanStart = 0.0, previousS = 0.0;
  bool previousHidden = hiddenAt(0.0);
  for (vtkIdType k = 1; k <= steps; ++k)
  {
    const double s = static_cast<double>(k) / steps;
    const bool hidden = hiddenAt(s);
    if (hidden != previousHidden)
    {
      double low = previousS, high = s;
      while ((high - low) * length > BisectionPixels)
      {
        const double middle = 0.5 * (low + high);
        (hiddenAt(middle) == previousHidden ? low : high) = middle;
      }
      const double change = 0.5 * (low + high);
      spans.push_back({ spanStart, change, previousHidden });
      spanStart = change;
    }
    previousS = s;
    previousHidden = hidden;
  }
  spans.push_back({ spanStart, 1.0, previousHidden });
  DropShortSpans(spans, clipped.First, length);
  clipped.Count = spans.size() - clipped.First;
}

Visibility FindVisibility(const std::vector<vtkNPRSceneLines::Segment>& segments,
  const vtkNPRSceneView& view, const vtkNPROccluders& occluders, double spacing, double epsilon)
{
  Visibility found;
  found.Edges.resize(segments.size());
  found.Blocks.resize((segments.size() + SegmentsPerBlock - 1) / SegmentsPerBlock);
  vtkSMPThreadLocal<vtkIdType> rays(0);
  vtkSMPTools::For(0, static_cast<vtkIdType>(found.Blocks.size()), 1,
    [&](vtkIdType firstBlock, vtkIdType lastBlock)
    {
      vtkIdType& raysHere = rays.Local();
      for (vtkIdType block = firstBlock; block < lastBlock; ++block)
      {
        const size_t first = static_cast<size_t>(block) * SegmentsPerBlock;
        const size_t last = std::min(segments.size(), first + SegmentsPerBlock);
        for (size_t i = first; i < last; ++i)
        {
          FindSpans(segments[i], view, occluders, spacing, epsilon, found.Edges[i],
            found.Blocks[block], raysHere);
        }
      }
    });
  for (vtkIdType count : rays)
  {
    found.RayCasts += count;
  }
  return found;
}

// The pieces of the edges, in the edges' order; their ends are the mesh's nodes where the edge
// was neither clipped nor split, new nodes numbered in order elsewhere.
std::vector<Piece> MakePieces(const std::vector<vtkNPRSceneLines::Segment>& segments,
  const vtkNPRSceneView& view, const Visibility& visibility, bool hiddenLines)
{
  vtkIdType nextNode = 0;
  for (const auto& segment : segments)
  {
    nextNode = std::max(nextNode, std::max(segment.NodeA, segment.NodeB) + 1);
  }
  std::vector<Piece> pieces;
  for (size_t e = 0; e < segments.size(); ++e)
  {
    const vtkNPRSceneLines::Segment& segment = segments[e];
    const ClippedEdge& clipped = visibility.Edges[e];
    const Span* spans = visibility.Blocks[e / SegmentsPerBlock].data() + clipped.First;
    const bool whole0 = clipped.T0 == 0.0, whole1 = clipped.T1 == 1.0;
    vtkIdType node = -1;
    for (size_t i = 0; i < clipped.Count; ++i)
    {
      Piece piece;
      PointAt(view, segment, clipped, spans[i].S0, piece.A);
      PointAt(view, segment, clipped, spans[i].S1, piece.B);
      const bool last = i + 1 == clipped.Count;
      piece.NodeA = i == 0 ? (whole0 ? segment.NodeA : nextNode++) : node;
      piece.NodeB = last ? (whole1 ? segment.NodeB : nextNode++) : nextNode++;
      if (i == 0 && whole0)
      {
        std::copy_n(segment.A, 3, piece.A);
      }
      if (last && whole1)
      {
        std::copy_n(segment.B, 3, piece.B);
      }
      node = piece.NodeB;
      piece.Type = StrokeType(segment.Type);
      piece.Hidden = spans[i].Hidden;
      piece.Mesh = segment.Mesh;
      if (!piece.Hidden || hiddenLines)
      {
        pieces.push_back(piece);
      }
    }
  }
  return pieces;
}

// For each piece end (2 x piece + side, side 0: A, 1: B), the one other piece end of the same
// kind (type and visibility) it continues into through its node, or -1 where one, three or more
// pieces of that kind meet.
std::vector<vtkIdType> LinkPieces(const std::vector<Piece>& pieces)
{
  struct End
  {
    vtkIdType Node;
    unsigned int Kind;
    vtkIdType Piece;
    int Side;
  };
  std::vector<End> ends;
  ends.reserve(2 * pieces.size());
  for (size_t i = 0; i < pieces.size(); ++i)
  {
    const unsigned int kind = pieces[i].Type | (pieces[i].Hidden ? 0x100u : 0u);
    ends.push_back({ pieces[i].NodeA, kind, static_cast<vtkIdType>(i), 0 });
    ends.push_back({ pieces[i].NodeB, kind, static_cast<vtkIdType>(i), 1 });
  }
  std::sort(ends.begin(), ends.end(),
    [](const End& a, const End& b)
    {
      return a.Node != b.Node ? a.Node < b.Node
                              : (a.Kind != b.Kind ? a.Kind < b.Kind : a.Piece < b.Piece);
    });
  std::vector<vtkIdType> next(2 * pieces.size(), -1);
  for (size_t first = 0; first < ends.size();)
  {
    size_t last = first + 1;
    while (last < ends.size() && ends[last].Node == ends[first].Node &&
      ends[last].Kind == ends[first].Kind)
    {
      ++last;
    }
    if (last - first == 2)
    {
      const vtkIdType a = 2 * ends[first].Piece + ends[first].Side;
      const vtkIdType b = 2 * ends[first + 1].Piece + ends[first + 1].Side;
      next[a] = b;
      next[b] = a;
    }
    first = last;
  }
  return next;
}

// The strokes: the linked pieces walked into polylines, open chains first (from an end where
// the chain stops), then the loops that are left.
class StrokeBuilder
{
public:
  StrokeBuilder(const std::vector<Piece>& pieces, const vtkNPRSceneView& view)
    : Pieces(pieces)
    , Next(LinkPieces(pieces))
    , Used(pieces.size(), 0)
    , View(view)
  {
    this->Points->SetDataTypeToDouble();
    this->Image->SetName("ImageCoordinates");
    this->Image->SetNumberOfComponents(3);
    this->Types->SetName("FeatureType");
    this->HiddenFlags->SetName("Hidden");
  }

  void Build(vtkPolyData* strokes)
  {
    for (size_t i = 0; i < this->Pieces.size(); ++i)
    {
      for (int side = 0; side < 2 && !this->Used[i]; ++side)
      {
        if (this->Next[2 * i + side] < 0)
        {
          this->Walk(static_cast<vtkIdType>(i), side);
        }
      }
    }
    for (size_t i = 0; i < this->Pieces.size(); ++i)
    {
      if (!this->Used[i])
      {
        this->Walk(static_cast<vtkIdType>(i), 0);
      }
    }
    strokes->SetPoints(this->Points);
    strokes->SetLines(this->Lines);
    strokes->GetPointData()->AddArray(this->Image);
    strokes->GetCellData()->AddArray(this->Types);
    strokes->GetCellData()->AddArray(this->HiddenFlags);
  }

private:
  void AddPoint(const double p[3])
  {
    double xyz[3];
    this->View.ToImage(p, xyz);
    this->Image->InsertNextTuple(xyz);
    this->Ids.push_back(this->Points->InsertNextPoint(p));
  }

  // Walks from piece `piece`, entered at its side `side`, to the end of the chain.
  void Walk(vtkIdType piece, int side)
  {
    this->Ids.clear();
    const Piece& first = this->Pieces[piece];
    this->AddPoint(side == 0 ? first.A : first.B);
    const vtkIdType firstEnd = 2 * piece + side;
    bool closed = false;
    for (;;)
    {
      this->Used[piece] = 1;
      const Piece& current = this->Pieces[piece];
      this->AddPoint(side == 0 ? current.B : current.A);
      const vtkIdType entry = this->Next[2 * piece + (1 - side)];
      if (entry < 0 || entry == firstEnd || this->Used[entry / 2])
      {
        closed = entry == firstEnd;
        break;
      }
      piece = entry / 2;
      side = static_cast<int>(entry % 2);
    }
    if (closed)
    {
      this->Ids.back() = this->Ids.front(); // the loop's last point is its first
      this->Points->GetData()->SetNumberOfTuples(this->Points->GetNumberOfPoints() - 1);
      this->Image->SetNumberOfTuples(this->Image->GetNumberOfTuples() - 1);
    }
    this->Lines->InsertNextCell(static_cast<vtkIdType>(this->Ids.size()), this->Ids.data());
    this->Types->InsertNextValue(first.Type);
    this->HiddenFlags->InsertNextValue(first.Hidden ? 1 : 0);
    this->Meshes.push_back(first.Mesh);
  }

public:
  // Each stroke's mesh (its first piece's; -1 for a crossing).
  std::vector<int> Meshes;

private:
  const std::vector<Piece>& Pieces;
  const std::vector<vtkIdType> Next;
  std::vector<char> Used;
  const vtkNPRSceneView& View;
  std::vector<vtkIdType> Ids;
  vtkNew<vtkPoints> Points;
  vtkNew<vtkDoubleArray> Image;
  vtkNew<vtkCellArray> Lines;
  vtkNew<vtkUnsignedCharArray> Types;
  vtkNew<vtkUnsignedCharArray> HiddenFlags;
};
}

namespace
{
// The strokes' "Colors" and "LineWidths": a LINE stroke's actor's colour and line width (a
// MESH_EDGE stroke's: its EdgeColor on a surface, its colour on a wireframe), black and 0 for the
// others.
void AddLineLooks(vtkPolyData* strokes, const std::vector<int>& meshes,
  const std::vector<vtkNPRMeshInstance>& actors)
{
  vtkDataArray* types = strokes->GetCellData()->GetArray("FeatureType");
  vtkNew<vtkUnsignedCharArray> colors;
  colors->SetName("Colors");
  colors->SetNumberOfComponents(3);
  colors->SetNumberOfTuples(static_cast<vtkIdType>(meshes.size()));
  vtkNew<vtkFloatArray> widths;
  widths->SetName("LineWidths");
  widths->SetNumberOfTuples(static_cast<vtkIdType>(meshes.size()));
  for (size_t i = 0; i < meshes.size(); ++i)
  {
    double color[3] = { 0.0, 0.0, 0.0 };
    double width = 0.0;
    const int mesh = meshes[i];
    const int type =
      types ? static_cast<int>(types->GetComponent(static_cast<vtkIdType>(i), 0)) : 0;
    if ((type == vtkNPRFeatureLines::LINE || type == vtkNPRFeatureLines::MESH_EDGE) && mesh >= 0 &&
      mesh < static_cast<int>(actors.size()))
    {
      vtkProperty* property = actors[mesh].Actor->GetProperty();
      const bool edgeColor =
        type == vtkNPRFeatureLines::MESH_EDGE && property->GetRepresentation() == VTK_SURFACE;
      (edgeColor ? property->GetEdgeColor(color) : property->GetColor(color));
      width = property->GetLineWidth();
    }
    for (int c = 0; c < 3; ++c)
    {
      colors->SetValue(3 * static_cast<vtkIdType>(i) + c,
        static_cast<unsigned char>(std::lround(255.0 * std::clamp(color[c], 0.0, 1.0))));
    }
    widths->SetValue(static_cast<vtkIdType>(i), static_cast<float>(width));
  }
  strokes->GetCellData()->AddArray(colors);
  strokes->GetCellData()->AddArray(widths);
}
}

struct vtkNPRDrawingLines::Internals
{
  vtkNew<vtkPolyData> Strokes;
  vtkNew<vtkPolyData> Points;
  vtkNew<vtkPolyData> Faces;
  vtkIdType FaceSplits = 0;
  double FacesTime = 0.0;
  vtkIdType StrokeCount = 0;
  double ChainTime = 0.0;
  std::vector<std::string> LeftOut; // the props' parts the last Update() drew nothing of
};

vtkStandardNewMacro(vtkNPRDrawingLines);

vtkNPRDrawingLines::vtkNPRDrawingLines()
  : Internal(new Internals)
{
}

vtkNPRDrawingLines::~vtkNPRDrawingLines() = default;

vtkPolyData* vtkNPRDrawingLines::GetStrokes()
{
  return this->Internal->Strokes;
}

vtkPolyData* vtkNPRDrawingLines::GetVisiblePoints()
{
  return this->Internal->Points;
}

vtkPolyData* vtkNPRDrawingLines::GetFaces()
{
  return this->Internal->Faces;
}

vtkIdType vtkNPRDrawingLines::GetNumberOfFaceSplits() const
{
  return this->Internal->FaceSplits;
}

double vtkNPRDrawingLines::GetFacesTime() const
{
  return this->Internal->FacesTime;
}

bool vtkNPRDrawingLines::UpdateFaces()
{
  Internals& internal = *this->Internal;
  internal.Faces->Initialize();
  internal.FaceSplits = 0;
  internal.FacesTime = 0.0;
  int width, height;
  if (!this->Renderer || !vtkNPRImageSize(this->Renderer, this->Size, width, height))
  {
    vtkErrorMacro(<< (this->Renderer ? "no size" : "no renderer") << ": no faces");
    return false;
  }
  const Clock::time_point start = Clock::now();
  vtkNPRSceneView view;
  view.Set(this->Renderer->GetActiveCamera(), width, height);
  const vtkNPRSceneFacesCounts counts =
    vtkNPRSceneFaces(vtkNPRDrawnMeshes(this->Renderer), view, internal.Faces);
  internal.FaceSplits = counts.Splits;
  internal.FacesTime = Seconds(start);
  return true;
}

vtkIdType vtkNPRDrawingLines::GetNumberOfStrokes() const
{
  return this->Internal->StrokeCount;
}

vtkIdType vtkNPRDrawingLines::GetNumberOfPropsLeftOut() const
{
  return static_cast<vtkIdType>(this->Internal->LeftOut.size());
}

const char* vtkNPRDrawingLines::GetPropLeftOut(vtkIdType index) const
{
  const std::vector<std::string>& leftOut = this->Internal->LeftOut;
  return index >= 0 && index < static_cast<vtkIdType>(leftOut.size()) ? leftOut[index].c_str()
                                                                      : nullptr;
}

double vtkNPRDrawingLines::GetChainTime() const
{
  return this->Internal->ChainTime;
}

size_t vtkNPRDrawingLines::GetMemorySize() const
{
  return this->GetScene().GetMemorySize();
}

bool vtkNPRDrawingLines::Update()
{
  Internals& internal = *this->Internal;
  internal.StrokeCount = 0;
  internal.ChainTime = 0.0;
  internal.Strokes->Initialize();
  internal.Points->Initialize();
  internal.LeftOut.clear();
  int width, height;
  if (!this->StartUpdate(width, height))
  {
    return false;
  }
  internal.LeftOut = vtkNPRPropsNotDrawn(this->Renderer);

  this->UpdateScene(16384);
  const vtkNPRSceneLines& scene = this->GetScene();
  const std::vector<vtkNPRSceneLines::Segment>& segments = scene.GetSegments();

  // Split each edge where it passes behind a surface (the rays on all cores).
  Clock::time_point start = Clock::now();
  vtkNPRSceneView view;
  view.Set(this->Renderer->GetActiveCamera(), width, height);
  const Visibility visibility = FindVisibility(
    segments, view, scene.GetOccluders(), this->SampleSpacing, this->OcclusionEpsilon);
  this->RayCasts = visibility.RayCasts;
  const std::vector<Piece> pieces = MakePieces(segments, view, visibility, this->HiddenLines);
  if (this->PointPrimitives)
  {
    this->RayCasts +=
      vtkNPRScenePoints(scene.GetMeshes(), vtkNPRDrawnMeshes(this->Renderer, vtkNPRDrawnAs::Points),
        view, scene.GetOccluders(), this->OcclusionEpsilon, internal.Points);
  }
  this->VisibilityTime = Seconds(start);

  // Chain the pieces of one kind through the nodes where exactly two of that kind meet.
  start = Clock::now();
  vtkPolyData* strokes = internal.Strokes;
  StrokeBuilder builder(pieces, view);
  builder.Build(strokes);
  AddLineLooks(strokes, builder.Meshes, scene.GetLineMeshes());
  vtkNew<vtkIntArray> imageSize;
  imageSize->SetName("ImageSize");
  imageSize->SetNumberOfComponents(2);
  imageSize->InsertNextTypedTuple(std::array<int, 2>{ width, height }.data());
  strokes->GetFieldData()->AddArray(imageSize);
  internal.StrokeCount = strokes->GetNumberOfLines();
  internal.ChainTime = Seconds(start);
  return true;
}

void vtkNPRDrawingLines::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "HiddenLines: " << this->HiddenLines << "\n";
  os << indent << "SampleSpacing: " << this->SampleSpacing << "\n";
  os << indent << "LinePrimitives: " << this->LinePrimitives << "\n";
  os << indent << "PointPrimitives: " << this->PointPrimitives << "\n";
  os << indent << "NumberOfStrokes: " << this->Internal->StrokeCount << "\n";
}
