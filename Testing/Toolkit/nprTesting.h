// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// The vtkNPR test toolkit (Testing/Toolkit): test cases and checks, headless windows and the
// scene of a vtkNPRPass. The toolkit's other headers, included here: nprTestMeshes.h (meshes,
// actors, models, cameras) and nprTestImages.h (pixels, PNG files, baseline comparison).
#ifndef nprTesting_h
#define nprTesting_h

#include "nprTestImages.h"
#include "nprTestMeshes.h"

#include "vtkNPRPass.h"
#include "vtkNew.h"
#include "vtkOutputWindow.h"
#include "vtkRenderWindow.h" // for nprPassScene
#include "vtkRenderer.h"     // for nprPassScene
#include "vtkSmartPointer.h"

#include <functional>
#include <iostream>
#include <map>
#include <string>

class vtkActor;
class vtkAlgorithm;
class vtkCamera;
class vtkImageData;
class vtkRenderWindow;
class vtkRenderer;

// Counts the errors and warnings VTK reports while a test runs: a pass that works reports none.
class nprCountingOutputWindow : public vtkOutputWindow
{
public:
  static nprCountingOutputWindow* New();
  vtkTypeMacro(nprCountingOutputWindow, vtkOutputWindow);
  void DisplayErrorText(const char* text) override;
  void DisplayWarningText(const char* text) override;
  void DisplayGenericWarningText(const char* text) override { this->DisplayWarningText(text); }
  int Errors = 0;
  int Warnings = 0;
};

// The data folder given to a test program (its second argument; "." without one).
std::string& nprTestDataDir();

// Updates the algorithm with VTK's messages counted into messages instead of the test's own
// window (for a check of the messages a bad input gives).
void nprUpdateCounting(vtkAlgorithm* algorithm, nprCountingOutputWindow* messages);

// The main of a test program of named cases: "PROGRAM CASE [DATA_DIR]". Runs the case with an
// nprCountingOutputWindow installed and fails it when VTK reported an error; 2 for a bad call.
// The toolkit's main (nprTestMain.cxx) calls it with nprTestCases().
int nprRunTestCase(
  int argc, char* argv[], const std::map<std::string, std::function<int()>>& cases);

// The cases registered by NPR_TEST_CASE in the program's sources, by name.
std::map<std::string, std::function<int()>>& nprTestCases();
struct nprTestCase
{
  nprTestCase(const std::string& name, std::function<int()> run); // aborts on a repeated name
};
// NPR_TEST_CASE("name", function or lambda returning nprTestResult()) at namespace scope, beside
// the function it runs: ctest's "PROGRAM name DATA_DIR" runs it.
#define NPR_TEST_CASE_JOIN(a, b) a##b
#define NPR_TEST_CASE_NAME(line) NPR_TEST_CASE_JOIN(nprTestCaseAt, line)
#define NPR_TEST_CASE(name, ...) const nprTestCase NPR_TEST_CASE_NAME(__LINE__)(name, __VA_ARGS__)

// A test window of the given size with one renderer (white background) drawn by a vtkNPRPass.
// Tests derive their own scene from it to add helpers.
struct nprPassScene
{
  vtkSmartPointer<vtkRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkNPRPass> Pass;
  int Width, Height;

  nprPassScene(int width, int height);
  vtkNPREdgePass* Edges() { return this->Pass->GetEdgePass(); }
  vtkNPRGBufferPass* GBuffer() { return this->Pass->GetGBufferPass(); }
  vtkNPRToonPass* Toon() { return this->Pass->GetToonPass(); }
  vtkNPRSketchPass* Sketch() { return this->Pass->GetSketchPass(); }
  vtkNPRInkPass* Ink() { return this->Pass->GetInkPass(); }
  vtkCamera* Camera() { return this->Renderer->GetActiveCamera(); }
  // Renders a frame and returns the window's colour buffer (nprCaptureImage).
  vtkSmartPointer<vtkImageData> Render();
  // The edge pass's line coverage alone, white lines on black (NPR_TEST_DUMP=prefix keeps them).
  vtkSmartPointer<vtkImageData> Mask();
  // The camera on +z at distance, looking at the origin, y up, clipping range 1..10.
  void LookAtOrigin(double distance);
  // Window coordinates of a world point (nprWorldToDisplay).
  void Project(const double world[3], double display[2]);
  // A renderer on layer 1 that keeps the depth buffer and shares the camera: it is depth-tested
  // against what the pass left.
  vtkSmartPointer<vtkRenderer> AddOverlay();
  // A parallel projection of the given scale.
  void ViewParallel(double scale);
  // A unit cube at the origin (nprAddCube) seen from +z at distance (LookAtOrigin).
  vtkSmartPointer<vtkActor> ShowCube(double distance, const double color[3] = nullptr);
  // The layer tests' red, unlit sphere behind the cube's right edge (centre (0.6, 0, -1.5),
  // radius 0.6) on an overlay (AddOverlay): nprIsRed where it shows.
  vtkSmartPointer<vtkActor> AddSphereBehind();
};

// Window coordinates (pixel centres at +0.5) of a world point through the renderer.
void nprWorldToDisplay(vtkRenderer* renderer, const double world[3], double display[2]);

// Distance from p to the segment ab, in the plane.
double nprSegmentDistance(const double p[2], const double a[2], const double b[2]);

// Counts failed checks; a test returns nprTestResult().
int& nprTestFailures();
inline int nprTestResult()
{
  std::cout << (nprTestFailures() ? "FAILED" : "PASSED") << " (" << nprTestFailures()
            << " failed checks)\n";
  return nprTestFailures() ? 1 : 0;
}
#define NPR_CHECK(condition, message)                                                              \
  do                                                                                               \
  {                                                                                                \
    if (!(condition))                                                                              \
    {                                                                                              \
      ++nprTestFailures();                                                                         \
      std::cerr << __FILE__ << ":" << __LINE__ << ": check failed: " #condition ": " << message    \
                << "\n";                                                                           \
    }                                                                                              \
  } while (0)

// A window from vtkNPRRenderWindowFactory (backend nullptr: the default), multisampling off.
vtkSmartPointer<vtkRenderWindow> nprCreateTestWindow(int width, int height, const char* backend);

#endif
