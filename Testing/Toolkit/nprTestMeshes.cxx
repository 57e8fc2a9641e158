// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nprTestMeshes.h"

#include "nprTesting.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkColorTransferFunction.h"
#include "vtkCubeSource.h"
#include "vtkDoubleArray.h"
#include "vtkGPUVolumeRayCastMapper.h"
#include "vtkIdList.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkNPRModelReader.h"
#include "vtkNPRShadingNormals.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cmath>
#include <limits>

vtkSmartPointer<vtkActor> nprAddActor(
  vtkRenderer* renderer, vtkAlgorithmOutput* port, const double color[3])
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(port);
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  if (color)
  {
    actor->GetProperty()->SetColor(color[0], color[1], color[2]);
  }
  renderer->AddActor(actor);
  return actor;
}
vtkSmartPointer<vtkActor> nprAddMesh(
  vtkRenderer* renderer, vtkPolyData* mesh, const double color[3])
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(mesh);
  mapper->ScalarVisibilityOff();
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(color[0], color[1], color[2]);
  renderer->AddActor(actor);
  return actor;
}

vtkSmartPointer<vtkActor> nprAddCube(
  vtkRenderer* renderer, const double center[3], double size, const double color[3])
{
  vtkNew<vtkCubeSource> cube;
  cube->SetCenter(center[0], center[1], center[2]);
  cube->SetXLength(size);
  cube->SetYLength(size);
  cube->SetZLength(size);
  return nprAddActor(renderer, cube->GetOutputPort(), color);
}

vtkSmartPointer<vtkSphereSource> nprSphereSource(
  double radius, int theta, int phi, const double center[3])
{
  auto sphere = vtkSmartPointer<vtkSphereSource>::New();
  if (center)
  {
    sphere->SetCenter(center[0], center[1], center[2]);
  }
  sphere->SetRadius(radius);
  sphere->SetThetaResolution(theta);
  sphere->SetPhiResolution(phi);
  return sphere;
}

vtkSmartPointer<vtkPolyData> nprSphere(double radius, int theta, int phi)
{
  vtkSmartPointer<vtkSphereSource> source = nprSphereSource(radius, theta, phi);
  source->Update();
  return source->GetOutput();
}

vtkSmartPointer<vtkActor> nprAddSphere(vtkRenderer* renderer, const double center[3], double radius,
  const double color[3], int resolution)
{
  vtkSmartPointer<vtkSphereSource> sphere =
    nprSphereSource(radius, resolution, resolution / 2, center);
  return nprAddActor(renderer, sphere->GetOutputPort(), color);
}

vtkSmartPointer<vtkPolyData> nprMakeTorus(double R, double r, int along, int around)
{
  const double pi = vtkMath::Pi();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> normals;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  for (int i = 0; i < along; ++i)
  {
    const double u = 2.0 * pi * i / along;
    for (int j = 0; j < around; ++j)
    {
      const double v = 2.0 * pi * j / around;
      const double c = R + r * std::cos(v);
      points->InsertNextPoint(c * std::cos(u), c * std::sin(u), r * std::sin(v));
      normals->InsertNextTuple3(std::cos(u) * std::cos(v), std::sin(u) * std::cos(v), std::sin(v));
    }
  }
  vtkSmartPointer<vtkPolyData> torus = nprMesh(points, nprTubeTriangles(along, around));
  torus->GetPointData()->SetNormals(normals);
  return torus;
}

vtkSmartPointer<vtkPolyData> nprBreakNormals(vtkPolyData* mesh, const std::vector<vtkIdType>& ids)
{
  auto broken = vtkSmartPointer<vtkPolyData>::New();
  broken->DeepCopy(mesh);
  vtkDataArray* normals = broken->GetPointData()->GetNormals();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const double kinds[3][3] = { { 0.0, 0.0, 0.0 }, { nan, 0.0, 0.0 }, { nan, inf, 0.0 } };
  for (size_t i = 0; i < ids.size(); ++i)
  {
    normals->SetTuple(ids[i], kinds[i % 3]);
  }
  return broken;
}

void nprLookAtOrigin(vtkCamera* camera, const double eye[3], double far)
{
  camera->SetPosition(eye[0], eye[1], eye[2]);
  camera->SetFocalPoint(0, 0, 0);
  camera->SetViewUp(0, 1, 0);
  camera->SetClippingRange(1.0, far);
}

void nprParallelFromFront(vtkCamera* camera, double scale, double nearPlane, double farPlane)
{
  const double eye[3] = { 0.0, 0.0, 10.0 };
  nprLookAtOrigin(camera, eye, farPlane);
  camera->SetClippingRange(nearPlane, farPlane);
  camera->ParallelProjectionOn();
  camera->SetParallelScale(scale);
}

vtkSmartPointer<vtkActor> nprNaNTriangleActor()
{
  vtkNew<vtkPolyData> broken;
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0, 0, 0);
  points->InsertNextPoint(1, 0, 0);
  points->InsertNextPoint(std::nan(""), 1, 0);
  points->InsertNextPoint(0, 1, 0);
  broken->SetPoints(points);
  vtkNew<vtkCellArray> polys;
  const vtkIdType good[3] = { 0, 1, 3 }, bad[3] = { 1, 2, 3 };
  polys->InsertNextCell(3, good);
  polys->InsertNextCell(3, bad);
  broken->SetPolys(polys);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(broken);
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  return actor;
}

void nprViewFromCorner(vtkCamera* camera, const double eye[3], bool parallel)
{
  nprLookAtOrigin(camera, eye, 10.0);
  camera->SetViewAngle(30);
  camera->SetParallelProjection(parallel);
  camera->SetParallelScale(1.0);
}

vtkSmartPointer<vtkVolume> nprAddBlockVolume(
  vtkRenderer* renderer, const double origin[3], const double spacing[3], const double color[3])
{
  vtkNew<vtkImageData> block;
  block->SetDimensions(16, 16, 16);
  block->SetSpacing(spacing[0], spacing[1], spacing[2]);
  block->SetOrigin(origin[0], origin[1], origin[2]);
  block->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
  std::fill_n(static_cast<unsigned char*>(block->GetScalarPointer()), 16 * 16 * 16, 200);
  vtkNew<vtkGPUVolumeRayCastMapper> mapper;
  mapper->SetInputData(block);
  vtkNew<vtkColorTransferFunction> colors;
  colors->AddRGBPoint(0, color[0], color[1], color[2]);
  colors->AddRGBPoint(255, color[0], color[1], color[2]);
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0, 1.0);
  opacity->AddPoint(255, 1.0);
  auto volume = vtkSmartPointer<vtkVolume>::New();
  volume->SetMapper(mapper);
  volume->GetProperty()->SetColor(colors);
  volume->GetProperty()->SetScalarOpacity(opacity);
  volume->GetProperty()->ShadeOff();
  renderer->AddVolume(volume);
  return volume;
}

vtkSmartPointer<vtkActor> nprAddCornerCube(
  vtkRenderer* renderer, bool parallel, const double color[3])
{
  const double origin[3] = { 0, 0, 0 };
  vtkSmartPointer<vtkActor> cube = nprAddCube(renderer, origin, 1.0, color);
  nprViewFromCorner(renderer->GetActiveCamera(), nprCornerEye, parallel);
  return cube;
}

bool nprSameCells(vtkCellArray* a, vtkCellArray* b)
{
  bool same = a->GetNumberOfCells() == b->GetNumberOfCells();
  vtkNew<vtkIdList> idsA, idsB;
  for (vtkIdType cell = 0; same && cell < a->GetNumberOfCells(); ++cell)
  {
    a->GetCellAtId(cell, idsA);
    b->GetCellAtId(cell, idsB);
    same = idsA->GetNumberOfIds() == idsB->GetNumberOfIds() &&
      std::equal(idsA->begin(), idsA->end(), idsB->begin());
  }
  return same;
}

vtkSmartPointer<vtkNPRModelReader> nprReadTestModel(const std::string& model)
{
  auto reader = vtkSmartPointer<vtkNPRModelReader>::New();
  reader->SetFileName((nprTestDataDir() + "/" + model).c_str());
  reader->Update();
  NPR_CHECK(!*reader->GetErrorMessage(), reader->GetErrorMessage());
  return reader;
}

void nprTurnBaselineCamera(vtkRenderer* renderer)
{
  renderer->ResetCamera();
  renderer->GetActiveCamera()->Azimuth(30);
  renderer->GetActiveCamera()->Elevation(30);
  renderer->GetActiveCamera()->OrthogonalizeViewUp();
  renderer->ResetCameraClippingRange();
}

vtkSmartPointer<vtkActor> nprAddBaselineModel(vtkRenderer* renderer, const std::string& model)
{
  vtkNew<vtkNPRShadingNormals> normals;
  normals->SetInputConnection(nprReadTestModel(model)->GetOutputPort());
  const double color[3] = { 0.85, 0.82, 0.75 };
  vtkSmartPointer<vtkActor> actor = nprAddActor(renderer, normals->GetOutputPort(), color);
  actor->GetProperty()->SetSpecular(0.3);
  actor->GetProperty()->SetSpecularPower(30.0);
  nprTurnBaselineCamera(renderer);
  return actor;
}
