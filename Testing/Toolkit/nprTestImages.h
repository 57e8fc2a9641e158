// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// The test toolkit's images: pixels, window captures, statistics, PNG files and baselines.
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
#ifndef nprTestImages_h
#define nprTestImages_h

#include "vtkSmartPointer.h"

#include <string>
#include <vector>

class vtkImageData;
class vtkRenderWindow;

// A channel (0..255) of an unsigned char image's pixel; 0 outside the image.
int nprPixel(vtkImageData* image, int x, int y, int component = 0);

// Whether the pixel is red (red above 200, green below 60), as nprPassScene::AddSphereBehind.
bool nprIsRed(vtkImageData* image, int x, int y);

// Whether a pixel among the 3x3 about (x, y) has a non-zero first channel (a line pixel within one
// pixel of it).
bool nprNearPixel(vtkImageData* mask, int x, int y);

// The pixels whose first channel exceeds threshold.
long long nprCountAbove(vtkImageData* image, int threshold);

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

// The most a window depth moves when a shader reads it from a depth texture and writes it back as
// gl_FragDepth (through a float: a few steps of the floats just below 1), against a copy.
constexpr double nprDepthReadRounding = 1.0 / (1 << 22);

// How many depths of two window depth buffers differ by more than `tolerance` (all, if their
// sizes differ).
long long nprCountDepthsApart(
  const std::vector<float>& depths, const std::vector<float>& others, double tolerance);

// Compares with Testing/Data/Baseline/<name>.png (see above). Returns true when it matches.
// <dir>/<name>.vtk-MAJOR.MINOR.png for the VTK this test is built with when that file exists,
// else <dir>/<name>.png.
std::string nprBaselinePath(const std::string& dir, const std::string& name);

bool nprCompareWithBaseline(vtkImageData* image, const std::string& name,
  const nprImageTolerance& tolerance = nprImageTolerance());
bool nprCompareWithBaselineFile(vtkImageData* image, const std::string& baselinePath,
  const std::string& name, const nprImageTolerance& tolerance = nprImageTolerance());

vtkSmartPointer<vtkImageData> nprReadPNG(const std::string& path);
// nprWritePNG (Examples/Common/nprWindowImage.h, which makes the folders above path) with its
// failure reported on stderr instead of thrown: whether the file was written.
bool nprSavePNG(vtkImageData* image, const std::string& path);

// The path of a file named name in $NPR_TEST_OUTPUT_DIR (default: the current directory), where
// a test leaves the files it writes.
std::string nprTestOutputPath(const std::string& name);

#endif
