// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// The ground-truth mask of the visible feature lines (vtkNPRReferenceMask), part of the
// TestReferenceMask program: the curves where surfaces cross.
//
// usage: TestReferenceMask CASE [DATA_DIR]   (CASE: the NPR_TEST_CASE names below)
#include "nprFeatureLineTesting.h"

#include "vtkActor.h"
#include "vtkActorCollection.h"
#include "vtkCamera.h"
#include "vtkCellData.h"
#include "vtkCubeSource.h"
#include "vtkIdTypeArray.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkNPRModelReader.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkSphereSource.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <numeric>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace
{
using namespace nprFeatureLineTesting;
// ---- Where surfaces cross: a post through a plate ----
// The post's sides cross the plate's top face along a square (at 90 degrees): creases of no mesh,
// in the mask with IntersectionCurves on (the default), not with it off or under a crease angle
// above 90 degrees.
int MaskIntersections()
{
  MaskScene scene(400, 300);
  vtkNew<vtkCubeSource> plate;
  plate->SetXLength(2.0);
  plate->SetYLength(0.2);
  plate->SetZLength(2.0);
  vtkNew<vtkCubeSource> post;
  post->SetXLength(0.4);
  post->SetYLength(1.6);
  post->SetZLength(0.4);
  nprAddActor(scene.Renderer, plate->GetOutputPort());
  nprAddActor(scene.Renderer, post->GetOutputPort());
  const double eye[3] = { 2.5, 3.0, 4.0 };
  vtkCamera* camera = scene.Camera();
  nprLookAtOrigin(camera, eye, 20.0);
  scene.Reference->SilhouettesOff();
  scene.Reference->BoundariesOff();
  // The square's two edges that face the camera, sampled away from their ends (where the post's
  // and the plate's own creases come near).
  auto pixelsOnSquare = [&](vtkImageData* mask, int& samples)
  {
    int found = 0;
    samples = 0;
    for (int edge = 0; edge < 2; ++edge)
    {
      for (int i = 2; i <= 18; ++i)
      {
        const double s = -0.2 + 0.4 * i / 20.0;
        const Point point = edge == 0 ? Point{ 0.2, 0.1, s } : Point{ s, 0.1, 0.2 };
        const auto display = scene.Project(point);
        bool near = false;
        for (int dy = -1; dy <= 1; ++dy)
        {
          for (int dx = -1; dx <= 1; ++dx)
          {
            near = near ||
              nprPixel(mask, static_cast<int>(display[0]) + dx, static_cast<int>(display[1]) + dy) >
                0;
          }
        }
        found += near ? 1 : 0;
        ++samples;
      }
    }
    return found;
  };
  int samples = 0;
  const int on = pixelsOnSquare(scene.Mask(), samples);
  scene.Reference->IntersectionCurvesOff();
  const int off = pixelsOnSquare(scene.Mask(), samples);
  scene.Reference->IntersectionCurvesOn();
  scene.Reference->SetCreaseAngle(95.0);
  const int steep = pixelsOnSquare(scene.Mask(), samples);
  std::cout << "samples of the crossing square with a line pixel: " << on << " of " << samples
            << " (IntersectionCurves off: " << off << ", crease angle 95: " << steep << ")\n";
  NPR_CHECK(on == samples, "the crossing is missing from the mask");
  NPR_CHECK(off == 0 && steep == 0, "a crossing drawn where it should not be");
  return nprTestResult();
}
NPR_TEST_CASE("mask-intersections", MaskIntersections);
}
