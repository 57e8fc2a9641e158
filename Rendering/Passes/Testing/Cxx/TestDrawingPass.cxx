// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// The technical-drawing style (vtkNPRDrawingPass through vtkNPRPass), checked with numbers: a
// cube's faces in the face colour, its visible edges solid in the line colour, its hidden edges
// dashed (the stated period) and lighter, none without hidden lines; the depth sprite (a second
// layer hidden where the drawing is in front, lines past the outline at the outline's depth); the
// strokes computed again only when the frame changes; the CAD part against its baseline.
//
// usage: TestDrawingPass CASE [DATA_DIR]   (CASE: the NPR_TEST_CASE names below)
#include "nprTesting.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkImageData.h"
#include "vtkNPRDrawingLines.h"
#include "vtkNPRDrawingPass.h"
#include "vtkNPREdgePass.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace
{
struct Scene : nprPassScene
{
  explicit Scene(int width = 400, int height = 300)
    : nprPassScene(width, height)
  {
    this->Pass->SetStyleToDrawing();
  }
  vtkNPRDrawingPass* Drawing() { return this->Pass->GetDrawingPass(); }
  std::vector<float> Depth()
  {
    std::vector<float> depth(static_cast<size_t>(this->Width) * this->Height);
    this->Window->GetZbufferData(0, 0, this->Width - 1, this->Height - 1, depth.data());
    return depth;
  }
  std::array<double, 2> Project(const double world[3])
  {
    std::array<double, 2> display;
    nprPassScene::Project(world, display.data());
    return display;
  }
};

// A unit cube (its 8 corners c: bit 0 +x, 1 +y, 2 +z) seen from above a corner: 9 visible edges
// and 3 hidden ones, those meeting at the far corner 0 (-x, -y, -z).
void ShowCube(Scene& scene)
{
  const double origin[3] = { 0, 0, 0 };
  const double colour[3] = { 0.9, 0.3, 0.2 }; // never drawn: the faces take the face colour
  nprAddCube(scene.Renderer, origin, 1.0, colour);
  // Off the diagonal, so that the hidden corner's image is far from the near corner's.
  const double eye[3] = { 3.2, 1.5, 1.4 };
  nprViewFromCorner(scene.Camera(), eye, false);
}

std::array<double, 3> Corner(int c)
{
  return { c & 1 ? 0.5 : -0.5, c & 2 ? 0.5 : -0.5, c & 4 ? 0.5 : -0.5 };
}

// Along the image of edge a-b (away from its ends), at each pixel step the darkest grey (mean
// of r, g, b) across the edge: pixels within 1.5 px of it along its normal.
std::vector<int> Profile(Scene& scene, vtkImageData* image, int a, int b)
{
  const auto ca = Corner(a), cb = Corner(b);
  const auto pa = scene.Project(ca.data()), pb = scene.Project(cb.data());
  const double length = std::hypot(pb[0] - pa[0], pb[1] - pa[1]);
  const double normal[2] = { -(pb[1] - pa[1]) / length, (pb[0] - pa[0]) / length };
  std::vector<int> profile;
  for (double s = 8.0; s <= length - 8.0; s += 1.0)
  {
    const double t = s / length;
    int darkest = 255;
    for (double o = -1.5; o <= 1.5; o += 0.25)
    {
      const int x = static_cast<int>(std::floor(pa[0] + t * (pb[0] - pa[0]) + o * normal[0]));
      const int y = static_cast<int>(std::floor(pa[1] + t * (pb[1] - pa[1]) + o * normal[1]));
      darkest = std::min(darkest,
        (nprPixel(image, x, y, 0) + nprPixel(image, x, y, 1) + nprPixel(image, x, y, 2)) / 3);
    }
    profile.push_back(darkest);
  }
  return profile;
}

// ---- The cube: faces, visible lines, hidden lines dashed and lighter ----
int DrawingCube()
{
  Scene scene;
  ShowCube(scene);
  scene.Edges()->SetLineWidth(2.0);
  vtkSmartPointer<vtkImageData> image = scene.Render();

  // A face pixel far from every edge is the face colour (white), not the actor's colour.
  const double faceCentre[3] = { 0.0, 0.5, 0.0 }; // the top face
  const auto top = scene.Project(faceCentre);
  const int topX = static_cast<int>(top[0]), topY = static_cast<int>(top[1]);
  NPR_CHECK(nprPixel(image, topX, topY, 0) == 255 && nprPixel(image, topX, topY, 1) == 255 &&
      nprPixel(image, topX, topY, 2) == 255,
    "the top face is not white at its centre");
  // Visible edges: solid black along their whole length (edge 6-7: +y +z, a crease in front).
  const std::vector<int> visible = Profile(scene, image, 6, 7);
  const int lightestVisible = *std::max_element(visible.begin(), visible.end());
  std::cout << "visible edge: " << visible.size() << " pixels, lightest " << lightestVisible
            << "\n";
  NPR_CHECK(lightestVisible < 40, "a visible edge is not solid: grey " << lightestVisible);
  // No hidden lines by default: the hidden edge 0-1 (-y -z) is not drawn.
  const std::vector<int> absent = Profile(scene, image, 0, 1);
  NPR_CHECK(*std::min_element(absent.begin(), absent.end()) == 255,
    "a hidden edge is drawn without hidden lines");

  // With hidden lines: edge 0-1 dashed, in grey.
  scene.Pass->SetHiddenLines(true);
  image = scene.Render();
  const std::vector<int> hidden = Profile(scene, image, 0, 1);
  int runs = 0, onPixels = 0, darkest = 255;
  bool on = false;
  for (int grey : hidden)
  {
    const bool dash = grey < 200;
    runs += dash && !on ? 1 : 0;
    onPixels += dash ? 1 : 0;
    on = dash;
    darkest = std::min(darkest, grey);
  }
  // The pattern (6 on, 4 off at 72 DPI, round caps of 0.6 x 2 px) repeats every 10 px.
  const double period = static_cast<double>(hidden.size()) / std::max(runs, 1);
  const double share = static_cast<double>(onPixels) / hidden.size();
  std::cout << "hidden edge: " << hidden.size() << " pixels, " << runs << " dashes (period "
            << period << " px), " << 100 * share << " % inked, darkest " << darkest << "\n";
  NPR_CHECK(period > 8.5 && period < 11.5, "hidden dashes repeat every " << period << " px");
  NPR_CHECK(share > 0.5 && share < 0.85, "hidden dashes cover " << 100 * share << " %");
  NPR_CHECK(darkest > 60 && darkest < 200, "hidden lines are not grey: " << darkest);
  // The visible edges are unchanged by the hidden lines.
  NPR_CHECK(Profile(scene, image, 6, 7) == visible, "hidden lines changed a visible edge");
  vtkPolyData* strokes = scene.Drawing()->GetStrokes();
  if (const char* dump = std::getenv("NPR_TEST_DUMP"))
  {
    nprSavePNG(image, std::string(dump) + "drawing_cube.png");
  }
  NPR_CHECK(strokes && strokes->GetNumberOfCells() == 7,
    "the cube's drawing has " << (strokes ? strokes->GetNumberOfCells() : 0) << " strokes, not 7");
  return nprTestResult();
}
NPR_TEST_CASE("cube", DrawingCube);

// ---- Depth sprite: a second layer behind the cube is hidden by the faces and by the lines
// drawn past the outline; beside the cube it shows ----
int DrawingLayer()
{
  const int width = 400, height = 300;
  Scene scene(width, height);
  scene.ShowCube(5.0);
  scene.Edges()->SetLineWidth(6.0);
  vtkSmartPointer<vtkActor> ball = scene.AddSphereBehind();
  ball->VisibilityOff();
  vtkSmartPointer<vtkImageData> alone = scene.Render();
  const std::vector<float> depth = scene.Depth();
  ball->VisibilityOn();
  vtkSmartPointer<vtkImageData> image = scene.Render();
  long long redOverDrawing = 0, redElsewhere = 0, linesPastOutline = 0;
  const double corner[3] = { 0.5, 0.5, 0.5 };
  const auto outline = scene.Project(corner); // the front face's top right corner
  for (int y = 0; y < height; ++y)
  {
    for (int x = 0; x < width; ++x)
    {
      const size_t i = static_cast<size_t>(y) * width + x;
      const bool isRed = nprIsRed(image, x, y);
      const bool drawn = nprPixel(alone, x, y, 0) < 250;
      if (depth[i] < 1.0f)
      {
        redOverDrawing += isRed ? 1 : 0;
        // Outside the square, the wide outline is drawn at the outline's depth.
        linesPastOutline += drawn && (x + 0.5 > outline[0] || y + 0.5 > outline[1]) ? 1 : 0;
      }
      else
      {
        redElsewhere += isRed ? 1 : 0;
      }
    }
  }
  std::cout << "layer-1 sphere: " << redOverDrawing << " red pixels over the drawing, "
            << redElsewhere << " beside it; " << linesPastOutline
            << " line pixels past the outline have the outline's depth\n";
  NPR_CHECK(redOverDrawing == 0, "the sphere behind the drawing shows through it");
  NPR_CHECK(redElsewhere > 100, "the part of the sphere beside the cube should be drawn");
  NPR_CHECK(linesPastOutline > 200, "the wide outline past the square has no depth");
  return nprTestResult();
}
NPR_TEST_CASE("layer", DrawingLayer);

// ---- Strokes are computed again only when the frame changed; an unchanged frame is identical ----
int DrawingReuse()
{
  Scene scene;
  ShowCube(scene);
  vtkNPRDrawingPass* drawing = scene.Drawing();
  vtkSmartPointer<vtkImageData> first = scene.Render();
  vtkSmartPointer<vtkImageData> second = scene.Render();
  NPR_CHECK(drawing->GetNumberOfStrokeUpdates() == 1,
    drawing->GetNumberOfStrokeUpdates() << " stroke updates for an unchanged frame");
  const auto* a = static_cast<unsigned char*>(first->GetScalarPointer());
  const auto* b = static_cast<unsigned char*>(second->GetScalarPointer());
  const size_t bytes =
    static_cast<size_t>(first->GetNumberOfPoints()) * first->GetNumberOfScalarComponents();
  NPR_CHECK(std::equal(a, a + bytes, b), "an unchanged frame drew differently");
  scene.Camera()->Azimuth(5);
  scene.Render();
  NPR_CHECK(drawing->GetNumberOfStrokeUpdates() == 2, "the camera moved: no new strokes");
  scene.Pass->SetHiddenLines(true);
  scene.Render();
  NPR_CHECK(drawing->GetNumberOfStrokeUpdates() == 3, "hidden lines switched on: no new strokes");
  scene.Edges()->SetCreaseAngle(60);
  scene.Render();
  NPR_CHECK(drawing->GetNumberOfStrokeUpdates() == 4, "the crease angle changed: no new strokes");
  NPR_CHECK(drawing->GetDrawingLines()->GetNumberOfLocatorBuilds() == 1,
    "the occluders were built " << drawing->GetDrawingLines()->GetNumberOfLocatorBuilds()
                                << " times for one unchanged mesh");
  // The window resized: strokes for the new size.
  scene.Window->SetSize(300, 200);
  vtkSmartPointer<vtkImageData> small = scene.Render();
  int dims[3];
  small->GetDimensions(dims);
  NPR_CHECK(dims[0] == 300 && dims[1] == 200 && drawing->GetNumberOfStrokeUpdates() == 5,
    "after a resize: " << dims[0] << "x" << dims[1] << ", " << drawing->GetNumberOfStrokeUpdates()
                       << " updates");
  return nprTestResult();
}
NPR_TEST_CASE("reuse", DrawingReuse);

// ---- Smooth silhouettes through the edge pass's SmoothSilhouettes ----
// A coarse sphere (24 x 12 facets): with the setting, its outline is one closed smooth stroke of
// pieces inside its triangles, so more points than its mesh silhouette's polygon; switching it
// computes the strokes again.
int DrawingSmooth()
{
  Scene scene;
  const double origin[3] = { 0, 0, 0 };
  nprAddSphere(scene.Renderer, origin, 1.0, nprGrey, 24);
  const double eye[3] = { 2.6, 1.8, 2.2 };
  nprLookAtOrigin(scene.Camera(), eye, 10.0);
  vtkNPRDrawingPass* drawing = scene.Drawing();
  vtkIdType points[2] = { 0, 0 }; // mesh, smooth
  for (int smooth = 0; smooth < 2; ++smooth)
  {
    scene.Edges()->SetSmoothSilhouettes(smooth == 1);
    scene.Render();
    vtkPolyData* strokes = drawing->GetStrokes();
    points[smooth] = strokes->GetNumberOfPoints();
    NPR_CHECK(drawing->GetNumberOfStrokeUpdates() == smooth + 1 &&
        drawing->GetDrawingLines()->GetSmoothContours() == (smooth == 1),
      "SmoothSilhouettes " << smooth << ": not passed to the drawing lines");
    NPR_CHECK(strokes->GetNumberOfLines() == 1,
      "SmoothSilhouettes " << smooth << ": " << strokes->GetNumberOfLines()
                           << " strokes for the sphere's outline");
  }
  std::cout << "outline points: " << points[0] << " mesh, " << points[1] << " smooth\n";
  NPR_CHECK(points[1] > points[0], "the smooth outline has no more points than the polygon");
  return nprTestResult();
}
NPR_TEST_CASE("smooth", DrawingSmooth);

// ---- The CAD part with hidden lines, against its baseline ----
int DrawingBaseline()
{
  Scene scene(480, 360);
  nprAddBaselineModel(scene.Renderer, "cad_part.vtp");
  scene.Pass->SetHiddenLines(true);
  vtkSmartPointer<vtkImageData> image = scene.Render();
  NPR_CHECK(nprCompareWithBaseline(image, "drawing_cad_part"), "differs from its baseline");
  return nprTestResult();
}
NPR_TEST_CASE("baseline", DrawingBaseline);
}
