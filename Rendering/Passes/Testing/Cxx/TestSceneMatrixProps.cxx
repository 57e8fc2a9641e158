// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// Ordinary VTK scenes under every style (issue 19), part of the TestSceneMatrix program: every
// kind of prop in one scene.
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
namespace
{
// Spheres with point, cell or no normals; one as wireframe, one as points.
void AddSpheres(vtkRenderer* renderer)
{
  ActorFor(renderer, Sphere(1), -1.0, 1.0);
  ActorFor(renderer, Sphere(2), 0.0, 1.0);
  ActorFor(renderer, Sphere(0), 1.0, 1.0);
  ActorFor(renderer, Sphere(1), 2.0, 1.0)->GetProperty()->SetRepresentationToWireframe();
  auto points = ActorFor(renderer, Sphere(1), 2.0, 0.0);
  points->GetProperty()->SetRepresentationToPoints();
  points->GetProperty()->SetPointSize(4);
}

// Lines and vertices of their own, and a tube around them: polygons, so styled (vtkTubeFilter).
void AddStrokes(vtkRenderer* renderer)
{
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
  vtkNew<vtkTubeFilter> tube;
  tube->SetInputData(strokes);
  tube->SetRadius(0.03);
  tube->SetNumberOfSides(8);
  tube->Update();
  ActorFor(renderer, tube->GetOutput(), 0.0, 0.3);
}

// An isosurface inside its outline.
void AddIsosurface(vtkRenderer* renderer)
{
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
}

// Glyphs and an image actor.
void AddGlyphsAndImage(vtkRenderer* renderer)
{
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
}

// Text, flat and in the scene, a scalar bar, and cube axes with grid lines and 3D labels.
void AddAnnotations(vtkRenderer* renderer, vtkCamera* camera)
{
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
  vtkNew<vtkCubeAxesActor> axes;
  axes->SetBounds(-1.5, 2.5, -1.5, 1.5, -0.5, 0.5);
  axes->SetCamera(camera);
  axes->DrawXGridlinesOn();
  axes->DrawYGridlinesOn();
  axes->DrawZGridlinesOn();
  axes->SetUse2DMode(false);
  renderer->AddActor(axes);
}
}

// Every kind of prop in one scene: nothing reported, nothing crashes, something drawn.
void EveryKind(int style)
{
  nprPassScene scene(360, 280);
  scene.Pass->SetStyle(style);
  vtkRenderer* renderer = scene.Renderer;
  AddSpheres(renderer);
  AddStrokes(renderer);
  AddIsosurface(renderer);
  AddGlyphsAndImage(renderer);
  AddAnnotations(renderer, scene.Camera());
  renderer->ResetCamera();
  auto shot = RenderTwice(scene);
  if (const char* dump = std::getenv("NPR_TEST_DUMP")) // a look at the scene
  {
    nprSavePNG(shot, std::string(dump) + vtkNPRPass::GetStyleName(style) + ".png");
  }
  const double white[3] = { 1, 1, 1 };
  const nprPixelStatistics stats = nprComputePixelStatistics(shot, white);
  std::cout << "every kind: " << stats.ObjectPixels << " object pixels\n";
  NPR_CHECK(stats.ObjectPixels > 2000, "the scene was not drawn");
}
}
