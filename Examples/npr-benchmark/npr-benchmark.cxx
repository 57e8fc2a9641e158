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
#include <vector>

namespace
{
int RunBenchmark(const nprBenchmarkOptions& options)
{
  const nprClock::time_point runStart = nprClock::now();
  const std::vector<nprBenchmarkMethod> methods = nprSelectBenchmarkMethods(options.Methods);
  if (methods.empty())
  {
    throw std::runtime_error("no method to run");
  }
  const std::vector<nprBenchmarkScene> scenes = nprStartBenchmarkRun(options);

  nprBenchmarkStage stage(options.LineWidth);
  std::vector<vtkSmartPointer<vtkNPRPass>> passes;
  for (const nprBenchmarkMethod& method : methods)
  {
    passes.push_back(stage.MakePass(method));
  }

  std::vector<nprBenchmarkRow> rows;
  const size_t views = scenes.size() * options.Cameras * options.Sizes.size();
  size_t view = 0;
  for (const nprBenchmarkScene& scene : scenes)
  {
    stage.SetMesh(scene.Mesh, scene.Raw);
    for (const auto& size : options.Sizes)
    {
      stage.Window->SetSize(size.first, size.second);
      for (int c = 0; c < options.Cameras; ++c)
      {
        const nprClock::time_point viewStart = nprClock::now();
        const nprBenchmarkCamera& camera = nprBenchmarkCameras()[c];
        stage.Activate(nullptr, false);
        nprApplyBenchmarkCamera(stage.Renderer, camera);
        stage.Window->Render(); // the camera as drawn, before the reference reads it
        ++view;
        std::cerr << "npr-benchmark: [" << view << "/" << views << "] " << scene.Name << " "
                  << camera.Name << " " << size.first << "x" << size.second << ": reference";
        const nprClock::time_point referenceStart = nprClock::now();
        const nprMask reference = stage.ReferenceMask();
        std::cerr << " " << nprFormat(nprSecondsSince(referenceStart), 3) << " s";
        const std::string prefix = options.Out + "/masks/" + scene.Name + "_" + camera.Name + "_" +
          std::to_string(size.first) + "x" + std::to_string(size.second) + "_";
        if (options.SaveMasks)
        {
          nprWriteMaskPNG(reference, prefix + "reference.png");
        }

        // Frame -1 warms every variant up (shaders, buffers of this size). Then the variants
        // alternate frame by frame: all see the same machine state.
        std::vector<double> shaded;
        std::vector<std::vector<double>> times(methods.size());
        for (int frame = -1; frame < options.Frames; ++frame)
        {
          stage.Activate(nullptr, false);
          const double ms = stage.TimedFrame(false);
          if (frame >= 0)
          {
            shaded.push_back(ms);
          }
          for (size_t m = 0; m < methods.size(); ++m)
          {
            const bool lines = methods[m].Family == nprBenchmarkMethod::ObjectLines;
            stage.Activate(passes[m], lines);
            const double t = stage.TimedFrame(lines);
            if (frame >= 0)
            {
              times[m].push_back(t);
            }
          }
        }
        const double shadedMedian = nprMedian(shaded);
        std::cerr << ", shaded " << nprFormat(shadedMedian, 3) << " ms";

        for (size_t m = 0; m < methods.size(); ++m)
        {
          const nprMask mask = stage.MethodMask(methods[m], passes[m]);
          if (options.SaveMasks)
          {
            nprWriteMaskPNG(mask, prefix + methods[m].Name + ".png");
          }
          nprEdgeMetrics metrics;
          metrics.Compute(mask.Pixels.data(), reference.Pixels.data(), mask.Width, mask.Height);
          nprBenchmarkRow row;
          row.Scene = scene.Name;
          row.Triangles = scene.Triangles;
          row.Camera = camera.Name;
          row.Width = size.first;
          row.Height = size.second;
          row.Method = methods[m].Name;
          row.Settings = methods[m].Settings;
          row.Frames = options.Frames;
          row.MedianMs = nprMedian(times[m]);
          row.MinMs = *std::min_element(times[m].begin(), times[m].end());
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
          rows.push_back(row);
        }
        stage.Activate(nullptr, false);
        std::cerr << "; done in " << nprFormat(nprSecondsSince(viewStart), 3) << " s\n";
      }
    }
  }

  nprBenchmarkInfo info;
  info.Renderer = vtkNPRRenderWindowFactory::GetGLRenderer(stage.Window);
  info.Backend = vtkNPRRenderWindowFactory::GetBackendName(stage.Window);
  info.Frames = options.Frames;
  info.Sizes = nprBenchmarkSizesLine(options);
  info.Scenes = nprBenchmarkSceneLines(scenes);
  info.Cameras = nprBenchmarkCameraLine(options.Cameras);
  for (const nprBenchmarkMethod& method : methods)
  {
    info.Methods += "- " + method.Name + ": " + method.Settings + "\n";
  }
  info.Methods += "\nEvery method draws lines " + nprFormat(options.LineWidth) +
    " px wide. Reference: vtkNPRReferenceMask (visible silhouettes, creases above 30 degrees, "
    "boundary and non-manifold edges, one pixel wide).\n";
  info.Seconds = nprSecondsSince(runStart);

  nprWriteBenchmarkCSV(options.Out + "/results.csv", rows);
  nprWriteBenchmarkMarkdown(options.Out + "/results.md", rows, info);
  const std::string title = "Line methods on " + info.Renderer;
  nprWritePlot(options.Out + "/time_vs_f1.png", nprPlotPoints(rows, "", true), title,
    "frame time / shaded frame time (median over scenes, cameras and sizes)");
  for (const auto& size : options.Sizes)
  {
    const std::string name = std::to_string(size.first) + "x" + std::to_string(size.second);
    nprWritePlot(options.Out + "/time_vs_f1_" + name + ".png", nprPlotPoints(rows, name, false),
      title + ", " + name, "median frame time (ms)");
  }
  std::cerr << "npr-benchmark: wrote " << options.Out << "/results.{csv,md}, time_vs_f1*.png in "
            << nprFormat(nprSecondsSince(runStart), 4) << " s\n";

  return nprBenchmarkStatus(nprCheckBenchmarkRows(rows), ": figures out of range");
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
