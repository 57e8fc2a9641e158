// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// Headless render windows, per backend: a lit object really is rendered (pixels read back),
// several windows one after another and two alive at once work, and every way a backend can be
// unavailable gives a clear error instead of a crash or a black image.
//
// usage: TestHeadlessWindows MODE [BACKEND]
//   render BACKEND     one window, a lit sphere, pixel checks
//   windows BACKEND    three windows in turn, then two alive at once, resize, release
//   egl-failure        run with no usable EGL vendor: clear error, no crash
//   osmesa-unlinked    OSMesa in a program not linked with NPR::OSMesa: clear error
//   osmesa-link-order  OSMesa with libOpenGL linked before libOSMesa: clear error
//   osmesa-unavailable a build without OSMesa (Mesa 25.1 and later): clear error
//   x-no-display       X backend without DISPLAY: clear error
//   unknown-backend    an unknown backend name: clear error
#include "nprTesting.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkConeSource.h"
#include "vtkImageData.h"
#include "vtkNPRConfigure.h"
#include "vtkNPRRenderWindowFactory.h"
#include "vtkNew.h"
#include "vtkStringOutputWindow.h"
#if NPR_HAS_OWN_HEADLESS_WINDOWS
#include "vtkNPREGLRenderWindow.h"
#include "vtkNPRHeadlessRenderWindow.h"
#include "vtkNPROSMesaRenderWindow.h"
#endif
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"

#include <cstdlib>
#include <string>

namespace
{
const double Background[3] = { 0.1, 0.1, 0.2 };

// A renderer with one lit, specular object of the given colour filling the middle of the view.
vtkSmartPointer<vtkRenderer> MakeScene(const double color[3], bool cone = false)
{
  vtkNew<vtkPolyDataMapper> mapper;
  if (cone)
  {
    vtkNew<vtkConeSource> source;
    source->SetResolution(48);
    mapper->SetInputConnection(source->GetOutputPort());
  }
  else
  {
    auto source = nprSphereSource(0.5, 64, 32);
    mapper->SetInputConnection(source->GetOutputPort());
  }
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(color[0], color[1], color[2]);
  actor->GetProperty()->SetSpecular(0.3);
  auto renderer = vtkSmartPointer<vtkRenderer>::New();
  renderer->AddActor(actor);
  renderer->SetBackground(Background[0], Background[1], Background[2]);
  renderer->ResetCamera();
  renderer->GetActiveCamera()->Azimuth(20);
  renderer->GetActiveCamera()->Elevation(15);
  return renderer;
}

// The object is there, lit (shaded, not flat), centred, of its colour, and not the whole image.
void CheckRendered(vtkRenderWindow* window, const double color[3], const std::string& what)
{
  vtkSmartPointer<vtkImageData> image = nprCaptureImage(window);
  int dims[3];
  image->GetDimensions(dims);
  const int* size = window->GetSize();
  NPR_CHECK(dims[0] == size[0] && dims[1] == size[1],
    what << ": image " << dims[0] << "x" << dims[1] << " for a window " << size[0] << "x"
         << size[1]);
  const nprPixelStatistics stats = nprComputePixelStatistics(image, Background);
  const double fraction = static_cast<double>(stats.ObjectPixels) / stats.Pixels;
  std::cout << what << ": " << dims[0] << "x" << dims[1] << ", object covers " << 100 * fraction
            << " %, luminance " << stats.MinObjectLuminance << ".." << stats.MaxObjectLuminance
            << ", mean colour " << stats.MeanObjectColor[0] << "," << stats.MeanObjectColor[1]
            << "," << stats.MeanObjectColor[2] << "\n";
  NPR_CHECK(
    fraction > 0.05 && fraction < 0.8, what << ": object covers " << 100 * fraction << " %");
  NPR_CHECK(stats.MaxObjectLuminance - stats.MinObjectLuminance > 60,
    what << ": no lighting gradient (" << stats.MinObjectLuminance << ".."
         << stats.MaxObjectLuminance << ")");
  const double centreX = 0.5 * (stats.Bounds[0] + stats.Bounds[1]);
  const double centreY = 0.5 * (stats.Bounds[2] + stats.Bounds[3]);
  NPR_CHECK(std::abs(centreX - 0.5 * dims[0]) < 0.1 * dims[0] &&
      std::abs(centreY - 0.5 * dims[1]) < 0.1 * dims[1],
    what << ": object not centred (" << centreX << "," << centreY << ")");
  // The dominant channel of the object is the dominant channel of its colour.
  int expected = 0, seen = 0;
  for (int c = 1; c < 3; ++c)
  {
    expected = color[c] > color[expected] ? c : expected;
    seen = stats.MeanObjectColor[c] > stats.MeanObjectColor[seen] ? c : seen;
  }
  NPR_CHECK(expected == seen, what << ": object has the wrong colour");
  const auto* corner = static_cast<unsigned char*>(image->GetScalarPointer(0, 0, 0));
  NPR_CHECK(std::abs(corner[2] - 255 * Background[2]) < 3, what << ": corner is not background");
}

void CheckContext(vtkRenderWindow* window, const char* backend)
{
  NPR_CHECK(std::string(vtkNPRRenderWindowFactory::GetBackendName(window)) == backend,
    "window of backend " << vtkNPRRenderWindowFactory::GetBackendName(window) << ", wanted "
                         << backend);
  const std::string renderer = vtkNPRRenderWindowFactory::GetGLRenderer(window);
  std::cout << backend << " renderer: " << renderer << "\n";
  NPR_CHECK(!renderer.empty(), "empty GL_RENDERER");
#if NPR_HAS_OWN_HEADLESS_WINDOWS
  if (auto* egl = vtkNPREGLRenderWindow::SafeDownCast(window))
  {
    const std::string device = egl->GetDeviceDescription();
    std::cout << "EGL device: " << device << (egl->GetUsesHardwareDevice() ? " (hardware)" : "")
              << "\n";
    NPR_CHECK(!device.empty(), "no EGL device description");
    const char* software = std::getenv("NPR_EGL_SOFTWARE");
    if (software && std::string(software) == "1")
    {
      NPR_CHECK(!egl->GetUsesHardwareDevice() &&
          (device.find("software") != std::string::npos ||
            device.find("surfaceless") != std::string::npos),
        "NPR_EGL_SOFTWARE=1 but the device is " << device);
      NPR_CHECK(renderer.find("llvmpipe") != std::string::npos ||
          renderer.find("softpipe") != std::string::npos,
        "NPR_EGL_SOFTWARE=1 but the renderer is " << renderer);
    }
  }
#endif
}

void TestRender(const char* backend)
{
  vtkSmartPointer<vtkRenderWindow> window = nprCreateTestWindow(320, 240, backend);
  NPR_CHECK(window, "no " << backend << " window");
  if (!window)
  {
    return;
  }
  const double orange[3] = { 1.0, 0.55, 0.2 };
  window->AddRenderer(MakeScene(orange));
  window->Render();
  CheckContext(window, backend);
  CheckRendered(window, orange, std::string(backend) + " sphere");
}

void TestWindows(const char* backend)
{
  const double colors[3][3] = { { 0.9, 0.2, 0.2 }, { 0.2, 0.8, 0.2 }, { 0.2, 0.3, 0.95 } };
  for (int i = 0; i < 3; ++i)
  {
    vtkSmartPointer<vtkRenderWindow> window =
      nprCreateTestWindow(200 + 60 * i, 160 + 40 * i, backend);
    NPR_CHECK(window, "no window " << i);
    if (!window)
    {
      return;
    }
    window->AddRenderer(MakeScene(colors[i], i == 1));
    window->Render();
    CheckRendered(window, colors[i], "sequential window " + std::to_string(i));
  }

  // Two alive at once, rendered alternately: each keeps its own context and image.
  vtkSmartPointer<vtkRenderWindow> a = nprCreateTestWindow(300, 200, backend);
  vtkSmartPointer<vtkRenderWindow> b = nprCreateTestWindow(160, 240, backend);
  NPR_CHECK(a && b, "could not make two windows at once");
  if (!a || !b)
  {
    return;
  }
  a->AddRenderer(MakeScene(colors[0]));
  b->AddRenderer(MakeScene(colors[2], true));
  for (int round = 0; round < 3; ++round)
  {
    a->Render();
    b->Render();
  }
  CheckRendered(a, colors[0], "window A of two");
  CheckRendered(b, colors[2], "window B of two");
  a->Render();
  CheckRendered(a, colors[0], "window A after B rendered");

  // Resize, and release graphics resources: the next render rebuilds everything.
  a->SetSize(400, 300);
  a->Render();
  CheckRendered(a, colors[0], "window A resized to 400x300");
  a->ReleaseGraphicsResources(a);
  a->Render();
  CheckRendered(a, colors[0], "window A after ReleaseGraphicsResources");
  b->Render();
  CheckRendered(b, colors[2], "window B after A was released");
}

// A backend that cannot work: the factory returns nullptr and its warning names the reason.
void TestFactoryRefuses(const char* backend, const char* reason)
{
  vtkNew<vtkStringOutputWindow> capture;
  vtkSmartPointer<vtkOutputWindow> previous = vtkOutputWindow::GetInstance();
  vtkOutputWindow::SetInstance(capture);
  vtkSmartPointer<vtkRenderWindow> made = nprCreateTestWindow(64, 64, backend);
  vtkOutputWindow::SetInstance(previous);
  NPR_CHECK(!made, "the factory made a " << backend << " window that cannot work");
  const std::string said = capture->GetOutput();
  std::cout << backend << " factory said: " << said << "\n";
  NPR_CHECK(said.find(std::string("no ") + backend + " render window") != std::string::npos &&
      said.find(reason) != std::string::npos,
    "the factory's warning does not say 'no " << backend << " render window' and '" << reason
                                              << "'");
}

#if NPR_HAS_OWN_HEADLESS_WINDOWS
// The module's own window made directly renders nothing, reports why, and does not crash.
void TestUnavailable(vtkNPRHeadlessRenderWindow* window, const char* backend, const char* reason)
{
  vtkSmartPointer<vtkRenderWindow> made = nprCreateTestWindow(64, 64, backend);
  NPR_CHECK(!made, "the factory made a " << backend << " window that cannot work");
  window->SetSize(64, 64);
  const double color[3] = { 1, 1, 1 };
  window->AddRenderer(MakeScene(color));
  window->Render(); // must not crash
  window->Render(); // nor report twice
  NPR_CHECK(!window->HasValidContext(), "context reported valid");
  const std::string error = window->GetContextError();
  std::cout << backend << " error: " << error << "\n";
  NPR_CHECK(error.find(reason) != std::string::npos,
    "error '" << error << "' does not mention '" << reason << "'");
}
#endif
}

int main(int argc, char* argv[])
{
  const std::string mode = argc > 1 ? argv[1] : "";
  const char* backend = argc > 2 ? argv[2] : nullptr;
  if (mode == "render" && backend)
  {
    TestRender(backend);
  }
  else if (mode == "windows" && backend)
  {
    TestWindows(backend);
  }
  else if (mode == "egl-failure")
  {
#if NPR_HAS_OWN_HEADLESS_WINDOWS
    TestFactoryRefuses("egl", "no EGL display");
    vtkNew<vtkNPREGLRenderWindow> window;
    TestUnavailable(window, "egl", "no EGL display");
#else
    TestFactoryRefuses("egl", "vtkEGLRenderWindow could not create an OpenGL 3.2 context");
#endif
  }
  else if (mode == "osmesa-unavailable")
  {
    NPR_CHECK(!NPR_HAS_OSMESA, "this build has the osmesa backend");
    TestFactoryRefuses("osmesa", "not available in this build");
  }
#if NPR_HAS_OWN_HEADLESS_WINDOWS
  else if (mode == "osmesa-unlinked")
  {
    NPR_CHECK(!vtkNPROSMesaRenderWindow::IsLinkedWithOSMesa(), "OSMesa reported linked");
    vtkNew<vtkNPROSMesaRenderWindow> window;
    TestUnavailable(window, "osmesa", "NPR::OSMesa");
  }
  else if (mode == "osmesa-link-order")
  {
    vtkNew<vtkNPROSMesaRenderWindow> window;
    TestUnavailable(window, "osmesa", "link order");
  }
#endif
  else if (mode == "x-no-display")
  {
    unsetenv("DISPLAY");
    NPR_CHECK(!nprCreateTestWindow(64, 64, "x"), "an X window without DISPLAY");
    setenv("DISPLAY", ":97", 1); // no server there: VTK itself would abort the process
    NPR_CHECK(!nprCreateTestWindow(64, 64, "x"), "an X window on a display that does not open");
  }
  else if (mode == "unknown-backend")
  {
    NPR_CHECK(!nprCreateTestWindow(64, 64, "vulkan"), "a window for an unknown backend");
    NPR_CHECK(!vtkNPRRenderWindowFactory::IsKnownBackend("vulkan"), "vulkan known");
    NPR_CHECK(vtkNPRRenderWindowFactory::IsKnownBackend("egl"), "egl unknown");
  }
  else
  {
    std::cerr << "usage: TestHeadlessWindows render|windows BACKEND | egl-failure | "
                 "osmesa-unlinked | osmesa-link-order | osmesa-unavailable | x-no-display | "
                 "unknown-backend\n";
    return 2;
  }
  return nprTestResult();
}
