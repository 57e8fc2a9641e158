// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// The ground-truth mask (vtkNPRReferenceMask) against the lines vtkNPREdgePass draws with the
// same camera (width 1, no anti-aliasing): on a cube and on the bunny they line up within a pixel;
// on generated CAD parts (nprMeshes) no crease above the crease angle is missed, concave or convex.
//
// usage: TestReferenceMaskEdgePass CASE [DATA_DIR]   (CASE: the NPR_TEST_CASE names below)
#include "nprFeatureLineTesting.h"
#include "nprModel.h"
#include "nprTestMeshes.h"

#include "vtkCamera.h"
#include "vtkImageData.h"
#include "vtkNPREdgePass.h"
#include "vtkNPRModelReader.h"
#include "vtkNPRPass.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkPolyDataNormals.h"

#include <algorithm>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace
{
using namespace nprFeatureLineTesting;

// ---- The mask against vtkNPREdgePass's lines of the same camera: they line up ----
// The reference's pixels with a drawn one (above half coverage) within a pixel, and the drawn
// pixels with a reference one within a pixel; the two-pixel frame is left out. With `without`,
// the reference's pixels that are lines of `without` too are no truth pixels (its drawn pixels
// are not counted then).
struct Agreement
{
  long long Truth = 0, TruthFound = 0, Drawn = 0, DrawnTrue = 0;
  double Recall() const { return this->Truth ? double(this->TruthFound) / this->Truth : 0.0; }
  double Precision() const { return this->Drawn ? double(this->DrawnTrue) / this->Drawn : 0.0; }
};

Agreement Compare(vtkImageData* rendered, vtkImageData* reference, int width, int height,
  vtkImageData* without = nullptr)
{
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
  Agreement agreement;
  for (int y = 2; y < height - 2; ++y)
  {
    for (int x = 2; x < width - 2; ++x)
    {
      if (nprPixel(reference, x, y) && !(without && nprPixel(without, x, y)))
      {
        ++agreement.Truth;
        agreement.TruthFound += near(rendered, x, y, 1, 127) ? 1 : 0;
      }
      if (nprPixel(rendered, x, y) > 127)
      {
        ++agreement.Drawn;
        agreement.DrawnTrue += near(reference, x, y, 1, 0) ? 1 : 0;
      }
    }
  }
  return agreement;
}

// A scene of the edge pass as the mask tests draw it: lines 1 px wide, no anti-aliasing, the
// lines' coverage alone.
void UseEdgePass(MaskScene& scene, vtkNPRPass* pass)
{
  scene.Renderer->SetPass(pass);
  vtkNPREdgePass* edges = pass->GetEdgePass();
  edges->SetLineWidth(1.0);
  edges->AntiAliasingOff();
  edges->CoverageOnlyOn();
}

int MaskAgainstEdgePass(const char* model)
{
  MaskScene scene(400, 300);
  vtkNew<vtkNPRPass> pass;
  UseEdgePass(scene, pass);
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
  const Agreement agreement = Compare(rendered, reference, scene.Width, scene.Height);
  const long long truth = agreement.Truth, drawn = agreement.Drawn;
  const double recall = agreement.Recall(), precision = agreement.Precision();
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

// ---- Generated CAD parts: every crease above the angle where both its faces are visible ----
// Circular creases, concave and convex, just below (28 degrees: no line, in the mask or drawn),
// just above (32) and well above the default crease angle of 30, each part seen from above at
// 20, 40 and 65 degrees and from below, from three sides. Issue 36: a concave crease where a cone
// meets a flange was missed along its far half seen from 40 degrees above, where the cone's side
// (36 and 38 degrees here) is seen nearly edge-on: the far side of a depth jump as large as a
// step's, which vtkNPREdgePass took for one. The mesh
// prepared as npr-render and npr-benchmark prepare it (nprPrepareMesh: normals split at 30
// degrees). Per view: recall >= 0.99 and precision >= 0.99 within a pixel, and recall >= 0.995 on
// the creases alone (the mask's pixels that are not also lines of the mask without creases). In
// perspective, and in a parallel view (CAD programs' usual one) with the camera 1.8 times closer
// (the same image, larger depth jumps against the view depth), where the cone at 38 degrees lost
// 0.7-0.9% of its crease pixels from 40 degrees above before the crease test covered parallel
// views (measured: crease recall 0.991-0.993, now 1).
int CadCreases(bool parallel)
{
  struct Part
  {
    std::string Name;
    vtkSmartPointer<vtkPolyData> Mesh;
  };
  const std::vector<Part> parts = { { "cone 28", nprConeOnFlange(28.0) },
    { "cone 32", nprConeOnFlange(32.0) }, { "cone 36", nprConeOnFlange(36.0) },
    { "cone 38", nprConeOnFlange(38.0) }, { "cone 45", nprConeOnFlange(45.0) },
    { "cone 60", nprConeOnFlange(60.0) }, { "boss and pocket", nprBossAndPocket() },
    { "filleted cylinder", nprFilletedCylinder() } };
  MaskScene scene(640, 480);
  vtkNew<vtkNPRPass> pass;
  UseEdgePass(scene, pass);
  scene.Camera()->SetParallelProjection(parallel);
  double worstRecall = 1.0, worstPrecision = 1.0;
  for (const Part& part : parts)
  {
    scene.Renderer->RemoveAllViewProps();
    nprAddMesh(scene.Renderer, nprPrepareMesh(part.Mesh));
    for (double elevation : { 20.0, 40.0, 65.0, -30.0 })
    {
      for (double azimuth : { 0.0, 100.0, 215.0 })
      {
        vtkCamera* camera = scene.Camera();
        camera->SetPosition(0.0, -1.0, 0.0);
        camera->SetFocalPoint(0.0, 0.0, 0.0);
        camera->SetViewUp(0.0, 0.0, 1.0);
        scene.Renderer->ResetCamera();
        camera->Azimuth(azimuth);
        camera->Elevation(elevation);
        camera->OrthogonalizeViewUp();
        if (parallel)
        {
          // Closer, the image unchanged: the depth jumps grow against the view depth.
          camera->Dolly(1.8);
        }
        scene.Renderer->ResetCameraClippingRange();
        scene.Window->Render();
        vtkSmartPointer<vtkImageData> rendered = nprCaptureImage(scene.Window);
        scene.Reference->SetCreases(false);
        vtkNew<vtkImageData> withoutCreases;
        withoutCreases->DeepCopy(scene.Mask());
        scene.Reference->SetCreases(true);
        const Agreement agreement = Compare(rendered, scene.Mask(), scene.Width, scene.Height);
        // The creases alone: a missed stretch is a small part of all the lines.
        const Agreement creases =
          Compare(rendered, scene.Mask(), scene.Width, scene.Height, withoutCreases);
        std::cout << part.Name << ", azimuth " << azimuth << ", elevation " << elevation << ": "
                  << agreement.Truth << " reference pixels, recall " << agreement.Recall()
                  << ", precision " << agreement.Precision() << "; " << creases.Truth
                  << " crease pixels, recall " << creases.Recall() << "\n";
        NPR_CHECK(agreement.Truth > 500, part.Name << ": too few reference pixels");
        NPR_CHECK(agreement.Recall() >= 0.99,
          part.Name << ", azimuth " << azimuth << ", elevation " << elevation
                    << ": a crease missed, recall " << agreement.Recall());
        NPR_CHECK(creases.Truth == 0 || creases.Recall() >= 0.995,
          part.Name << ", azimuth " << azimuth << ", elevation " << elevation
                    << ": a crease missed, crease recall " << creases.Recall());
        NPR_CHECK(agreement.Precision() >= 0.99,
          part.Name << ", azimuth " << azimuth << ", elevation " << elevation
                    << ": lines off the reference, precision " << agreement.Precision());
        worstRecall = std::min({ worstRecall, agreement.Recall(), creases.Recall() });
        worstPrecision = std::min(worstPrecision, agreement.Precision());
      }
    }
  }
  std::cout << "CAD creases (" << (parallel ? "parallel" : "perspective")
            << " view): lowest recall " << worstRecall << ", lowest precision " << worstPrecision
            << "\n";
  return nprTestResult();
}
NPR_TEST_CASE("mask-edge-pass-cad-creases", [] { return CadCreases(false); });
NPR_TEST_CASE("mask-edge-pass-cad-creases-parallel", [] { return CadCreases(true); });
}
