// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// Ordinary VTK scenes under every style (issue 19), part of the TestSceneMatrix program: line
// primitives keep their colour and width; a shader replacement that breaks the passes' code
// (the failure case); cube axes' grid lines and labels.
//
// usage: TestSceneMatrix STYLE [DATA_DIR]   (STYLE: see TestSceneMatrix.cxx)
#include "TestSceneMatrix.h"

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

namespace nprSceneMatrix
{
// A 1-px black outline (a flat box seen head-on) around a sphere, and a 1-px white line over a
// grey plane: the line primitives keep their colour and width.
void LineLooks(int style)
{
  nprPassScene scene(200, 200);
  scene.Pass->SetStyle(style);
  vtkRenderer* renderer = scene.Renderer;
  auto sphere = nprSphereSource(0.3, 32, 16);
  sphere->SetCenter(0.0, 0.3, 0.0);
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
  UnlitActor(renderer, outline->GetOutput(), 0.0, 0.0, 0.0);
  // A grey plane below with a white line in front of it (a grid line over a surface).
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-0.9, -0.8, -0.1);
  plane->SetPoint1(0.9, -0.8, -0.1);
  plane->SetPoint2(-0.9, -0.3, -0.1);
  plane->Update();
  auto grey = UnlitActor(renderer, plane->GetOutput(), 0.3, 0.3, 0.3);
  vtkNew<vtkLineSource> line;
  line->SetPoint1(-0.6, -0.55, 0.0);
  line->SetPoint2(0.6, -0.55, 0.0);
  line->Update();
  UnlitActor(renderer, line->GetOutput(), 1.0, 1.0, 1.0);
  scene.LookAtOrigin(4.0);
  scene.ViewParallel(1.0);
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
NPR_TEST_CASE("failure", Failure);

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
    nprSavePNG(shot,
      std::string(dump) + vtkNPRPass::GetStyleName(style) + (labels ? "-labels.png" : "-grid.png"));
  }
  return nprCountAbove(shot, 200);
}
}
