// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// The edge pass's lines on smooth surfaces, part of the TestEdgePassSmooth program: a crease
// whose angle wavers about the threshold along a tessellated arc.
//
// usage: TestEdgePassSmooth CASE [DATA_DIR]   (CASE: the NPR_TEST_CASE names below)
#include "nprTesting.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkNPREdgePass.h"
#include "vtkNPRReferenceMask.h"
#include "vtkNPRShadingNormals.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace
{
using Scene = nprPassScene;

const double Pi = vtkMath::Pi();

// ---- A crease whose angle wavers about the threshold along a tessellated arc ----
// A flat annulus and a cone rising from its inner rim (a concave crease seen from above, convex
// from below), the cone's first ring of points raised by a different amount at each point, so
// that the angle between the faces across the rim wavers between 26 and 42 degrees. Where it
// exceeds 30 degrees the mesh has a crease; vtkPolyDataNormals splits the normals only along
// unbroken chains of such edges, so elsewhere the shading normals are averaged across it.
vtkSmartPointer<vtkPolyData> WaveringCrease()
{
  const int n = 48;
  const double rings[][3] = { { 2.0, 0.0, 0.0 }, { 1.5, 0.0, 0.5 }, { 1.15, 0.0, 0.0 },
    { 1.0, 0.0, 0.5 }, { 0.85, -1.0, 0.0 }, { 0.6, 0.4, 0.5 }, { 0.4, 0.6, 0.0 } };
  const int ringCount = 7;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  unsigned state = 12345u;
  for (const auto& ring : rings)
  {
    for (int i = 0; i < n; ++i)
    {
      const double angle = 2.0 * Pi * (i + ring[2]) / n;
      double z = ring[1] * std::tan(vtkMath::RadiansFromDegrees(34.0));
      if (ring[1] < 0.0)
      {
        state = state * 1103515245u + 12345u;
        const double jitter = ((state >> 8) % 1000) / 999.0 * 16.0 - 8.0;
        z = 0.15 * std::tan(vtkMath::RadiansFromDegrees(34.0 + jitter));
      }
      points->InsertNextPoint(ring[0] * std::cos(angle), ring[0] * std::sin(angle), z);
    }
  }
  vtkNew<vtkCellArray> triangles;
  for (int k = 0; k + 1 < ringCount; ++k)
  {
    const bool shifted = rings[k + 1][2] > rings[k][2];
    for (int i = 0; i < n; ++i)
    {
      const vtkIdType a0 = k * n + i, a1 = k * n + (i + 1) % n;
      const vtkIdType b0 = (k + 1) * n + i;
      const vtkIdType b1 = (k + 1) * n + (shifted ? (i + n - 1) % n : (i + 1) % n);
      const vtkIdType first[3] = { a0, a1, b0 };
      const vtkIdType second[3] = { a0, b0, b1 };
      const vtkIdType third[3] = { a1, b1, b0 };
      triangles->InsertNextCell(3, first);
      triangles->InsertNextCell(3, shifted ? second : third);
    }
  }
  const vtkIdType apex = points->InsertNextPoint(0.0, 0.0, 0.6 * std::tan(0.6) + 0.2);
  for (int i = 0; i < n; ++i)
  {
    const vtkIdType cap[3] = { (ringCount - 1) * n + i, (ringCount - 1) * n + (i + 1) % n, apex };
    triangles->InsertNextCell(3, cap);
  }
  vtkNew<vtkPolyData> mesh;
  mesh->SetPoints(points);
  mesh->SetPolys(triangles);
  vtkNew<vtkNPRShadingNormals> normals; // as npr-render prepares a model: split at 30 degrees
  normals->SetInputData(mesh);
  normals->Update();
  auto prepared = vtkSmartPointer<vtkPolyData>::New();
  prepared->ShallowCopy(normals->GetOutput());
  return prepared;
}

int WaveringCreaseCase()
{
  Scene scene(400, 300);
  nprAddMesh(scene.Renderer, WaveringCrease());
  scene.Edges()->ContoursOff();
  vtkNew<vtkNPRReferenceMask> reference;
  reference->SetRenderer(scene.Renderer);
  reference->SilhouettesOff();
  reference->BoundariesOff();
  reference->NonManifoldEdgesOff();
  // Recall of the mesh's creases (faces meeting beyond 30 degrees) within 1 px, over views
  // from above and below.
  auto recall = [&](bool faceCreases, double& worst)
  {
    scene.Edges()->SetFaceCreases(faceCreases);
    long long truth = 0, found = 0;
    worst = 1.0;
    for (double azimuth : { 0.0, 70.0, 150.0, 260.0 })
    {
      for (double elevation : { -50.0, -25.0, 25.0, 50.0 })
      {
        const double a = vtkMath::RadiansFromDegrees(azimuth);
        const double e = vtkMath::RadiansFromDegrees(elevation);
        vtkCamera* camera = scene.Camera();
        camera->SetFocalPoint(0.0, 0.0, 0.0);
        camera->SetPosition(
          6.0 * std::cos(e) * std::cos(a), 6.0 * std::cos(e) * std::sin(a), 6.0 * std::sin(e));
        camera->SetViewUp(0.0, 0.0, 1.0);
        camera->SetClippingRange(2.0, 12.0);
        auto mask = scene.Mask();
        reference->Update();
        vtkImageData* creases = reference->GetMask();
        long long viewTruth = 0, viewFound = 0;
        for (int y = 0; y < 300; ++y)
        {
          for (int x = 0; x < 400; ++x)
          {
            if (!nprPixel(creases, x, y))
            {
              continue;
            }
            ++viewTruth;
            bool near = false;
            for (const auto& d :
              { std::array<int, 2>{ 0, 0 }, { 1, 0 }, { -1, 0 }, { 0, 1 }, { 0, -1 } })
            {
              near = near || nprPixel(mask, x + d[0], y + d[1]) >= 128;
            }
            viewFound += near ? 1 : 0;
          }
        }
        truth += viewTruth;
        found += viewFound;
        worst = std::min(worst, viewTruth ? double(viewFound) / viewTruth : 1.0);
      }
    }
    return truth ? double(found) / truth : 0.0;
  };
  double worstFaces = 0.0, worstShading = 0.0;
  const double faces = recall(true, worstFaces);
  const double shading = recall(false, worstShading);
  std::cout << "crease recall at 1 px: face normals " << faces << " (worst view " << worstFaces
            << "), shading normals " << shading << " (worst view " << worstShading << ")\n";
  NPR_CHECK(faces >= 0.97 && worstFaces >= 0.9, "creases from face normals missed");
  // The case is one where the shading normals lose part of the crease: the test means something.
  NPR_CHECK(shading < faces - 0.1, "the shading normals no longer lose this crease");
  return nprTestResult();
}
NPR_TEST_CASE("wavering-crease", WaveringCreaseCase);
}
