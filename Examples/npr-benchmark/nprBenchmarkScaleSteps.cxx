// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// npr-benchmark --scale-steps: one model's steps in this process (a child of --scale, so that
// its memory is its own), in the order npr-render runs them.
#include "nprBenchmarkOptions.h"
#include "nprBenchmarkProcess.h"
#include "nprBenchmarkReport.h"
#include "nprBenchmarkScale.h"
#include "nprBenchmarkScenes.h"
#include "nprBenchmarkStage.h"
#include "nprModel.h"
#include "nprPassSettings.h"
#include "nprTiming.h"

#include "vtkCamera.h"
#include "vtkNPRDrawingLines.h"
#include "vtkNPRDrawingPass.h"
#include "vtkNPRFeatureLines.h"
#include "vtkNPRPass.h"
#include "vtkNPRRenderWindowFactory.h"
#include "vtkPolyData.h"
#include "vtkTimerLog.h"

#include <algorithm>
#include <cstring>
#include <fstream>
#include <functional>
#include <iostream>
#include <sstream>
#include <stdexcept>

namespace
{
// The styles of the breakdown; "shaded" is VTK's own chain, as npr-render draws it.
const char* const Styles[] = { "shaded", "edges", "sketch", "toon+edges", "drawing" };

// The events vtkNPRModelReader and vtkNPRShadingNormals log in vtkTimerLog.
const char* const ReaderEvents[] = { "vtkNPRModelReader: validate", "vtkNPRModelReader: read",
  "vtkNPRModelReader: check points" };
const char* const NormalsEvents[] = { "vtkNPRShadingNormals: merge",
  "vtkNPRShadingNormals: normals" };

// The summed time of an event's START/END pairs in vtkTimerLog; -1 when it was not logged.
double LoggedSeconds(const char* event)
{
  double total = 0.0;
  bool found = false;
  std::vector<double> starts;
  for (int i = 0; i < vtkTimerLog::GetNumberOfEvents(); ++i)
  {
    if (std::strcmp(vtkTimerLog::GetEventString(i), event) != 0)
    {
      continue;
    }
    if (vtkTimerLog::GetEventType(i) == vtkTimerLogEntry::START)
    {
      starts.push_back(vtkTimerLog::GetEventWallTime(i));
    }
    else if (vtkTimerLog::GetEventType(i) == vtkTimerLogEntry::END && !starts.empty())
    {
      total += vtkTimerLog::GetEventWallTime(i) - starts.back();
      starts.pop_back();
      found = true;
    }
  }
  return found ? total : -1.0;
}

class StepLog
{
public:
  // Runs work with the peak memory reset first. work returns the step's time in seconds (a
  // median of frames), or < 0 for its whole wall time.
  void Measure(const std::string& name, const std::function<double()>& work)
  {
    const bool reset = nprResetPeakMemory();
    const double before = nprResidentMB();
    const nprClock::time_point start = nprClock::now();
    double seconds = work();
    seconds = seconds < 0.0 ? nprSecondsSince(start) : seconds;
    const double peak = nprPeakResidentMB();
    // The memory may shrink between the reset and its reading: then the step added nothing.
    const double added = std::max(0.0, peak - before);
    this->Rows.push_back({ name, seconds, reset ? peak : -1.0, reset ? added : -1.0 });
    std::cerr << "npr-benchmark: " << name << ": " << nprFixed(1e3 * seconds, 1) << " ms, peak "
              << nprFixed(peak, 0) << " MB\n";
  }
  // A part of the step before (no peak of its own); seconds < 0: not measured.
  void Part(const std::string& name, double seconds)
  {
    this->Rows.push_back({ name, seconds, -1.0, -1.0 });
  }
  // The timer-log events of the step just measured, as its parts.
  template <size_t N>
  void LoggedParts(const char* const (&events)[N])
  {
    for (const char* event : events)
    {
      this->Part(event, LoggedSeconds(event));
    }
    vtkTimerLog::ResetLog();
  }
  std::vector<nprScaleStep> Rows;
};

// vtkNPRFeatureLines on the file's mesh: the first update (its adjacency) and each camera change
// after it. Its own filter, freed after, so the frames below do not carry its memory.
void MeasureFeatureLines(StepLog& log, vtkPolyData* raw, vtkCamera* camera, int frames)
{
  vtkNew<vtkNPRFeatureLines> lines;
  lines->SetInputData(raw);
  log.Measure("feature lines: first update (adjacency)",
    [&]()
    {
      lines->SetCamera(camera);
      lines->Update();
      return -1.0;
    });
  log.Measure("feature lines per camera change",
    [&]()
    {
      std::vector<double> times;
      for (int frame = 0; frame < frames; ++frame)
      {
        camera->Azimuth(1.0);
        const nprClock::time_point start = nprClock::now();
        lines->SetCamera(camera);
        lines->Update();
        times.push_back(nprSecondsSince(start));
      }
      return nprMedian(times);
    });
}

// The seconds the drawing's last stroke update took (vtkNPRDrawingLines' own clocks).
double StrokeSeconds(vtkNPRPass* pass)
{
  vtkNPRDrawingLines* lines = pass->GetDrawingPass()->GetDrawingLines();
  return lines->GetLinesTime() + lines->GetLocatorTime() + lines->GetVisibilityTime() +
    lines->GetChainTime();
}

// A style's first frame (a new pass: its buffers, shaders and, for the drawing, the adjacency
// and occluders built) and its later frames, the camera turned 1 degree before each.
void MeasureStyle(StepLog& log, nprBenchmarkStage& stage, const std::string& style, int frames)
{
  vtkSmartPointer<vtkNPRPass> pass;
  if (style != "shaded")
  {
    nprPassSettings settings;
    settings.Style = style;
    pass = nprMakePass(settings);
  }
  const bool drawing = style == "drawing";
  stage.Renderer->SetPass(pass);
  nprApplyBenchmarkCamera(stage.Renderer, nprBenchmarkCameras()[0]);
  log.Measure(style == "shaded" ? "first frame: shaded (mesh upload)" : "first frame: " + style,
    [&]() { return 1e-3 * nprTimeFrame(stage.Window, stage.Camera()); });
  if (drawing)
  {
    log.Part("drawing: first stroke update", StrokeSeconds(pass));
  }
  std::vector<double> strokes;
  log.Measure("later frames: " + style,
    [&]()
    {
      std::vector<double> times;
      for (int frame = 0; frame < frames; ++frame)
      {
        stage.Camera()->Azimuth(1.0);
        stage.Renderer->ResetCameraClippingRange();
        times.push_back(1e-3 * nprTimeFrame(stage.Window, stage.Camera()));
        if (drawing)
        {
          strokes.push_back(StrokeSeconds(pass));
        }
      }
      return nprMedian(times);
    });
  if (drawing)
  {
    log.Part("drawing: stroke update per camera change", nprMedian(strokes));
  }
  stage.Renderer->SetPass(nullptr);
  if (pass)
  {
    pass->ReleaseGraphicsResources(stage.Window);
  }
}

void WriteSteps(const std::string& path, const std::vector<nprScaleStep>& steps)
{
  std::ofstream file(path);
  file << "step,seconds,peak_mb,added_mb\n";
  for (const nprScaleStep& step : steps)
  {
    file << step.Name << "," << nprFormat(step.Seconds, 6) << "," << nprFormat(step.PeakMB, 6)
         << "," << nprFormat(step.AddedMB, 6) << "\n";
  }
  if (!file)
  {
    throw std::runtime_error(path + ": cannot write");
  }
}
}

int nprRunScaleSteps(const nprBenchmarkOptions& options)
{
  nprMakeBenchmarkFolders(options);
  vtkTimerLog::SetMaxEntries(10000);
  vtkTimerLog::LoggingOn();
  vtkTimerLog::ResetLog();
  StepLog log;
  vtkSmartPointer<vtkPolyData> raw, mesh;
  log.Measure("read (vtkNPRModelReader)",
    [&]()
    {
      raw = nprReadModel(options.ScaleSteps);
      return -1.0;
    });
  log.LoggedParts(ReaderEvents);
  log.Measure("shading normals (vtkNPRShadingNormals)",
    [&]()
    {
      mesh = nprPrepareMesh(raw);
      return -1.0;
    });
  log.LoggedParts(NormalsEvents);
  vtkTimerLog::LoggingOff();

  nprBenchmarkStage stage(options.LineWidth);
  stage.Window->SetSize(options.Sizes.front().first, options.Sizes.front().second);
  stage.SetMesh(mesh, raw);
  nprApplyBenchmarkCamera(stage.Renderer, nprBenchmarkCameras()[0]);
  MeasureFeatureLines(log, raw, stage.Camera(), options.Frames);
  for (const char* style : Styles)
  {
    MeasureStyle(log, stage, style, options.Frames);
  }
  WriteSteps(options.Out + "/steps.csv", log.Rows);
  std::ofstream(options.Out + "/renderer.txt")
    << vtkNPRRenderWindowFactory::GetGLRenderer(stage.Window) << "\n";
  return 0;
}

std::vector<nprScaleStep> nprReadScaleSteps(const std::string& path)
{
  std::ifstream file(path);
  std::string line;
  if (!std::getline(file, line) || line != "step,seconds,peak_mb,added_mb")
  {
    throw std::runtime_error(path + ": missing or not the steps of --scale-steps");
  }
  std::vector<nprScaleStep> steps;
  while (std::getline(file, line))
  {
    std::istringstream fields(line);
    nprScaleStep step;
    std::string seconds, peak, added;
    if (!std::getline(fields, step.Name, ',') || !std::getline(fields, seconds, ',') ||
      !std::getline(fields, peak, ',') || !std::getline(fields, added))
    {
      throw std::runtime_error(path + ": a malformed line: " + line);
    }
    step.Seconds = std::stod(seconds);
    step.PeakMB = std::stod(peak);
    step.AddedMB = std::stod(added);
    steps.push_back(step);
  }
  return steps;
}
