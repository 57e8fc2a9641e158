// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nprModel.h"

#include "nprTiming.h"

#include "vtkActor.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkNPRModelReader.h"
#include "vtkNPRShadingNormals.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkUnsignedCharArray.h"

#include <iostream>
#include <stdexcept>

vtkSmartPointer<vtkPolyData> nprReadModel(const std::string& path, std::string* warning)
{
  vtkNew<vtkNPRModelReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  if (*reader->GetErrorMessage())
  {
    throw std::runtime_error(reader->GetErrorMessage());
  }
  if (warning)
  {
    *warning = reader->GetWarningMessage();
  }
  return reader->GetOutput();
}

vtkSmartPointer<vtkPolyData> nprPrepareMesh(vtkPolyData* raw)
{
  vtkNew<vtkNPRShadingNormals> normals;
  normals->SetInputData(raw);
  normals->Update();
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->ShallowCopy(normals->GetOutput());
  return mesh;
}

long long nprCountTriangles(vtkPolyData* mesh)
{
  long long triangles = 0;
  for (vtkCellArray* cells : { mesh->GetPolys(), mesh->GetStrips() })
  {
    triangles += cells->GetNumberOfConnectivityIds() - 2 * cells->GetNumberOfCells();
  }
  return triangles;
}

void nprApplyModelLook(vtkProperty* property, size_t index)
{
  static const double palette[][3] = { { 0.85, 0.82, 0.75 }, { 0.55, 0.70, 0.85 },
    { 0.90, 0.60, 0.45 }, { 0.60, 0.80, 0.55 }, { 0.80, 0.65, 0.85 } };
  const double* color = palette[index % (sizeof(palette) / sizeof(palette[0]))];
  property->SetColor(color[0], color[1], color[2]);
  property->SetSpecular(0.2);
  property->SetSpecularPower(30.0);
}

long long nprAddModel(vtkRenderer* renderer, const std::string& path, size_t index,
  const std::string& program, nprProgress* progress)
{
  std::string warning;
  if (progress)
  {
    progress->Start();
  }
  vtkSmartPointer<vtkPolyData> model = nprReadModel(path, &warning);
  const long long triangles = nprCountTriangles(model);
  if (progress)
  {
    progress->Done("read " + path + " (" + std::to_string(triangles) + " triangles)");
  }
  if (!warning.empty())
  {
    std::cerr << program << ": warning: " << warning << "\n";
  }
  if (progress)
  {
    progress->Start();
  }
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(nprPrepareMesh(model));
  if (progress)
  {
    progress->Done("normals of " + path);
  }
  // Colours stored in the file (PLY, OFF, VTK) are shown as they are; other arrays are not.
  vtkDataArray* colors = model->GetPointData()->GetScalars() ? model->GetPointData()->GetScalars()
                                                             : model->GetCellData()->GetScalars();
  const bool fileColors = vtkUnsignedCharArray::SafeDownCast(colors) &&
    (colors->GetNumberOfComponents() == 3 || colors->GetNumberOfComponents() == 4);
  mapper->SetScalarVisibility(fileColors);
  mapper->SetColorModeToDirectScalars();
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  nprApplyModelLook(actor->GetProperty(), index);
  renderer->AddActor(actor);
  return triangles;
}
