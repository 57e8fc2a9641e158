// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// npr-view: shows model files in an X window with the vtkNPR styles, switched and tuned by keys.
// Run `npr-view --help` for the flags and keys; Documentation/viewer.md describes them.
#include "nprCameraJson.h"
#include "nprModel.h"
#include "nprOutputWindow.h"
#include "nprProgram.h"
#include "nprTiming.h"
#include "nprViewOptions.h"
#include "nprViewer.h"

#include "vtkCamera.h"
#include "vtkNPRRenderWindowFactory.h"
#include "vtkNew.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"

#include <X11/Xlib.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace
{
const char* const Headless = "; use npr-render for headless rendering";

// The X connection, checked before VTK opens its window: VTK 9.1's X window aborts the process
// when it cannot open the display. It stays open until the end, as an X server such as Xvfb
// resets when its last client disconnects.
struct XConnection
{
  Display* Connection = nullptr;
  XConnection()
  {
    const char* name = std::getenv("DISPLAY");
    if (!name || !*name)
    {
      throw std::runtime_error(std::string("no X display (DISPLAY is not set)") + Headless);
    }
    this->Connection = XOpenDisplay(name);
    if (!this->Connection)
    {
      throw std::runtime_error(
        std::string("no X display: cannot open DISPLAY '") + name + "'" + Headless);
    }
  }
  ~XConnection() { XCloseDisplay(this->Connection); }
  XConnection(const XConnection&) = delete;
  XConnection& operator=(const XConnection&) = delete;
};

std::string BaseName(const std::string& path)
{
  const size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

// --orbit-benchmark: the camera turns 1 degree about the view up per frame; each frame's time
// (to glFinish) is taken, and one JSON line prints their median, minimum and maximum.
void OrbitBenchmark(const nprViewOptions& options, vtkRenderWindow* window, vtkRenderer* renderer,
  long long triangles)
{
  vtkCamera* camera = renderer->GetActiveCamera();
  std::vector<double> times;
  for (int i = 0; i < options.OrbitFrames; ++i)
  {
    camera->Azimuth(1.0);
    renderer->ResetCameraClippingRange();
    times.push_back(nprTimeFrame(window, camera));
  }
  auto milliseconds = [](double value) { return nprFormatNumber(std::round(value * 1e3) / 1e3); };
  const int* size = window->GetSize();
  std::cout << "{\"style\":" << nprJsonString(options.Pass.Style) << ",\"frames\":" << times.size()
            << ",\"median_ms\":" << milliseconds(nprMedian(times))
            << ",\"min_ms\":" << milliseconds(*std::min_element(times.begin(), times.end()))
            << ",\"max_ms\":" << milliseconds(*std::max_element(times.begin(), times.end()))
            << ",\"triangles\":" << triangles << ",\"width\":" << size[0]
            << ",\"height\":" << size[1]
            << ",\"renderer\":" << nprJsonString(vtkNPRRenderWindowFactory::GetGLRenderer(window))
            << "}" << std::endl;
}

int Run(const nprViewOptions& options, nprOutputWindow* messages)
{
  XConnection display; // before the models: no display fails fast, even with a large model

  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(options.Background[0], options.Background[1], options.Background[2]);
  long long triangles = 0;
  for (size_t i = 0; i < options.Models.size(); ++i)
  {
    triangles += nprAddModel(renderer, options.Models[i], i, "npr-view");
  }
  int width, height;
  const nprCameraState given = nprReadStartCamera(options, width, height);

  // The factory's X window (VTK's, without multisampling, as npr-render --backend x), shown.
  vtkSmartPointer<vtkRenderWindow> window =
    vtkSmartPointer<vtkRenderWindow>::Take(vtkNPRRenderWindowFactory::CreateRenderWindow("x"));
  if (!window)
  {
    throw std::runtime_error(messages->Last);
  }
  window->SetOffScreenRendering(0);
  window->SetSize(width, height);
  std::string title = "npr-view:";
  for (const std::string& model : options.Models)
  {
    title += " " + BaseName(model);
  }
  window->SetWindowName(title.c_str());
  window->AddRenderer(renderer);

  nprViewer viewer(window, renderer, options.Pass, options.OutputPrefix);
  vtkNew<nprViewInteractorStyle> style;
  style->Viewer = &viewer;
  vtkNew<vtkRenderWindowInteractor> interactor;
  interactor->SetRenderWindow(window);
  interactor->SetInteractorStyle(style);
  interactor->Initialize();

  vtkCamera* camera = renderer->GetActiveCamera();
  if (!options.CameraIn.empty())
  {
    given.ApplyTo(camera); // clipping range as given; the interaction resets it later
  }
  else
  {
    nprApplyCameraMove(renderer, options.Camera); // after the window exists: fits its aspect
  }
  window->Render(); // the first frame, with the shaders' compilation

  if (options.OrbitFrames > 0)
  {
    OrbitBenchmark(options, window, renderer, triangles);
    return 0;
  }
  interactor->Start();
  return 0;
}
}

int main(int argc, char* argv[])
{
  return nprRunProgram("npr-view",
    [&](nprOutputWindow* messages) { return Run(nprParseViewOptions(argc, argv), messages); });
}
