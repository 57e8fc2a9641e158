// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nprTesting.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCubeSource.h"
#include "vtkIdList.h"
#include "vtkImageData.h"
#include "vtkNPREdgePass.h"
#include "vtkNPRModelReader.h"
#include "vtkNPRRenderWindowFactory.h"
#include "vtkNPRShadingNormals.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPNGReader.h"
#include "vtkPNGWriter.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"
#include "vtkUnsignedCharArray.h"
#include "vtkVersionMacros.h"
#include "vtkWindowToImageFilter.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>

#ifndef NPR_BASELINE_DIR
#error "NPR_BASELINE_DIR must name Testing/Data/Baseline"
#endif

vtkStandardNewMacro(nprCountingOutputWindow);

void nprCountingOutputWindow::DisplayErrorText(const char* text)
{
  ++this->Errors;
  std::cerr << "VTK error: " << text << "\n";
}

void nprCountingOutputWindow::DisplayWarningText(const char* text)
{
  ++this->Warnings;
  std::cerr << "VTK warning: " << text << "\n";
}

std::string& nprTestDataDir()
{
  static std::string folder = ".";
  return folder;
}

int nprRunTestCase(int argc, char* argv[], const std::map<std::string, std::function<int()>>& cases)
{
  const auto found = argc >= 2 ? cases.find(argv[1]) : cases.end();
  if (found == cases.end())
  {
    std::cerr << "usage: " << argv[0] << " CASE [DATA_DIR]; CASE is one of:";
    for (const auto& entry : cases)
    {
      std::cerr << " " << entry.first;
    }
    std::cerr << "\n";
    return 2;
  }
  nprTestDataDir() = argc > 2 ? argv[2] : ".";
  vtkNew<nprCountingOutputWindow> output;
  vtkOutputWindow::SetInstance(output);
  int result = found->second();
  NPR_CHECK(output->Errors == 0, output->Errors << " VTK errors reported");
  if (output->Errors)
  {
    result = nprTestResult();
  }
  vtkOutputWindow::SetInstance(nullptr);
  return result;
}

vtkSmartPointer<vtkActor> nprAddActor(
  vtkRenderer* renderer, vtkAlgorithmOutput* port, const double color[3])
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(port);
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  if (color)
  {
    actor->GetProperty()->SetColor(color[0], color[1], color[2]);
  }
  renderer->AddActor(actor);
  return actor;
}

nprPassScene::nprPassScene(int width, int height)
  : Width(width)
  , Height(height)
{
  this->Window = nprCreateTestWindow(width, height, nullptr);
  this->Renderer->SetBackground(1.0, 1.0, 1.0);
  this->Renderer->SetPass(this->Pass);
  this->Window->AddRenderer(this->Renderer);
}

vtkSmartPointer<vtkImageData> nprPassScene::Render()
{
  this->Window->Render();
  return nprCaptureImage(this->Window);
}

vtkSmartPointer<vtkImageData> nprPassScene::Mask()
{
  this->Edges()->CoverageOnlyOn();
  auto image = this->Render();
  this->Edges()->CoverageOnlyOff();
  if (const char* dump = std::getenv("NPR_TEST_DUMP")) // NPR_TEST_DUMP=prefix: keep the masks
  {
    static int count = 0;
    nprWritePNG(image, std::string(dump) + std::to_string(count++) + ".png");
  }
  return image;
}

void nprPassScene::LookAtOrigin(double distance)
{
  this->Camera()->SetPosition(0, 0, distance);
  this->Camera()->SetFocalPoint(0, 0, 0);
  this->Camera()->SetViewUp(0, 1, 0);
  this->Camera()->SetClippingRange(1, 10);
}

void nprPassScene::Project(const double world[3], double display[2])
{
  nprWorldToDisplay(this->Renderer, world, display);
}

vtkSmartPointer<vtkRenderer> nprPassScene::AddOverlay()
{
  auto overlay = vtkSmartPointer<vtkRenderer>::New();
  overlay->SetLayer(1);
  overlay->PreserveDepthBufferOn();
  overlay->SetActiveCamera(this->Camera());
  overlay->InteractiveOff();
  this->Window->SetNumberOfLayers(2);
  this->Window->AddRenderer(overlay);
  return overlay;
}

void nprWorldToDisplay(vtkRenderer* renderer, const double world[3], double display[2])
{
  renderer->SetWorldPoint(world[0], world[1], world[2], 1.0);
  renderer->WorldToDisplay();
  const double* point = renderer->GetDisplayPoint();
  display[0] = point[0];
  display[1] = point[1];
}

double nprSegmentDistance(const double p[2], const double a[2], const double b[2])
{
  const double abx = b[0] - a[0], aby = b[1] - a[1];
  const double length2 = abx * abx + aby * aby;
  double t = length2 > 0 ? ((p[0] - a[0]) * abx + (p[1] - a[1]) * aby) / length2 : 0.0;
  t = std::min(1.0, std::max(0.0, t));
  return std::hypot(p[0] - (a[0] + t * abx), p[1] - (a[1] + t * aby));
}

vtkSmartPointer<vtkActor> nprAddCube(
  vtkRenderer* renderer, const double center[3], double size, const double color[3])
{
  vtkNew<vtkCubeSource> cube;
  cube->SetCenter(center[0], center[1], center[2]);
  cube->SetXLength(size);
  cube->SetYLength(size);
  cube->SetZLength(size);
  return nprAddActor(renderer, cube->GetOutputPort(), color);
}

vtkSmartPointer<vtkActor> nprAddSphere(vtkRenderer* renderer, const double center[3], double radius,
  const double color[3], int resolution)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(center[0], center[1], center[2]);
  sphere->SetRadius(radius);
  sphere->SetThetaResolution(resolution);
  sphere->SetPhiResolution(resolution / 2);
  return nprAddActor(renderer, sphere->GetOutputPort(), color);
}

void nprViewFromCorner(vtkCamera* camera, const double eye[3], bool parallel)
{
  camera->SetPosition(eye[0], eye[1], eye[2]);
  camera->SetFocalPoint(0, 0, 0);
  camera->SetViewUp(0, 1, 0);
  camera->SetViewAngle(30);
  camera->SetParallelProjection(parallel);
  camera->SetParallelScale(1.0);
  camera->SetClippingRange(1.0, 10.0);
}

bool nprSameCells(vtkCellArray* a, vtkCellArray* b)
{
  bool same = a->GetNumberOfCells() == b->GetNumberOfCells();
  vtkNew<vtkIdList> idsA, idsB;
  for (vtkIdType cell = 0; same && cell < a->GetNumberOfCells(); ++cell)
  {
    a->GetCellAtId(cell, idsA);
    b->GetCellAtId(cell, idsB);
    same = idsA->GetNumberOfIds() == idsB->GetNumberOfIds() &&
      std::equal(idsA->begin(), idsA->end(), idsB->begin());
  }
  return same;
}

vtkSmartPointer<vtkNPRModelReader> nprReadTestModel(const std::string& model)
{
  auto reader = vtkSmartPointer<vtkNPRModelReader>::New();
  reader->SetFileName((nprTestDataDir() + "/" + model).c_str());
  reader->Update();
  NPR_CHECK(!*reader->GetErrorMessage(), reader->GetErrorMessage());
  return reader;
}

void nprTurnBaselineCamera(vtkRenderer* renderer)
{
  renderer->ResetCamera();
  renderer->GetActiveCamera()->Azimuth(30);
  renderer->GetActiveCamera()->Elevation(30);
  renderer->GetActiveCamera()->OrthogonalizeViewUp();
  renderer->ResetCameraClippingRange();
}

vtkSmartPointer<vtkActor> nprAddBaselineModel(vtkRenderer* renderer, const std::string& model)
{
  vtkNew<vtkNPRShadingNormals> normals;
  normals->SetInputConnection(nprReadTestModel(model)->GetOutputPort());
  const double color[3] = { 0.85, 0.82, 0.75 };
  vtkSmartPointer<vtkActor> actor = nprAddActor(renderer, normals->GetOutputPort(), color);
  actor->GetProperty()->SetSpecular(0.3);
  actor->GetProperty()->SetSpecularPower(30.0);
  nprTurnBaselineCamera(renderer);
  return actor;
}

int nprPixel(vtkImageData* image, int x, int y, int component)
{
  const int* dims = image->GetDimensions();
  if (x < 0 || y < 0 || x >= dims[0] || y >= dims[1])
  {
    return 0;
  }
  return static_cast<unsigned char*>(image->GetScalarPointer(x, y, 0))[component];
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

int& nprTestFailures()
{
  static int failures = 0;
  return failures;
}

vtkSmartPointer<vtkRenderWindow> nprCreateTestWindow(int width, int height, const char* backend)
{
  auto window =
    vtkSmartPointer<vtkRenderWindow>::Take(vtkNPRRenderWindowFactory::CreateRenderWindow(backend));
  if (window)
  {
    window->SetMultiSamples(0);
    window->SetSize(width, height);
  }
  return window;
}

vtkSmartPointer<vtkImageData> nprCaptureImage(vtkRenderWindow* window)
{
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();
  grab->ShouldRerenderOff();
  grab->Update();
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->DeepCopy(grab->GetOutput());
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

bool nprWritePNG(vtkImageData* image, const std::string& path)
{
  vtkNew<vtkPNGWriter> writer;
  writer->SetFileName(path.c_str());
  writer->SetInputData(image);
  writer->Write();
  return writer->GetErrorCode() == 0;
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
    const bool written = nprWritePNG(image, baselinePath);
    std::cout << (written ? "updated baseline " : "could not write baseline ") << baselinePath
              << "\n";
    return written;
  }
  const std::string rendered = OutputDirectory() + "/" + name + ".png";
  vtkSmartPointer<vtkImageData> baseline = nprReadPNG(baselinePath);
  if (!baseline)
  {
    nprWritePNG(image, rendered);
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
    nprWritePNG(image, rendered);
    std::cerr << "rendered image: " << rendered << "\n";
    if (difference.DiffImage)
    {
      const std::string diff = OutputDirectory() + "/" + name + ".diff.png";
      nprWritePNG(difference.DiffImage, diff);
      std::cerr << "diff image: " << diff << "\n";
    }
  }
  return passed;
}
