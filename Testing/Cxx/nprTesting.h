// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// The vtkNPR test harness: headless windows, pixel statistics and baseline comparison.
//
// Baseline comparison (nprCompareWithBaseline, npr-image-compare):
// - A pixel's difference is the largest channel difference (0..255) between it and the best
//   match among the 3x3 neighbourhood of the same pixel in the other image, taken both ways, so
//   that edges moved by one pixel (rasteriser differences between drivers) do not count.
// - A pixel differs when that difference exceeds PixelThreshold (default 16).
// - The comparison fails when the images' sizes differ or when more than MaxDifferingFraction of
//   the pixels differ (default 0.002, i.e. 0.2 %).
// On failure the rendered image and a diff image (differing pixels red on a dimmed copy) are
// written to $NPR_TEST_OUTPUT_DIR (default: the current directory) and their paths printed.
// With NPR_UPDATE_BASELINES=1 the rendered image replaces the baseline instead, and the
// comparison passes: baselines change only on purpose (target `update-baselines`).
// One baseline serves every VTK release. Where a release's own shading differs, a baseline
// <name>.vtk-MAJOR.MINOR.png beside <name>.png is used for that release instead
// (nprBaselinePath); the tolerance is never loosened for it.
#ifndef nprTesting_h
#define nprTesting_h

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
class vtkAlgorithmOutput;
class vtkCamera;
class vtkCellArray;
class vtkImageData;
class vtkNPRModelReader;
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

// The main of a test program of named cases: "PROGRAM CASE [DATA_DIR]". Runs the case with an
// nprCountingOutputWindow installed and fails it when VTK reported an error; 2 for a bad call.
int nprRunTestCase(
  int argc, char* argv[], const std::map<std::string, std::function<int()>>& cases);

// An actor of the port's polygons (through a vtkPolyDataMapper) added to the renderer.
vtkSmartPointer<vtkActor> nprAddActor(
  vtkRenderer* renderer, vtkAlgorithmOutput* port, const double color[3] = nullptr);

// A cube of edge length size about center (vtkCubeSource), added as by nprAddActor.
vtkSmartPointer<vtkActor> nprAddCube(
  vtkRenderer* renderer, const double center[3], double size, const double color[3] = nullptr);

// A sphere of resolution x resolution / 2 facets (theta x phi), added as by nprAddActor.
vtkSmartPointer<vtkActor> nprAddSphere(vtkRenderer* renderer, const double center[3], double radius,
  const double color[3], int resolution = 128);

// The cube tests' camera: at eye, looking at the origin, y up, a view angle of 30 degrees or a
// parallel scale of 1, clipping range 1..10.
void nprViewFromCorner(vtkCamera* camera, const double eye[3], bool parallel);

// Testing/Data/<model> read by vtkNPRModelReader (updated); a failed check when it reports one.
vtkSmartPointer<vtkNPRModelReader> nprReadTestModel(const std::string& model);

// The same cells with the same point ids in the same order, whatever the storage (VTK 9.6's
// readers and filters keep 32-bit ids where they fit, this project's cell arrays vtkIdType).
bool nprSameCells(vtkCellArray* a, vtkCellArray* b);

// The baseline scenes' view: the camera reset, then turned 30 degrees in azimuth and elevation.
void nprTurnBaselineCamera(vtkRenderer* renderer);

// The baseline scenes' model: nprReadTestModel, prepared by vtkNPRShadingNormals as npr-render
// prepares it, in a warm grey with a little specular, added to the renderer; then
// nprTurnBaselineCamera.
vtkSmartPointer<vtkActor> nprAddBaselineModel(vtkRenderer* renderer, const std::string& model);

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
};

// Window coordinates (pixel centres at +0.5) of a world point through the renderer.
void nprWorldToDisplay(vtkRenderer* renderer, const double world[3], double display[2]);

// Distance from p to the segment ab, in the plane.
double nprSegmentDistance(const double p[2], const double a[2], const double b[2]);

// A channel (0..255) of an unsigned char image's pixel; 0 outside the image.
int nprPixel(vtkImageData* image, int x, int y, int component = 0);

// The pixels whose first channel exceeds threshold.
long long nprCountAbove(vtkImageData* image, int threshold);

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

// The window's colour buffer as RGB (3 x unsigned char, origin bottom left).
vtkSmartPointer<vtkImageData> nprCaptureImage(vtkRenderWindow* window);

struct nprPixelStatistics
{
  long long Pixels = 0;          // all pixels
  long long ObjectPixels = 0;    // pixels farther than 30 (max channel) from the background
  double MinObjectLuminance = 0; // 0..255, over object pixels
  double MaxObjectLuminance = 0;
  double MeanObjectColor[3] = { 0, 0, 0 };
  int Bounds[4] = { 0, 0, 0, 0 }; // xmin, xmax, ymin, ymax of the object pixels
};
nprPixelStatistics nprComputePixelStatistics(vtkImageData* image, const double background[3]);

struct nprImageTolerance
{
  int PixelThreshold = 16;
  double MaxDifferingFraction = 0.002;
};

struct nprImageDifference
{
  bool SizeMatches = false;
  long long DifferingPixels = 0;
  double DifferingFraction = 1.0;
  int MaxDifference = 255;
  vtkSmartPointer<vtkImageData> DiffImage;
};
nprImageDifference nprCompareImages(
  vtkImageData* image, vtkImageData* baseline, const nprImageTolerance& tolerance);

// Compares with Testing/Data/Baseline/<name>.png (see above). Returns true when it matches.
// <dir>/<name>.vtk-MAJOR.MINOR.png for the VTK this test is built with when that file exists,
// else <dir>/<name>.png.
std::string nprBaselinePath(const std::string& dir, const std::string& name);

bool nprCompareWithBaseline(vtkImageData* image, const std::string& name,
  const nprImageTolerance& tolerance = nprImageTolerance());
bool nprCompareWithBaselineFile(vtkImageData* image, const std::string& baselinePath,
  const std::string& name, const nprImageTolerance& tolerance = nprImageTolerance());

vtkSmartPointer<vtkImageData> nprReadPNG(const std::string& path);
bool nprWritePNG(vtkImageData* image, const std::string& path);

#endif
