// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nprBenchmarkCoherence.h"

#include "nprBenchmarkOptions.h"
#include "nprBenchmarkReport.h"
#include "nprBenchmarkScenes.h"
#include "nprBenchmarkStage.h"
#include "nprCoherence.h"
#include "nprPassSettings.h"
#include "nprTiming.h"

#include "vtkCamera.h"
#include "vtkNPRPass.h"
#include "vtkNPRRenderWindowFactory.h"
#include "vtkNPRSketchPass.h"

#include <cmath>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace
{
struct CoherenceStyle
{
  std::string Name;
  vtkSmartPointer<vtkNPRPass> Pass;
};

std::vector<CoherenceStyle> MakeStyles(double lineWidth)
{
  std::vector<CoherenceStyle> styles;
  auto add = [&](const std::string& name, const char* style, int noiseSpace)
  {
    nprPassSettings settings;
    settings.Style = style;
    settings.LineWidth = lineWidth;
    settings.NoiseSpace = noiseSpace;
    styles.push_back({ name, nprMakePass(settings) });
  };
  add("edges", "edges", vtkNPRSketchPass::SURFACE);
  add("toon+edges", "toon+edges", vtkNPRSketchPass::SURFACE);
  add("sketch, surface noise", "sketch", vtkNPRSketchPass::SURFACE);
  add("sketch, screen noise", "sketch", vtkNPRSketchPass::SCREEN);
  add("inked", "inked", vtkNPRSketchPass::SURFACE);
  return styles;
}

enum class Path
{
  Pan,   // parallel camera moved right by 20 pixels per frame
  Orbit, // 1 degree of azimuth per frame
  Dolly  // 2 % closer per frame
};
const char* PathName(Path path)
{
  return path == Path::Pan ? "pan 20 px" : (path == Path::Orbit ? "orbit 1 deg" : "dolly 2 %");
}
constexpr int Steps = 8;
constexpr int PanPixels = 20;

void StartPath(nprBenchmarkStage& stage, Path path)
{
  nprApplyBenchmarkCamera(stage.Renderer, nprBenchmarkCameras()[0]);
  vtkCamera* camera = stage.Camera();
  camera->SetParallelProjection(path == Path::Pan);
  stage.Renderer->ResetCamera();
  stage.Renderer->ResetCameraClippingRange();
}

void StepPath(nprBenchmarkStage& stage, Path path, int height)
{
  vtkCamera* camera = stage.Camera();
  if (path == Path::Pan)
  {
    nprPanParallelCamera(camera, PanPixels, height);
  }
  else if (path == Path::Orbit)
  {
    camera->Azimuth(1.0);
    camera->OrthogonalizeViewUp();
  }
  else
  {
    camera->Dolly(1.02);
  }
  stage.Renderer->ResetCameraClippingRange();
}

struct CoherenceRow
{
  std::string Scene, Size, Path, Style;
  double Landed = 0, LandedExactly = 0, Appeared = 0, Vanished = 0;
  double PanIoU = -1; // pan only
};

struct CostRow
{
  std::string Scene, Size;
  double ScreenMs = 0, SurfaceMs = 0;
};

// One style along one camera path from its start: what its line pixels did at each step.
CoherenceRow FollowPath(nprBenchmarkStage& stage, CoherenceStyle& style, Path path, int height,
  const std::string& scene, const std::string& sizeName)
{
  stage.Activate(style.Pass, false);
  StartPath(stage, path);
  stage.Window->Render();
  nprCoherenceFrame previous = nprCaptureCoherenceFrame(stage.Window, stage.Renderer);
  CoherenceRow row{ scene, sizeName, PathName(path), style.Name };
  row.PanIoU = path == Path::Pan ? 0.0 : -1.0;
  for (int step = 0; step < Steps; ++step)
  {
    StepPath(stage, path, height);
    stage.Window->Render();
    nprCoherenceFrame next = nprCaptureCoherenceFrame(stage.Window, stage.Renderer);
    const nprCoherenceStep figures = nprCompareCoherenceFrames(previous, next);
    row.Landed += figures.LandedFraction / Steps;
    row.LandedExactly += figures.LandedExactlyFraction / Steps;
    row.Appeared += figures.AppearedFraction / Steps;
    row.Vanished += figures.VanishedFraction / Steps;
    if (path == Path::Pan)
    {
      row.PanIoU += nprShiftedLineIoU(previous, next, -PanPixels, 0, 8) / Steps;
    }
    previous = std::move(next);
  }
  std::cerr << "npr-benchmark: " << scene << " " << sizeName << " " << row.Path << " " << style.Name
            << ": landed " << nprFixed(row.Landed, 3) << "\n";
  return row;
}

// The cost of surface noise: both sketches' frames interleaved, the camera turned a little every
// frame so nothing is reused.
CostRow MeasureNoiseCost(nprBenchmarkStage& stage, std::vector<CoherenceStyle>& styles, int frames,
  const std::string& scene, const std::string& sizeName)
{
  StartPath(stage, Path::Orbit);
  std::vector<double> screen, surface;
  CoherenceStyle& surfaceStyle = styles[2];
  CoherenceStyle& screenStyle = styles[3];
  for (int frame = -1; frame < frames; ++frame) // frame -1: warm-up
  {
    for (CoherenceStyle* style : { &screenStyle, &surfaceStyle })
    {
      stage.Activate(style->Pass, false);
      stage.Camera()->Azimuth(0.5);
      const double ms = nprTimeFrame(stage.Window, stage.Camera());
      if (frame >= 0)
      {
        (style == &screenStyle ? screen : surface).push_back(ms);
      }
    }
  }
  return { scene, sizeName, nprMedian(screen), nprMedian(surface) };
}

// coherence.csv and the paths' table; returns false if the file could not be written.
bool WriteCoherenceRows(const std::string& out, const std::vector<CoherenceRow>& rows,
  std::ostringstream& md, std::string& problems)
{
  std::ofstream csv(out + "/coherence.csv");
  csv << "scene,size,path,style,landed,landed_exactly,appeared,vanished,pan_iou\n";
  md << "| scene | size | camera path | style | landed within 1 px | landed exactly | appeared | "
        "vanished | IoU after the pan |\n|---|---|---|---|---|---|---|---|---|\n";
  for (const CoherenceRow& row : rows)
  {
    csv << row.Scene << "," << row.Size << "," << row.Path << ",\"" << row.Style << "\","
        << row.Landed << "," << row.LandedExactly << "," << row.Appeared << "," << row.Vanished
        << "," << row.PanIoU << "\n";
    md << "| " << row.Scene << " | " << row.Size << " | " << row.Path << " | " << row.Style << " | "
       << nprFixed(row.Landed, 3) << " | " << nprFixed(row.LandedExactly, 3) << " | "
       << nprFixed(row.Appeared, 3) << " | " << nprFixed(row.Vanished, 3) << " | "
       << (row.PanIoU >= 0 ? nprFixed(row.PanIoU, 3) : "") << " |\n";
    for (double value : { row.Landed, row.LandedExactly, row.Appeared, row.Vanished })
    {
      if (!(value >= 0.0 && value <= 1.0 + 1e-9))
      {
        problems += row.Scene + " " + row.Path + " " + row.Style + ": a fraction out of [0, 1]\n";
      }
    }
  }
  return static_cast<bool>(csv);
}

// coherence_cost.csv and the noise's table; returns false if the file could not be written.
bool WriteCostRows(const std::string& out, const std::vector<CostRow>& costs,
  std::ostringstream& md, std::string& problems)
{
  md << "\n"
     << nprMarkdownHead({ "scene", "size", "sketch, screen noise (ms)",
          "sketch, surface noise (ms)", "surface / screen" });
  std::ofstream costCsv(out + "/coherence_cost.csv");
  costCsv << "scene,size,sketch_screen_ms,sketch_surface_ms\n";
  for (const CostRow& cost : costs)
  {
    md << nprMarkdownRow({ cost.Scene, cost.Size, nprFixed(cost.ScreenMs, 1),
      nprFixed(cost.SurfaceMs, 1), nprFixed(cost.SurfaceMs / cost.ScreenMs, 3) });
    costCsv << nprCsvRow({ cost.Scene, cost.Size }, { cost.ScreenMs, cost.SurfaceMs });
    if (!(cost.ScreenMs > 0.0 && cost.SurfaceMs > 0.0))
    {
      problems += cost.Scene + " " + cost.Size + ": a frame time is not positive\n";
    }
  }
  return static_cast<bool>(costCsv);
}
}

int nprRunBenchmarkCoherence(const nprBenchmarkOptions& options)
{
  const nprClock::time_point runStart = nprClock::now();
  const std::vector<nprBenchmarkScene> scenes = nprStartBenchmarkRun(options);
  nprBenchmarkStage stage(options.LineWidth);
  std::vector<CoherenceStyle> styles = MakeStyles(options.LineWidth);
  std::vector<CoherenceRow> rows;
  std::vector<CostRow> costs;
  for (const nprBenchmarkScene& scene : scenes)
  {
    stage.SetMesh(scene.Mesh, scene.Raw);
    for (const auto& size : options.Sizes)
    {
      stage.Window->SetSize(size.first, size.second);
      const std::string sizeName = std::to_string(size.first) + "x" + std::to_string(size.second);
      for (Path path : { Path::Pan, Path::Orbit, Path::Dolly })
      {
        for (CoherenceStyle& style : styles)
        {
          rows.push_back(FollowPath(stage, style, path, size.second, scene.Name, sizeName));
        }
      }
      costs.push_back(MeasureNoiseCost(stage, styles, options.Frames, scene.Name, sizeName));
    }
  }

  std::ostringstream md;
  std::string problems;
  const bool rowsWritten = WriteCoherenceRows(options.Out, rows, md, problems);
  const bool costsWritten = WriteCostRows(options.Out, costs, md, problems);
  std::ofstream markdown(options.Out + "/coherence.md");
  markdown << "Coherence of the drawn lines along camera paths (" << Steps
           << " steps each; npr-benchmark --coherence), on "
           << vtkNPRRenderWindowFactory::GetGLRenderer(stage.Window) << ", medians of "
           << options.Frames << " frames for the times.\n\n"
           << md.str();
  std::cout << md.str();
  if (!rowsWritten || !costsWritten || !markdown)
  {
    throw std::runtime_error(options.Out +
      ": cannot write coherence.csv, coherence_cost.csv or "
      "coherence.md");
  }
  std::cerr << "npr-benchmark: wrote " << options.Out
            << "/coherence.{csv,md}, coherence_cost.csv in "
            << nprFormat(nprSecondsSince(runStart), 4) << " s\n";
  return nprBenchmarkStatus(problems, ": figures out of range");
}
