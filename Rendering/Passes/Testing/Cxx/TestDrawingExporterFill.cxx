// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// Part of the TestDrawingExporter program: vector figures with filled faces (FillFaces), the file
// rasterised by rsvg-convert against the render, away from the lines and the faces' borders:
// - SURFACE_COLORS against VTK's own unlit render of a block, a pin through it and a sphere
//   through both (the depth order where surfaces cross);
// - FACE_COLOR against the drawing style's render of the same scene, lines and hidden lines on;
//   without FillFaces the faces are not there (the comparison can fail); an outline box is
//   written as strokes of its colour (class npr-line), not where the image is embedded;
// - TOON_BANDS against the toon style's render of flat faces (a cube and a faceted sphere).
//
// usage: TestDrawingExporter fill|fill-toon [DATA_DIR]
#include "TestDrawingExporter.h"
#include "nprTestImages.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCubeSource.h"
#include "vtkCylinderSource.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkNPRDrawingExporter.h"
#include "vtkNPRDrawingPass.h"
#include "vtkNPREdgePass.h"
#include "vtkNPRPass.h"
#include "vtkOutlineSource.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>

namespace
{
using namespace nprDrawingExporter;
constexpr int Width = 400, Height = 300;

void AddUnlit(vtkRenderer* renderer, vtkAlgorithm* source, double r, double g, double b)
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(source->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(r, g, b);
  actor->GetProperty()->SetAmbient(1.0); // flat, as SURFACE_COLORS fills
  actor->GetProperty()->SetDiffuse(0.0);
  actor->GetProperty()->SetSpecular(0.0);
  renderer->AddActor(actor);
}

// A block, a pin through it and a sphere through both, seen from above at an angle.
void BuildScene(vtkRenderer* renderer)
{
  vtkNew<vtkCubeSource> block;
  block->SetXLength(2.0);
  block->SetYLength(1.0);
  block->SetZLength(0.5);
  AddUnlit(renderer, block, 0.9, 0.2, 0.2);
  vtkNew<vtkCylinderSource> pin; // along y: through the block's thin side when seen from +z
  pin->SetRadius(0.2);
  pin->SetHeight(1.6);
  pin->SetResolution(64);
  pin->SetCenter(-0.4, 0.0, 0.0);
  AddUnlit(renderer, pin, 0.2, 0.8, 0.2);
  vtkNew<vtkSphereSource> sphere;
  sphere->SetRadius(0.6);
  sphere->SetCenter(0.9, 0.2, -0.1);
  sphere->SetThetaResolution(48);
  sphere->SetPhiResolution(24);
  AddUnlit(renderer, sphere, 0.2, 0.3, 0.9);
  renderer->SetBackground(0.2, 0.3, 0.4);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(3.0, 4.0, 5.0);
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  camera->SetViewUp(0.0, 1.0, 0.0);
  renderer->ResetCamera();
  camera->Zoom(1.2);
}

// The share of the render's inner pixels (a 5 x 5 square of one colour about them: away from
// lines and borders) whose colour in `file` differs by more than 8 of 255 in a channel.
double DifferingShare(vtkImageData* render, vtkImageData* file, int& inner)
{
  inner = 0;
  int differing = 0;
  const int rc = render->GetNumberOfScalarComponents(), fc = file->GetNumberOfScalarComponents();
  const auto* r = static_cast<const unsigned char*>(render->GetScalarPointer());
  const auto* f = static_cast<const unsigned char*>(file->GetScalarPointer());
  for (int y = 2; y < Height - 2; ++y)
  {
    for (int x = 2; x < Width - 2; ++x)
    {
      const unsigned char* p = r + rc * (y * Width + x);
      bool uniform = true;
      for (int dy = -2; dy <= 2 && uniform; ++dy)
      {
        for (int dx = -2; dx <= 2 && uniform; ++dx)
        {
          const unsigned char* q = r + rc * ((y + dy) * Width + x + dx);
          uniform = std::equal(p, p + 3, q);
        }
      }
      if (!uniform)
      {
        continue;
      }
      ++inner;
      const unsigned char* q = f + fc * (y * Width + x);
      int worst = 0;
      for (int c = 0; c < 3; ++c)
      {
        worst = std::max(worst, std::abs(int(p[c]) - int(q[c])));
      }
      differing += worst > 8 ? 1 : 0;
    }
  }
  return inner ? static_cast<double>(differing) / inner : 1.0;
}

// Writes the renderer's drawing with the exporter's fill settings and compares it with `render`.
double ExportAndCompare(
  vtkRenderer* renderer, vtkImageData* render, bool fill, int colors, const std::string& name)
{
  vtkNew<vtkNPRDrawingExporter> exporter;
  exporter->SetRenderer(renderer);
  exporter->SetEmbedImage(0);
  exporter->SetFillFaces(fill);
  exporter->SetFillColors(colors);
  const std::string svg = nprTestOutputPath(name);
  exporter->SetFileName(svg.c_str());
  NPR_CHECK(exporter->Write(), "write: " << exporter->GetErrorMessage());
  NPR_CHECK(fill == (exporter->GetNumberOfFilledFaces() > 0),
    exporter->GetNumberOfFilledFaces() << " faces filled");
  vtkSmartPointer<vtkImageData> file = Rasterise(svg, Width, Height);
  if (!file || !render)
  {
    return 1.0;
  }
  int inner = 0;
  const double share = DifferingShare(render, file, inner);
  std::cout << name << ": " << exporter->GetNumberOfFilledFaces() << " polygons, "
            << exporter->GetNumberOfStrokes() << " strokes; " << 100.0 * share << " % of " << inner
            << " inner pixels differ from the render\n";
  return share;
}

int Fill()
{
  // SURFACE_COLORS against VTK's own render, unlit, with no lines in the file.
  vtkSmartPointer<vtkRenderWindow> window = nprCreateTestWindow(Width, Height, nullptr);
  vtkNew<vtkRenderer> plain;
  window->AddRenderer(plain);
  BuildScene(plain);
  window->Render();
  vtkSmartPointer<vtkImageData> render = nprCaptureImage(window);
  vtkNew<vtkNPRPass> linesOff; // its edge pass with no line type: a file of faces alone
  linesOff->GetEdgePass()->SetSilhouettes(false);
  linesOff->GetEdgePass()->SetCreases(false);
  plain->SetPass(linesOff);
  const double surface = ExportAndCompare(
    plain, render, true, vtkNPRDrawingExporter::SURFACE_COLORS, "fill_surface_colors.svg");
  plain->SetPass(nullptr);
  NPR_CHECK(surface <= 0.01, 100.0 * surface << " % of the inner pixels differ (1 % allowed)");

  // FACE_COLOR against the drawing style's render, lines and hidden lines on.
  vtkSmartPointer<vtkRenderWindow> drawingWindow = nprCreateTestWindow(Width, Height, nullptr);
  vtkNew<vtkRenderer> drawing;
  drawingWindow->AddRenderer(drawing);
  BuildScene(drawing);
  vtkNew<vtkNPRPass> pass;
  pass->SetStyleToDrawing();
  pass->GetDrawingPass()->HiddenLinesOn();
  pass->GetDrawingPass()->SetFaceColor(0.95, 0.85, 0.5);
  drawing->SetPass(pass);
  drawingWindow->Render();
  render = nprCaptureImage(drawingWindow);
  const double face = ExportAndCompare(
    drawing, render, true, vtkNPRDrawingExporter::FACE_COLOR, "fill_face_color.svg");
  NPR_CHECK(face <= 0.01, 100.0 * face << " % of the inner pixels differ (1 % allowed)");
  const double none =
    ExportAndCompare(drawing, render, false, vtkNPRDrawingExporter::FACE_COLOR, "fill_none.svg");
  NPR_CHECK(none > 0.1, "without FillFaces only " << 100.0 * none << " % differ");

  // The scene's own lines: an outline box, as strokes of its colour where no image is embedded.
  vtkNew<vtkOutlineSource> box;
  box->SetBounds(-1.3, 1.6, -0.9, 0.9, -0.8, 0.6);
  vtkNew<vtkPolyDataMapper> boxMapper;
  boxMapper->SetInputConnection(box->GetOutputPort());
  vtkNew<vtkActor> outline;
  outline->SetMapper(boxMapper);
  outline->GetProperty()->SetColor(0.0, 0.0, 1.0);
  drawing->AddActor(outline);
  drawingWindow->Render();
  for (int embed : { 0, 1 })
  {
    vtkNew<vtkNPRDrawingExporter> exporter;
    exporter->SetRenderer(drawing);
    exporter->SetEmbedImage(embed);
    const std::string svg = nprTestOutputPath("fill_outline.svg");
    exporter->SetFileName(svg.c_str());
    NPR_CHECK(exporter->Write(), "write: " << exporter->GetErrorMessage());
    const std::string text = ReadFile(svg);
    const vtkIdType lines = exporter->GetNumberOfStrokes(6);
    std::cout << "outline, image " << embed << ": " << lines << " line strokes\n";
    NPR_CHECK(embed ? lines == 0
                    : lines >= 4 && text.find("<g class=\"npr-line\">") != std::string::npos &&
          (text.find("stroke:rgb(0%,0%,100%)") != std::string::npos ||       // Cairo 1.16
            text.find("stroke=\"rgb(0%, 0%, 100%)\"") != std::string::npos), // 1.18
      (embed ? "line strokes over the image" : "the outline's blue strokes are missing"));
  }
  drawing->SetPass(nullptr);
  return nprTestResult();
}
NPR_TEST_CASE("fill", Fill);

// TOON_BANDS against the toon style's render of flat faces: a turned cube and a faceted sphere
// (no point normals: VTK lights each face with its own normal) under a light from the side.
int FillToon()
{
  vtkSmartPointer<vtkRenderWindow> window = nprCreateTestWindow(Width, Height, nullptr);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  renderer->SetBackground(0.2, 0.3, 0.4);
  vtkNew<vtkCubeSource> cube;
  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(0.7, 0.2, 0.3);
  sphere->SetRadius(0.55);
  sphere->SetThetaResolution(16);
  sphere->SetPhiResolution(8);
  sphere->Update();
  vtkNew<vtkPolyData> faceted;
  faceted->ShallowCopy(sphere->GetOutput());
  faceted->GetPointData()->SetNormals(nullptr);
  for (vtkPolyData* mesh : { static_cast<vtkPolyData*>(nullptr), faceted.Get() })
  {
    vtkNew<vtkPolyDataMapper> mapper;
    if (mesh)
    {
      mapper->SetInputData(mesh);
    }
    else
    {
      mapper->SetInputConnection(cube->GetOutputPort());
    }
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    actor->GetProperty()->SetColor(mesh ? 0.3 : 0.9, mesh ? 0.6 : 0.7, mesh ? 0.9 : 0.3);
    actor->RotateX(mesh ? 0.0 : 30.0);
    actor->RotateY(mesh ? 0.0 : 40.0);
    renderer->AddActor(actor);
  }
  renderer->GetActiveCamera()->Azimuth(20.0);
  renderer->GetActiveCamera()->Elevation(15.0);
  renderer->ResetCamera();
  // A scene light from the side, so that the faces fall into every band.
  renderer->AutomaticLightCreationOff();
  vtkNew<vtkLight> light;
  light->SetLightTypeToSceneLight();
  light->SetPosition(1.0, 0.4, 0.3);
  light->SetFocalPoint(0.0, 0.0, 0.0);
  renderer->AddLight(light);
  vtkNew<vtkNPRPass> pass;
  pass->SetStyleToToon();
  pass->GetEdgePass()->SetSilhouettes(false); // no lines in the file
  pass->GetEdgePass()->SetCreases(false);
  renderer->SetPass(pass);
  window->Render();
  vtkSmartPointer<vtkImageData> render = nprCaptureImage(window);
  const double toon = ExportAndCompare(
    renderer, render, true, vtkNPRDrawingExporter::TOON_BANDS, "fill_toon_bands.svg");
  NPR_CHECK(toon <= 0.01, 100.0 * toon << " % of the inner pixels differ (1 % allowed)");
  const double flat = ExportAndCompare(
    renderer, render, true, vtkNPRDrawingExporter::SURFACE_COLORS, "fill_toon_flat.svg");
  NPR_CHECK(flat > 0.1, "unlit colours match the toon render: " << 100.0 * flat << " % differ");
  renderer->SetPass(nullptr);
  return nprTestResult();
}
NPR_TEST_CASE("fill-toon", FillToon);
}
