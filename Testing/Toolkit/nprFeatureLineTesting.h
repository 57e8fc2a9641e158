// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// Helpers of the tests of vtkNPRFeatureLines and vtkNPRReferenceMask: an axis-aligned box stated
// analytically, the filter's output as sets of edges, and a window whose renderer a reference mask
// reads (TestFeatureLines*, TestReferenceMask*).
#ifndef nprFeatureLineTesting_h
#define nprFeatureLineTesting_h

#include "nprTesting.h"

#include "vtkNPRDrawingLines.h"
#include "vtkNPRFeatureLines.h"
#include "vtkNPRReferenceMask.h"
#include "vtkNew.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"

#include <array>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

class vtkPolyData;

namespace nprFeatureLineTesting
{
using Point = std::array<double, 3>;
using Edge = std::pair<Point, Point>; // ends in lexicographic order

constexpr int AllTypes = vtkNPRFeatureLines::SILHOUETTE | vtkNPRFeatureLines::CREASE |
  vtkNPRFeatureLines::BOUNDARY | vtkNPRFeatureLines::NON_MANIFOLD;

Edge MakeEdge(Point a, Point b);

// The output lines of the filter: each edge with its FeatureType bits.
std::map<Edge, int> Lines(vtkNPRFeatureLines* filter);
std::set<Edge> EdgesOf(const std::map<Edge, int>& lines, int type);
// Output cells whose FeatureType is exactly `type` (edges with equal coordinates counted apart).
long long CountCells(vtkNPRFeatureLines* filter, int type);
// A filter that finds the line types of the bits in `types`.
vtkSmartPointer<vtkNPRFeatureLines> MakeFilter(int types);
// A failed check for each edge missing from `got` or not expected in it.
void CheckEdges(const std::set<Edge>& got, const std::set<Edge>& expected, const std::string& what);

// ---- An axis-aligned box of half size h about the origin, analytically ----
// Corner c (bits 0..2: +x, +y, +z); face (axis, positive) has the outward normal +-e_axis.
Point Corner(int c, double h = 0.5);

struct BoxEdge
{
  Edge Ends;
  int Faces[2][2]; // (axis, positive) of its two faces
};

std::vector<BoxEdge> BoxEdges(double h = 0.5);

// Whether a face of the box faces the viewer: the eye strictly on its outer side (perspective),
// or the direction of projection strictly against its normal (parallel).
bool BoxFaceFront(int axis, int positive, bool parallel, const double view[3], double h = 0.5);

// The box's edges between a face towards the viewer and one away from it.
std::set<Edge> BoxSilhouettes(bool parallel, const double view[3]);
std::set<Edge> AllBoxEdges();

// A box of 8 shared points and 6 outward quads; `skip` leaves a face out, `flip` reverses one.
vtkSmartPointer<vtkPolyData> MakeBox(int skip = -1, int flip = -1);
vtkSmartPointer<vtkPolyData> Triangulated(vtkPolyData* input);
// vtkCubeSource's cube: 24 points, each face with its own four.
vtkSmartPointer<vtkPolyData> CubeSource(double size = 1.0);

// Andrew's monotone chain: the convex hull of 2D points, counter-clockwise.
std::vector<std::array<double, 2>> ConvexHull(std::vector<std::array<double, 2>> points);

// The smooth-contour segments of the output, chained by their shared points.
struct Contour
{
  std::vector<std::array<vtkIdType, 2>> Segments;  // output point ids
  std::vector<std::array<vtkIdType, 3>> Triangles; // ContourTriangle of each
  std::map<vtkIdType, int> Uses;                   // segments per point
  int Loops = 0;                                   // connected pieces
  bool Closed = false;                             // every point used by exactly two segments
};
// The output's smooth-contour segments, each checked to be of type SMOOTH_CONTOUR | SILHOUETTE.
Contour SmoothContour(vtkNPRFeatureLines* filter);
// The largest distance of a segment end from the zero of the facing function interpolated along
// an edge of its triangle (from the mesh's normals made unit length, recomputed here).
double WorstZeroPoint(vtkNPRFeatureLines* filter, vtkPolyData* mesh, const Contour& contour);

// A window whose renderer the reference mask reads; nothing is rendered unless a test does.
struct MaskScene
{
  vtkSmartPointer<vtkRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkNPRReferenceMask> Reference;
  int Width, Height;

  MaskScene(int width, int height)
    : Width(width)
    , Height(height)
  {
    this->Window = nprCreateTestWindow(width, height, nullptr);
    this->Window->AddRenderer(this->Renderer);
    this->Reference->SetRenderer(this->Renderer);
  }
  vtkCamera* Camera() { return this->Renderer->GetActiveCamera(); }
  vtkImageData* Mask()
  {
    NPR_CHECK(this->Reference->Update(), "the reference mask failed");
    return this->Reference->GetMask();
  }
  // Window coordinates of a world point through the renderer (not the mask's code).
  std::array<double, 2> Project(const Point& world)
  {
    std::array<double, 2> display;
    nprWorldToDisplay(this->Renderer, world.data(), display.data());
    return display;
  }
};

// ---- The strokes of technical drawings (vtkNPRDrawingLines) ----
using Image2 = std::array<double, 2>;

// A stroke as read back: its points in the image, its type and visibility.
struct Stroke
{
  std::vector<Image2> Points;
  std::vector<vtkIdType> Ids;
  int Type;
  bool Hidden;
  bool Closed() const { return this->Ids.size() > 2 && this->Ids.front() == this->Ids.back(); }
};

// The strokes of the lines' output, with checks of their arrays, depths and sizes.
std::vector<Stroke> ReadStrokes(vtkNPRDrawingLines* lines);

// A reference-mask scene whose drawing lines read the same renderer.
struct DrawingScene : MaskScene
{
  vtkNew<vtkNPRDrawingLines> Lines;
  DrawingScene(int width, int height)
    : MaskScene(width, height)
  {
    this->Lines->SetRenderer(this->Renderer);
  }
  std::vector<Stroke> Strokes()
  {
    NPR_CHECK(this->Lines->Update(), "the drawing lines failed");
    return ReadStrokes(this->Lines);
  }
};
}

#endif
