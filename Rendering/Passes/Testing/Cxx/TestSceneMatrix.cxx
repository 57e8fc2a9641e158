// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// Ordinary VTK scenes under every style (issue 19): polygons with point, cell and no normals,
// lines, points, a wireframe, tubes, an outline around an isosurface, cube axes with grid lines and
// labels, text, a scalar bar, glyphs, an image actor, a vtkAxesActor, a volume, a translucent actor
// with and without depth peeling and two layers. Fails on any VTK error or warning and on a crash;
// checks that lines and annotations keep their own look: a white line stays white, a 1-px outline
// stays about 1 px wide, white grid lines and 3D labels stay white, and the translucent blend, the
// volume, the axes and the second layer keep their colours.
//
// usage: TestSceneMatrix STYLE [DATA_DIR]   (STYLE: a vtkNPRPass style name, '+' written '-')
#include "nprTesting.h"

#include "vtkActor.h"
#include "vtkAxesActor.h"
#include "vtkBillboardTextActor3D.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkColorTransferFunction.h"
#include "vtkConeSource.h"
#include "vtkContourFilter.h"
#include "vtkCubeAxesActor.h"
#include "vtkDataSetMapper.h"
#include "vtkGPUVolumeRayCastMapper.h"
#include "vtkGlyph3DMapper.h"
#include "vtkImageActor.h"
#include "vtkImageData.h"
#include "vtkImageMapper3D.h"
#include "vtkLineSource.h"
#include "vtkLookupTable.h"
#include "vtkNew.h"
#include "vtkOutlineFilter.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkPolyDataNormals.h"
#include "vtkProperty.h"
#include "vtkRTAnalyticSource.h"
#include "vtkScalarBarActor.h"
#include "vtkShaderProperty.h"
#include "vtkSphereSource.h"
#include "vtkTextActor.h"
#include "vtkTextProperty.h"
#include "vtkTransform.h"
#include "vtkTubeFilter.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <map>
#include <string>

namespace
{
int Style = vtkNPRPass::SHADED;

vtkSmartPointer<vtkActor> ActorFor(vtkRenderer* renderer, vtkPolyData* data, double x, double y)
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(data);
  mapper->ScalarVisibilityOff();
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->SetPosition(x, y, 0.0);
  actor->GetProperty()->SetColor(0.8, 0.6, 0.4);
  renderer->AddActor(actor);
  return actor;
}

vtkSmartPointer<vtkPolyData> Sphere(int normals) // 0 none, 1 point, 2 cell
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetRadius(0.4);
  sphere->SetThetaResolution(16);
  sphere->SetPhiResolution(8);
  sphere->Update();
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->DeepCopy(sphere->GetOutput());
  data->GetPointData()->SetNormals(nullptr);
  if (normals > 0)
  {
    vtkNew<vtkPolyDataNormals> filter;
    filter->SetInputData(data);
    filter->SetComputePointNormals(normals == 1);
    filter->SetComputeCellNormals(normals == 2);
    filter->Update();
    data->DeepCopy(filter->GetOutput());
  }
  return data;
}

// Renders twice (the second frame may reuse the G-buffer) and returns the last image.
vtkSmartPointer<vtkImageData> RenderTwice(nprPassScene& scene)
{
  scene.Render();
  return scene.Render();
}

// Every kind of prop in one scene: nothing reported, nothing crashes, something drawn.
void EveryKind()
{
  nprPassScene scene(360, 280);
  scene.Pass->SetStyle(Style);
  vtkRenderer* renderer = scene.Renderer;
  ActorFor(renderer, Sphere(1), -1.0, 1.0);
  ActorFor(renderer, Sphere(2), 0.0, 1.0);
  ActorFor(renderer, Sphere(0), 1.0, 1.0);
  ActorFor(renderer, Sphere(1), 2.0, 1.0)->GetProperty()->SetRepresentationToWireframe();
  auto points = ActorFor(renderer, Sphere(1), 2.0, 0.0);
  points->GetProperty()->SetRepresentationToPoints();
  points->GetProperty()->SetPointSize(4);

  // Lines and vertices of their own.
  vtkNew<vtkPolyData> strokes;
  vtkNew<vtkPoints> strokePoints;
  vtkNew<vtkCellArray> lines, verts;
  for (int i = 0; i < 8; ++i)
  {
    strokePoints->InsertNextPoint(-1.4 + 0.1 * i, -1.0 + 0.05 * i, 0.0);
    verts->InsertNextCell(1);
    verts->InsertCellPoint(i);
  }
  lines->InsertNextCell(8);
  for (int i = 0; i < 8; ++i)
  {
    lines->InsertCellPoint(i);
  }
  strokes->SetPoints(strokePoints);
  strokes->SetLines(lines);
  strokes->SetVerts(verts);
  ActorFor(renderer, strokes, 0.0, 0.0)->GetProperty()->SetPointSize(5);

  // A tube around the strokes: polygons, so styled (vtkTubeFilter).
  vtkNew<vtkTubeFilter> tube;
  tube->SetInputData(strokes);
  tube->SetRadius(0.03);
  tube->SetNumberOfSides(8);
  tube->Update();
  ActorFor(renderer, tube->GetOutput(), 0.0, 0.3);

  // An isosurface inside its outline.
  vtkNew<vtkRTAnalyticSource> wavelet;
  wavelet->SetWholeExtent(-8, 8, -8, 8, -8, 8);
  vtkNew<vtkContourFilter> contour;
  contour->SetInputConnection(wavelet->GetOutputPort());
  contour->SetValue(0, 160.0);
  contour->Update();
  auto iso = ActorFor(renderer, contour->GetOutput(), -0.5, -0.5);
  iso->SetScale(0.05);
  vtkNew<vtkOutlineFilter> outline;
  outline->SetInputConnection(wavelet->GetOutputPort());
  outline->Update();
  auto box = ActorFor(renderer, outline->GetOutput(), -0.5, -0.5);
  box->SetScale(0.05);
  box->GetProperty()->SetColor(0.0, 0.0, 0.0);

  // Glyphs.
  vtkNew<vtkPlaneSource> grid;
  grid->SetResolution(2, 2);
  grid->SetCenter(1.0, -1.0, 0.0);
  vtkNew<vtkConeSource> cone;
  cone->SetHeight(0.2);
  cone->SetRadius(0.1);
  vtkNew<vtkGlyph3DMapper> glyphs;
  glyphs->SetInputConnection(grid->GetOutputPort());
  glyphs->SetSourceConnection(cone->GetOutputPort());
  vtkNew<vtkActor> glyphActor;
  glyphActor->SetMapper(glyphs);
  renderer->AddActor(glyphActor);

  // An image actor.
  vtkNew<vtkImageData> image;
  image->SetDimensions(8, 8, 1);
  image->SetSpacing(0.05, 0.05, 1.0);
  image->SetOrigin(-2.0, -0.5, 0.0);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
  for (int i = 0; i < 64; ++i)
  {
    static_cast<unsigned char*>(image->GetScalarPointer())[i] = static_cast<unsigned char>(4 * i);
  }
  vtkNew<vtkImageActor> imageActor;
  imageActor->GetMapper()->SetInputData(image);
  renderer->AddActor(imageActor);

  // Text, flat and in the scene.
  vtkNew<vtkTextActor> text;
  text->SetInput("vtkTextActor");
  text->GetTextProperty()->SetColor(0.0, 0.0, 0.0);
  text->SetPosition(10, 10);
  renderer->AddActor2D(text);
  vtkNew<vtkLookupTable> table;
  table->Build();
  vtkNew<vtkScalarBarActor> scalarBar;
  scalarBar->SetLookupTable(table);
  scalarBar->SetPosition(0.88, 0.1);
  scalarBar->SetWidth(0.1);
  scalarBar->SetHeight(0.8);
  renderer->AddActor2D(scalarBar);
  vtkNew<vtkBillboardTextActor3D> billboard;
  billboard->SetInput("billboard");
  billboard->SetPosition(0.0, -1.5, 0.0);
  billboard->GetTextProperty()->SetColor(0.0, 0.0, 1.0);
  renderer->AddActor(billboard);

  // Cube axes with grid lines and 3D labels.
  vtkNew<vtkCubeAxesActor> axes;
  axes->SetBounds(-1.5, 2.5, -1.5, 1.5, -0.5, 0.5);
  axes->SetCamera(scene.Camera());
  axes->DrawXGridlinesOn();
  axes->DrawYGridlinesOn();
  axes->DrawZGridlinesOn();
  axes->SetUse2DMode(false);
  renderer->AddActor(axes);

  renderer->ResetCamera();
  auto shot = RenderTwice(scene);
  if (const char* dump = std::getenv("NPR_TEST_DUMP")) // a look at the scene
  {
    nprWritePNG(shot, std::string(dump) + vtkNPRPass::GetStyleName(Style) + ".png");
  }
  const double white[3] = { 1, 1, 1 };
  const nprPixelStatistics stats = nprComputePixelStatistics(shot, white);
  std::cout << "every kind: " << stats.ObjectPixels << " object pixels\n";
  NPR_CHECK(stats.ObjectPixels > 2000, "the scene was not drawn");
}

// A 1-px black outline (a flat box seen head-on) around a sphere, and a 1-px white line over a
// grey plane: the line primitives keep their colour and width.
void LineLooks()
{
  nprPassScene scene(200, 200);
  scene.Pass->SetStyle(Style);
  vtkRenderer* renderer = scene.Renderer;
  vtkNew<vtkSphereSource> sphere;
  sphere->SetRadius(0.3);
  sphere->SetCenter(0.0, 0.3, 0.0);
  sphere->SetThetaResolution(32);
  sphere->SetPhiResolution(16);
  sphere->Update();
  ActorFor(renderer, sphere->GetOutput(), 0.0, 0.0);
  // The outline of a flat box: a rectangle from -0.8 to 0.8 in x, -0.7 to 0.8 in y.
  vtkNew<vtkPlaneSource> rectangle;
  rectangle->SetOrigin(-0.8, -0.7, 0.0);
  rectangle->SetPoint1(0.8, -0.7, 0.0);
  rectangle->SetPoint2(-0.8, 0.8, 0.0);
  vtkNew<vtkOutlineFilter> outline;
  outline->SetInputConnection(rectangle->GetOutputPort());
  outline->Update();
  auto box = ActorFor(renderer, outline->GetOutput(), 0.0, 0.0);
  box->GetProperty()->SetColor(0.0, 0.0, 0.0);
  box->GetProperty()->LightingOff();
  // A grey plane below with a white line in front of it (a grid line over a surface).
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-0.9, -0.8, -0.1);
  plane->SetPoint1(0.9, -0.8, -0.1);
  plane->SetPoint2(-0.9, -0.3, -0.1);
  plane->Update();
  auto grey = ActorFor(renderer, plane->GetOutput(), 0.0, 0.0);
  grey->GetProperty()->SetColor(0.3, 0.3, 0.3);
  grey->GetProperty()->LightingOff();
  vtkNew<vtkLineSource> line;
  line->SetPoint1(-0.6, -0.55, 0.0);
  line->SetPoint2(0.6, -0.55, 0.0);
  line->Update();
  auto whiteLine = ActorFor(renderer, line->GetOutput(), 0.0, 0.0);
  whiteLine->GetProperty()->SetColor(1.0, 1.0, 1.0);
  whiteLine->GetProperty()->LightingOff();
  scene.LookAtOrigin(4.0);
  scene.Camera()->ParallelProjectionOn();
  scene.Camera()->SetParallelScale(1.0);
  auto shot = RenderTwice(scene);

  // Dark pixels across the outline's left side, on a row between the sphere and the plane.
  double p[2];
  const double left[3] = { -0.8, 0.0, 0.0 };
  scene.Project(left, p);
  const int row = static_cast<int>(p[1]);
  int dark = 0;
  for (int x = static_cast<int>(p[0]) - 6; x <= static_cast<int>(p[0]) + 6; ++x)
  {
    dark += nprPixel(shot, x, row) < 128 ? 1 : 0;
  }
  std::cout << "outline: " << dark << " dark pixels across\n";
  NPR_CHECK(dark >= 1 && dark <= 2, "the 1-px outline is " << dark << " px wide");
  // The same side in front of the grey plane (76): still 1 px, no lines traced beside it.
  const double overPlane[3] = { -0.8, -0.45, 0.0 };
  scene.Project(overPlane, p);
  dark = 0;
  for (int x = static_cast<int>(p[0]) - 6; x <= static_cast<int>(p[0]) + 6; ++x)
  {
    // Anything but the plane's grey: the outline, or lines traced beside it.
    dark += std::abs(nprPixel(shot, x, static_cast<int>(p[1])) - 76) > 20 ? 1 : 0;
  }
  std::cout << "outline over the plane: " << dark << " pixels across\n";
  NPR_CHECK(dark >= 1 && dark <= 2, "the 1-px outline over the plane is " << dark << " px wide");

  // The white line over the grey plane: white on its row, and no dark pixels around it.
  const double onLine[3] = { 0.0, -0.55, 0.0 };
  scene.Project(onLine, p);
  int brightest = 0, darkest = 255;
  for (int y = static_cast<int>(p[1]) - 4; y <= static_cast<int>(p[1]) + 4; ++y)
  {
    const int value = nprPixel(shot, static_cast<int>(p[0]), y);
    brightest = std::max(brightest, value);
    darkest = std::min(darkest, value);
  }
  std::cout << "white line: brightest " << brightest << ", darkest " << darkest << "\n";
  NPR_CHECK(brightest > 240, "the white line is not white: " << brightest);
  NPR_CHECK(darkest > 40, "lines were drawn along the white line: " << darkest);
}

// A user's shader replacement that leaves VTK's shader intact and breaks the passes' code: the
// sphere is drawn as VTK draws it, with one warning per pass, no error, no crash.
int Failure()
{
  for (int style :
    { vtkNPRPass::EDGES, vtkNPRPass::TOON, vtkNPRPass::TOON_EDGES, vtkNPRPass::INKED })
  {
    nprPassScene scene(120, 120);
    scene.Pass->SetStyle(style);
    auto sphere = ActorFor(scene.Renderer, Sphere(1), 0.0, 0.0);
    sphere->GetShaderProperty()->AddFragmentShaderReplacement("//VTK::Output::Dec", true,
      "//VTK::Output::Dec\n#define nprGeometry 1.0\n#define nprColor 1.0\n#define nprInkColor "
      "1.0\n",
      false);
    scene.Renderer->ResetCamera();
    auto* output = nprCountingOutputWindow::SafeDownCast(vtkOutputWindow::GetInstance());
    const int warnings = output->Warnings;
    auto shot = RenderTwice(scene);
    const double white[3] = { 1, 1, 1 };
    const nprPixelStatistics stats = nprComputePixelStatistics(shot, white);
    const int warned = output->Warnings - warnings;
    std::cout << vtkNPRPass::GetStyleName(style) << ": " << stats.ObjectPixels << " object pixels, "
              << warned << " warnings\n";
    NPR_CHECK(stats.ObjectPixels > 2000, "the sphere was not drawn");
    NPR_CHECK(warned >= 1 && warned <= 2, warned << " warnings (one per pass that failed)");
  }
  return nprTestResult();
}

// Bright pixels of a vtkCubeAxesActor's white grid lines, or of its white 3D labels and titles
// (vector-text followers, drawn through inner actors), on a dark background around a dark sphere.
long long CubeAxesPixels(int style, bool labels)
{
  nprPassScene scene(240, 240);
  scene.Pass->SetStyle(style);
  scene.Renderer->SetBackground(0.1, 0.1, 0.1);
  ActorFor(scene.Renderer, Sphere(1), 0.0, 0.0)->GetProperty()->SetColor(0.3, 0.2, 0.1);
  vtkNew<vtkCubeAxesActor> axes;
  axes->SetBounds(-1.0, 1.0, -1.0, 1.0, -1.0, 1.0);
  axes->SetCamera(scene.Camera());
  axes->SetDrawXGridlines(!labels);
  axes->SetDrawYGridlines(!labels);
  axes->SetDrawZGridlines(!labels);
  axes->SetUse2DMode(false);
  for (vtkProperty* lines : { axes->GetXAxesGridlinesProperty(), axes->GetYAxesGridlinesProperty(),
         axes->GetZAxesGridlinesProperty() })
  {
    lines->SetColor(1.0, 1.0, 1.0);
  }
  for (vtkProperty* lines :
    { axes->GetXAxesLinesProperty(), axes->GetYAxesLinesProperty(), axes->GetZAxesLinesProperty() })
  {
    lines->SetColor(0.3, 0.3, 0.3); // not bright: the grid lines or the text alone
  }
  axes->SetXAxisLabelVisibility(labels);
  axes->SetYAxisLabelVisibility(labels);
  axes->SetZAxisLabelVisibility(labels);
  for (int axis = 0; axis < 3; ++axis)
  {
    const double grey = labels ? 1.0 : 0.3;
    axes->GetTitleTextProperty(axis)->SetColor(grey, grey, grey);
    axes->GetLabelTextProperty(axis)->SetColor(grey, grey, grey);
  }
  scene.Renderer->AddActor(axes);
  scene.Camera()->SetPosition(0.5, 0.8, 5.0);
  scene.Camera()->SetFocalPoint(0.0, 0.0, 0.0);
  scene.Camera()->SetViewUp(0.0, 1.0, 0.0);
  scene.Renderer->ResetCamera();
  auto shot = RenderTwice(scene);
  if (const char* dump = std::getenv("NPR_TEST_DUMP"))
  {
    nprWritePNG(shot,
      std::string(dump) + vtkNPRPass::GetStyleName(style) + (labels ? "-labels.png" : "-grid.png"));
  }
  return nprCountAbove(shot, 200);
}

// Pixels whose colour is within 60 (each channel) of rgb (0..255).
long long CountNear(vtkImageData* image, int r, int g, int b)
{
  long long count = 0;
  const int* dims = image->GetDimensions();
  for (int y = 0; y < dims[1]; ++y)
  {
    for (int x = 0; x < dims[0]; ++x)
    {
      count += std::abs(nprPixel(image, x, y, 0) - r) < 60 &&
          std::abs(nprPixel(image, x, y, 1) - g) < 60 && std::abs(nprPixel(image, x, y, 2) - b) < 60
        ? 1
        : 0;
    }
  }
  return count;
}

// What composites with the styled surfaces: a translucent red sphere in front of a flat blue box,
// a GPU ray-cast volume (green), a vtkAxesActor (its X shaft red, Z shaft blue) and a yellow cone
// on a second layer; with and without depth peeling. Returns the image.
vtkSmartPointer<vtkImageData> Composited(int style, bool peeling)
{
  nprPassScene scene(300, 200);
  scene.Pass->SetStyle(style);
  scene.Renderer->SetUseDepthPeeling(peeling);
  scene.Renderer->SetMaximumNumberOfPeels(8);
  scene.Renderer->SetOcclusionRatio(0.0);
  vtkNew<vtkPlaneSource> box;
  box->SetOrigin(-1.6, -0.6, -0.5);
  box->SetPoint1(-0.4, -0.6, -0.5);
  box->SetPoint2(-1.6, 0.6, -0.5);
  box->Update();
  auto blue = ActorFor(scene.Renderer, box->GetOutput(), 0.0, 0.0);
  blue->GetProperty()->SetColor(0.0, 0.0, 1.0);
  blue->GetProperty()->LightingOff();
  auto glass = ActorFor(scene.Renderer, Sphere(1), -1.0, 0.0);
  glass->GetProperty()->SetColor(1.0, 0.0, 0.0);
  glass->GetProperty()->SetOpacity(0.5);
  glass->GetProperty()->LightingOff();

  vtkNew<vtkImageData> field;
  field->SetDimensions(16, 16, 16);
  field->SetSpacing(0.05, 0.05, 0.05);
  field->SetOrigin(0.6, -0.4, -0.4);
  field->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
  std::fill_n(static_cast<unsigned char*>(field->GetScalarPointer()), 16 * 16 * 16, 200);
  vtkNew<vtkGPUVolumeRayCastMapper> volumeMapper;
  volumeMapper->SetInputData(field);
  vtkNew<vtkColorTransferFunction> green;
  green->AddRGBPoint(0.0, 0.0, 1.0, 0.0);
  green->AddRGBPoint(255.0, 0.0, 1.0, 0.0);
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0.0, 1.0);
  opacity->AddPoint(255.0, 1.0);
  vtkNew<vtkVolume> volume;
  volume->SetMapper(volumeMapper);
  volume->GetProperty()->SetColor(green);
  volume->GetProperty()->SetScalarOpacity(opacity);
  volume->GetProperty()->ShadeOff();
  scene.Renderer->AddVolume(volume);

  vtkNew<vtkAxesActor> axes;
  axes->SetTotalLength(0.8, 0.8, 0.8);
  axes->AxisLabelsOff();
  vtkNew<vtkTransform> place;
  place->Translate(-0.2, -0.9, 0.0);
  axes->SetUserTransform(place);
  scene.Renderer->AddActor(axes);

  vtkNew<vtkConeSource> cone;
  cone->SetCenter(0.1, 0.6, 0.0);
  cone->SetRadius(0.25);
  cone->SetHeight(0.5);
  cone->Update();
  auto yellow = ActorFor(scene.AddOverlay(), cone->GetOutput(), 0.0, 0.0);
  yellow->GetProperty()->SetColor(1.0, 1.0, 0.0);
  yellow->GetProperty()->LightingOff();

  scene.LookAtOrigin(5.0);
  scene.Camera()->ParallelProjectionOn();
  scene.Camera()->SetParallelScale(1.1);
  auto shot = RenderTwice(scene);
  if (const char* dump = std::getenv("NPR_TEST_DUMP"))
  {
    nprWritePNG(shot,
      std::string(dump) + vtkNPRPass::GetStyleName(style) +
        (peeling ? "-peeled.png" : "-layers.png"));
  }
  return shot;
}

// Each composited kind keeps, within 15 %, the pixels of its colour it has in the shaded style.
void CompositedKinds()
{
  struct Kind
  {
    const char* Name;
    int Color[3];
  };
  for (bool peeling : { false, true })
  {
    auto plain = Composited(vtkNPRPass::SHADED, peeling);
    auto styled = Composited(Style, peeling);
    // The blend VTK makes of the translucent sphere over the box (at the sphere's centre: the
    // view is 2.2 units high, 200 px, centred on the origin).
    const int blendX = 150 - 100 / 1.1, blendY = 100;
    const Kind kinds[] = { { "translucent red over blue",
                             { nprPixel(plain, blendX, blendY, 0),
                               nprPixel(plain, blendX, blendY, 1),
                               nprPixel(plain, blendX, blendY, 2) } },
      { "green volume", { 0, 255, 0 } }, { "axes' red shaft", { 255, 0, 0 } },
      { "yellow cone on layer 1", { 255, 255, 0 } } };
    for (const Kind& kind : kinds)
    {
      const long long expected = CountNear(plain, kind.Color[0], kind.Color[1], kind.Color[2]);
      const long long got = CountNear(styled, kind.Color[0], kind.Color[1], kind.Color[2]);
      std::cout << kind.Name << (peeling ? " (peeled)" : "") << ": " << got << " pixels, "
                << expected << " shaded\n";
      NPR_CHECK(expected > 40, kind.Name << " not drawn in the shaded style");
      NPR_CHECK(got > 0.85 * expected && got < 1.15 * expected,
        kind.Name << ": " << got << " pixels instead of " << expected);
    }
  }
}

// Dark (line) pixels of a light sphere drawn through a vtkDataSetMapper (PyVista's mapper for every
// data set) or a vtkPolyDataMapper.
long long SphereLinePixels(bool dataSetMapper)
{
  nprPassScene scene(160, 160);
  scene.Pass->SetStyle(Style);
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(32);
  sphere->SetPhiResolution(16);
  vtkSmartPointer<vtkMapper> mapper;
  if (dataSetMapper)
  {
    mapper = vtkSmartPointer<vtkDataSetMapper>::New();
  }
  else
  {
    mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  }
  mapper->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(1.0, 0.9, 0.7);
  actor->GetProperty()->SetAmbient(0.6);
  scene.Renderer->AddActor(actor);
  scene.Renderer->ResetCamera();
  auto shot = RenderTwice(scene);
  return static_cast<long long>(shot->GetNumberOfPoints()) - nprCountAbove(shot, 60);
}

int RunStyle()
{
  EveryKind();
  LineLooks();
  CompositedKinds();
  // A vtkDataSetMapper gets the same lines (or ink) as a vtkPolyDataMapper.
  const long long polyData = SphereLinePixels(false), dataSet = SphereLinePixels(true);
  std::cout << "sphere lines: " << dataSet << " dark pixels through a vtkDataSetMapper, "
            << polyData << " through a vtkPolyDataMapper\n";
  NPR_CHECK(std::abs(dataSet - polyData) <= polyData / 10 + 5,
    "vtkDataSetMapper: " << dataSet << " dark pixels instead of " << polyData);
  // The grid lines and the 3D labels stay white and thin: as many bright pixels as without the
  // pass's style (no lines traced along them, no toon bands, nothing darkened).
  for (bool labels : { false, true })
  {
    const char* what = labels ? "labels" : "grid lines";
    const long long plain = CubeAxesPixels(vtkNPRPass::SHADED, labels);
    const long long styled = CubeAxesPixels(Style, labels);
    std::cout << what << ": " << styled << " bright pixels, " << plain << " shaded\n";
    NPR_CHECK(plain > 200, "no " << what << " drawn");
    NPR_CHECK(styled > 0.9 * plain && styled < 1.1 * plain,
      what << ": " << styled << " bright pixels instead of " << plain);
  }
  // Warnings count too: a pass that handles these scenes has nothing to say about them.
  auto* output = nprCountingOutputWindow::SafeDownCast(vtkOutputWindow::GetInstance());
  NPR_CHECK(
    output && output->Warnings == 0, (output ? output->Warnings : -1) << " VTK warnings reported");
  return nprTestResult();
}
}

int main(int argc, char* argv[])
{
  std::map<std::string, std::function<int()>> cases;
  for (int style = vtkNPRPass::SHADED; style <= vtkNPRPass::INKED; ++style)
  {
    std::string name = vtkNPRPass::GetStyleName(style);
    std::replace(name.begin(), name.end(), '+', '-');
    cases[name] = [style]
    {
      Style = style;
      return RunStyle();
    };
  }
  cases["failure"] = Failure;
  return nprRunTestCase(argc, argv, cases);
}
