// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// Long-running processes: a thousand windows one after another, and five hundred frames of a
// changing scene in one window, each with vtkNPRPass changing its style all the time. After a
// warm-up of 50 cycles (frames) the resident memory of the process must stay within a bound, and
// OpenGL must report no error at any point.
//
// usage: TestLongRunning CASE [DATA_DIR]   (CASE: the NPR_TEST_CASE names below)
//
// The bounds come from measurement (Documentation/testing.md, "Long-running tests"): a leak of a
// window's, a pass's or a frame's resources (framebuffers, textures, shader programs, VTK
// objects) grows the process by far more per cycle than the bounds allow over the whole run.
// Built with AddressSanitizer (the bootstrap's sanitize stage) the memory is printed but not
// checked: ASan keeps freed memory in quarantine (up to 256 MiB) and adds shadow memory, so the
// resident set grows whatever the program does; the OpenGL checks stay, and LeakSanitizer checks
// the process at exit.
#include "nprTesting.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCubeSource.h"
#include "vtkImageData.h"
#include "vtkNPROpenGL.h"
#include "vtkNPRPass.h"
#include "vtkNew.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"
#include "vtkVersionMacros.h"

#include <malloc.h>
#include <unistd.h>

#include <cmath>
#include <deque>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <sstream>
#include <string>

namespace
{
constexpr int WarmUp = 50; // cycles (frames) before the first measurement
constexpr int WindowCycles = 1000;
constexpr int SceneFrames = 500;
// Growth of the resident memory allowed from the end of the warm-up to the end of the run.
// Measured on llvmpipe (Mesa 22.3, VTK 9.1; Documentation/testing.md): between windows the
// resident set stays within 0.1 MiB of the same value over 1000 cycles; with the window alive it
// moves by up to 1.5 MiB from frame to frame (llvmpipe's and glibc's buffers) with no trend.
constexpr double WindowCyclesBoundMiB = 2.0; // 950 cycles: 2.2 KiB per cycle
constexpr double SceneFramesBoundMiB = 4.0;  // 450 frames: 9.1 KiB per frame

#if defined(__SANITIZE_ADDRESS__)
constexpr bool CheckResidentMemory = false;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool CheckResidentMemory = false;
#else
constexpr bool CheckResidentMemory = true;
#endif
#else
constexpr bool CheckResidentMemory = true;
#endif

// The resident set of this process in MiB (/proc/self/statm), after returning the heap's free
// memory to the system (malloc_trim), so that what is measured is memory in use, not free
// blocks glibc keeps.
double ResidentMiB()
{
  malloc_trim(0);
  std::ifstream statm("/proc/self/statm");
  long long size = 0, resident = 0;
  statm >> size >> resident;
  return static_cast<double>(resident) * sysconf(_SC_PAGESIZE) / (1024.0 * 1024.0);
}

// Reads and clears the OpenGL error flags of the window's context; the codes, or "" when none.
std::string OpenGLErrors(vtkRenderWindow* window)
{
  window->MakeCurrent();
  std::ostringstream codes;
  // Each flag is returned once, then cleared; an implementation has only a few.
  for (int i = 0; i < 16; ++i)
  {
    const GLenum error = glGetError();
    if (error == GL_NO_ERROR)
    {
      break;
    }
    codes << " 0x" << std::hex << error;
  }
  return codes.str();
}

// Pixels that are not the white background.
long long ObjectPixels(vtkImageData* image)
{
  const int* size = image->GetDimensions();
  long long count = 0;
  for (int y = 0; y < size[1]; ++y)
  {
    for (int x = 0; x < size[0]; ++x)
    {
      count += (nprPixel(image, x, y, 0) < 250 || nprPixel(image, x, y, 2) < 250) ? 1 : 0;
    }
  }
  return count;
}

// Checks the growth after the warm-up against the bound and prints the figures.
void CheckGrowth(
  const char* what, const char* unit, double warm, double last, int count, double boundMiB)
{
  const double growth = last - warm;
  std::cout << what << ": resident memory " << warm << " MiB after " << WarmUp << ", " << last
            << " MiB after " << WarmUp + count << ": growth " << growth * 1024.0 << " KiB, "
            << growth * 1024.0 / count << " KiB per " << unit << " (bound " << boundMiB << " MiB"
            << (CheckResidentMemory ? "" : ", not checked under AddressSanitizer") << ")\n";
  NPR_CHECK(!CheckResidentMemory || growth < boundMiB,
    what << ": resident memory grew by " << growth << " MiB in " << count << " " << unit << "s");
}

// What a long run records step by step: the steps with OpenGL errors or no image (the first ten
// reported, one line each) and its resident memory (after the warm-up, then every `Every`
// steps). Check fails on either.
struct RunLog
{
  const char* What; // "window cycles"
  const char* Unit; // "cycle"
  int Every;
  int Failed = 0;
  double Warm = 0.0;

  void Record(int step, const std::string& detail, const std::string& errors, bool drawn)
  {
    if ((!errors.empty() || !drawn) && ++this->Failed <= 10)
    {
      std::cerr << this->Unit << " " << step << detail
                << ": OpenGL errors:" << (errors.empty() ? " none" : errors)
                << (drawn ? "" : "; nothing drawn") << "\n";
    }
    if (step + 1 == WarmUp)
    {
      this->Warm = ResidentMiB();
    }
    if ((step + 1) % this->Every == 0)
    {
      std::cout << "after " << this->Unit << " " << step + 1 << ": " << ResidentMiB() << " MiB\n";
    }
  }

  void Check(int steps, double boundMiB)
  {
    // A warm-up reading of 0 (no /proc/self/statm) would make the growth bound meaningless.
    NPR_CHECK(
      !CheckResidentMemory || this->Warm > 0.0, "no resident memory read after the warm-up");
    NPR_CHECK(
      this->Failed == 0, this->Failed << " " << this->Unit << "s with OpenGL errors or no image");
    CheckGrowth(this->What, this->Unit, this->Warm, ResidentMiB(), steps - WarmUp, boundMiB);
  }
};

// ---- 1000 windows, one after another: styles, a resize, renders, ReleaseGraphicsResources ----
// One cycle: a window with a sphere and a cube drawn in two styles, resized, released and drawn
// again, then destroyed. Returns false when there was no window; errors gets the OpenGL errors.
bool WindowCycle(int cycle, std::string& errors, bool& drawn)
{
  const double origin[3] = { 0, 0, 0 }, side[3] = { 1.2, 0.3, -0.2 };
  const double orange[3] = { 0.9, 0.6, 0.3 }, grey[3] = { 0.7, 0.7, 0.75 };
  const int size = 64 + (cycle % 5) * 16; // 64..128
  nprPassScene scene(size, size);
  if (!scene.Window)
  {
    return false;
  }
  nprAddSphere(scene.Renderer, origin, 1.0, orange, 24);
  nprAddCube(scene.Renderer, side, 0.8, grey);
  scene.Camera()->Azimuth(cycle % 360);
  scene.Renderer->ResetCamera();

  // Two styles a cycle, every pair of the six in turn.
  const int first = cycle % 6, second = (cycle / 6 + first + 1) % 6;
  scene.Pass->SetStyle(first);
  drawn = ObjectPixels(scene.Render()) > size * size / 20;
  errors += OpenGLErrors(scene.Window);

  scene.Window->SetSize(size + 24, size + 8);
  scene.Pass->SetStyle(second);
  scene.Window->Render();
  errors += OpenGLErrors(scene.Window);

  // Release the pass alone, or everything the window (from VTK 9.4 on, the renderer) holds, and
  // draw again. VTK 9.6's own window cannot draw after its ReleaseGraphicsResources, with or
  // without vtkNPR ("Hardware does not support the number of textures defined", OpenGL errors
  // from glTexImage2D, then an assertion in vtkTextureObject::Bind), so from 9.4 on, where the
  // windows are VTK's, the renderer releases its pass and props instead.
  if (cycle % 2)
  {
    scene.Pass->ReleaseGraphicsResources(scene.Window);
  }
  else
  {
#if VTK_VERSION_NUMBER >= VTK_VERSION_CHECK(9, 4, 0)
    scene.Renderer->ReleaseGraphicsResources(scene.Window);
#else
    scene.Window->ReleaseGraphicsResources(scene.Window);
#endif
  }
  scene.Window->Render();
  errors += OpenGLErrors(scene.Window);
  return true;
}

int WindowCyclesCase()
{
  RunLog log{ "window cycles", "cycle", 100 };
  for (int cycle = 0; cycle < WindowCycles; ++cycle)
  {
    std::string errors;
    bool drawn = false;
    if (!WindowCycle(cycle, errors, drawn))
    {
      NPR_CHECK(false, "no window in cycle " << cycle);
      return nprTestResult();
    }
    log.Record(cycle, "", errors, drawn); // memory measured between cycles, no window alive
  }
  log.Check(WindowCycles, WindowCyclesBoundMiB);
  return nprTestResult();
}
NPR_TEST_CASE("window-cycles", WindowCyclesCase);

// ---- 500 frames of a changing scene in one window, a style change every frame ----
int SceneFramesCase()
{
  nprPassScene scene(160, 120);
  if (!scene.Window)
  {
    NPR_CHECK(false, "no window");
    return nprTestResult();
  }
  auto sphere = nprSphereSource(0.8, 8, 8);
  vtkNew<vtkPolyDataMapper> sphereMapper;
  sphereMapper->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkActor> centre;
  centre->SetMapper(sphereMapper);
  scene.Renderer->AddActor(centre);

  // Cubes come and go: one added every 4th frame, the oldest removed beyond six.
  std::deque<vtkSmartPointer<vtkActor>> cubes;
  RunLog log{ "scene frames", "frame", 50 };
  for (int frame = 0; frame < SceneFrames; ++frame)
  {
    if (frame % 4 == 0)
    {
      const double angle = frame * 0.7;
      const double center[3] = { 1.6 * std::cos(angle), 0.5 * std::sin(frame * 0.3),
        1.6 * std::sin(angle) };
      const double color[3] = { 0.3 + 0.1 * (frame % 7), 0.5, 0.9 - 0.1 * (frame % 5) };
      cubes.push_back(nprAddCube(scene.Renderer, center, 0.4 + 0.05 * (frame % 5), color));
      if (cubes.size() > 6)
      {
        scene.Renderer->RemoveActor(cubes.front());
        cubes.pop_front();
      }
    }
    // New geometry every 10th frame, a moved and recoloured actor and a moved camera every one.
    if (frame % 10 == 0)
    {
      sphere->SetThetaResolution(12 + (frame / 10) % 5 * 6);
      sphere->SetPhiResolution(8 + (frame / 10) % 4 * 4);
    }
    centre->SetPosition(0.2 * std::sin(frame * 0.1), 0.0, 0.0);
    centre->GetProperty()->SetColor(0.9, 0.4 + 0.4 * ((frame % 9) / 8.0), 0.3);
    scene.Camera()->Azimuth(7.0);
    scene.Camera()->Elevation(frame % 40 < 20 ? 1.5 : -1.5);
    scene.Camera()->OrthogonalizeViewUp();
    scene.Renderer->ResetCamera();

    // A different style every frame, in an order that meets every pair of styles.
    const int style = (frame + frame / 6) % 6;
    scene.Pass->SetStyle(style);
    std::string errors;
    bool drawn = true;
    if (frame % 25 == 0)
    {
      drawn = ObjectPixels(scene.Render()) > 160 * 120 / 20;
    }
    else
    {
      scene.Window->Render();
    }
    errors += OpenGLErrors(scene.Window);
    log.Record(frame, " (style " + std::to_string(style) + ")", errors, drawn);
  }
  log.Check(SceneFrames, SceneFramesBoundMiB);
  return nprTestResult();
}
NPR_TEST_CASE("scene-frames", SceneFramesCase);
}
