// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// The frame time of inking an actor that shows its mesh edges (Documentation/classic-techniques.md,
// "Mesh edges"): a 1.28M-triangle sphere at 800x600, the camera turned 1 degree a frame, shaded
// and inked, without and with mesh edges, in one process. Prints each case's median of 5 frames
// (after 2 that prepare the shaders) and the inked frames' ratio to the shaded one with the same
// edges, in CPU time of the process (all threads: llvmpipe's too; wall time moves with whatever
// else the machine runs) up to glFinish. A measurement, not a test: nothing is checked.
//
// usage: InkEdgesTiming timing
#include "nprTesting.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkNPRPass.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkSphereSource.h"

#include <algorithm>
#include <cstdio>
#include <ctime>
#include <vector>

namespace
{
double CpuMs()
{
  timespec now;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &now);
  return 1e3 * now.tv_sec + 1e-6 * now.tv_nsec;
}

// The median frame time in milliseconds of `frames` frames after `warmUp`.
double MedianFrameMs(nprPassScene& scene, int warmUp, int frames)
{
  std::vector<double> times;
  for (int i = 0; i < warmUp + frames; ++i)
  {
    scene.Camera()->Azimuth(1.0);
    const double start = CpuMs();
    scene.Window->Render();
    scene.Window->WaitForCompletion();
    const double ms = CpuMs() - start;
    if (i >= warmUp)
    {
      times.push_back(ms);
    }
  }
  std::sort(times.begin(), times.end());
  return times[times.size() / 2];
}

int Timing()
{
  nprPassScene scene(800, 600);
  auto sphere = nprSphereSource(1.0, 1000, 642);
  vtkSmartPointer<vtkActor> actor = nprAddActor(scene.Renderer, sphere->GetOutputPort(), nprGrey);
  scene.Renderer->ResetCamera();
  double ms[2][2]; // [inked][edges]
  for (int edges = 0; edges < 2; ++edges)
  {
    actor->GetProperty()->SetEdgeVisibility(edges);
    for (int inked = 0; inked < 2; ++inked)
    {
      scene.Pass->SetStyle(inked ? vtkNPRPass::INKED : vtkNPRPass::SHADED);
      ms[inked][edges] = MedianFrameMs(scene, 2, 5);
    }
  }
  std::printf("CPU time: shaded %.0f ms, shaded+edges %.0f ms, inked %.0f ms (%.2fx shaded), "
              "inked+edges %.0f ms (%.2fx shaded+edges)\n",
    ms[0][0], ms[0][1], ms[1][0], ms[1][0] / ms[0][0], ms[1][1], ms[1][1] / ms[0][1]);
  return 0;
}
NPR_TEST_CASE("timing", Timing);
}
