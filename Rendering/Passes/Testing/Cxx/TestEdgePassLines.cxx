// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// The lines of the edge pass (vtkNPREdgePass over vtkNPRGBufferPass) where their place can be
// stated: no false line on a plane seen at a grazing angle, nor on a shallow fold seen nearly
// edge-on (while a step of that size is drawn); creases from the crease angle on, never below.
// The program's other cases: TestEdgePassLinesCube.cxx, TestEdgePassLinesObjects.cxx.
//
// usage: TestEdgePassLines CASE [DATA_DIR]   (CASE: the NPR_TEST_CASE names below)
#include "nprTesting.h"

#include "vtkAppendPolyData.h"
#include "vtkCamera.h"
#include "vtkCleanPolyData.h"
#include "vtkCubeSource.h"
#include "vtkImageData.h"
#include "vtkNPREdgePass.h"
#include "vtkNPRGBufferPass.h"
#include "vtkNew.h"
#include "vtkPlaneSource.h"
#include "vtkTransform.h"
#include "vtkTransformPolyDataFilter.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace
{
using Scene = nprPassScene;

// The camera of the fold scenes: straight down the z axis at the fold along x (y = 0), and the
// fold's ends (x = -0.8 and 0.8) in pixels.
void LookAtFold(Scene& scene, bool parallel)
{
  vtkCamera* camera = scene.Camera();
  camera->SetPosition(0, 0, 10);
  camera->SetFocalPoint(0, 0, 0);
  camera->SetViewUp(0, 1, 0);
  camera->SetViewAngle(14);
  camera->SetParallelProjection(parallel);
  camera->SetParallelScale(1.2);
  camera->SetClippingRange(5, 15);
}

void ProjectFold(Scene& scene, double left[2], double right[2])
{
  const double foldLeft[3] = { -0.8, 0, 0 };
  const double foldRight[3] = { 0.8, 0, 0 };
  scene.Project(foldLeft, left);
  scene.Project(foldRight, right);
}

// ---- A plane at a grazing angle: its far border is a silhouette, its inside has no line ----
int GrazingPlane()
{
  Scene scene(400, 300);
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-50, 0, -50);
  plane->SetPoint1(50, 0, -50);
  plane->SetPoint2(-50, 0, 50);
  plane->SetResolution(20, 20);
  const double grey[3] = { 0.7, 0.7, 0.7 };
  nprAddActor(scene.Renderer, plane->GetOutputPort(), grey);
  vtkCamera* camera = scene.Camera();
  camera->SetPosition(0, 0.3, 30);
  camera->SetFocalPoint(0, -0.5, -50);
  camera->SetViewUp(0, 1, 0);
  camera->SetViewAngle(30);
  camera->SetClippingRange(0.1, 200);
  auto mask = scene.Mask();
  const double farEdge[3] = { 0, 0, -50 };
  double horizon[2];
  scene.Project(farEdge, horizon);
  long long far = 0, inside = 0;
  for (int y = 0; y < 300; ++y)
  {
    for (int x = 0; x < 400; ++x)
    {
      if (nprPixel(mask, x, y) > 0)
      {
        (std::abs(y + 0.5 - horizon[1]) <= 3.0 ? far : inside)++;
      }
    }
  }
  std::cout << "far border row " << horizon[1] << ": " << far << " line pixels there, " << inside
            << " elsewhere\n";
  NPR_CHECK(far > 300, "the far border should be a silhouette line: " << far << " pixels");
  NPR_CHECK(inside == 0, inside << " false line pixels on the grazing plane");
  return nprTestResult();
}
NPR_TEST_CASE("grazing-plane", GrazingPlane);

// ---- A 15-degree fold seen nearly edge-on bends the depth as much as a step: no line ----
// Seen from the eye, face A (n.v 0.31) runs down the screen to the fold, face B (n.v 0.05) on
// from it, receding eight times as steeply. The depth's second difference at the fold is 2.5
// times the silhouette threshold, but the surface is continuous and front-facing: the mesh has
// no silhouette and no crease there. With a gap (B moved back by a relative depth step of 3 %)
// the same place is a step, which must be drawn. (A step smaller than B's own depth change over
// a pixel, 1.5 %, fits a fold between the pixels as well: the pass takes it for one.)
int GrazingFold(bool parallel, bool gap)
{
  Scene scene(400, 300);
  const double pi = std::acos(-1.0);
  const double angleA = 18.0 * pi / 180.0; // between each face and the view direction
  const double angleB = 3.0 * pi / 180.0;
  const double back = gap ? 0.3 : 0.0;
  vtkNew<vtkPlaneSource> faceA;
  faceA->SetOrigin(-1, 0, 0);
  faceA->SetPoint1(1, 0, 0);
  faceA->SetPoint2(-1, 2 * std::sin(angleA), 2 * std::cos(angleA));
  vtkNew<vtkPlaneSource> faceB;
  faceB->SetOrigin(-1, 0, -back); // wound as faceA: both normals towards the eye
  faceB->SetPoint1(-1, -2 * std::sin(angleB), -back - 2 * std::cos(angleB));
  faceB->SetPoint2(1, 0, -back);
  vtkNew<vtkAppendPolyData> both;
  both->AddInputConnection(faceA->GetOutputPort());
  both->AddInputConnection(faceB->GetOutputPort());
  vtkNew<vtkCleanPolyData> merged; // one surface along the fold: the faces share its points
  merged->SetInputConnection(both->GetOutputPort());
  nprAddActor(scene.Renderer, merged->GetOutputPort(), nprGrey);
  LookAtFold(scene, parallel);
  auto mask = scene.Mask();
  double left[2], right[2];
  ProjectFold(scene, left, right);
  long long near = 0;
  for (int y = 0; y < 300; ++y)
  {
    for (int x = static_cast<int>(left[0]); x <= static_cast<int>(right[0]); ++x)
    {
      near += std::abs(y + 0.5 - left[1]) <= 3.0 && nprPixel(mask, x, y) > 0 ? 1 : 0;
    }
  }
  const double length = right[0] - left[0];
  std::cout << (gap ? "step" : "fold") << " at row " << left[1] << ", " << length
            << " px long: " << near << " line pixels within 3 px\n";
  if (gap)
  {
    NPR_CHECK(near >= 0.9 * length, "the step is drawn along only " << near << " pixels");
  }
  else
  {
    NPR_CHECK(near == 0, near << " line pixels on the fold");
  }
  return nprTestResult();
}
NPR_TEST_CASE("grazing-fold", [] { return GrazingFold(false, false); });
NPR_TEST_CASE("grazing-fold-parallel", [] { return GrazingFold(true, false); });
NPR_TEST_CASE("grazing-step", [] { return GrazingFold(false, true); });
NPR_TEST_CASE("grazing-step-parallel", [] { return GrazingFold(true, true); });

// ---- A roof seen from the front: a crease where its faces turn by more than the crease angle ----
// The faces turn by `turn` degrees at the fold (flat normals, one object, no depth step); the
// crease is drawn from the crease angle less its ramp (a quarter of the angle, at most 1 degree)
// and in full past it, never below. Angles inside the ramp check that no pixel on a crease is
// skipped as plain surface before its test.
int CreaseThreshold(double creaseAngle, double turn)
{
  Scene scene(400, 300);
  const double pi = std::acos(-1.0);
  const double half = 0.5 * turn * pi / 180.0;
  vtkNew<vtkPlaneSource> faceA; // upwards from the fold, receding; its normal towards the eye
  faceA->SetOrigin(-1, 0, 0);
  faceA->SetPoint1(1, 0, 0);
  faceA->SetPoint2(-1, std::cos(half), -std::sin(half));
  vtkNew<vtkPlaneSource> faceB; // downwards
  faceB->SetOrigin(-1, 0, 0);
  faceB->SetPoint1(-1, -std::cos(half), -std::sin(half));
  faceB->SetPoint2(1, 0, 0);
  // Not merged: each face keeps its own normals along the fold, as a mesh split at its creases.
  vtkNew<vtkAppendPolyData> both;
  both->AddInputConnection(faceA->GetOutputPort());
  both->AddInputConnection(faceB->GetOutputPort());
  nprAddActor(scene.Renderer, both->GetOutputPort(), nprGrey);
  LookAtFold(scene, false);
  scene.Edges()->SetCreaseAngle(creaseAngle);
  scene.Edges()->SetLineWidth(1.0);
  scene.Edges()->AntiAliasingOff();
  auto mask = scene.Mask();
  double left[2], right[2];
  ProjectFold(scene, left, right);
  long long near = 0, elsewhere = 0;
  for (int y = 0; y < 300; ++y)
  {
    for (int x = static_cast<int>(left[0]); x <= static_cast<int>(right[0]); ++x)
    {
      const bool onFold = std::abs(y + 0.5 - left[1]) <= 3.0;
      const bool lit = nprPixel(mask, x, y) > 127;
      near += onFold && lit ? 1 : 0;
      // The faces' far borders are silhouettes: only the rows between them and the fold count.
      elsewhere += !onFold && std::abs(y + 0.5 - left[1]) < 40.0 && lit ? 1 : 0;
    }
  }
  const double ramp = std::min(1.0, 0.25 * creaseAngle) * 1.0027; // 0.0175 rad
  const double length = right[0] - left[0];
  std::cout << "crease angle " << creaseAngle << ", faces turning by " << turn << ": " << near
            << " line pixels on the " << length << " px fold, " << elsewhere << " beside it\n";
  NPR_CHECK(elsewhere == 0, elsewhere << " line pixels on the faces beside the fold");
  if (turn < creaseAngle - ramp)
  {
    NPR_CHECK(near == 0, near << " line pixels on a fold below the crease angle");
  }
  else
  {
    NPR_CHECK(near >= 0.95 * length, "the crease is drawn along only " << near << " pixels");
  }
  return nprTestResult();
}
// Below the ramp, inside it (0.7 of the way up) and past it, at three crease angles.
NPR_TEST_CASE("crease-threshold",
  []
  {
    int failed = 0;
    for (double angle : { 30.0, 10.0, 2.0 })
    {
      const double ramp = std::min(1.0, 0.25 * angle) * 1.0027;
      for (double turn : { angle - ramp - 0.5, angle + 0.7 * ramp, angle + ramp + 1.0 })
      {
        failed |= CreaseThreshold(angle, turn);
      }
    }
    return failed;
  });
}
