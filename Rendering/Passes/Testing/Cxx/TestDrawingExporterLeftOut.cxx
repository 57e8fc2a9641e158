// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// Part of the TestDrawingExporter program: the 3D props a vector figure without the window's
// image cannot draw are counted and named in one warning: a translucent actor (also inside an
// assembly), an actor of an unstructured grid, a volume and glyphs of vtkGlyph3DMapper; an opaque
// mesh, a hidden volume and a 2D text are not. With the window's image embedded nothing is left
// out and nothing is reported.
//
// usage: TestDrawingExporter left-out [DATA_DIR]
#include "TestDrawingExporter.h"

#include "vtkActor.h"
#include "vtkAppendFilter.h"
#include "vtkAssembly.h"
#include "vtkDataSetMapper.h"
#include "vtkGPUVolumeRayCastMapper.h"
#include "vtkGlyph3DMapper.h"
#include "vtkImageData.h"
#include "vtkNPRDrawingExporter.h"
#include "vtkNPRDrawingLines.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"
#include "vtkTextActor.h"
#include "vtkVolume.h"

#include <map>
#include <string>

namespace
{
using namespace nprDrawingExporter;

vtkSmartPointer<vtkActor> SphereActor(const double centre[3], double opacity)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(centre[0], centre[1], centre[2]);
  sphere->SetRadius(0.4);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(sphere->GetOutputPort());
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetOpacity(opacity);
  return actor;
}

vtkSmartPointer<vtkVolume> SmallVolume(bool visible)
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(4, 4, 4);
  image->SetOrigin(2.0, 0.0, 0.0);
  image->SetSpacing(0.2, 0.2, 0.2);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
  vtkNew<vtkGPUVolumeRayCastMapper> mapper;
  mapper->SetInputData(image);
  auto volume = vtkSmartPointer<vtkVolume>::New();
  volume->SetMapper(mapper);
  volume->SetVisibility(visible);
  return volume;
}

// Two opaque spheres (one in an assembly), which the figure draws, and the props it cannot
// draw: two translucent spheres (one in the assembly), an unstructured grid, glyphs and a volume;
// besides them a hidden volume and a 2D text, which it does not report.
void AddPropsOfEveryKind(vtkRenderer* renderer)
{
  const double origin[3] = { 0, 0, 0 }, right[3] = { 1, 0, 0 }, up[3] = { 0, 1, 0 },
               down[3] = { 0, -1, 0 };
  renderer->AddActor(SphereActor(origin, 1.0)); // drawn
  renderer->AddActor(SphereActor(right, 0.5));  // translucent
  vtkNew<vtkAssembly> assembly;                 // one part drawn, one translucent
  assembly->AddPart(SphereActor(up, 1.0));
  assembly->AddPart(SphereActor(down, 0.3));
  renderer->AddActor(assembly);
  vtkNew<vtkSphereSource> sphere;
  vtkNew<vtkAppendFilter> grid; // an unstructured grid through a vtkDataSetMapper
  grid->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkDataSetMapper> gridMapper;
  gridMapper->SetInputConnection(grid->GetOutputPort());
  vtkNew<vtkActor> gridActor;
  gridActor->SetMapper(gridMapper);
  gridActor->SetPosition(-1.0, 0.0, 0.0);
  renderer->AddActor(gridActor);
  vtkNew<vtkGlyph3DMapper> glyphs;
  glyphs->SetInputConnection(sphere->GetOutputPort());
  glyphs->SetSourceConnection(sphere->GetOutputPort());
  glyphs->SetScaleFactor(0.05);
  vtkNew<vtkActor> glyphActor;
  glyphActor->SetMapper(glyphs);
  glyphActor->SetPosition(0.0, 0.0, 1.0);
  renderer->AddActor(glyphActor);
  renderer->AddVolume(SmallVolume(true));
  renderer->AddVolume(SmallVolume(false)); // hidden: not reported
  vtkNew<vtkTextActor> text;               // 2D: the overlays'
  text->SetInput("caption");
  renderer->AddActor2D(text);
}

int LeftOut()
{
  auto* output = nprCountingOutputWindow::SafeDownCast(vtkOutputWindow::GetInstance());
  vtkSmartPointer<vtkRenderWindow> window = nprCreateTestWindow(320, 240, nullptr);
  NPR_CHECK(window, "no window");
  if (!window)
  {
    return nprTestResult();
  }
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  AddPropsOfEveryKind(renderer);
  renderer->ResetCamera();
  window->Render();

  vtkNew<vtkNPRDrawingExporter> exporter;
  exporter->SetRenderer(renderer);
  exporter->SetEmbedImage(0);
  exporter->SetFileName(nprTestOutputPath("left-out.svg").c_str());
  const int warnings = output ? output->Warnings : 0;
  NPR_CHECK(exporter->Write(), "write: " << exporter->GetErrorMessage());
  NPR_CHECK(exporter->GetNumberOfPropsLeftOut() == 5,
    exporter->GetNumberOfPropsLeftOut() << " props left out, expected 5");
  std::map<std::string, int> kinds;
  vtkNPRDrawingLines* lines = exporter->GetDrawingLines();
  for (vtkIdType i = 0; i < lines->GetNumberOfPropsLeftOut(); ++i)
  {
    std::cout << "left out: " << lines->GetPropLeftOut(i) << "\n";
    ++kinds[lines->GetPropLeftOut(i)];
  }
  NPR_CHECK(lines->GetPropLeftOut(lines->GetNumberOfPropsLeftOut()) == nullptr,
    "a description past the last");
  // The classes as made, not as VTK's object factory overrides them (vtkOpenGLActor).
  const std::map<std::string, int> expected = { { "translucent vtkActor", 2 },
    { "vtkActor of a vtkUnstructuredGrid", 1 }, { "vtkActor drawn by vtkGlyph3DMapper", 1 },
    { "vtkVolume", 1 } };
  NPR_CHECK(kinds == expected, "the props left out are not the expected ones");
  NPR_CHECK(exporter->GetNumberOfStrokes() > 0, "the opaque spheres have no lines");
  if (output)
  {
    NPR_CHECK(output->Warnings == warnings + 1, "one warning naming them");
    output->Warnings = warnings; // expected
  }

  // The window's image under the lines shows them: nothing left out, nothing said.
  exporter->SetEmbedImage(1);
  NPR_CHECK(exporter->Write(), "write with the image: " << exporter->GetErrorMessage());
  NPR_CHECK(exporter->GetNumberOfPropsLeftOut() == 0,
    exporter->GetNumberOfPropsLeftOut() << " props left out with the image embedded");
  NPR_CHECK(!output || output->Warnings == warnings, "a warning with the image embedded");
  return nprTestResult();
}
NPR_TEST_CASE("left-out", LeftOut);
}
