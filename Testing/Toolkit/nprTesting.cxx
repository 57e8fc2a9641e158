// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nprTesting.h"

#include "vtkActor.h"
#include "vtkAlgorithm.h"
#include "vtkCamera.h"
#include "vtkImageData.h"
#include "vtkNPREdgePass.h"
#include "vtkNPRRenderWindowFactory.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

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

void nprUpdateCounting(vtkAlgorithm* algorithm, nprCountingOutputWindow* messages)
{
  vtkOutputWindow* previous = vtkOutputWindow::GetInstance();
  previous->Register(nullptr);
  vtkOutputWindow::SetInstance(messages);
  algorithm->Update();
  vtkOutputWindow::SetInstance(previous);
  previous->UnRegister(nullptr);
}

std::map<std::string, std::function<int()>>& nprTestCases()
{
  static std::map<std::string, std::function<int()>> cases;
  return cases;
}

nprTestCase::nprTestCase(const std::string& name, std::function<int()> run)
{
  if (!nprTestCases().emplace(name, std::move(run)).second)
  {
    std::cerr << "the test case " << name << " is registered twice\n";
    std::abort();
  }
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
    nprSavePNG(image, std::string(dump) + std::to_string(count++) + ".png");
  }
  return image;
}

void nprPassScene::LookAtOrigin(double distance)
{
  const double eye[3] = { 0, 0, distance };
  nprLookAtOrigin(this->Camera(), eye, 10.0);
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

void nprPassScene::ViewParallel(double scale)
{
  this->Camera()->ParallelProjectionOn();
  this->Camera()->SetParallelScale(scale);
}

vtkSmartPointer<vtkActor> nprPassScene::ShowCube(double distance, const double color[3])
{
  const double origin[3] = { 0, 0, 0 };
  vtkSmartPointer<vtkActor> cube = nprAddCube(this->Renderer, origin, 1.0, color);
  this->LookAtOrigin(distance);
  return cube;
}

vtkSmartPointer<vtkActor> nprPassScene::AddSphereBehind()
{
  const double behind[3] = { 0.6, 0, -1.5 }, red[3] = { 1, 0, 0 };
  vtkSmartPointer<vtkActor> ball = nprAddSphere(this->AddOverlay(), behind, 0.6, red, 32);
  ball->GetProperty()->LightingOff();
  return ball;
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
