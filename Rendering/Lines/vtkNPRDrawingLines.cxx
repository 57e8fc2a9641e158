// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNPRDrawingLines.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdList.h"
#include "vtkIntArray.h"
#include "vtkNPRFeatureLines.h"
#include "vtkNPRSceneLines.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkRenderer.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <array>
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
  if (bits & vtkNPRFeatureLines::CREASE)
  {
    return vtkNPRFeatureLines::CREASE;
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
};
}

struct vtkNPRDrawingLines::Internals
{
  vtkNPRSceneLines Scene;
  vtkNew<vtkPolyData> Strokes;
  vtkIdType FeatureEdges = 0, RayCasts = 0, StrokeCount = 0;
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
  return this->Internal->StrokeCount;
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
  return this->Internal->Scene.GetNumberOfLocatorBuilds();
}

bool vtkNPRDrawingLines::Update()
{
  Internals& internal = *this->Internal;
  internal.FeatureEdges = internal.RayCasts = internal.StrokeCount = 0;
  internal.LinesTime = internal.LocatorTime = internal.VisibilityTime = internal.ChainTime = 0.0;
  internal.Strokes->Initialize();
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

  vtkNPRSceneLines::Settings settings;
  settings.Silhouettes = this->Silhouettes;
  settings.Creases = this->Creases;
  settings.Boundaries = this->Boundaries;
  settings.NonManifoldEdges = this->NonManifoldEdges;
  settings.CreaseAngle = this->CreaseAngle;
  internal.Scene.Update(this->Renderer, settings, 16384);
  const std::vector<vtkNPRSceneLines::Segment>& segments = internal.Scene.GetSegments();
  internal.FeatureEdges = static_cast<vtkIdType>(segments.size());
  internal.LinesTime = internal.Scene.GetLinesTime();
  internal.LocatorTime = internal.Scene.GetLocatorTime();
  const vtkNPROccluders& occluders = internal.Scene.GetOccluders();

  // Split each edge where it passes behind a surface.
  Clock::time_point start = Clock::now();
  vtkNPRSceneView view;
  view.Set(this->Renderer->GetActiveCamera(), width, height);
  vtkIdType nextNode = 0;
  for (const auto& segment : segments)
  {
    nextNode = std::max(nextNode, std::max(segment.NodeA, segment.NodeB) + 1);
  }
  vtkNew<vtkIdList> candidates;
  std::vector<Piece> pieces;
  struct Span
  {
    double S0, S1; // image fractions of the clipped edge
    bool Hidden;
  };
  std::vector<Span> spans;
  for (const auto& segment : segments)
  {
    double t0, t1;
    if (!view.ClipSegment(segment.A, segment.B, ClipMarginPixels, t0, t1))
    {
      continue;
    }
    const double length = view.ImageLength(segment.A, segment.B, t0, t1);
    auto pointAt = [&](double s, double p[3])
    {
      const double t = view.ParameterAt(segment.A, segment.B, t0, t1, s);
      for (int i = 0; i < 3; ++i)
      {
        p[i] = segment.A[i] + t * (segment.B[i] - segment.A[i]);
      }
    };
    auto hiddenAt = [&](double s)
    {
      double p[3], from[3], to[3];
      pointAt(s, p);
      view.Ray(p, this->OcclusionEpsilon, from, to);
      ++internal.RayCasts;
      return occluders.Hidden(from, to, candidates);
    };
    const vtkIdType steps =
      std::max<vtkIdType>(1, static_cast<vtkIdType>(std::ceil(length / this->SampleSpacing)));
    spans.clear();
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
    // A span too short to see goes to its neighbours (an edge ending on a silhouette is
    // visible only at its end); neighbours of the same visibility then join.
    for (size_t i = 0; spans.size() > 1 && i < spans.size();)
    {
      if ((spans[i].S1 - spans[i].S0) * length >= ShortestPiecePixels)
      {
        ++i;
        continue;
      }
      if (i == 0)
      {
        spans[1].S0 = 0.0;
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
      if (i > 0 && i < spans.size() && spans[i - 1].Hidden == spans[i].Hidden)
      {
        spans[i - 1].S1 = spans[i].S1;
        spans.erase(spans.begin() + static_cast<std::ptrdiff_t>(i));
      }
      i = i > 0 ? i - 1 : 0;
    }
    // Pieces; their ends are the mesh's nodes where the edge was neither clipped nor split.
    const unsigned char type = StrokeType(segment.Type);
    vtkIdType node = -1;
    for (size_t i = 0; i < spans.size(); ++i)
    {
      const Span& span = spans[i];
      Piece piece;
      pointAt(span.S0, piece.A);
      pointAt(span.S1, piece.B);
      piece.NodeA = i == 0 ? (t0 == 0.0 ? segment.NodeA : nextNode++) : node;
      piece.NodeB = i + 1 == spans.size() ? (t1 == 1.0 ? segment.NodeB : nextNode++) : nextNode++;
      if (i == 0 && t0 == 0.0)
      {
        std::copy_n(segment.A, 3, piece.A);
      }
      if (i + 1 == spans.size() && t1 == 1.0)
      {
        std::copy_n(segment.B, 3, piece.B);
      }
      node = piece.NodeB;
      piece.Type = type;
      piece.Hidden = span.Hidden;
      if (!piece.Hidden || this->HiddenLines)
      {
        pieces.push_back(piece);
      }
    }
  }
  internal.VisibilityTime = Seconds(start);

  // Chain the pieces of one kind through the nodes where exactly two of that kind meet.
  start = Clock::now();
  struct End
  {
    vtkIdType Node;
    unsigned int Kind;
    vtkIdType Piece;
    int Side; // 0: A, 1: B
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
  // For each piece end: the one other piece end it continues into, or -1.
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

  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> image;
  image->SetName("ImageCoordinates");
  image->SetNumberOfComponents(3);
  vtkNew<vtkCellArray> lines;
  vtkNew<vtkUnsignedCharArray> types;
  types->SetName("FeatureType");
  vtkNew<vtkUnsignedCharArray> hiddenFlags;
  hiddenFlags->SetName("Hidden");
  std::vector<char> used(pieces.size(), 0);
  std::vector<vtkIdType> ids;
  auto addPoint = [&](const double p[3])
  {
    double xyz[3];
    view.ToImage(p, xyz);
    image->InsertNextTuple(xyz);
    ids.push_back(points->InsertNextPoint(p));
  };
  // Walks from piece `piece`, entered at its side `side`, to the end of the chain.
  auto walk = [&](vtkIdType piece, int side)
  {
    ids.clear();
    const Piece& first = pieces[piece];
    addPoint(side == 0 ? first.A : first.B);
    const vtkIdType firstEnd = 2 * piece + side;
    bool closed = false;
    for (;;)
    {
      used[piece] = 1;
      const Piece& current = pieces[piece];
      addPoint(side == 0 ? current.B : current.A);
      const vtkIdType exit = 2 * piece + (1 - side);
      const vtkIdType entry = next[exit];
      if (entry < 0)
      {
        break;
      }
      if (entry == firstEnd)
      {
        closed = true;
        break;
      }
      if (used[entry / 2])
      {
        break;
      }
      piece = entry / 2;
      side = static_cast<int>(entry % 2);
    }
    if (closed)
    {
      ids.back() = ids.front(); // the loop's last point is its first
      points->GetData()->SetNumberOfTuples(points->GetNumberOfPoints() - 1);
      image->SetNumberOfTuples(image->GetNumberOfTuples() - 1);
    }
    lines->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
    types->InsertNextValue(first.Type);
    hiddenFlags->InsertNextValue(first.Hidden ? 1 : 0);
  };
  // Open chains first, from an end where the chain stops; what is left are loops.
  for (size_t i = 0; i < pieces.size(); ++i)
  {
    for (int side = 0; side < 2 && !used[i]; ++side)
    {
      if (next[2 * i + side] < 0)
      {
        walk(static_cast<vtkIdType>(i), side);
      }
    }
  }
  for (size_t i = 0; i < pieces.size(); ++i)
  {
    if (!used[i])
    {
      walk(static_cast<vtkIdType>(i), 0);
    }
  }

  vtkPolyData* strokes = internal.Strokes;
  strokes->SetPoints(points);
  strokes->SetLines(lines);
  strokes->GetPointData()->AddArray(image);
  strokes->GetCellData()->AddArray(types);
  strokes->GetCellData()->AddArray(hiddenFlags);
  vtkNew<vtkIntArray> imageSize;
  imageSize->SetName("ImageSize");
  imageSize->SetNumberOfComponents(2);
  imageSize->InsertNextTypedTuple(std::array<int, 2>{ width, height }.data());
  strokes->GetFieldData()->AddArray(imageSize);
  internal.StrokeCount = lines->GetNumberOfCells();
  internal.ChainTime = Seconds(start);
  return true;
}

void vtkNPRDrawingLines::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Renderer: " << this->Renderer << "\n";
  os << indent << "Size: " << this->Size[0] << " x " << this->Size[1] << "\n";
  os << indent << "Silhouettes: " << this->Silhouettes << "\n";
  os << indent << "Creases: " << this->Creases << "\n";
  os << indent << "Boundaries: " << this->Boundaries << "\n";
  os << indent << "NonManifoldEdges: " << this->NonManifoldEdges << "\n";
  os << indent << "CreaseAngle: " << this->CreaseAngle << "\n";
  os << indent << "HiddenLines: " << this->HiddenLines << "\n";
  os << indent << "SampleSpacing: " << this->SampleSpacing << "\n";
  os << indent << "OcclusionEpsilon: " << this->OcclusionEpsilon << "\n";
  os << indent << "NumberOfStrokes: " << this->Internal->StrokeCount << "\n";
}
