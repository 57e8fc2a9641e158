// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// Part of the TestDrawingExporter program: what a vector figure draws besides the faces and the
// feature lines, each file rasterised by rsvg-convert against VTK's own render of the scene:
// - "points": vertex cells (squares of their PointSize, in their mapped scalar colours) and a
//   mesh drawn with the Points representation as spheres (discs), a point behind the sphere
//   left out; the painted points counted against the scene's geometry, their pixels against
//   the render's;
// - "overlays": 2D text (vtkTextActor: plain, and rotated on two lines with a background box
//   and a frame; a vtkActor2D of a vtkTextMapper) as glyph outlines, and a scalar bar as an
//   image of its pixels; the window's picture is the same after the export as before it, with
//   and without a vtkNPRPass; Overlays off leaves them out; the PDF has the texts too.
//
// - "wireframe": the polygon edges of a surface with EdgeVisibility (its EdgeColor) and of a
//   wireframe (its colour), hidden where VTK hides them, against the render's pixels of each.
//
// usage: TestDrawingExporter points|overlays|wireframe [DATA_DIR]
#include "TestDrawingExporter.h"
#include "nprTestImages.h"

#include "vtkActor.h"
#include "vtkActor2D.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCubeSource.h"
#include "vtkElevationFilter.h"
#include "vtkImageData.h"
#include "vtkLookupTable.h"
#include "vtkNPRDrawingExporter.h"
#include "vtkNPREdgePass.h"
#include "vtkNPRPass.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkScalarBarActor.h"
#include "vtkSphereSource.h"
#include "vtkTextActor.h"
#include "vtkTextMapper.h"
#include "vtkTextProperty.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <tuple>

namespace
{
using namespace nprDrawingExporter;
constexpr int Width = 400, Height = 300;

// A pixel test on RGB.
using Colour = std::function<bool(int r, int g, int b)>;

// A region of the image, [X0, X1) x [Y0, Y1), row 0 at the bottom.
struct Box
{
  int X0 = 0, Y0 = 0, X1 = Width, Y1 = Height;
};

// Whether the pixel passes `colour`; false outside the image.
bool Passes(vtkImageData* image, int x, int y, const Colour& colour)
{
  return x >= 0 && y >= 0 && x < Width && y < Height &&
    colour(nprPixel(image, x, y, 0), nprPixel(image, x, y, 1), nprPixel(image, x, y, 2));
}

// How well the pixels of `file` that pass `colour` match those of `render` inside `box`: the F1
// score within one pixel (a pixel matches when one of the other's 3 x 3 about it passes), as the
// line accuracy is measured; thin glyph strokes moved by half a pixel keep their score. Sets how
// many pixels each has.
double Match(vtkImageData* render, vtkImageData* file, const Colour& colour, const Box& box,
  int& inRender, int& inFile)
{
  auto near = [&](vtkImageData* image, int x, int y)
  {
    for (int dy = -1; dy <= 1; ++dy)
    {
      for (int dx = -1; dx <= 1; ++dx)
      {
        if (Passes(image, x + dx, y + dy, colour))
        {
          return true;
        }
      }
    }
    return false;
  };
  int found = 0, kept = 0;
  inRender = inFile = 0;
  for (int y = box.Y0; y < box.Y1; ++y)
  {
    for (int x = box.X0; x < box.X1; ++x)
    {
      if (Passes(render, x, y, colour))
      {
        ++inRender;
        found += near(file, x, y) ? 1 : 0;
      }
      if (Passes(file, x, y, colour))
      {
        ++inFile;
        kept += near(render, x, y) ? 1 : 0;
      }
    }
  }
  const double recall = inRender ? static_cast<double>(found) / inRender : 0.0;
  const double precision = inFile ? static_cast<double>(kept) / inFile : 0.0;
  return precision + recall > 0.0 ? 2.0 * precision * recall / (precision + recall) : 0.0;
}

// Whether two captures are the same picture, bit for bit.
bool SamePicture(vtkImageData* a, vtkImageData* b)
{
  const int* da = a->GetDimensions();
  const int* db = b->GetDimensions();
  return da[0] == db[0] && da[1] == db[1] &&
    std::equal(static_cast<const unsigned char*>(a->GetScalarPointer()),
      static_cast<const unsigned char*>(a->GetScalarPointer()) + 3 * da[0] * da[1],
      static_cast<const unsigned char*>(b->GetScalarPointer()));
}

void Frame(vtkRenderer* renderer, double zoom)
{
  renderer->SetBackground(0.1, 0.1, 0.15);
  renderer->ResetCamera();
  renderer->GetActiveCamera()->Zoom(zoom);
}

vtkActor* AddActor(vtkRenderer* renderer, vtkPolyData* mesh, double r, double g, double b)
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(mesh);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(r, g, b);
  actor->GetProperty()->SetAmbient(1.0); // flat, as SURFACE_COLORS fills
  actor->GetProperty()->SetDiffuse(0.0);
  actor->GetProperty()->SetSpecular(0.0);
  renderer->AddActor(actor);
  return actor;
}

// Writes `path` (no lines: the faces in their colours, the points, the overlays).
vtkSmartPointer<vtkImageData> Export(
  vtkRenderer* renderer, const std::string& name, vtkNPRDrawingExporter* exporter)
{
  exporter->SetRenderer(renderer);
  exporter->SetEmbedImage(0);
  exporter->FillFacesOn();
  exporter->SetFillColors(vtkNPRDrawingExporter::SURFACE_COLORS);
  const std::string path = nprTestOutputPath(name);
  exporter->SetFileName(path.c_str());
  NPR_CHECK(exporter->Write(), "write " << name << ": " << exporter->GetErrorMessage());
  return Rasterise(path, Width, Height);
}

// A 13 x 9 grid of points in the plane z = 0 through a sphere of radius 1: those inside it are
// behind its front; coloured red on the left and yellow on the right by direct RGB scalars.
vtkSmartPointer<vtkPolyData> PointGrid(int& visible)
{
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> verts;
  vtkNew<vtkUnsignedCharArray> colors;
  colors->SetNumberOfComponents(3);
  visible = 0;
  for (int j = 0; j < 9; ++j)
  {
    for (int i = 0; i < 13; ++i)
    {
      const double x = -1.5 + 0.25 * i, y = -1.1 + 0.275 * j;
      const vtkIdType id = points->InsertNextPoint(x, y, 0.0);
      verts->InsertNextCell(1, &id);
      const unsigned char rgb[3] = { 255, static_cast<unsigned char>(x < 0.0 ? 0 : 255), 0 };
      colors->InsertNextTypedTuple(rgb);
      visible += x * x + y * y > 1.0 ? 1 : 0; // none lies within 0.05 of the sphere
    }
  }
  auto grid = vtkSmartPointer<vtkPolyData>::New();
  grid->SetPoints(points);
  grid->SetVerts(verts);
  grid->GetPointData()->SetScalars(colors);
  return grid;
}

int Points()
{
  vtkSmartPointer<vtkRenderWindow> window = nprCreateTestWindow(Width, Height, nullptr);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  vtkNew<vtkSphereSource> sphere;
  sphere->SetRadius(1.0);
  sphere->SetThetaResolution(64);
  sphere->SetPhiResolution(32);
  sphere->Update();
  AddActor(renderer, sphere->GetOutput(), 0.6, 0.6, 0.6);
  int visible = 0;
  vtkSmartPointer<vtkPolyData> grid = PointGrid(visible);
  vtkActor* gridActor = AddActor(renderer, grid, 1.0, 1.0, 1.0);
  vtkMapper::SafeDownCast(gridActor->GetMapper())->SetColorModeToDirectScalars();
  gridActor->GetProperty()->SetPointSize(6.0);
  // A 3 x 3 plane drawn as points, as spheres, in front of the grid at the bottom left.
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-1.4, -1.4, 0.5);
  plane->SetPoint1(-0.9, -1.4, 0.5);
  plane->SetPoint2(-1.4, -0.9, 0.5);
  plane->SetResolution(2, 2);
  plane->Update();
  vtkActor* spheres = AddActor(renderer, plane->GetOutput(), 0.1, 0.9, 0.2);
  spheres->GetProperty()->SetRepresentationToPoints();
  spheres->GetProperty()->RenderPointsAsSpheresOn();
  spheres->GetProperty()->SetPointSize(10.0);
  Frame(renderer, 1.1);
  window->Render();
  vtkSmartPointer<vtkImageData> render = nprCaptureImage(window);
  nprSavePNG(render, nprTestOutputPath("points_render.png")); // beside the file's raster

  vtkNew<vtkNPRPass> linesOff; // the file's faces and points alone
  linesOff->GetEdgePass()->SetSilhouettes(false);
  linesOff->GetEdgePass()->SetCreases(false);
  renderer->SetPass(linesOff);
  vtkNew<vtkNPRDrawingExporter> exporter;
  vtkSmartPointer<vtkImageData> file = Export(renderer, "points.svg", exporter);
  renderer->SetPass(nullptr);
  const vtkIdType painted = exporter->GetNumberOfStrokes(7);
  std::cout << "points: " << painted << " painted, " << visible
            << " grid points visible + 9 spheres\n";
  NPR_CHECK(painted == visible + 9, painted << " points painted, " << visible + 9 << " expected");
  const std::string svg = ReadFile(nprTestOutputPath("points.svg"));
  NPR_CHECK(svg.find("<g class=\"npr-point\">") != std::string::npos, "no npr-point group");
  if (!file || !render)
  {
    return nprTestResult();
  }
  const Colour red = [](int r, int g, int b) { return r > 180 && g < 80 && b < 80; };
  const Colour yellow = [](int r, int g, int b) { return r > 180 && g > 180 && b < 80; };
  const Colour green = [](int r, int g, int b) { return g > r + 40 && g > b + 40; };
  const std::pair<const char*, Colour> colours[] = { { "red", red }, { "yellow", yellow },
    { "green", green } };
  for (const auto& entry : colours)
  {
    int inRender, inFile;
    const double f1 = Match(render, file, entry.second, Box(), inRender, inFile);
    std::cout << entry.first << " pixels: render " << inRender << ", file " << inFile
              << ", F1 within 1 px " << f1 << "\n";
    NPR_CHECK(
      inRender > 50 && f1 >= 0.95, entry.first << " points: F1 " << f1 << " (0.95 required)");
  }
  return nprTestResult();
}
NPR_TEST_CASE("points", Points);

// A sphere drawn with its edges (EdgeVisibility, blue) and a cube as a wireframe (red) around
// it: the edges are strokes of their colours (class npr-line), the sphere's back edges and the
// cube's edges behind the sphere left out, as in the render.
int Wireframe()
{
  vtkSmartPointer<vtkRenderWindow> window = nprCreateTestWindow(Width, Height, nullptr);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  vtkNew<vtkSphereSource> sphere;
  sphere->SetRadius(0.8);
  sphere->SetThetaResolution(12);
  sphere->SetPhiResolution(8);
  sphere->Update();
  vtkActor* edged = AddActor(renderer, sphere->GetOutput(), 0.8, 0.8, 0.8);
  edged->GetProperty()->EdgeVisibilityOn();
  edged->GetProperty()->SetEdgeColor(0.0, 0.0, 1.0);
  edged->GetProperty()->SetLineWidth(2.0);
  vtkNew<vtkCubeSource> cube;
  cube->SetXLength(2.2);
  cube->SetYLength(1.4);
  cube->SetZLength(1.4);
  cube->Update();
  vtkActor* wireframe = AddActor(renderer, cube->GetOutput(), 1.0, 0.0, 0.0);
  wireframe->GetProperty()->SetRepresentationToWireframe();
  wireframe->GetProperty()->SetLineWidth(2.0);
  Frame(renderer, 1.0);
  renderer->GetActiveCamera()->Azimuth(30.0);
  renderer->GetActiveCamera()->Elevation(20.0);
  renderer->ResetCameraClippingRange();
  window->Render();
  vtkSmartPointer<vtkImageData> render = nprCaptureImage(window);
  nprSavePNG(render, nprTestOutputPath("wireframe_render.png")); // beside the file's raster

  vtkNew<vtkNPRPass> linesOff; // the file's faces and the scene's own lines alone
  linesOff->GetEdgePass()->SetSilhouettes(false);
  linesOff->GetEdgePass()->SetCreases(false);
  renderer->SetPass(linesOff);
  vtkNew<vtkNPRDrawingExporter> exporter;
  vtkSmartPointer<vtkImageData> file = Export(renderer, "wireframe.svg", exporter);
  renderer->SetPass(nullptr);
  std::cout << "wireframe: " << exporter->GetNumberOfStrokes(6) << " line strokes\n";
  NPR_CHECK(exporter->GetNumberOfStrokes(6) >= 12, exporter->GetNumberOfStrokes(6) << " strokes");
  if (!file || !render)
  {
    return nprTestResult();
  }
  const Colour blue = [](int r, int g, int b) { return b > r + 80 && b > g + 80; };
  const Colour red = [](int r, int g, int b) { return r > g + 80 && r > b + 80; };
  const std::pair<const char*, Colour> colours[] = { { "sphere edges", blue },
    { "wireframe", red } };
  for (const auto& entry : colours)
  {
    int inRender, inFile;
    const double f1 = Match(render, file, entry.second, Box(), inRender, inFile);
    std::cout << entry.first << " pixels: render " << inRender << ", file " << inFile
              << ", F1 within 1 px " << f1 << "\n";
    NPR_CHECK(inRender > 200 && f1 >= 0.9, entry.first << ": F1 " << f1 << " (0.9 required)");
  }
  return nprTestResult();
}
NPR_TEST_CASE("wireframe", Wireframe);

// The overlays' scene: a sphere coloured by elevation with its scalar bar on the right, and three
// texts in the corners, over the background.
struct OverlayScene
{
  vtkSmartPointer<vtkRenderWindow> Window = nprCreateTestWindow(Width, Height, nullptr);
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkScalarBarActor> Bar;

  OverlayScene()
  {
    this->Window->AddRenderer(this->Renderer);
    vtkNew<vtkSphereSource> sphere;
    sphere->SetThetaResolution(48);
    sphere->SetPhiResolution(24);
    vtkNew<vtkElevationFilter> elevation;
    elevation->SetInputConnection(sphere->GetOutputPort());
    elevation->SetLowPoint(0.0, -0.5, 0.0);
    elevation->SetHighPoint(0.0, 0.5, 0.0);
    elevation->Update();
    vtkActor* actor =
      AddActor(this->Renderer, vtkPolyData::SafeDownCast(elevation->GetOutput()), 1, 1, 1);
    vtkNew<vtkLookupTable> table;
    table->Build();
    actor->GetMapper()->SetLookupTable(table);
    actor->GetMapper()->SetScalarRange(0.0, 1.0);
    this->Bar->SetLookupTable(table);
    this->Bar->SetNumberOfLabels(3);
    this->Bar->SetPosition(0.82, 0.1);
    this->Bar->SetPosition2(0.16, 0.8);
    this->Renderer->AddViewProp(this->Bar);
    this->AddText("vtkNPR figure", 10, 10, 0.0, false)->GetTextProperty()->SetColor(1, 0, 0);
    vtkTextActor* framed = this->AddText("two lines,\nturned", 80, 220, 20.0, true);
    framed->GetTextProperty()->SetColor(1.0, 1.0, 0.0);
    framed->GetTextProperty()->SetBackgroundColor(0.0, 0.0, 0.6);
    framed->GetTextProperty()->SetBackgroundOpacity(1.0);
    framed->GetTextProperty()->FrameOn();
    framed->GetTextProperty()->SetFrameColor(0.0, 1.0, 1.0);
    framed->GetTextProperty()->SetFrameWidth(2);
    vtkNew<vtkTextMapper> mapper;
    mapper->SetInput("mapper text");
    mapper->GetTextProperty()->SetFontSize(18);
    mapper->GetTextProperty()->SetColor(1.0, 0.0, 1.0);
    vtkNew<vtkActor2D> mapped;
    mapped->SetMapper(mapper);
    mapped->SetPosition(160, 270);
    this->Renderer->AddViewProp(mapped);
    Frame(this->Renderer, 0.8);
  }

  vtkTextActor* AddText(const char* text, double x, double y, double orientation, bool centred)
  {
    vtkNew<vtkTextActor> actor;
    actor->SetInput(text);
    actor->SetPosition(x, y);
    actor->GetTextProperty()->SetFontSize(22);
    actor->GetTextProperty()->SetOrientation(orientation);
    if (centred)
    {
      actor->GetTextProperty()->SetJustificationToCentered();
      actor->GetTextProperty()->SetVerticalJustificationToCentered();
    }
    this->Renderer->AddViewProp(actor);
    return actor;
  }
};

// The bar's pixels: the share of its box's pixels in the file that differ from the render by
// more than 24 in a channel.
double BarDifference(vtkImageData* render, vtkImageData* file)
{
  const int x0 = static_cast<int>(0.82 * Width), x1 = static_cast<int>(0.98 * Width);
  const int y0 = static_cast<int>(0.1 * Height), y1 = static_cast<int>(0.9 * Height);
  int differing = 0, all = 0;
  for (int y = y0; y < y1; ++y)
  {
    for (int x = x0; x < x1; ++x, ++all)
    {
      int worst = 0;
      for (int c = 0; c < 3; ++c)
      {
        worst = std::max(worst, std::abs(nprPixel(render, x, y, c) - nprPixel(file, x, y, c)));
      }
      differing += worst > 24 ? 1 : 0;
    }
  }
  return static_cast<double>(differing) / all;
}

int Overlays()
{
  OverlayScene scene;
  scene.Window->Render();
  vtkSmartPointer<vtkImageData> render = nprCaptureImage(scene.Window);
  nprSavePNG(render, nprTestOutputPath("overlays_render.png")); // beside the file's raster
  vtkNew<vtkNPRDrawingExporter> exporter;
  vtkSmartPointer<vtkImageData> file = Export(scene.Renderer, "overlays.svg", exporter);
  vtkSmartPointer<vtkImageData> after = nprCaptureImage(scene.Window);
  std::cout << "overlays: " << exporter->GetNumberOfTexts() << " texts ("
            << exporter->GetNumberOfStrokes(8) << " paths), "
            << exporter->GetNumberOfImagedOverlays() << " 2D props as an image\n";
  NPR_CHECK(exporter->GetNumberOfTexts() == 3, exporter->GetNumberOfTexts() << " texts");
  NPR_CHECK(exporter->GetNumberOfStrokes(8) == 5, exporter->GetNumberOfStrokes(8) << " text paths");
  NPR_CHECK(exporter->GetNumberOfImagedOverlays() == 1, "the scalar bar is not the image");
  const std::string svg = ReadFile(nprTestOutputPath("overlays.svg"));
  NPR_CHECK(svg.find("<g class=\"npr-text\">") != std::string::npos && Count(svg, "<image") == 1,
    "no npr-text group or not one image");
  NPR_CHECK(SamePicture(render, after), "the window's picture changed");
  if (!file || !render)
  {
    return nprTestResult();
  }
  const Colour red = [](int r, int g, int b) { return r > 150 && g < 90 && b < 90; };
  const Colour yellow = [](int r, int g, int b) { return r > 150 && g > 150 && b < 90; };
  const Colour magenta = [](int r, int g, int b) { return r > 150 && g < 90 && b > 150; };
  const Colour backgroundBox = [](int r, int g, int b) { return r < 40 && g < 40 && b > 120; };
  // Each text's region, clear of the sphere and the bar.
  const std::tuple<const char*, Colour, Box> texts[] = { { "red text", red, { 0, 0, 200, 50 } },
    { "yellow text", yellow, { 0, 150, 150, 300 } },
    { "magenta text", magenta, { 120, 250, 300, 300 } },
    { "background box", backgroundBox, { 0, 150, 150, 300 } } };
  for (const auto& text : texts)
  {
    int inRender, inFile;
    const double f1 = Match(render, file, std::get<1>(text), std::get<2>(text), inRender, inFile);
    std::cout << std::get<0>(text) << " pixels: render " << inRender << ", file " << inFile
              << ", F1 within 1 px " << f1 << "\n";
    NPR_CHECK(
      inRender > 50 && f1 >= 0.95, std::get<0>(text) << ": F1 " << f1 << " (0.95 required)");
  }
  const double bar = BarDifference(render, file);
  std::cout << "scalar bar: " << 100.0 * bar << " % of its box's pixels differ\n";
  NPR_CHECK(bar <= 0.01, 100.0 * bar << " % of the bar's pixels differ (1 % allowed)");

  // Overlays off: no text and no image; the PDF holds the texts too.
  vtkNew<vtkNPRDrawingExporter> without;
  without->OverlaysOff();
  vtkSmartPointer<vtkImageData> bare = Export(scene.Renderer, "overlays_off.svg", without);
  int inRender = 0, inBare = 0;
  Match(render, bare, red, std::get<2>(texts[0]), inRender, inBare);
  NPR_CHECK(without->GetNumberOfTexts() == 0 && inBare == 0 &&
      Count(ReadFile(nprTestOutputPath("overlays_off.svg")), "<image") == 0,
    "Overlays off: " << without->GetNumberOfTexts() << " texts, " << inBare << " red pixels");
  if (std::string(PDFTOPPM).find('/') != std::string::npos)
  {
    vtkNew<vtkNPRDrawingExporter> pdf;
    vtkSmartPointer<vtkImageData> page = Export(scene.Renderer, "overlays.pdf", pdf);
    int inPage = 0;
    const double f1 =
      page ? Match(render, page, red, std::get<2>(texts[0]), inRender, inPage) : 0.0;
    std::cout << "PDF red text: F1 within 1 px " << f1 << "\n";
    NPR_CHECK(f1 >= 0.95, "PDF red text: F1 " << f1 << " (0.95 required)");
  }

  // With a vtkNPRPass (the drawing style) the window shows the same picture after the export.
  vtkNew<vtkNPRPass> pass;
  pass->SetStyleToDrawing();
  scene.Renderer->SetPass(pass);
  scene.Window->Render();
  vtkSmartPointer<vtkImageData> styled = nprCaptureImage(scene.Window);
  vtkNew<vtkNPRDrawingExporter> drawing;
  Export(scene.Renderer, "overlays_drawing.svg", drawing);
  vtkSmartPointer<vtkImageData> styledAfter = nprCaptureImage(scene.Window);
  NPR_CHECK(
    SamePicture(styled, styledAfter), "the drawing style's picture changed after the export");
  scene.Renderer->SetPass(nullptr);
  return nprTestResult();
}
NPR_TEST_CASE("overlays", Overlays);
}
