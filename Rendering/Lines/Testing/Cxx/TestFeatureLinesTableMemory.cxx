// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// Part of the TestFeatureLinesTable program: the memory vtkNPRFeatureLines's edge table and the
// drawing's tables and occlusion structure hold, in bytes per triangle of a 400x400 sphere.
//
// usage: TestFeatureLinesTable table-memory [DATA_DIR]
#include "nprFeatureLineTesting.h"

#include "vtkActor.h"
#include "vtkNPRDrawingLines.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkSphereSource.h"

#include <iostream>

namespace
{
using namespace nprFeatureLineTesting;

int TableMemory()
{
  auto sphere = nprSphereSource(0.5, 400, 400);
  sphere->Update();
  vtkPolyData* mesh = sphere->GetOutput();
  const double triangles = static_cast<double>(mesh->GetNumberOfPolys());
  auto filter = MakeFilter(AllTypes);
  filter->SetInputData(mesh);
  filter->SetEyePosition(0.0, 0.0, 5.0);
  filter->Update();
  const double table = static_cast<double>(filter->GetAdjacencyMemorySize()) / triangles;

  MaskScene scene(400, 300);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(mesh);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  scene.Renderer->AddActor(actor);
  scene.Renderer->ResetCamera();
  vtkNew<vtkNPRDrawingLines> drawing;
  drawing->SetRenderer(scene.Renderer);
  drawing->SetSize(400, 300);
  drawing->Update();
  const double drawn = static_cast<double>(drawing->GetMemorySize()) / triangles;
  std::cout << triangles << " triangles: the edge table holds " << table
            << " bytes a triangle, the drawing's tables and occlusion structure " << drawn << "\n";
  // About 40 and 75 (Documentation/drawing.md); the tables before them held over 290.
  NPR_CHECK(table > 20.0 && table <= 44.0, table << " bytes a triangle in the edge table");
  NPR_CHECK(drawn > table && drawn <= 84.0, drawn << " bytes a triangle for the drawing");
  NPR_CHECK(drawing->GetNumberOfStrokes() > 0, "no strokes");
  return nprTestResult();
}
NPR_TEST_CASE("table-memory", TableMemory);
}
