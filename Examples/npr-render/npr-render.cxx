// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// npr-render: renders model files headless into a PNG or a vector drawing (SVG, PDF), with the
// vtkNPR styles.
// Run `npr-render --help` for the flags; Documentation/cli.md describes them.
#include "nprCameraJson.h"
#include "nprFiles.h"
#include "nprModel.h"
#include "nprOrbit.h"
#include "nprOutputWindow.h"
#include "nprPassSettings.h"
#include "nprProgram.h"
#include "nprRenderOptions.h"
#include "nprTiming.h"
#include "nprWindowImage.h"

#include "vtkCamera.h"
#include "vtkFloatArray.h"
#include "vtkNPRDrawingSheet.h"
#include "vtkNPRInkPass.h"
#include "vtkNPRPass.h"
#include "vtkNPRReferenceMask.h"
#include "vtkNPRRenderWindowFactory.h"
#include "vtkNew.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace
{
// The visible object-space lines of what --lines asks for, as a white-on-black 8-bit grey PNG:
// silhouettes and creases as named (with --smooth-silhouettes, silhouettes as smooth contours);
// contours (object outlines) are silhouettes and boundaries; non-manifold edges, where surfaces
// meet at an angle, go with creases.
void WriteReferenceMask(
  vtkRenderer* renderer, const nprRenderOptions& options, int width, int height)
{
  const nprPassSettings& lines = options.Pass;
  vtkNew<vtkNPRReferenceMask> reference;
  reference->SetRenderer(renderer);
  reference->SetSize(width, height);
  reference->SetSilhouettes(lines.Silhouettes || lines.Contours);
  reference->SetBoundaries(lines.Contours);
  reference->SetCreases(lines.Creases);
  reference->SetNonManifoldEdges(lines.Creases);
  reference->SetCreaseAngle(lines.CreaseAngle);
  reference->SetSmoothContours(lines.SmoothSilhouettes);
  if (!reference->Update())
  {
    throw std::runtime_error("cannot compute the reference mask");
  }
  nprWritePNG(reference->GetMask(), options.ReferenceMask);
}

// --sheet: the views on one page, as a vector file.
void WriteSheet(vtkRenderer* renderer, const nprRenderOptions& options)
{
  vtkNew<vtkNPRDrawingSheet> sheet;
  sheet->SetRenderer(renderer);
  sheet->SetFileName(options.Output.c_str());
  sheet->SetViews(options.Sheet.c_str());
  sheet->SetPaperSize(vtkNPRDrawingSheet::GetPaperSizeFromName(options.SheetPaper.c_str()));
  sheet->SetArrangement(
    options.SheetThirdAngle ? vtkNPRDrawingSheet::THIRD_ANGLE : vtkNPRDrawingSheet::FIRST_ANGLE);
  sheet->SetMargin(options.SheetMargin);
  sheet->SetFillFaces(options.FillFaces);
  sheet->SetFillColors(options.FillColors);
  if (!sheet->Write())
  {
    throw std::runtime_error(sheet->GetErrorMessage());
  }
}

// --frames: times the main style and every --compare-style, and prints one JSON line about the
// scene (its triangles, the window's size) and the times.
void TimeFrames(const nprRenderOptions& options, vtkRenderWindow* window, vtkRenderer* renderer,
  vtkNPRPass* pass, long long triangles, int width, int height)
{
  // Each timed frame is a real one (the camera is modified, so nothing is reused) and ends
  // with glFinish. With --compare-style the styles alternate frame by frame in this window, so
  // all see the same machine state.
  // One pass per style; "shaded" is VTK's own chain (no pass).
  std::vector<std::string> styles = { options.Pass.Style };
  styles.insert(styles.end(), options.CompareStyles.begin(), options.CompareStyles.end());
  std::vector<vtkSmartPointer<vtkNPRPass>> passes = { pass };
  for (size_t i = 1; i < styles.size(); ++i)
  {
    nprPassSettings compare = options.Pass;
    compare.Style = styles[i];
    passes.push_back(styles[i] == "shaded" ? nullptr : nprMakePass(compare));
  }
  std::vector<std::vector<double>> times(styles.size());
  for (int i = -1; i < options.Frames; ++i) // frame -1: warm-up of every style
  {
    for (size_t variant = 0; variant < styles.size(); ++variant)
    {
      renderer->SetPass(passes[variant]);
      const double ms = nprTimeFrame(window, renderer->GetActiveCamera());
      if (i >= 0)
      {
        times[variant].push_back(ms);
      }
    }
  }
  renderer->SetPass(pass);
  auto milliseconds = [](double value) { return nprFormatNumber(std::round(value * 1e3) / 1e3); };
  auto ratio = [](double value) { return nprFormatNumber(std::round(value * 1e3) / 1e3); };
  const std::vector<double>& main = times[0];
  const double mainMedian = nprMedian(main);
  std::cout << "{\"style\":" << nprJsonString(options.Pass.Style) << ",\"frames\":" << main.size()
            << ",\"median_ms\":" << milliseconds(mainMedian)
            << ",\"min_ms\":" << milliseconds(*std::min_element(main.begin(), main.end()))
            << ",\"max_ms\":" << milliseconds(*std::max_element(main.begin(), main.end()));
  if (styles.size() > 1)
  {
    // The first compared style as before; every compared style with its time over the main's.
    std::cout << ",\"compare_style\":" << nprJsonString(styles[1])
              << ",\"compare_median_ms\":" << milliseconds(nprMedian(times[1]))
              << ",\"ratio\":" << ratio(mainMedian / nprMedian(times[1])) << ",\"compare\":[";
    for (size_t i = 1; i < styles.size(); ++i)
    {
      std::cout << (i > 1 ? "," : "") << "{\"style\":" << nprJsonString(styles[i])
                << ",\"median_ms\":" << milliseconds(nprMedian(times[i]))
                << ",\"ratio_to_main\":" << ratio(nprMedian(times[i]) / mainMedian) << "}";
    }
    std::cout << "]";
  }
  std::cout << ",\"triangles\":" << triangles
            << ",\"pixels\":" << static_cast<long long>(width) * height << ",\"width\":" << width
            << ",\"height\":" << height
            << ",\"backend\":" << nprJsonString(vtkNPRRenderWindowFactory::GetBackendName(window))
            << ",\"renderer\":" << nprJsonString(vtkNPRRenderWindowFactory::GetGLRenderer(window))
            << "}" << std::endl;
}

// The factory's reason, told to a command-line user: where this npr-render cannot load OSMesa
// (VTK 9.1-9.3), the program that can is npr-render-osmesa, not a CMake target.
std::string WhyNoWindow(const std::string& reason)
{
  if (reason.find("NPR::OSMesa") == std::string::npos)
  {
    return reason;
  }
  return "no osmesa render window: this npr-render renders with EGL or X; for OSMesa run "
         "npr-render-osmesa with the same options";
}

// The folders of every file the options write, before minutes of reading and rendering.
void MakeOutputFolders(const nprRenderOptions& options)
{
  for (const std::string* path :
    { &options.Output, &options.CameraOut, &options.EdgeMask, &options.ReferenceMask })
  {
    if (!path->empty())
    {
      nprMakeOutputFolders(*path);
    }
  }
}

// --edge-mask: the style's line pass draws its coverage alone for one render (the edge pass reuses
// its G-buffer and line image: only the composite runs).
void WriteEdgeMask(vtkRenderWindow* window, vtkNPRPass* pass, const nprRenderOptions& options)
{
  auto write = [&](auto* linePass)
  {
    linePass->CoverageOnlyOn();
    window->Render();
    nprWriteWindowPNG(window, options.EdgeMask, true);
    linePass->CoverageOnlyOff();
  };
  if (options.Pass.Style == "inked")
  {
    write(pass->GetInkPass());
  }
  else
  {
    write(pass->GetEdgePass());
  }
}

// A picture of the background alone is never silent: nothing wrote a depth (a model far smaller
// than a pixel at this camera, or one the camera file points away from).
void WarnWhenNothingDrawn(vtkRenderWindow* window, long long triangles)
{
  const int* size = window->GetSize();
  vtkNew<vtkFloatArray> depth;
  if (window->GetZbufferData(0, 0, size[0] - 1, size[1] - 1, depth) != VTK_OK)
  {
    return;
  }
  const float* values = depth->GetPointer(0);
  if (std::all_of(values, values + depth->GetNumberOfValues(), [](float z) { return z >= 1.0f; }))
  {
    std::cerr << "npr-render: warning: the " << size[0] << "x" << size[1]
              << " picture shows only the background: none of the " << triangles
              << " triangles covers a pixel (the model is far smaller than a pixel at this "
                 "camera, or out of its view)\n";
  }
}

// -o: the sheet, the drawing as a vector file, or the window's image.
void WriteOutput(vtkRenderWindow* window, vtkRenderer* renderer, const nprRenderOptions& options)
{
  if (!options.Sheet.empty())
  {
    WriteSheet(renderer, options);
  }
  else if (!options.Output.empty() && nprIsDrawingFile(options.Output))
  {
    // .svg, .pdf, .ps, .eps
    nprWriteDrawing(renderer, options.Output, options.FillFaces, options.FillColors);
  }
  else if (!options.Output.empty())
  {
    // The first frame is what it writes, unless --frames drew others since.
    nprWriteWindowPNG(window, options.Output, false, options.Frames > 0);
  }
}

// The window at the start camera's size, with the renderer; the camera as given or moved.
vtkSmartPointer<vtkRenderWindow> OpenWindow(const nprRenderOptions& options, vtkRenderer* renderer,
  const nprCameraState& given, int width, int height, nprOutputWindow* messages)
{
  vtkSmartPointer<vtkRenderWindow> window = vtkSmartPointer<vtkRenderWindow>::Take(
    vtkNPRRenderWindowFactory::CreateRenderWindow(options.Backend.c_str()));
  if (!window)
  {
    throw std::runtime_error(WhyNoWindow(messages->Last));
  }
  window->SetSize(width, height);
  window->AddRenderer(renderer);
  if (!options.CameraIn.empty())
  {
    given.ApplyTo(renderer->GetActiveCamera()); // clipping range as given
  }
  else
  {
    // After the window exists: the reset fits the scene to its aspect ratio.
    nprApplyCameraMove(renderer, options.Camera);
  }
  return window;
}

// What a still render writes, after its timed frames if any: the image or drawing, the masks
// and the camera file.
void WriteStill(const nprRenderOptions& options, vtkRenderWindow* window, vtkRenderer* renderer,
  vtkNPRPass* pass, nprProgress& progress, int width, int height)
{
  progress.Start();
  WriteOutput(window, renderer, options);
  if (!options.Output.empty())
  {
    progress.Done("wrote " + options.Output);
  }
  if (!options.EdgeMask.empty())
  {
    WriteEdgeMask(window, pass, options);
  }
  if (!options.ReferenceMask.empty())
  {
    WriteReferenceMask(renderer, options, width, height); // the camera of the render above
  }
  if (!options.CameraOut.empty())
  {
    nprWriteCameraFile(
      options.CameraOut, nprCameraState::FromCamera(renderer->GetActiveCamera(), width, height));
  }
}

int Run(const nprRenderOptions& options, nprOutputWindow* messages)
{
  MakeOutputFolders(options);
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(options.Background[0], options.Background[1], options.Background[2]);
  // "shaded" is VTK's own chain, untouched: the baseline every style is measured against.
  vtkSmartPointer<vtkNPRPass> pass;
  if (options.Pass.Style != "shaded")
  {
    pass = nprMakePass(options.Pass);
    renderer->SetPass(pass);
  }
  nprProgress progress("npr-render", options.Quiet);
  long long triangles = 0;
  for (size_t i = 0; i < options.Models.size(); ++i)
  {
    triangles += nprAddModel(renderer, options.Models[i], i, "npr-render", &progress);
  }
  int width, height;
  const nprCameraState given = nprReadStartCamera(options, width, height);
  vtkSmartPointer<vtkRenderWindow> window =
    OpenWindow(options, renderer, given, width, height, messages);
  progress.Start();
  window->Render();
  progress.Done("first frame (" + options.Pass.Style + ")");
  WarnWhenNothingDrawn(window, triangles);
  if (options.Orbit > 0)
  {
    if (!options.CameraOut.empty())
    {
      nprWriteCameraFile(
        options.CameraOut, nprCameraState::FromCamera(renderer->GetActiveCamera(), width, height));
    }
    nprOrbitSettings orbit;
    orbit.Output = options.Output;
    orbit.Frames = options.Orbit;
    orbit.Degrees = options.OrbitDegrees;
    orbit.Rate = options.Rate;
    nprWriteOrbit(window, renderer, orbit);
    return 0;
  }
  if (options.Frames > 0)
  {
    TimeFrames(options, window, renderer, pass, triangles, width, height);
  }
  WriteStill(options, window, renderer, pass, progress, width, height);
  return 0;
}
}

int main(int argc, char* argv[])
{
  return nprRunProgram("npr-render",
    [&](nprOutputWindow* messages) { return Run(nprParseRenderOptions(argc, argv), messages); });
}
