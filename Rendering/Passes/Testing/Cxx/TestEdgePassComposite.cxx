// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// How the edge pass's lines and depth sprite (vtkNPRPass) compose with the rest of a scene: a
// translucent plane in front of the lines tints them and one behind does not, with and without
// depth peeling; a renderer on a higher layer and a volume are depth-tested against the sprite, a
// 2D actor is drawn over everything; picking (prop, world point, hardware selection) works with
// the pass installed.
//
// usage: TestEdgePassComposite CASE [DATA_DIR]   (CASE: the NPR_TEST_CASE names below)
#include "nprTesting.h"

#include "vtkActor.h"
#include "vtkColorTransferFunction.h"
#include "vtkGPUVolumeRayCastMapper.h"
#include "vtkHardwareSelector.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkNPREdgePass.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPlaneSource.h"
#include "vtkPropPicker.h"
#include "vtkProperty.h"
#include "vtkSelection.h"
#include "vtkSelectionNode.h"
#include "vtkTextActor.h"
#include "vtkTextProperty.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"
#include "vtkWorldPointPicker.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <string>

namespace
{
using Scene = nprPassScene;

// ---- A translucent plane in front tints the lines; behind the surface it does not ----
int Translucency()
{
  Scene scene(400, 300);
  const double origin[3] = { 0, 0, 0 };
  nprAddCube(scene.Renderer, origin, 1.0, nprGrey);
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-2, -2, 1);
  plane->SetPoint1(0, -2, 1);
  plane->SetPoint2(-2, 2, 1);
  const double red[3] = { 1, 0, 0 };
  vtkSmartPointer<vtkActor> glass = nprAddActor(scene.Renderer, plane->GetOutputPort(), red);
  glass->GetProperty()->SetOpacity(0.5);
  glass->GetProperty()->LightingOff();
  scene.LookAtOrigin(5);
  scene.Edges()->SetLineWidth(2.0);

  auto lineColumns = [&](vtkImageData* mask, int y, int& first, int& last)
  {
    first = last = -1;
    for (int x = 0; x < 400; ++x)
    {
      if (nprPixel(mask, x, y) == 255)
      {
        first = first < 0 ? x : first;
        last = x;
      }
    }
  };
  for (int depthPeeling = 0; depthPeeling < 2; ++depthPeeling)
  {
    scene.Renderer->SetUseDepthPeeling(depthPeeling);
    glass->SetPosition(0, 0, 0);
    auto mask = scene.Mask();
    auto image = scene.Render();
    int first, last;
    lineColumns(mask, 150, first, last);
    NPR_CHECK(first > 0 && last > first, "no silhouette found on the middle row");
    const int r = nprPixel(image, first, 150, 0), g = nprPixel(image, first, 150, 1);
    const int rr = nprPixel(image, last, 150, 0), rg = nprPixel(image, last, 150, 1);
    std::cout << "peeling " << depthPeeling << ": left line under the glass (" << r << "," << g
              << "), right line (" << rr << "," << rg << ")\n";
    NPR_CHECK(r > 90 && r < 200 && g < 40, "the line under the glass should be tinted red");
    NPR_CHECK(rr < 60 && rg < 60, "the line beside the glass should stay black");
    // Behind the cube, the glass covers the background only.
    glass->SetPosition(0, 0, -2);
    image = scene.Render();
    const int br = nprPixel(image, first, 150, 0);
    NPR_CHECK(br < 60, "glass behind the cube tinted its line: red " << br);
    NPR_CHECK(nprPixel(image, 80, 150, 0) > 200 && nprPixel(image, 80, 150, 1) < 200,
      "the glass behind the cube should still tint the background");
  }
  return nprTestResult();
}
NPR_TEST_CASE("translucency", Translucency);

// ---- A renderer on a higher layer is depth-tested against the sprite ----
int Layers()
{
  Scene scene(400, 300);
  scene.ShowCube(5.0, nprGrey);
  scene.AddSphereBehind();
  auto image = scene.Render();

  const double corner0[3] = { -0.5, -0.5, 0.5 }, corner1[3] = { 0.5, 0.5, 0.5 };
  double a[2], b[2];
  scene.Project(corner0, a);
  scene.Project(corner1, b);
  long long redInside = 0, redOutside = 0;
  for (int y = 0; y < 300; ++y)
  {
    for (int x = 0; x < 400; ++x)
    {
      const bool red = nprIsRed(image, x, y);
      const bool inside = x > a[0] + 3 && x < b[0] - 3 && y > a[1] + 3 && y < b[1] - 3;
      (inside ? redInside : redOutside) += red ? 1 : 0;
    }
  }
  std::cout << "red pixels of the layer-1 sphere: " << redInside << " over the cube, " << redOutside
            << " beside it\n";
  NPR_CHECK(redInside == 0, "the sphere behind the cube shows through it");
  NPR_CHECK(redOutside > 100, "the part of the sphere beside the cube should be drawn");
  return nprTestResult();
}
NPR_TEST_CASE("layers", Layers);

// ---- A volume behind the surface is hidden by it; a 2D actor is drawn over everything ----
int VolumeAndOverlay()
{
  Scene scene(400, 300);
  const double origin[3] = { 0, 0, 0 };
  nprAddCube(scene.Renderer, origin, 1.0, nprGrey);
  // x -0.9..2.1, behind the cube
  const double blockOrigin[3] = { -0.9, -0.75, -3.0 }, spacing[3] = { 0.2, 0.1, 0.1 };
  const double red[3] = { 1, 0, 0 };
  nprAddBlockVolume(scene.Renderer, blockOrigin, spacing, red);
  vtkNew<vtkTextActor> label;
  label->SetInput("NPR");
  label->GetTextProperty()->SetFontSize(40);
  label->GetTextProperty()->SetColor(0, 0, 1);
  label->SetDisplayPosition(10, 10);
  scene.Renderer->AddActor2D(label);
  scene.LookAtOrigin(5);
  auto image = scene.Render();
  const double corner0[3] = { -0.5, -0.5, 0.5 }, corner1[3] = { 0.5, 0.5, 0.5 };
  double a[2], b[2];
  scene.Project(corner0, a);
  scene.Project(corner1, b);
  long long redOver = 0, redBeside = 0, blue = 0;
  for (int y = 0; y < 300; ++y)
  {
    for (int x = 0; x < 400; ++x)
    {
      const int r = nprPixel(image, x, y, 0), g = nprPixel(image, x, y, 1),
                bl = nprPixel(image, x, y, 2);
      const bool inside = x > a[0] + 3 && x < b[0] - 3 && y > a[1] + 3 && y < b[1] - 3;
      if (r > 150 && g < 80 && bl < 80)
      {
        (inside ? redOver : redBeside)++;
      }
      blue += (x < 150 && y < 70 && bl > 150 && r < 80) ? 1 : 0;
    }
  }
  std::cout << "volume: " << redOver << " red pixels over the cube, " << redBeside
            << " beside it; text: " << blue << " blue pixels\n";
  NPR_CHECK(redOver == 0, "the volume behind the cube shows through it");
  NPR_CHECK(redBeside > 1000, "the volume beside the cube should be drawn");
  NPR_CHECK(blue > 100, "the 2D text actor should be drawn");
  return nprTestResult();
}
NPR_TEST_CASE("volume-overlay", VolumeAndOverlay);

// ---- Picking with the pass installed ----
int Picking()
{
  Scene scene(400, 300);
  const double left[3] = { -1, 0, 0 }, right[3] = { 1, 0, 0 };
  vtkSmartPointer<vtkActor> a = nprAddCube(scene.Renderer, left, 1.0, nprGrey);
  vtkSmartPointer<vtkActor> b = nprAddCube(scene.Renderer, right, 1.0, nprGrey);
  scene.LookAtOrigin(5);
  scene.Render();
  const double frontA[3] = { -1, 0, 0.5 }, frontB[3] = { 1, 0, 0.5 };
  double pa[2], pb[2];
  scene.Project(frontA, pa);
  scene.Project(frontB, pb);

  vtkNew<vtkPropPicker> propPicker;
  propPicker->Pick(pa[0], pa[1], 0, scene.Renderer);
  NPR_CHECK(propPicker->GetViewProp() == a, "vtkPropPicker missed the left cube");
  propPicker->Pick(pb[0], pb[1], 0, scene.Renderer);
  NPR_CHECK(propPicker->GetViewProp() == b, "vtkPropPicker missed the right cube");
  propPicker->Pick(5, 5, 0, scene.Renderer);
  NPR_CHECK(propPicker->GetViewProp() == nullptr, "vtkPropPicker picked the background");

  vtkNew<vtkWorldPointPicker> worldPicker;
  worldPicker->Pick(pa[0], pa[1], 0, scene.Renderer);
  const double* world = worldPicker->GetPickPosition();
  std::cout << "world point on the left cube's front face: " << world[0] << " " << world[1] << " "
            << world[2] << "\n";
  NPR_CHECK(std::abs(world[2] - 0.5) < 0.01 && std::abs(world[0] + 1) < 0.02,
    "vtkWorldPointPicker should find the front face at z = 0.5");

  vtkNew<vtkHardwareSelector> selector;
  selector->SetRenderer(scene.Renderer);
  selector->SetArea(0, 0, 399, 299);
  selector->SetFieldAssociation(vtkDataObject::FIELD_ASSOCIATION_CELLS);
  vtkSmartPointer<vtkSelection> selection = vtkSmartPointer<vtkSelection>::Take(selector->Select());
  bool foundA = false, foundB = false;
  for (unsigned int i = 0; selection && i < selection->GetNumberOfNodes(); ++i)
  {
    vtkObjectBase* prop = selection->GetNode(i)->GetProperties()->Get(vtkSelectionNode::PROP());
    foundA = foundA || prop == a;
    foundB = foundB || prop == b;
  }
  NPR_CHECK(foundA && foundB, "vtkHardwareSelector should select both cubes");

  // Lines are still drawn after the selection renders.
  NPR_CHECK(nprCountAbove(scene.Mask(), 127) > 400, "no lines after picking");
  return nprTestResult();
}
NPR_TEST_CASE("picking", Picking);
}
