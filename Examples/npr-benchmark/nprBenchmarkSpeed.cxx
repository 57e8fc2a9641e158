// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nprBenchmarkSpeed.h"

#include "nprBenchmarkOptions.h"
#include "nprBenchmarkReport.h"
#include "nprBenchmarkScenes.h"
#include "nprBenchmarkStage.h"
#include "nprOneFetchPass.h"
#include "nprPassSettings.h"
#include "nprTiming.h"
#include "nprWindowImage.h"

#include "vtkCamera.h"
#include "vtkEDLShading.h"
#include "vtkImageData.h"
#include "vtkNPREdgePass.h"
#include "vtkNPRGBufferPass.h"
#include "vtkNPRInkPass.h"
#include "vtkNPRPass.h"
#include "vtkNPRRenderWindowFactory.h"
#include "vtkOpaquePass.h"
#include "vtkOpenGLRenderTimer.h"
#include "vtkOutlineGlowPass.h"
#include "vtkPolyDataSilhouette.h"
#include "vtkProperty.h"
#include "vtkRenderPass.h"
#include "vtkRenderStepsPass.h"
#include "vtkSSAOPass.h"
#include "vtkSobelGradientMagnitudePass.h"

#include <algorithm>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace
{
const char* const FeatureLinesName = "vtkNPRFeatureLines per camera change (SetCamera + Update)";

// How one method draws its frame.
struct SpeedMethod
{
  std::string Key; // its name in --methods
  std::string Name;
  vtkSmartPointer<vtkRenderPass> Pass; // nullptr: VTK's own chain
  bool Unchanged = false;              // time a second render of the same frame
  bool Silhouette = false;             // vtkPolyDataSilhouette's lines over the plain surface
  bool CopiesPlain = false;            // draws the plain frame's pixels: checked in the warm-up
  bool ObjectLines = false;            // vtkNPRFeatureLines' lines over the plain surface
};

struct SpeedRow
{
  std::string Scene, Size, Method;
  int Run = 0;
  double MedianMs = 0.0;
  double GPUMedianMs = -1.0; // < 0: no timer query
};

// The GPU time of what a frame submits (VTK's vtkOpenGLRenderTimer: timestamp queries around
// Render(), read once the frame has finished): on a GPU, what the frame costs the device apart
// from the CPU's work. Not every OpenGL has them; on llvmpipe they are Mesa's own clock.
class GPUTimer
{
public:
  explicit GPUTimer(vtkRenderWindow* window)
    : Window(window)
  {
  }
  ~GPUTimer()
  {
    this->Window->MakeCurrent();
    this->Timer.ReleaseGraphicsResources();
  }
  GPUTimer(const GPUTimer&) = delete;
  GPUTimer& operator=(const GPUTimer&) = delete;
  void Begin()
  {
    this->Window->MakeCurrent();
    this->Supported = this->Supported && vtkOpenGLRenderTimer::IsSupported();
    if (this->Supported)
    {
      this->Timer.Reset();
      this->Timer.Start();
    }
  }
  // Milliseconds, or -1 without timer queries.
  double End()
  {
    if (!this->Supported)
    {
      return -1.0;
    }
    this->Window->MakeCurrent();
    this->Timer.Stop();
    this->Window->WaitForCompletion();
    for (int tries = 0; tries < 1000 && !this->Timer.Ready(); ++tries)
    {
      std::this_thread::sleep_for(std::chrono::microseconds(100));
    }
    return this->Timer.Ready() ? 1e-6 * static_cast<double>(this->Timer.GetElapsedNanoseconds())
                               : -1.0;
  }

private:
  vtkRenderWindow* Window;
  vtkOpenGLRenderTimer Timer;
  bool Supported = true;
};

vtkSmartPointer<vtkRenderPass> NPRStyle(const std::string& style)
{
  nprPassSettings settings;
  settings.Style = style;
  return nprMakePass(settings);
}

// Each of VTK's image passes over the ordinary render steps, as VTK's own examples use them.
template <typename Pass>
vtkSmartPointer<vtkRenderPass> OverRenderSteps()
{
  auto pass = vtkSmartPointer<Pass>::New();
  vtkNew<vtkRenderStepsPass> steps;
  pass->SetDelegatePass(steps);
  return pass;
}

// A vtkRenderStepsPass whose opaque step is the edge style's G-buffer pass alone.
vtkSmartPointer<vtkRenderPass> GBufferAlone()
{
  vtkNew<vtkNPRGBufferPass> gbuffer;
  vtkNew<vtkOpaquePass> opaque;
  gbuffer->SetDelegatePass(opaque);
  gbuffer->NormalsRequestedOn();
  gbuffer->ObjectIdsRequestedOn();
  auto steps = vtkSmartPointer<vtkRenderStepsPass>::New();
  steps->SetOpaquePass(gbuffer);
  return steps;
}

// The edge style with parts of it off, and as it was before its composite and coverage were
// drawn over the blocks near lines and its surfaces copied back by a blit.
void AddEdgeVariants(std::vector<SpeedMethod>& methods)
{
  // What bounds two of them, measured beside them: the edge pass with every line type off (the
  // G-buffer capture and the depth-sprite copy back, no line taps) and with silhouettes only (no
  // normals written or compared), and the inking pass with a one-pixel wireframe (no wide lines:
  // its two geometry draws alone).
  auto edgesWith = [](bool silhouettes)
  {
    auto pass = NPRStyle("edges");
    vtkNPREdgePass* edges = vtkNPRPass::SafeDownCast(pass)->GetEdgePass();
    edges->SetSilhouettes(silhouettes);
    edges->CreasesOff();
    edges->ContoursOff();
    return pass;
  };
  methods.push_back({ "edges-silhouettes", "vtkNPRPass edges, silhouettes only", edgesWith(true) });
  methods.push_back({ "edges-floor", "vtkNPRPass edges, every line type off", edgesWith(false) });
  // The composite before it was drawn over the blocks near lines alone: one full-screen pass.
  auto fullComposite = NPRStyle("edges");
  vtkNPRPass::SafeDownCast(fullComposite)->GetEdgePass()->SkipLineFreeBlocksOff();
  vtkNPRPass::SafeDownCast(fullComposite)->GetEdgePass()->CopySurfacesBackOff();
  methods.push_back(
    { "edges-full-composite", "vtkNPRPass edges, composite over every pixel", fullComposite });
  // And over the blocks, before the surfaces were copied back whole: a copy shader elsewhere.
  auto shaderCopy = NPRStyle("edges");
  vtkNPRPass::SafeDownCast(shaderCopy)->GetEdgePass()->CopySurfacesBackOff();
  methods.push_back(
    { "edges-shader-copy", "vtkNPRPass edges, surfaces copied by a shader", shaderCopy });
  // The sketch's line coverage before it was drawn over the blocks near lines alone.
  auto fullCoverage = NPRStyle("sketch");
  vtkNPRPass::SafeDownCast(fullCoverage)->GetEdgePass()->SkipLineFreeBlocksOff();
  methods.push_back(
    { "sketch-full-coverage", "vtkNPRPass sketch, line coverage over every pixel", fullCoverage });
}

void AddBounds(std::vector<SpeedMethod>& methods)
{
  // The bound under the floor: the G-buffer drawn as the edge style draws it (normals, ids) and
  // nothing shown from it, so the floor's difference to it is the copy into the window.
  methods.push_back(
    { "gbuffer-only", "vtkNPRGBufferPass alone (drawn, not shown)", GBufferAlone() });
  // The bound under every screen-space style: the render steps drawn into a texture and copied
  // into the window by one full-screen fetch per pixel (nprOneFetchPass).
  methods.push_back({ "one-fetch", "render steps into a texture, one full-screen fetch",
    OverRenderSteps<nprOneFetchPass>(), false, false, true });
}

void AddOptionalLineTests(std::vector<SpeedMethod>& methods)
{
  // What the optional line tests cost: creases from the face normals (the G-buffer's geometry
  // attachment RGBA32F instead of RG32F), smooth silhouettes, suggestive contours.
  auto faceCreases = NPRStyle("edges");
  vtkNPRPass::SafeDownCast(faceCreases)->GetEdgePass()->FaceCreasesOn();
  methods.push_back(
    { "edges-face-creases", "vtkNPRPass edges, creases from face normals", faceCreases });
  auto smooth = NPRStyle("edges");
  vtkNPRPass::SafeDownCast(smooth)->GetEdgePass()->SmoothSilhouettesOn();
  methods.push_back({ "edges-smooth", "vtkNPRPass edges, smooth silhouettes on", smooth });
  auto suggestive = NPRStyle("edges");
  vtkNPRPass::SafeDownCast(suggestive)->GetEdgePass()->SuggestiveContoursOn();
  methods.push_back({ "edges-suggestive", "vtkNPRPass edges, suggestive contours on", suggestive });
  auto thin = NPRStyle("inked");
  vtkNPRPass::SafeDownCast(thin)->GetInkPass()->SetLineWidth(0.5);
  methods.push_back({ "inked-thin", "vtkNPRPass inked, 1 px wireframe", thin });
}

void AddUnchangedFrames(std::vector<SpeedMethod>& methods)
{
  // Its own pass, so that the edges method above draws every frame from scratch.
  methods.push_back(
    { "unchanged", "vtkNPRPass edges, unchanged frame drawn again", NPRStyle("edges"), true });
  methods.push_back({ "unchanged-sketch", "vtkNPRPass sketch, unchanged frame drawn again",
    NPRStyle("sketch"), true });
  methods.push_back({ "unchanged-drawing", "vtkNPRPass drawing, unchanged frame drawn again",
    NPRStyle("drawing"), true });
}

// VTK's own passes, and lines over the plain surface in object space.
void AddPeers(std::vector<SpeedMethod>& methods)
{
  methods.push_back(
    { "sobel", "vtkSobelGradientMagnitudePass", OverRenderSteps<vtkSobelGradientMagnitudePass>() });
  methods.push_back({ "glow", "vtkOutlineGlowPass", OverRenderSteps<vtkOutlineGlowPass>() });
  methods.push_back({ "ssao", "vtkSSAOPass", OverRenderSteps<vtkSSAOPass>() });
  methods.push_back({ "edl", "vtkEDLShading", OverRenderSteps<vtkEDLShading>() });
  methods.push_back(
    { "silhouette", "vtkPolyDataSilhouette re-extracted + surface", nullptr, false, true });
  // The project's object-space lines (silhouettes, creases, borders) for each frame's camera,
  // drawn over the plain surface: what the edge style's lines cost in object space.
  methods.push_back({ "objectlines", "vtkNPRFeatureLines re-extracted + surface", nullptr, false,
    false, false, true });
}

std::vector<SpeedMethod> MakeMethods()
{
  std::vector<SpeedMethod> methods;
  methods.push_back({ "plain", "plain VTK frame", nullptr });
  for (const char* style : { "edges", "toon+edges", "sketch", "toon", "inked", "drawing" })
  {
    methods.push_back({ style, std::string("vtkNPRPass ") + style, NPRStyle(style) });
  }
  AddEdgeVariants(methods);
  AddBounds(methods);
  AddOptionalLineTests(methods);
  AddUnchangedFrames(methods);
  AddPeers(methods);
  return methods;
}

// --methods: the plain frame always (the reference of every ratio), then the methods named.
std::vector<SpeedMethod> SelectMethods(const std::vector<std::string>& keys)
{
  std::vector<SpeedMethod> all = MakeMethods();
  if (keys.empty())
  {
    return all;
  }
  std::vector<SpeedMethod> methods = { all.front() };
  for (const std::string& key : keys)
  {
    auto found = std::find_if(
      all.begin(), all.end(), [&](const SpeedMethod& method) { return method.Key == key; });
    if (found == all.end() && key != "featurelines")
    {
      std::string known;
      for (const SpeedMethod& method : all)
      {
        known += " " + method.Key;
      }
      throw std::runtime_error(
        "--speed --methods: unknown method '" + key + "' (known:" + known + " featurelines)");
    }
    if (found != all.end() && found != all.begin())
    {
      methods.push_back(*found);
    }
  }
  return methods;
}

// SSAO's radius and bias follow the scene's size (as in VTK's SSAO example: a tenth and a
// thousandth of it), so that the occlusion is sampled alike on both scenes.
void FitSSAO(const std::vector<SpeedMethod>& methods, double sceneSize)
{
  for (const SpeedMethod& method : methods)
  {
    if (auto* ssao = vtkSSAOPass::SafeDownCast(method.Pass))
    {
      ssao->SetRadius(0.1 * sceneSize);
      ssao->SetBias(0.001 * sceneSize);
      ssao->SetKernelSize(128);
      ssao->BlurOff();
    }
  }
}

// vtkPolyDataSilhouette for the current camera, drawn as black lines over the surface (the
// `silhouette` method). A new filter per scene: it keeps its edge table while the input is older
// than the table, so a scene loaded before the previous one was measured would be drawn from
// stale edges.
struct SilhouetteLines
{
  vtkSmartPointer<vtkPolyDataSilhouette> Filter;
  vtkNew<vtkPolyDataMapper> Mapper;
  vtkNew<vtkActor> Actor;

  SilhouetteLines(nprBenchmarkStage& stage, double lineWidth)
  {
    this->Mapper->ScalarVisibilityOff();
    this->Actor->SetMapper(this->Mapper);
    this->Actor->GetProperty()->SetColor(0.0, 0.0, 0.0);
    this->Actor->GetProperty()->SetLineWidth(static_cast<float>(lineWidth));
    this->Actor->GetProperty()->LightingOff();
    this->Actor->VisibilityOff();
    stage.Renderer->AddActor(this->Actor);
  }

  void SetScene(nprBenchmarkStage& stage, vtkPolyData* mesh)
  {
    this->Filter = vtkSmartPointer<vtkPolyDataSilhouette>::New();
    this->Filter->SetCamera(stage.Camera());
    this->Filter->SetProp3D(stage.MeshActor);
    this->Filter->SetDirectionToCameraOrigin();
    this->Filter->BorderEdgesOn();
    this->Filter->SetInputData(mesh);
    this->Mapper->SetInputConnection(this->Filter->GetOutputPort());
  }
};

// Draws and times one method's frames on the stage, wall clock and GPU.
class SpeedFrames
{
public:
  SpeedFrames(nprBenchmarkStage& stage, SilhouetteLines& silhouette)
    : Stage(stage)
    , Silhouette(silhouette)
    , GPU(stage.Window)
  {
  }

  void Activate(const SpeedMethod& method)
  {
    // Coincident-topology resolution as users get it; polygon offset for object lines.
    this->Stage.Activate(nullptr, method.ObjectLines);
    this->Stage.Renderer->SetPass(method.Pass);
    this->Silhouette.Actor->SetVisibility(method.Silhouette);
    if (method.Silhouette)
    {
      // Lines on the surface win the depth test as they would in an application.
      vtkMapper::SetResolveCoincidentTopology(VTK_RESOLVE_POLYGON_OFFSET);
    }
  }

  // The frame's wall-clock milliseconds; gpuMs its GPU time (< 0 without timer queries).
  double Time(const SpeedMethod& method, double& gpuMs)
  {
    this->Activate(method);
    vtkRenderWindow* window = this->Stage.Window;
    double ms = 0.0;
    if (method.Unchanged)
    {
      nprTimeFrame(window, this->Stage.Camera()); // this frame drawn once, untimed
      const nprClock::time_point start = nprClock::now();
      this->GPU.Begin();
      window->Render(); // nothing changed: what the pass reuses
      window->WaitForCompletion();
      ms = std::chrono::duration<double, std::milli>(nprClock::now() - start).count();
    }
    else
    {
      this->GPU.Begin();
      ms = nprTimeFrame(window, this->Stage.Camera(),
        [&]()
        {
          if (method.Silhouette)
          {
            this->Silhouette.Filter->Modified(); // the extraction is part of every frame
          }
          if (method.ObjectLines)
          {
            this->Stage.UpdateFeatureLines(); // for this frame's camera
          }
        });
    }
    gpuMs = this->GPU.End();
    return ms;
  }

private:
  nprBenchmarkStage& Stage;
  SilhouetteLines& Silhouette;
  GPUTimer GPU;
};

std::string SizeName(const std::pair<int, int>& size)
{
  return std::to_string(size.first) + "x" + std::to_string(size.second);
}

// A bound that drew less than the plain frame would not bound anything: throws unless the
// window's image equals the plain frame's, pixel for pixel.
void CheckCopiesPlain(vtkRenderWindow* window, vtkImageData* plain, const SpeedMethod& method)
{
  vtkSmartPointer<vtkImageData> image = nprReadWindowImage(window, false);
  const auto* a = static_cast<const unsigned char*>(plain->GetScalarPointer());
  const auto* b = static_cast<const unsigned char*>(image->GetScalarPointer());
  const vtkIdType bytes = plain->GetNumberOfPoints() * plain->GetNumberOfScalarComponents();
  vtkIdType differ = 0;
  for (vtkIdType i = 0; i < bytes; ++i)
  {
    differ += a[i] != b[i];
  }
  if (image->GetNumberOfPoints() != plain->GetNumberOfPoints() || differ > 0)
  {
    throw std::runtime_error(method.Key + ": its frame is not the plain frame (" +
      std::to_string(differ) + " bytes differ), so it bounds nothing");
  }
}

// One run at the window's size: the same camera path in every run, each frame drawn by every
// method in turn; frame -1 warms every method up (shaders, buffers of this size, the
// silhouette's edge table) and checks the copies of the plain frame. One row a method: the
// median of its frames.
void MeasureRun(SpeedFrames& frames, nprBenchmarkStage& stage,
  const std::vector<SpeedMethod>& methods, int frameCount, const SpeedRow& where,
  std::vector<SpeedRow>& rows)
{
  stage.Activate(nullptr, false);
  nprApplyBenchmarkCamera(stage.Renderer, nprBenchmarkCameras()[0]);
  std::vector<std::vector<double>> times(methods.size()), gpuTimes(methods.size());
  vtkSmartPointer<vtkImageData> plainImage;
  for (int frame = -1; frame < frameCount; ++frame)
  {
    if (frame >= 0)
    {
      stage.Camera()->Azimuth(1.0);
      stage.Renderer->ResetCameraClippingRange();
    }
    for (size_t m = 0; m < methods.size(); ++m)
    {
      double gpuMs = -1.0;
      const double ms = frames.Time(methods[m], gpuMs);
      if (frame < 0 && m == 0)
      {
        plainImage = nprReadWindowImage(stage.Window, false);
      }
      else if (frame < 0 && methods[m].CopiesPlain)
      {
        CheckCopiesPlain(stage.Window, plainImage, methods[m]);
      }
      if (frame >= 0)
      {
        times[m].push_back(ms);
        gpuTimes[m].push_back(gpuMs);
      }
    }
  }
  for (size_t m = 0; m < methods.size(); ++m)
  {
    SpeedRow row = where;
    row.Method = methods[m].Name;
    row.MedianMs = nprMedian(times[m]);
    row.GPUMedianMs = nprMedian(gpuTimes[m]);
    rows.push_back(row);
  }
}

// Object-space feature lines per camera change, each run's median (the first update, untimed,
// builds the adjacency).
void MeasureFeatureLines(SpeedFrames& frames, nprBenchmarkStage& stage, const SpeedMethod& plain,
  const nprBenchmarkOptions& options, const std::string& scene, std::vector<SpeedRow>& rows)
{
  frames.Activate(plain);
  nprApplyBenchmarkCamera(stage.Renderer, nprBenchmarkCameras()[0]);
  stage.FeatureLines->SetCamera(stage.Camera());
  stage.FeatureLines->Update();
  for (int run = 0; run < options.Runs; ++run)
  {
    std::vector<double> times;
    for (int frame = 0; frame < options.Frames; ++frame)
    {
      stage.Camera()->Azimuth(1.0);
      const nprClock::time_point start = nprClock::now();
      stage.FeatureLines->SetCamera(stage.Camera());
      stage.FeatureLines->Update();
      times.push_back(std::chrono::duration<double, std::milli>(nprClock::now() - start).count());
    }
    rows.push_back({ scene, "any", FeatureLinesName, run + 1, nprMedian(times) });
  }
}

// Every scene at every size, options.Runs times; then the feature lines of each scene.
std::vector<SpeedRow> MeasureScenes(nprBenchmarkStage& stage,
  const std::vector<nprBenchmarkScene>& scenes, std::vector<SpeedMethod>& methods,
  const nprBenchmarkOptions& options, bool featureLines)
{
  SilhouetteLines silhouette(stage, options.LineWidth);
  SpeedFrames frames(stage, silhouette);
  std::vector<SpeedRow> rows;
  for (const nprBenchmarkScene& scene : scenes)
  {
    stage.SetMesh(scene.Mesh, scene.Raw);
    silhouette.SetScene(stage, scene.Mesh);
    FitSSAO(methods, nprModelSize(scene.Mesh));
    for (const auto& size : options.Sizes)
    {
      stage.Window->SetSize(size.first, size.second);
      for (int run = 0; run < options.Runs; ++run)
      {
        const nprClock::time_point viewStart = nprClock::now();
        const size_t first = rows.size();
        MeasureRun(frames, stage, methods, options.Frames,
          { scene.Name, SizeName(size), std::string(), run + 1 }, rows);
        std::cerr << "npr-benchmark: " << scene.Name << " " << SizeName(size) << " run " << run + 1
                  << ": plain " << nprFixed(rows[first].MedianMs, 1) << " ms, done in "
                  << nprFixed(nprSecondsSince(viewStart), 1) << " s\n";
      }
    }
    if (featureLines)
    {
      MeasureFeatureLines(frames, stage, methods[0], options, scene.Name, rows);
    }
  }
  for (const SpeedMethod& method : methods)
  {
    if (method.Pass)
    {
      method.Pass->ReleaseGraphicsResources(stage.Window);
    }
  }
  stage.Renderer->SetPass(nullptr);
  return rows;
}

// speed.csv: one row a run; the rows without a positive time are returned as problems.
std::string WriteSpeedCSV(const std::vector<SpeedRow>& rows, const std::string& path)
{
  std::ofstream csv(path);
  csv << "scene,size,method,run,median_ms,gpu_median_ms\n";
  std::string problems;
  for (const SpeedRow& row : rows)
  {
    csv << row.Scene << "," << row.Size << ",\"" << row.Method << "\"," << row.Run << ","
        << row.MedianMs << "," << row.GPUMedianMs << "\n";
    if (!(row.MedianMs > 0.0))
    {
      problems += row.Scene + " " + row.Size + " " + row.Method + ": no positive time\n";
    }
  }
  if (!csv)
  {
    throw std::runtime_error(path + ": cannot write");
  }
  return problems;
}

// The lowest and highest of the runs' figures ("8.2 to 10.1"), or the one run's: the spread a
// difference between two methods has to beat.
std::string RunRange(const std::vector<double>& values)
{
  if (values.empty())
  {
    return "n/a";
  }
  const auto range = std::minmax_element(values.begin(), values.end());
  return values.size() == 1 ? nprFixed(*range.first, 1)
                            : nprFixed(*range.first, 1) + " to " + nprFixed(*range.second, 1);
}

// One scene and size's table: the median of the runs' medians; the ratio and the difference to
// the plain frame are taken within each run.
void WriteSpeedTable(std::ostream& md, const std::vector<SpeedRow>& rows,
  const std::vector<SpeedMethod>& methods, const nprBenchmarkScene& scene,
  const std::string& sizeName)
{
  std::map<int, double> plain, plainGPU;
  for (const SpeedRow& row : rows)
  {
    if (row.Scene == scene.Name && row.Size == sizeName && row.Method == methods[0].Name)
    {
      plain[row.Run] = row.MedianMs;
      plainGPU[row.Run] = row.GPUMedianMs;
    }
  }
  md << "\n"
     << scene.Name << " (" << scene.Triangles << " triangles), " << sizeName << ":\n\n"
     << "| method | median (ms) | ratio to plain | over plain (ms) "
        "| over plain, lowest to highest run (ms) | GPU (ms) | GPU over plain (ms) |\n"
        "|---|---|---|---|---|---|---|\n";
  for (const SpeedMethod& method : methods)
  {
    std::vector<double> ms, ratios, extra, gpu, gpuExtra;
    for (const SpeedRow& row : rows)
    {
      if (row.Scene == scene.Name && row.Size == sizeName && row.Method == method.Name)
      {
        ms.push_back(row.MedianMs);
        ratios.push_back(row.MedianMs / plain[row.Run]);
        extra.push_back(row.MedianMs - plain[row.Run]);
        if (row.GPUMedianMs >= 0.0 && plainGPU[row.Run] >= 0.0)
        {
          gpu.push_back(row.GPUMedianMs);
          gpuExtra.push_back(row.GPUMedianMs - plainGPU[row.Run]);
        }
      }
    }
    md << "| " << method.Name << " | " << nprFixed(nprMedian(ms), 1) << " | "
       << nprFixed(nprMedian(ratios), 2) << " | " << nprFixed(nprMedian(extra), 1) << " | "
       << RunRange(extra) << " | "
       << (gpu.empty() ? std::string("n/a") : nprFixed(nprMedian(gpu), 3)) << " | "
       << (gpuExtra.empty() ? std::string("n/a") : nprFixed(nprMedian(gpuExtra), 3)) << " |\n";
  }
}

// speed.md: how the figures were taken, then a table per scene and size, and the feature lines.
std::string SpeedMarkdown(const std::vector<SpeedRow>& rows,
  const std::vector<SpeedMethod>& methods, const std::vector<nprBenchmarkScene>& scenes,
  const nprBenchmarkOptions& options, const std::string& renderer, bool featureLines)
{
  std::ostringstream md;
  md << "Frame times (npr-benchmark --speed) on " << renderer << ", no MSAA: median of "
     << options.Frames << " frames (camera turned 1 degree per frame, the methods interleaved), "
     << "median of " << options.Runs << " run" << (options.Runs > 1 ? "s" : "")
     << "; the ratio is to the plain VTK frame of the same run. GPU: the frame's GL_TIME_ELAPSED "
     << "(timestamp queries around Render(): median, and over the plain frame's), n/a without "
        "them.\n";
  for (const nprBenchmarkScene& scene : scenes)
  {
    for (const auto& size : options.Sizes)
    {
      WriteSpeedTable(md, rows, methods, scene, SizeName(size));
    }
    if (!featureLines)
    {
      continue;
    }
    std::vector<double> lines;
    for (const SpeedRow& row : rows)
    {
      if (row.Scene == scene.Name && row.Method == FeatureLinesName)
      {
        lines.push_back(row.MedianMs);
      }
    }
    md << "\n"
       << scene.Name << ": " << FeatureLinesName << ": " << nprFixed(nprMedian(lines), 1)
       << " ms (any size)\n";
  }
  return md.str();
}
}

int nprRunBenchmarkSpeed(const nprBenchmarkOptions& options)
{
  const nprClock::time_point runStart = nprClock::now();
  const std::vector<nprBenchmarkScene> scenes = nprStartBenchmarkRun(options);
  nprBenchmarkStage stage(options.LineWidth);
  stage.Window->SetMultiSamples(0);
  std::vector<SpeedMethod> methods = SelectMethods(options.Methods);
  const bool featureLines = options.Methods.empty() ||
    std::find(options.Methods.begin(), options.Methods.end(), "featurelines") !=
      options.Methods.end();
  const std::vector<SpeedRow> rows = MeasureScenes(stage, scenes, methods, options, featureLines);

  const std::string problems = WriteSpeedCSV(rows, options.Out + "/speed.csv");
  const char* renderer = vtkNPRRenderWindowFactory::GetGLRenderer(stage.Window);
  const std::string md =
    SpeedMarkdown(rows, methods, scenes, options, renderer ? renderer : "unknown", featureLines);
  std::ofstream markdown(options.Out + "/speed.md");
  markdown << md;
  std::cout << md;
  if (!markdown)
  {
    throw std::runtime_error(options.Out + "/speed.md: cannot write");
  }
  std::cerr << "npr-benchmark: wrote " << options.Out << "/speed.{csv,md} in "
            << nprFormat(nprSecondsSince(runStart), 4) << " s\n";
  return nprBenchmarkStatus(problems);
}
