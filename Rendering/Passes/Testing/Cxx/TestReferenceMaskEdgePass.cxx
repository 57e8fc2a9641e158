// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// The ground-truth mask (vtkNPRReferenceMask) against the lines vtkNPREdgePass draws with the
// same camera (width 1, no anti-aliasing): on a cube and on the bunny they line up within a pixel.
//
// usage: TestReferenceMaskEdgePass CASE [DATA_DIR]   (CASE: the NPR_TEST_CASE names below)
#include "nprFeatureLineTesting.h"

#include "vtkCamera.h"
#include "vtkImageData.h"
#include "vtkNPREdgePass.h"
#include "vtkNPRModelReader.h"
#include "vtkNPRPass.h"
#include "vtkNew.h"
#include "vtkPolyDataNormals.h"

#include <functional>
#include <map>
#include <string>

namespace
{
using namespace nprFeatureLineTesting;

// ---- The mask against vtkNPREdgePass's lines of the same camera: they line up ----
int MaskAgainstEdgePass(const char* model)
{
  MaskScene scene(400, 300);
  vtkNew<vtkNPRPass> pass;
  scene.Renderer->SetPass(pass);
  vtkNPREdgePass* edges = pass->GetEdgePass();
  edges->SetLineWidth(1.0);
  edges->AntiAliasingOff();
  edges->CoverageOnlyOn();
  vtkNew<vtkNPRModelReader> reader;
  vtkNew<vtkPolyDataNormals> normals;
  if (model)
  {
    reader->SetFileName((nprTestDataDir() + "/" + model).c_str());
    normals->SetInputConnection(reader->GetOutputPort());
    normals->SetFeatureAngle(30.0);
    normals->SplittingOn();
    nprAddActor(scene.Renderer, normals->GetOutputPort());
    scene.Renderer->ResetCamera();
    scene.Camera()->Azimuth(30);
    scene.Camera()->Elevation(20);
    scene.Camera()->OrthogonalizeViewUp();
    scene.Renderer->ResetCameraClippingRange();
  }
  else
  {
    const double origin[3] = { 0, 0, 0 };
    nprAddCube(scene.Renderer, origin, 1.0);
    scene.Camera()->SetPosition(2.2, 1.7, 2.9);
    scene.Camera()->SetFocalPoint(0, 0, 0);
    scene.Camera()->SetClippingRange(1.0, 10.0);
  }
  scene.Window->Render();
  vtkSmartPointer<vtkImageData> rendered = nprCaptureImage(scene.Window);
  vtkImageData* reference = scene.Mask();
  auto near = [](vtkImageData* image, int x, int y, int radius, int threshold)
  {
    for (int oy = -radius; oy <= radius; ++oy)
    {
      for (int ox = -radius; ox <= radius; ++ox)
      {
        if (nprPixel(image, x + ox, y + oy) > threshold)
        {
          return true;
        }
      }
    }
    return false;
  };
  long long truth = 0, truthFound = 0, drawn = 0, drawnTrue = 0;
  for (int y = 2; y < scene.Height - 2; ++y)
  {
    for (int x = 2; x < scene.Width - 2; ++x)
    {
      if (nprPixel(reference, x, y))
      {
        ++truth;
        truthFound += near(rendered, x, y, 1, 127) ? 1 : 0;
      }
      if (nprPixel(rendered, x, y) > 127)
      {
        ++drawn;
        drawnTrue += near(reference, x, y, 1, 0) ? 1 : 0;
      }
    }
  }
  const double recall = truth ? double(truthFound) / truth : 0.0;
  const double precision = drawn ? double(drawnTrue) / drawn : 0.0;
  std::cout << (model ? model : "cube") << ": " << truth << " reference pixels, " << drawn
            << " edge-pass pixels; within 1 px: recall " << recall << ", precision " << precision
            << "\n";
  NPR_CHECK(truth > 500 && drawn > 500, "too few line pixels");
  NPR_CHECK(recall >= (model ? 0.95 : 0.97), "the edge pass misses the reference: " << recall);
  NPR_CHECK(
    precision >= (model ? 0.85 : 0.97), "the edge pass is off the reference: " << precision);
  return nprTestResult();
}
NPR_TEST_CASE("mask-edge-pass-cube", [] { return MaskAgainstEdgePass(nullptr); });
NPR_TEST_CASE("mask-edge-pass-bunny", [] { return MaskAgainstEdgePass("bunny.ply"); });
}
