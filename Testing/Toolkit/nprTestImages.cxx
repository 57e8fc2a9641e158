// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nprTestImages.h"

#include "nprTesting.h"
#include "nprWindowImage.h"

#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPNGReader.h"
#include "vtkUnsignedCharArray.h"
#include "vtkVersionMacros.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <stdexcept>

#ifndef NPR_BASELINE_DIR
#error "NPR_BASELINE_DIR must name Testing/Data/Baseline"
#endif

int nprPixel(vtkImageData* image, int x, int y, int component)
{
  const int* dims = image->GetDimensions();
  if (x < 0 || y < 0 || x >= dims[0] || y >= dims[1])
  {
    return 0;
  }
  return static_cast<unsigned char*>(image->GetScalarPointer(x, y, 0))[component];
}

bool nprIsRed(vtkImageData* image, int x, int y)
{
  return nprPixel(image, x, y, 0) > 200 && nprPixel(image, x, y, 1) < 60;
}

bool nprNearPixel(vtkImageData* mask, int x, int y)
{
  for (int oy = -1; oy <= 1; ++oy)
  {
    for (int ox = -1; ox <= 1; ++ox)
    {
      if (nprPixel(mask, x + ox, y + oy) != 0)
      {
        return true;
      }
    }
  }
  return false;
}

long long nprCountAbove(vtkImageData* image, int threshold)
{
  const int* dims = image->GetDimensions();
  long long count = 0;
  for (int y = 0; y < dims[1]; ++y)
  {
    for (int x = 0; x < dims[0]; ++x)
    {
      count += nprPixel(image, x, y) > threshold ? 1 : 0;
    }
  }
  return count;
}
vtkSmartPointer<vtkImageData> nprCaptureImage(vtkRenderWindow* window)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->DeepCopy(nprReadWindowImage(window, false));
  return image;
}

namespace
{
const unsigned char* Pixel(vtkImageData* image, int x, int y)
{
  return static_cast<const unsigned char*>(image->GetScalarPointer(x, y, 0));
}

bool FileExists(const std::string& path)
{
  return static_cast<bool>(std::ifstream(path));
}

std::string OutputDirectory()
{
  const char* directory = std::getenv("NPR_TEST_OUTPUT_DIR");
  return directory && *directory ? directory : ".";
}

bool UpdatingBaselines()
{
  const char* update = std::getenv("NPR_UPDATE_BASELINES");
  return update && *update && std::strcmp(update, "0") != 0;
}

// Smallest largest-channel difference between pixel (x, y) of a and the 3x3 neighbourhood of
// (x, y) in b.
int NeighbourhoodDifference(vtkImageData* a, vtkImageData* b, int x, int y, int w, int h)
{
  const unsigned char* pa = Pixel(a, x, y);
  int best = 255;
  for (int dy = -1; dy <= 1; ++dy)
  {
    for (int dx = -1; dx <= 1; ++dx)
    {
      const int nx = x + dx, ny = y + dy;
      if (nx < 0 || ny < 0 || nx >= w || ny >= h)
      {
        continue;
      }
      const unsigned char* pb = Pixel(b, nx, ny);
      int difference = 0;
      for (int c = 0; c < 3; ++c)
      {
        difference = std::max(difference, std::abs(int(pa[c]) - int(pb[c])));
      }
      best = std::min(best, difference);
    }
  }
  return best;
}
}

nprPixelStatistics nprComputePixelStatistics(vtkImageData* image, const double background[3])
{
  nprPixelStatistics stats;
  int dims[3];
  image->GetDimensions(dims);
  stats.Pixels = static_cast<long long>(dims[0]) * dims[1];
  stats.MinObjectLuminance = 255.0;
  stats.Bounds[0] = dims[0];
  stats.Bounds[2] = dims[1];
  stats.Bounds[1] = stats.Bounds[3] = -1;
  double sum[3] = { 0, 0, 0 };
  for (int y = 0; y < dims[1]; ++y)
  {
    for (int x = 0; x < dims[0]; ++x)
    {
      const unsigned char* p = Pixel(image, x, y);
      double distance = 0;
      for (int c = 0; c < 3; ++c)
      {
        distance = std::max(distance, std::abs(p[c] - 255.0 * background[c]));
      }
      if (distance <= 30.0)
      {
        continue;
      }
      ++stats.ObjectPixels;
      const double luminance = 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
      stats.MinObjectLuminance = std::min(stats.MinObjectLuminance, luminance);
      stats.MaxObjectLuminance = std::max(stats.MaxObjectLuminance, luminance);
      for (int c = 0; c < 3; ++c)
      {
        sum[c] += p[c];
      }
      stats.Bounds[0] = std::min(stats.Bounds[0], x);
      stats.Bounds[1] = std::max(stats.Bounds[1], x);
      stats.Bounds[2] = std::min(stats.Bounds[2], y);
      stats.Bounds[3] = std::max(stats.Bounds[3], y);
    }
  }
  for (int c = 0; c < 3 && stats.ObjectPixels; ++c)
  {
    stats.MeanObjectColor[c] = sum[c] / stats.ObjectPixels;
  }
  return stats;
}

long long nprCountDepthsApart(
  const std::vector<float>& depths, const std::vector<float>& others, double tolerance)
{
  if (depths.size() != others.size())
  {
    return static_cast<long long>(std::max(depths.size(), others.size()));
  }
  long long apart = 0;
  for (size_t i = 0; i < depths.size(); ++i)
  {
    apart += std::abs(static_cast<double>(depths[i]) - others[i]) <= tolerance ? 0 : 1;
  }
  return apart;
}

nprImageDifference nprCompareImages(
  vtkImageData* image, vtkImageData* baseline, const nprImageTolerance& tolerance)
{
  nprImageDifference result;
  int a[3], b[3];
  image->GetDimensions(a);
  baseline->GetDimensions(b);
  result.SizeMatches = a[0] == b[0] && a[1] == b[1] && image->GetNumberOfScalarComponents() >= 3 &&
    baseline->GetNumberOfScalarComponents() >= 3;
  if (!result.SizeMatches)
  {
    return result;
  }
  const int w = a[0], h = a[1];
  result.DiffImage = vtkSmartPointer<vtkImageData>::New();
  result.DiffImage->SetDimensions(w, h, 1);
  result.DiffImage->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  result.MaxDifference = 0;
  for (int y = 0; y < h; ++y)
  {
    for (int x = 0; x < w; ++x)
    {
      const int difference = std::max(NeighbourhoodDifference(image, baseline, x, y, w, h),
        NeighbourhoodDifference(baseline, image, x, y, w, h));
      result.MaxDifference = std::max(result.MaxDifference, difference);
      auto* out = static_cast<unsigned char*>(result.DiffImage->GetScalarPointer(x, y, 0));
      const unsigned char* in = Pixel(image, x, y);
      if (difference > tolerance.PixelThreshold)
      {
        ++result.DifferingPixels;
        out[0] = 255;
        out[1] = out[2] = 0;
      }
      else
      {
        for (int c = 0; c < 3; ++c)
        {
          out[c] = static_cast<unsigned char>(in[c] / 4);
        }
      }
    }
  }
  result.DifferingFraction = static_cast<double>(result.DifferingPixels) / (double(w) * h);
  return result;
}

vtkSmartPointer<vtkImageData> nprReadPNG(const std::string& path)
{
  if (!FileExists(path))
  {
    return nullptr;
  }
  vtkNew<vtkPNGReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  if (reader->GetErrorCode() != 0)
  {
    return nullptr;
  }
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->DeepCopy(reader->GetOutput());
  return image;
}

bool nprSavePNG(vtkImageData* image, const std::string& path)
{
  try
  {
    nprWritePNG(image, path);
    return true;
  }
  catch (const std::runtime_error& error)
  {
    std::cerr << error.what() << "\n";
    return false;
  }
}

std::string nprBaselinePath(const std::string& dir, const std::string& name)
{
  const std::string release = dir + "/" + name + ".vtk-" + std::to_string(VTK_MAJOR_VERSION) + "." +
    std::to_string(VTK_MINOR_VERSION) + ".png";
  return std::ifstream(release) ? release : dir + "/" + name + ".png";
}

bool nprCompareWithBaseline(
  vtkImageData* image, const std::string& name, const nprImageTolerance& tolerance)
{
  return nprCompareWithBaselineFile(
    image, nprBaselinePath(NPR_BASELINE_DIR, name), name, tolerance);
}

bool nprCompareWithBaselineFile(vtkImageData* image, const std::string& baselinePath,
  const std::string& name, const nprImageTolerance& tolerance)
{
  if (UpdatingBaselines())
  {
    const bool written = nprSavePNG(image, baselinePath);
    std::cout << (written ? "updated baseline " : "could not write baseline ") << baselinePath
              << "\n";
    return written;
  }
  const std::string rendered = nprTestOutputPath(name + ".png");
  vtkSmartPointer<vtkImageData> baseline = nprReadPNG(baselinePath);
  if (!baseline)
  {
    nprSavePNG(image, rendered);
    std::cerr << "no baseline " << baselinePath << " (rendered image: " << rendered
              << "; run with NPR_UPDATE_BASELINES=1 to create it)\n";
    return false;
  }
  const nprImageDifference difference = nprCompareImages(image, baseline, tolerance);
  const bool passed =
    difference.SizeMatches && difference.DifferingFraction <= tolerance.MaxDifferingFraction;
  std::cout << "image " << name << " against " << baselinePath << ": "
            << (difference.SizeMatches ? "" : "size differs, ") << difference.DifferingPixels
            << " pixels differ by more than " << tolerance.PixelThreshold << " ("
            << 100.0 * difference.DifferingFraction << " %, allowed "
            << 100.0 * tolerance.MaxDifferingFraction << " %), max difference "
            << difference.MaxDifference << (passed ? ": passed" : ": FAILED") << "\n";
  if (!passed)
  {
    nprSavePNG(image, rendered);
    std::cerr << "rendered image: " << rendered << "\n";
    if (difference.DiffImage)
    {
      const std::string diff = nprTestOutputPath(name + ".diff.png");
      nprSavePNG(difference.DiffImage, diff);
      std::cerr << "diff image: " << diff << "\n";
    }
  }
  return passed;
}

std::string nprTestOutputPath(const std::string& name)
{
  return OutputDirectory() + "/" + name;
}
