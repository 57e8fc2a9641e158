// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// The baseline comparison itself can fail: identical and one-pixel-shifted images pass, a changed
// block or a different size fails and leaves the rendered and diff images behind, and
// NPR_UPDATE_BASELINES writes the baseline instead of comparing.
//
// usage: TestHarness SCRATCH_DIR
#include "nprTesting.h"

#include "vtkImageData.h"
#include "vtkVersionMacros.h"

#include <cstdlib>
#include <fstream>

namespace
{
vtkSmartPointer<vtkImageData> Gradient(int width, int height, int shift = 0)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(width, height, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  for (int y = 0; y < height; ++y)
  {
    for (int x = 0; x < width; ++x)
    {
      auto* p = static_cast<unsigned char*>(image->GetScalarPointer(x, y, 0));
      const bool disc = (x - shift - 40) * (x - shift - 40) + (y - 30) * (y - 30) < 400;
      p[0] = disc ? 230 : 20;
      p[1] = static_cast<unsigned char>(2 * y);
      p[2] = static_cast<unsigned char>(x);
    }
  }
  return image;
}

bool Exists(const std::string& path)
{
  return static_cast<bool>(std::ifstream(path));
}
}

int main(int argc, char* argv[])
{
  if (argc != 2)
  {
    return 2;
  }
  const std::string scratch = argv[1];
  setenv("NPR_TEST_OUTPUT_DIR", scratch.c_str(), 1);
  unsetenv("NPR_UPDATE_BASELINES");
  const std::string baseline = scratch + "/harness_baseline.png";
  NPR_CHECK(nprSavePNG(Gradient(80, 60), baseline), "cannot write " << baseline);
  const nprImageTolerance tolerance;

  NPR_CHECK(nprCompareWithBaselineFile(Gradient(80, 60), baseline, "harness_same", tolerance),
    "identical images differ");
  NPR_CHECK(nprCompareWithBaselineFile(Gradient(80, 60, 1), baseline, "harness_shift", tolerance),
    "a one-pixel shift is not tolerated");

  vtkSmartPointer<vtkImageData> changed = Gradient(80, 60);
  for (int y = 0; y < 10; ++y)
  {
    for (int x = 0; x < 10; ++x)
    {
      static_cast<unsigned char*>(changed->GetScalarPointer(60 + x, 40 + y, 0))[0] = 255;
    }
  }
  const nprImageDifference difference = nprCompareImages(changed, Gradient(80, 60), tolerance);
  NPR_CHECK(difference.DifferingPixels >= 64 && difference.DifferingPixels <= 144,
    "a 10x10 block gives " << difference.DifferingPixels << " differing pixels");
  std::remove((scratch + "/harness_block.png").c_str());
  std::remove((scratch + "/harness_block.diff.png").c_str());
  NPR_CHECK(!nprCompareWithBaselineFile(changed, baseline, "harness_block", tolerance),
    "a changed block passes");
  NPR_CHECK(Exists(scratch + "/harness_block.png") && Exists(scratch + "/harness_block.diff.png"),
    "a failed comparison left no rendered or diff image");
  NPR_CHECK(!nprCompareWithBaselineFile(Gradient(81, 60), baseline, "harness_size", tolerance),
    "a different size passes");
  NPR_CHECK(!nprCompareWithBaselineFile(
              Gradient(80, 60), scratch + "/missing.png", "harness_missing", tolerance),
    "a missing baseline passes");

  // A release's own baseline is preferred to the shared one, only where it exists.
  const std::string release = scratch + "/harness_release.vtk-" +
    std::to_string(VTK_MAJOR_VERSION) + "." + std::to_string(VTK_MINOR_VERSION) + ".png";
  std::remove(release.c_str());
  NPR_CHECK(nprBaselinePath(scratch, "harness_release") == scratch + "/harness_release.png",
    "a missing release baseline is chosen");
  NPR_CHECK(nprSavePNG(Gradient(80, 60), release), "cannot write " << release);
  NPR_CHECK(nprBaselinePath(scratch, "harness_release") == release,
    "the release baseline " << release << " is not chosen");

  setenv("NPR_UPDATE_BASELINES", "1", 1);
  const std::string created = scratch + "/harness_created.png";
  std::remove(created.c_str());
  NPR_CHECK(
    nprCompareWithBaselineFile(changed, created, "harness_created", tolerance) && Exists(created),
    "NPR_UPDATE_BASELINES did not write the baseline");
  unsetenv("NPR_UPDATE_BASELINES");
  NPR_CHECK(nprCompareWithBaselineFile(changed, created, "harness_created", tolerance),
    "the written baseline does not match");
  return nprTestResult();
}
