// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// Line weights along depth and along strokes (issue 37), measured in pixels as the ink across a
// line (its coverage summed along a row that crosses it):
// - depth: two squares side by side under a parallel camera, one at the near end of the clipping
//   range and one at the far end; with DepthFalloff (near scale 2, far 0.5, 4 px lines) the
//   near square's outline is 8 px and the far one's 2 px: the drawing's strokes to 0.2 px, the
//   edges style's outline 1.985 and 0.515 times its plain width within 10 %;
//   without it, both alike;
// - taper: the drawing's crease along a roof's ridge (an open stroke, 4 px, TaperLength 40): full
//   width in its middle, a quarter of it 10 px from an end; without a taper, full width there;
// - curvature: with CurvatureWidth 1 the straight ridge keeps its width and the roof outline's
//   corners (full bends) are wider.
//
// usage: TestLineWeightsDepth depth|taper
#include "nprTestImages.h"
#include "nprTestMeshes.h"
#include "nprTesting.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkImageData.h"
#include "vtkNPRDrawingPass.h"
#include "vtkNPREdgePass.h"
#include "vtkNPRPass.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include <array>
#include <cmath>

namespace
{
void AddMesh(vtkRenderer* renderer, vtkPolyData* mesh)
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(mesh);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  renderer->AddActor(actor);
}

// The ink (1 - red / 255 summed) in the box [x0, x1) x [y0, y1) of an image on a white ground.
double InkIn(vtkImageData* image, int x0, int x1, int y0, int y1)
{
  const int width = image->GetDimensions()[0];
  const int components = image->GetNumberOfScalarComponents();
  const auto* rgb = static_cast<const unsigned char*>(image->GetScalarPointer());
  double ink = 0.0;
  for (int y = y0; y < y1; ++y)
  {
    for (int x = x0; x < x1; ++x)
    {
      ink += 1.0 - rgb[components * (y * width + x)] / 255.0;
    }
  }
  return ink;
}

// Along row y from x0 to x1; down column x from y0 to y1.
double InkAcross(vtkImageData* image, int y, int x0, int x1)
{
  return InkIn(image, x0, x1, y, y + 1);
}
double InkDown(vtkImageData* image, int x, int y0, int y1)
{
  return InkIn(image, x, x + 1, y0, y1);
}

// Two 2 x 2 squares facing +z, the left at z = 0 (near), the right at z = -10 (far), seen by a
// parallel camera on +z whose clipping range runs from just before z = 0 to just past z = -10:
// 100 px a unit.
struct DepthScene : nprPassScene
{
  DepthScene()
    : nprPassScene(600, 300)
  {
    for (const std::array<double, 2>& at : { std::array<double, 2>{ -1.2, 0.0 }, { 1.2, -10.0 } })
    {
      vtkNew<vtkPlaneSource> square;
      square->SetOrigin(at[0] - 1.0, -1.0, at[1]);
      square->SetPoint1(at[0] + 1.0, -1.0, at[1]);
      square->SetPoint2(at[0] - 1.0, 1.0, at[1]);
      square->Update();
      AddMesh(this->Renderer, square->GetOutput());
    }
    nprParallelFromFront(this->Camera(), 1.5, 9.9, 20.1);
    vtkNPREdgePass* edges = this->Edges();
    edges->SetLineWidth(4.0);
    edges->SetNearLineScale(2.0);
    edges->SetFarLineScale(0.5);
    edges->ContoursOff();
  }

  // The ink across each square's left side (x = -2.2 and 0.2: pixels 80 and 320), mid-height.
  void Widths(bool mask, double& nearInk, double& farInk)
  {
    vtkSmartPointer<vtkImageData> image = mask ? this->Mask() : this->Render();
    nearInk = InkAcross(image, 150, 50, 110);
    farInk = InkAcross(image, 150, 290, 350);
    if (mask) // white lines on black
    {
      nearInk = 60.0 - nearInk;
      farInk = 60.0 - farInk;
    }
  }
};

int Depth()
{
  DepthScene scene;
  double nearInk, farInk;
  // The drawing's strokes: exact widths.
  scene.Pass->SetStyleToDrawing();
  scene.Widths(false, nearInk, farInk);
  std::cout << "drawing, no falloff: " << nearInk << " px near, " << farInk << " px far\n";
  NPR_CHECK(std::abs(nearInk - 4.0) < 0.2 && std::abs(farInk - 4.0) < 0.2,
    "without DepthFalloff the outlines are not both 4 px");
  scene.Edges()->DepthFalloffOn();
  scene.Widths(false, nearInk, farInk);
  std::cout << "drawing, falloff: " << nearInk << " px near, " << farInk << " px far\n";
  NPR_CHECK(std::abs(nearInk - 7.94) < 0.2 && std::abs(farInk - 2.06) < 0.2,
    "with DepthFalloff the outlines are not 7.94 px near and 2.06 px far (scales 1.985, 0.515)");
  // The edges style: its level sets of the Gaussian, within 25 %.
  scene.Pass->SetStyleToEdges();
  scene.Edges()->DepthFalloffOff();
  scene.Widths(true, nearInk, farInk);
  std::cout << "edges, no falloff: " << nearInk << " px near, " << farInk << " px far\n";
  NPR_CHECK(std::abs(nearInk - farInk) < 0.1, "without DepthFalloff the outlines differ");
  const double plain = nearInk;
  scene.Edges()->DepthFalloffOn();
  scene.Widths(true, nearInk, farInk);
  std::cout << "edges, falloff: " << nearInk << " px near, " << farInk << " px far ("
            << nearInk / plain << " and " << farInk / plain << " of the plain width)\n";
  NPR_CHECK(std::abs(nearInk / plain - 1.985) < 0.2 && std::abs(farInk / plain - 0.515) < 0.05,
    "with DepthFalloff the outlines are not 1.985 and 0.515 times as wide (10 %)");
  return nprTestResult();
}
NPR_TEST_CASE("depth", Depth);

// A roof: two faces meeting along a ridge on the x axis at 53 degrees (a crease), seen from +z
// under a parallel camera, 100 px a unit: the ridge runs from pixel x 100 to 300 at row 150.
vtkSmartPointer<vtkPolyData> Roof()
{
  vtkNew<vtkPoints> points;
  for (const std::array<double, 3>& p : { std::array<double, 3>{ -1, -1, 0 }, { 1, -1, 0 },
         { 1, 0, 0.5 }, { -1, 0, 0.5 }, { -1, 1, 0 }, { 1, 1, 0 } })
  {
    points->InsertNextPoint(p.data());
  }
  vtkNew<vtkCellArray> faces;
  const vtkIdType a[4] = { 0, 1, 2, 3 }, b[4] = { 3, 2, 5, 4 };
  faces->InsertNextCell(4, a);
  faces->InsertNextCell(4, b);
  auto roof = vtkSmartPointer<vtkPolyData>::New();
  roof->SetPoints(points);
  roof->SetPolys(faces);
  return roof;
}

int Taper()
{
  nprPassScene scene(400, 300);
  AddMesh(scene.Renderer, Roof());
  nprParallelFromFront(scene.Camera(), 1.5, 5.0, 15.0);
  scene.Pass->SetStyleToDrawing();
  scene.Edges()->SetLineWidth(4.0);
  scene.Edges()->ContoursOff();
  vtkNPRDrawingPass* drawing = scene.Pass->GetDrawingPass();
  // The ridge's ink down the columns at its middle and 10 px from its left end.
  auto across = [&](double& middle, double& nearEnd)
  {
    vtkSmartPointer<vtkImageData> image = scene.Render();
    middle = InkDown(image, 200, 130, 170);
    nearEnd = InkDown(image, 110, 130, 170);
  };
  double middle, nearEnd;
  across(middle, nearEnd);
  std::cout << "no taper: " << middle << " px in the middle, " << nearEnd << " px near the end\n";
  NPR_CHECK(std::abs(middle - 4.0) < 0.2 && std::abs(nearEnd - 4.0) < 0.2,
    "without a taper the ridge is not 4 px along its length");
  drawing->SetTaperLength(40.0);
  across(middle, nearEnd);
  std::cout << "taper 40 px: " << middle << " px in the middle, " << nearEnd
            << " px 10 px from the end\n";
  NPR_CHECK(std::abs(middle - 4.0) < 0.2, "the taper thinned the ridge's middle");
  NPR_CHECK(
    std::abs(nearEnd - 1.0) < 0.3, "10 px from its end the ridge is not 1 px (4 x 10 / 40)");
  // Width from curvature: the straight ridge keeps its width; the roof's outline is a square
  // whose corners bend fully.
  drawing->SetTaperLength(0.0);
  drawing->SetCurvatureWidth(1.0);
  across(middle, nearEnd);
  vtkSmartPointer<vtkImageData> image = scene.Render();
  const double corner = InkIn(image, 94, 106, 44, 56); // the outline's corner (-1, -1)
  std::cout << "curvature 1: the ridge " << middle << " px; the outline's corner ink " << corner
            << "\n";
  NPR_CHECK(std::abs(middle - 4.0) < 0.2, "the straight ridge changed width");
  drawing->SetCurvatureWidth(0.0);
  image = scene.Render();
  const double plainCorner = InkIn(image, 94, 106, 44, 56);
  NPR_CHECK(corner > plainCorner + 2.0,
    "the outline's corner is not wider with CurvatureWidth: " << corner << " against "
                                                              << plainCorner);
  return nprTestResult();
}
NPR_TEST_CASE("taper", Taper);
}
