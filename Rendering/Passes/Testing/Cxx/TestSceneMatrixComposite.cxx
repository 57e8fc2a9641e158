// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// Ordinary VTK scenes under every style (issue 19), part of the TestSceneMatrix program: what
// composites with the styled surfaces (translucency, a volume, axes, a second layer), and a
// vtkDataSetMapper's lines.
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
  UnlitActor(scene.Renderer, box->GetOutput(), 0.0, 0.0, 1.0);
  auto glass = ActorFor(scene.Renderer, Sphere(1), -1.0, 0.0);
  glass->GetProperty()->SetColor(1.0, 0.0, 0.0);
  glass->GetProperty()->SetOpacity(0.5);
  glass->GetProperty()->LightingOff();

  const double fieldOrigin[3] = { 0.6, -0.4, -0.4 }, spacing[3] = { 0.05, 0.05, 0.05 };
  const double green[3] = { 0, 1, 0 };
  nprAddBlockVolume(scene.Renderer, fieldOrigin, spacing, green);

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
  UnlitActor(scene.AddOverlay(), cone->GetOutput(), 1.0, 1.0, 0.0);

  scene.LookAtOrigin(5.0);
  scene.ViewParallel(1.1);
  auto shot = RenderTwice(scene);
  if (const char* dump = std::getenv("NPR_TEST_DUMP"))
  {
    nprSavePNG(shot,
      std::string(dump) + vtkNPRPass::GetStyleName(style) +
        (peeling ? "-peeled.png" : "-layers.png"));
  }
  return shot;
}

// Each composited kind keeps, within 15 %, the pixels of its colour it has in the shaded style.
void CompositedKinds(int style)
{
  struct Kind
  {
    const char* Name;
    int Color[3];
  };
  for (bool peeling : { false, true })
  {
    auto plain = Composited(vtkNPRPass::SHADED, peeling);
    auto styled = Composited(style, peeling);
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
long long SphereLinePixels(int style, bool dataSetMapper)
{
  nprPassScene scene(160, 160);
  scene.Pass->SetStyle(style);
  auto sphere = nprSphereSource(0.5, 32, 16);
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
}
