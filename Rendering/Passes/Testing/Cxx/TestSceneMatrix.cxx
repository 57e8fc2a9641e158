// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// Ordinary VTK scenes under every style (issue 19): polygons with point, cell and no normals,
// lines, points, a wireframe, tubes, an outline around an isosurface, cube axes with grid lines and
// labels, text, a scalar bar, glyphs, an image actor, a vtkAxesActor, a volume, a translucent actor
// with and without depth peeling and two layers. Fails on any VTK error or warning and on a crash;
// checks that lines and annotations keep their own look: a white line stays white, a 1-px outline
// stays about 1 px wide, white grid lines and 3D labels stay white, and the translucent blend, the
// volume, the axes and the second layer keep their colours.
// This file runs each style's checks, which live in TestSceneMatrixProps.cxx,
// TestSceneMatrixLooks.cxx and TestSceneMatrixComposite.cxx.
//
// usage: TestSceneMatrix STYLE [DATA_DIR]   (STYLE: a vtkNPRPass style name, '+' written
// '-', or failure)
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
vtkSmartPointer<vtkActor> ActorFor(vtkRenderer* renderer, vtkPolyData* data, double x, double y)
{
  const double tan[3] = { 0.8, 0.6, 0.4 };
  vtkSmartPointer<vtkActor> actor = nprAddMesh(renderer, data, tan);
  actor->SetPosition(x, y, 0.0);
  return actor;
}

vtkSmartPointer<vtkActor> UnlitActor(
  vtkRenderer* renderer, vtkPolyData* data, double red, double green, double blue)
{
  vtkSmartPointer<vtkActor> actor = ActorFor(renderer, data, 0.0, 0.0);
  actor->GetProperty()->SetColor(red, green, blue);
  actor->GetProperty()->LightingOff();
  return actor;
}

vtkSmartPointer<vtkPolyData> Sphere(int normals) // 0 none, 1 point, 2 cell
{
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->DeepCopy(nprSphere(0.4, 16, 8));
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

vtkSmartPointer<vtkImageData> RenderTwice(nprPassScene& scene)
{
  scene.Render();
  return scene.Render();
}

int RunStyle(int style)
{
  EveryKind(style);
  LineLooks(style);
  CompositedKinds(style);
  // A vtkDataSetMapper gets the same lines (or ink) as a vtkPolyDataMapper.
  const long long polyData = SphereLinePixels(style, false),
                  dataSet = SphereLinePixels(style, true);
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
    const long long styled = CubeAxesPixels(style, labels);
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
// A case per style, named as the style with '+' written '-' (toon+edges: toon-edges).
const bool StyleCasesRegistered = []
{
  for (int style = vtkNPRPass::SHADED; style <= vtkNPRPass::INKED; ++style)
  {
    std::string name = vtkNPRPass::GetStyleName(style);
    std::replace(name.begin(), name.end(), '+', '-');
    nprTestCase(name, [style] { return RunStyle(style); });
  }
  return true;
}();
}
