// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// The edge pass over every kind of opaque actor: point normals, cell normals only, no normals,
// flat, unlit, zero-length normals, scalar colours, a texture, the wireframe and points
// representations, a composite (multiblock) mapper and glyphs. Each is drawn; each surface has
// lines, the wireframe and points none (they are line and point primitives, not geometry).
//
// usage: TestEdgePassActorKinds CASE [DATA_DIR]   (CASE: the NPR_TEST_CASE names below)
#include "nprTesting.h"

#include "vtkActor.h"
#include "vtkVersionMacros.h"
#if VTK_VERSION_NUMBER >= VTK_VERSION_CHECK(9, 3, 0)
#include "vtkCompositePolyDataMapper.h" // VTK 9.3 replaced Mapper2 with it (removed in 9.5)
using nprCompositeMapper = vtkCompositePolyDataMapper;
#else
#include "vtkCompositePolyDataMapper2.h"
using nprCompositeMapper = vtkCompositePolyDataMapper2;
#endif
#include "vtkConeSource.h"
#include "vtkElevationFilter.h"
#include "vtkFloatArray.h"
#include "vtkGlyph3DMapper.h"
#include "vtkImageData.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkPolyDataNormals.h"
#include "vtkProperty.h"
#include "vtkSphereSource.h"
#include "vtkTexture.h"
#include "vtkTextureMapToSphere.h"
#include "vtkTransform.h"
#include "vtkTransformPolyDataFilter.h"

#include <functional>
#include <map>
#include <string>

namespace
{
using Scene = nprPassScene;

// The test sphere (radius 0.5), with or without its point normals.
vtkSmartPointer<vtkPolyData> SphereData(bool pointNormals)
{
  auto sphere = nprSphereSource(0.5, 24, 12);
  sphere->Update();
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->DeepCopy(sphere->GetOutput());
  if (!pointNormals)
  {
    data->GetPointData()->SetNormals(nullptr);
  }
  return data;
}

vtkSmartPointer<vtkActor> ActorFor(vtkPolyData* data)
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(data);
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  return actor;
}

// The sphere drawn as wireframe or points, lines and points of the given size.
vtkSmartPointer<vtkProp> DrawnAs(int representation, float lineWidth, float pointSize)
{
  auto actor = ActorFor(SphereData(true));
  actor->GetProperty()->SetRepresentation(representation);
  actor->GetProperty()->SetLineWidth(lineWidth);
  actor->GetProperty()->SetPointSize(pointSize);
  return actor;
}

vtkSmartPointer<vtkProp> CellNormalsOnly()
{
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputData(SphereData(false));
  normals->ComputePointNormalsOff();
  normals->ComputeCellNormalsOn();
  normals->Update();
  return ActorFor(normals->GetOutput());
}

vtkSmartPointer<vtkProp> Flat()
{
  auto actor = ActorFor(SphereData(true));
  actor->GetProperty()->SetInterpolationToFlat();
  return actor;
}

vtkSmartPointer<vtkProp> Unlit()
{
  auto actor = ActorFor(SphereData(true));
  actor->GetProperty()->LightingOff();
  return actor;
}

vtkSmartPointer<vtkProp> ZeroLengthNormals()
{
  auto data = SphereData(false);
  vtkNew<vtkFloatArray> zero;
  zero->SetNumberOfComponents(3);
  zero->SetNumberOfTuples(data->GetNumberOfPoints());
  zero->Fill(0.0);
  zero->SetName("Normals");
  data->GetPointData()->SetNormals(zero);
  return ActorFor(data);
}

vtkSmartPointer<vtkProp> ScalarColours()
{
  vtkNew<vtkElevationFilter> elevation;
  elevation->SetInputData(SphereData(true));
  elevation->SetLowPoint(0, -0.5, 0);
  elevation->SetHighPoint(0, 0.5, 0);
  elevation->Update();
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->ShallowCopy(elevation->GetOutput());
  return ActorFor(data);
}

// The sphere with an 8 x 8 checker texture.
vtkSmartPointer<vtkProp> Textured()
{
  vtkNew<vtkTextureMapToSphere> map;
  map->SetInputData(SphereData(true));
  map->Update();
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->ShallowCopy(map->GetOutput());
  auto actor = ActorFor(data);
  vtkNew<vtkImageData> checker;
  checker->SetDimensions(8, 8, 1);
  checker->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  for (int y = 0; y < 8; ++y)
  {
    for (int x = 0; x < 8; ++x)
    {
      for (int c = 0; c < 3; ++c)
      {
        checker->SetScalarComponentFromDouble(x, y, 0, c, (x + y) % 2 ? 230 : 60);
      }
    }
  }
  vtkNew<vtkTexture> texture;
  texture->SetInputData(checker);
  actor->SetTexture(texture);
  return actor;
}

// Two spheres side by side, the blocks of one composite mapper.
vtkSmartPointer<vtkProp> Multiblock()
{
  vtkNew<vtkMultiBlockDataSet> blocks;
  blocks->SetNumberOfBlocks(2);
  auto left = SphereData(true);
  auto right = SphereData(true);
  vtkNew<vtkTransform> shift;
  shift->Translate(0.8, 0, 0);
  vtkNew<vtkTransformPolyDataFilter> moved;
  moved->SetTransform(shift);
  moved->SetInputData(right);
  moved->Update();
  blocks->SetBlock(0, left);
  blocks->SetBlock(1, moved->GetOutput());
  vtkNew<nprCompositeMapper> mapper;
  mapper->SetInputDataObject(blocks);
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  return actor;
}

// Cones on a 4 x 4 grid of points (vtkGlyph3DMapper).
vtkSmartPointer<vtkProp> Glyphs()
{
  vtkNew<vtkPlaneSource> grid;
  grid->SetResolution(3, 3);
  grid->Update();
  vtkNew<vtkConeSource> cone;
  cone->SetResolution(16);
  cone->SetHeight(0.2);
  cone->SetRadius(0.1);
  vtkNew<vtkGlyph3DMapper> mapper;
  mapper->SetInputConnection(grid->GetOutputPort());
  mapper->SetSourceConnection(cone->GetOutputPort());
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  return actor;
}

// ---- Every kind of opaque actor: lines appear, nothing is reported, nothing crashes ----
int ActorKinds()
{
  struct Kind
  {
    const char* Name;
    std::function<vtkSmartPointer<vtkProp>()> Make;
  };
  const Kind kinds[] = {
    { "point normals", [] { return vtkSmartPointer<vtkProp>(ActorFor(SphereData(true))); } },
    { "cell normals only", CellNormalsOnly },
    { "no normals", [] { return vtkSmartPointer<vtkProp>(ActorFor(SphereData(false))); } },
    { "flat", Flat },
    { "unlit", Unlit },
    { "zero-length normals", ZeroLengthNormals },
    { "scalar colours", ScalarColours },
    { "textured", Textured },
    { "wireframe lines", [] { return DrawnAs(VTK_WIREFRAME, 2, 1); } },
    { "points", [] { return DrawnAs(VTK_POINTS, 1, 6); } },
    { "composite (multiblock)", Multiblock },
    { "glyphs", Glyphs },
  };
  for (const Kind& kind : kinds)
  {
    Scene scene(240, 180);
    scene.Renderer->AddViewProp(kind.Make());
    scene.Renderer->ResetCamera();
    auto image = scene.Render();
    auto mask = scene.Mask();
    const double white[3] = { 1, 1, 1 };
    const nprPixelStatistics stats = nprComputePixelStatistics(image, white);
    const long long lines = nprCountAbove(mask, 127);
    std::cout << kind.Name << ": " << stats.ObjectPixels << " object pixels, " << lines
              << " line pixels\n";
    NPR_CHECK(stats.ObjectPixels > 500, kind.Name << ": the actor was not drawn");
    // Line and point primitives are not geometry: no lines traced around them (issue 19).
    const std::string name = kind.Name;
    if (name == "wireframe lines" || name == "points")
    {
      NPR_CHECK(lines < 10, kind.Name << ": lines traced along line or point primitives");
    }
    else
    {
      NPR_CHECK(lines > 40, kind.Name << ": no lines");
    }
  }
  return nprTestResult();
}
NPR_TEST_CASE("actor-kinds", ActorKinds);
}
