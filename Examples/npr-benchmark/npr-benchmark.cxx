// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// npr-benchmark: run time against error of every line method, for a set of scenes and cameras,
// against the object-space reference mask. Documentation/benchmarks.md describes the scenes,
// methods and figures; `npr-benchmark --help` the flags.
#include "nprBenchmarkCoherence.h"
#include "nprBenchmarkContours.h"
#include "nprBenchmarkDrawing.h"
#include "nprBenchmarkMethods.h"
#include "nprBenchmarkOptions.h"
#include "nprBenchmarkReport.h"
#include "nprBenchmarkScale.h"
#include "nprBenchmarkScenes.h"
#include "nprBenchmarkSpeed.h"
#include "nprBenchmarkStage.h"
#include "nprBenchmarkStress.h"
#include "nprEdgeMetrics.h"
#include "nprOutputWindow.h"
#include "nprProgram.h"
#include "nprTiming.h"

#include "vtkNPRPass.h"
#include "vtkNPRRenderWindowFactory.h"
#include "vtkRenderWindow.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <iostream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace
{
// Every method's frames in one view, interleaved: frame -1 warms every method up (shaders,
// buffers of this size), then they alternate frame by frame, so all see the same machine state.
struct ViewTimes
{
  std::vector<double> Shaded;
  std::vector<std::vector<double>> Methods;
};

ViewTimes TimeMethods(nprBenchmarkStage& stage, const std::vector<nprBenchmarkMethod>& methods,
  const std::vector<vtkSmartPointer<vtkNPRPass>>& passes, int frames)
{
  ViewTimes times;
  times.Methods.resize(methods.size());
  for (int frame = -1; frame < frames; ++frame)
  {
    stage.Activate(nullptr, false);
    const double ms = stage.TimedFrame(false);
    if (frame >= 0)
    {
      times.Shaded.push_back(ms);
    }
    for (size_t m = 0; m < methods.size(); ++m)
    {
      const bool lines = methods[m].Family == nprBenchmarkMethod::ObjectLines;
      stage.Activate(passes[m], lines);
      const double t = stage.TimedFrame(lines);
      if (frame >= 0)
      {
        times.Methods[m].push_back(t);
      }
    }
  }
  return times;
}

// One method's row in one view: its times and its mask against the reference.
nprBenchmarkRow ScoreMethod(const nprBenchmarkMethod& method, const nprMask& mask,
  const nprMask& reference, const std::vector<double>& times, double shadedMedian)
{
  nprEdgeMetrics metrics;
  metrics.Compute(mask.Pixels.data(), reference.Pixels.data(), mask.Width, mask.Height);
  nprBenchmarkRow row;
  row.Width = mask.Width;
  row.Height = mask.Height;
  row.Method = method.Name;
  row.Settings = method.Settings;
  row.Frames = static_cast<int>(times.size());
  row.MedianMs = nprMedian(times);
  row.MinMs = *std::min_element(times.begin(), times.end());
  row.ShadedMedianMs = shadedMedian;
  row.Ratio = shadedMedian > 0 ? row.MedianMs / shadedMedian : 0.0;
  row.MethodPixels = metrics.GetMethodPixels();
  row.ReferencePixels = metrics.GetReferencePixels();
  for (int t = 0; t < 2; ++t)
  {
    row.Precision[t] = metrics.Precision(t + 1.0);
    row.Recall[t] = metrics.Recall(t + 1.0);
    row.F1[t] = metrics.F1(t + 1.0);
  }
  row.MeanDistance = metrics.MeanSymmetricDistance();
  return row;
}

using LineMethodsRun = nprBenchmarkRun<nprBenchmarkRow>;

// One scene at the window's size from one camera: the reference, every method timed and scored.
void MeasureView(LineMethodsRun& run, const nprBenchmarkScene& scene,
  const nprBenchmarkCamera& camera, const std::string& progress)
{
  nprBenchmarkStage& stage = run.Stage;
  const nprClock::time_point viewStart = nprClock::now();
  const int* size = stage.Window->GetSize();
  const std::string sizeName = std::to_string(size[0]) + "x" + std::to_string(size[1]);
  stage.Activate(nullptr, false);
  nprApplyBenchmarkCamera(stage.Renderer, camera);
  stage.Window->Render(); // the camera as drawn, before the reference reads it
  std::cerr << "npr-benchmark: " << progress << " " << scene.Name << " " << camera.Name << " "
            << sizeName << ": reference";
  const nprClock::time_point referenceStart = nprClock::now();
  const nprMask reference = stage.ReferenceMask();
  std::cerr << " " << nprFormat(nprSecondsSince(referenceStart), 3) << " s";
  const std::string prefix =
    run.Options.Out + "/masks/" + scene.Name + "_" + camera.Name + "_" + sizeName + "_";
  if (run.Options.SaveMasks)
  {
    nprWriteMaskPNG(reference, prefix + "reference.png");
  }
  const ViewTimes times = TimeMethods(stage, run.Methods, run.Passes, run.Options.Frames);
  const double shadedMedian = nprMedian(times.Shaded);
  std::cerr << ", shaded " << nprFormat(shadedMedian, 3) << " ms";
  for (size_t m = 0; m < run.Methods.size(); ++m)
  {
    const nprMask mask = stage.MethodMask(run.Methods[m], run.Passes[m]);
    if (run.Options.SaveMasks)
    {
      nprWriteMaskPNG(mask, prefix + run.Methods[m].Name + ".png");
    }
    nprBenchmarkRow row =
      ScoreMethod(run.Methods[m], mask, reference, times.Methods[m], shadedMedian);
    row.Scene = scene.Name;
    row.Triangles = scene.Triangles;
    row.Camera = camera.Name;
    run.Rows.push_back(row);
  }
  stage.Activate(nullptr, false);
  std::cerr << "; done in " << nprFormat(nprSecondsSince(viewStart), 3) << " s\n";
}

// results.csv, results.md and the time-against-F1 plots.
void WriteLineMethodResults(
  const LineMethodsRun& run, const std::vector<nprBenchmarkScene>& scenes, double seconds)
{
  const nprBenchmarkOptions& options = run.Options;
  nprBenchmarkInfo info;
  info.Renderer = vtkNPRRenderWindowFactory::GetGLRenderer(run.Stage.Window);
  info.Backend = vtkNPRRenderWindowFactory::GetBackendName(run.Stage.Window);
  info.Frames = options.Frames;
  info.Sizes = nprBenchmarkSizesLine(options);
  info.Scenes = nprBenchmarkSceneLines(scenes);
  info.Cameras = nprBenchmarkCameraLine(options.Cameras);
  for (const nprBenchmarkMethod& method : run.Methods)
  {
    info.Methods += "- " + method.Name + ": " + method.Settings + "\n";
  }
  info.Methods += "\nEvery method draws lines " + nprFormat(options.LineWidth) +
    " px wide. Reference: vtkNPRReferenceMask (visible silhouettes, creases above 30 degrees, "
    "boundary and non-manifold edges, one pixel wide).\n";
  info.Seconds = seconds;
  nprWriteBenchmarkCSV(options.Out + "/results.csv", run.Rows);
  nprWriteBenchmarkMarkdown(options.Out + "/results.md", run.Rows, info);
  const std::string title = "Line methods on " + info.Renderer;
  nprWritePlot(options.Out + "/time_vs_f1.png", nprPlotPoints(run.Rows, "", true), title,
    "frame time / shaded frame time (median over scenes, cameras and sizes)");
  for (const auto& size : options.Sizes)
  {
    const std::string name = std::to_string(size.first) + "x" + std::to_string(size.second);
    nprWritePlot(options.Out + "/time_vs_f1_" + name + ".png", nprPlotPoints(run.Rows, name, false),
      title + ", " + name, "median frame time (ms)");
  }
}

int RunBenchmark(const nprBenchmarkOptions& options)
{
  const nprClock::time_point runStart = nprClock::now();
  std::vector<nprBenchmarkMethod> methods = nprSelectBenchmarkMethods(options.Methods);
  if (methods.empty())
  {
    throw std::runtime_error("no method to run");
  }
  const std::vector<nprBenchmarkScene> scenes = nprStartBenchmarkRun(options);
  LineMethodsRun run(options, std::move(methods));
  const size_t views = scenes.size() * options.Cameras * options.Sizes.size();
  size_t view = 0;
  for (const nprBenchmarkScene& scene : scenes)
  {
    run.Stage.SetMesh(scene.Mesh, scene.Raw);
    for (const auto& size : options.Sizes)
    {
      run.Stage.Window->SetSize(size.first, size.second);
      for (int c = 0; c < options.Cameras; ++c)
      {
        const std::string progress =
          "[" + std::to_string(++view) + "/" + std::to_string(views) + "]";
        MeasureView(run, scene, nprBenchmarkCameras()[c], progress);
      }
    }
  }
  WriteLineMethodResults(run, scenes, nprSecondsSince(runStart));
  std::cerr << "npr-benchmark: wrote " << options.Out << "/results.{csv,md}, time_vs_f1*.png in "
            << nprFormat(nprSecondsSince(runStart), 4) << " s\n";
  return nprBenchmarkStatus(nprCheckBenchmarkRows(run.Rows), ": figures out of range");
}
}

int main(int argc, char* argv[])
{
  return nprRunProgram("npr-benchmark",
    [&](nprOutputWindow* messages)
    {
      messages->EchoPrefix = "npr-benchmark: vtk: ";
      const nprBenchmarkOptions options = nprParseBenchmarkOptions(argc, argv);
      if (options.Coherence)
      {
        return nprRunBenchmarkCoherence(options);
      }
      if (options.Drawing)
      {
        return nprRunBenchmarkDrawing(options);
      }
      if (options.Contours)
      {
        return nprRunBenchmarkContours(options);
      }
      if (options.Speed)
      {
        return nprRunBenchmarkSpeed(options);
      }
      if (!options.ScaleSteps.empty())
      {
        return nprRunScaleSteps(options);
      }
      if (options.Scale)
      {
        return nprRunBenchmarkScale(options);
      }
      return options.Stress ? nprRunBenchmarkStress(options) : RunBenchmark(options);
    });
}
