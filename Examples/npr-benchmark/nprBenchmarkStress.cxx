// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nprBenchmarkStress.h"

#include "nprBenchmarkOptions.h"
#include "nprBenchmarkReport.h"
#include "nprBenchmarkScenes.h"
#include "nprBenchmarkStage.h"
#include "nprEdgeMetrics.h"
#include "nprMeshes.h"
#include "nprModel.h"
#include "nprTiming.h"

#include "vtkCamera.h"
#include "vtkNPRGBufferPass.h"
#include "vtkNPRPass.h"
#include "vtkNPRRenderWindowFactory.h"
#include "vtkPixelBufferObject.h"
#include "vtkPolyData.h"
#include "vtkTextureObject.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace
{
struct StressCase
{
  enum Kinds
  {
    Unit,
    Scale,
    Translate,
    FarPlane,  // far pulled out: far = near x ratio
    NearPlane, // near pulled in: near = far / ratio
    Slivers,
    Soup,
    ZeroNormals,
    NaNPoints
  };
  std::string Name;
  Kinds Kind;
  double Value;
};

std::vector<StressCase> StressCases()
{
  std::vector<StressCase> cases = { { "unit", StressCase::Unit, 1.0 } };
  for (const char* factor : { "1e-6", "1e-3", "1e3", "1e6" })
  {
    cases.push_back({ std::string("scale ") + factor, StressCase::Scale, std::atof(factor) });
  }
  for (const char* distance : { "1e3", "1e4", "1e5", "1e6", "1e7" })
  {
    cases.push_back(
      { std::string("translate ") + distance, StressCase::Translate, std::atof(distance) });
  }
  for (const char* ratio : { "1e3", "1e6" })
  {
    cases.push_back(
      { std::string("near/far ") + ratio + " (far)", StressCase::FarPlane, std::atof(ratio) });
    cases.push_back(
      { std::string("near/far ") + ratio + " (near)", StressCase::NearPlane, std::atof(ratio) });
  }
  cases.push_back({ "slivers", StressCase::Slivers, 0.0 });
  cases.push_back({ "duplicate vertices", StressCase::Soup, 0.0 });
  cases.push_back({ "zero normals", StressCase::ZeroNormals, 0.0 });
  cases.push_back({ "NaN points", StressCase::NaNPoints, 0.0 });
  return cases;
}

// What the float G-buffer's geometry texture holds: view depth (r), normal code (g).
struct GBufferFigures
{
  long long Covered = 0;
  long long NonFinite = 0;
  long long BadDepth = 0;
  std::vector<unsigned char> Coverage; // 1 where covered, row 0 = bottom
};

GBufferFigures ReadGBuffer(
  vtkRenderWindow* window, vtkNPRGBufferPass* gbuffer, double nearPlane, double farPlane)
{
  GBufferFigures figures;
  vtkTextureObject* texture = gbuffer->GetGeometryTexture();
  if (!texture)
  {
    return figures; // nothing drawn
  }
  window->MakeCurrent();
  vtkPixelBufferObject* buffer = texture->Download();
  const int components = texture->GetComponents();
  const size_t count = static_cast<size_t>(texture->GetWidth()) * texture->GetHeight();
  const auto* texels = static_cast<const float*>(buffer->MapPackedBuffer());
  figures.Coverage.assign(count, 0);
  for (size_t i = 0; texels && i < count; ++i)
  {
    const float* texel = texels + i * components;
    // Background is cleared to 0; the shader clamps depths to >= 1e-30 (NaN may pass).
    if (texel[0] == 0.0f)
    {
      continue;
    }
    ++figures.Covered;
    figures.Coverage[i] = 1;
    bool finite = std::isfinite(texel[0]);
    for (int c = 1; c < std::min(components, 3); ++c)
    {
      finite = finite && std::isfinite(texel[c]);
    }
    figures.NonFinite += finite ? 0 : 1;
    const double depth = texel[0];
    const bool inRange =
      depth > 1e-29 && depth >= nearPlane * (1.0 - 1e-3) && depth <= farPlane * (1.0 + 1e-3);
    figures.BadDepth += finite && !inRange ? 1 : 0;
  }
  buffer->UnmapPackedBuffer();
  buffer->Delete();
  return figures;
}

// The case's meshes (raw: its topology, mesh: what is drawn), and what was done, in numbers.
void StressMeshes(const nprBenchmarkScene& scene, const StressCase& stress, double modelSize,
  std::ostream& detail, vtkSmartPointer<vtkPolyData>& raw, vtkSmartPointer<vtkPolyData>& mesh)
{
  raw = scene.Raw;
  mesh = nullptr;
  switch (stress.Kind)
  {
    case StressCase::Scale:
      raw = nprScaledMesh(scene.Raw, stress.Value);
      detail << "points x " << nprFormat(stress.Value);
      break;
    case StressCase::Translate:
      raw = nprTranslatedMesh(scene.Raw, stress.Value * modelSize);
      detail << "points moved " << nprFormat(stress.Value) << " model sizes ("
             << nprFormat(stress.Value * modelSize, 3) << ")";
      break;
    case StressCase::Slivers:
      raw = nprSliverMesh(scene.Raw);
      detail << (raw->GetNumberOfPolys() - scene.Raw->GetNumberOfPolys()) / 2
             << " triangles split in a needle and two (apex 1e-6 edge length off the edge)";
      break;
    case StressCase::Soup:
      raw = nprPolygonSoup(scene.Raw);
      detail << "every triangle its own 3 points (" << raw->GetNumberOfPoints() << " points)";
      break;
    case StressCase::NaNPoints:
      raw = nprNaNPointsMesh(scene.Raw);
      detail << raw->GetNumberOfPoints() - scene.Raw->GetNumberOfPoints()
             << " NaN points, each in one added triangle";
      break;
    case StressCase::ZeroNormals:
      // As a file with such normals reaches the mapper through npr-render's preparation.
      mesh = nprPrepareMesh(nprZeroNormalsMesh(scene.Mesh));
      detail << "every 7th point normal (0,0,0), through vtkNPRShadingNormals";
      break;
    default:
      break;
  }
  if (!mesh)
  {
    mesh = raw == scene.Raw ? scene.Mesh : nprPrepareMesh(raw);
  }
}

// The unit case and the cases --stress-cases names (every case without it).
std::vector<StressCase> SelectStressCases(const nprBenchmarkOptions& options)
{
  std::vector<StressCase> cases;
  for (const StressCase& stress : StressCases())
  {
    bool wanted = stress.Kind == StressCase::Unit || options.StressCases.empty();
    for (const std::string& part : options.StressCases)
    {
      wanted = wanted || stress.Name.find(part) != std::string::npos;
    }
    if (wanted)
    {
      cases.push_back(stress);
    }
  }
  return cases;
}

// The unit case's figures at one scene, size and camera, which the other cases are compared with.
struct UnitFigures
{
  nprMask Reference;
  GBufferFigures Buffer;
  double F1 = 0.0;
};

// What one case draws: the reference mask, and the edge pass's mask and G-buffer.
struct CaseFrames
{
  nprMask Reference;
  nprMask Mask;
  GBufferFigures Buffer;
  double ReferenceSeconds = 0.0;
};

// The camera's clipping range as the near/far cases stretch it, written to the row.
void ApplyStressRange(
  nprBenchmarkStage& stage, const StressCase& stress, std::ostream& detail, nprStressRow& row)
{
  double range[2];
  stage.Camera()->GetClippingRange(range);
  if (stress.Kind == StressCase::FarPlane)
  {
    range[1] = range[0] * stress.Value;
  }
  else if (stress.Kind == StressCase::NearPlane)
  {
    range[0] = range[1] / stress.Value;
  }
  if (stress.Kind == StressCase::FarPlane || stress.Kind == StressCase::NearPlane)
  {
    detail << "clipping range [" << nprFormat(range[0], 3) << ", " << nprFormat(range[1], 3) << "]";
  }
  stage.Camera()->SetClippingRange(range);
  row.Near = range[0];
  row.Far = range[1];
}

// The reference for the camera as drawn, then the edge pass's frame at the row's clipping range.
CaseFrames DrawCase(nprBenchmarkStage& stage, vtkNPRPass* pass, const nprBenchmarkMethod& method,
  const nprStressRow& row)
{
  CaseFrames frames;
  stage.Window->Render(); // the camera as drawn, before the reference reads it
  const nprClock::time_point referenceStart = nprClock::now();
  frames.Reference = stage.ReferenceMask();
  frames.ReferenceSeconds = nprSecondsSince(referenceStart);
  // The range as the user set it, whatever the reference did.
  stage.Camera()->SetClippingRange(row.Near, row.Far);
  stage.Activate(pass, false);
  stage.TimedFrame(false);
  frames.Buffer = ReadGBuffer(stage.Window, pass->GetGBufferPass(), row.Near, row.Far);
  frames.Mask = stage.MethodMask(method, pass);
  stage.Activate(nullptr, false);
  return frames;
}

void SaveCaseMasks(const nprBenchmarkOptions& options, const std::string& scene,
  const StressCase& stress, const CaseFrames& frames)
{
  std::string name = scene + "_" + stress.Name;
  std::replace_if(
    name.begin(), name.end(),
    [](char ch) { return !std::isalnum(static_cast<unsigned char>(ch)) && ch != '-'; }, '_');
  nprWriteMaskPNG(frames.Mask, options.Out + "/masks/" + name + ".png");
  nprWriteMaskPNG(frames.Reference, options.Out + "/masks/" + name + "_reference.png");
}

// The row's scores: the mask against its own reference and the unit case's, and the G-buffer's
// coverage and depths against the unit case's. The unit case is its own unit.
void ScoreCase(
  const StressCase& stress, const CaseFrames& frames, UnitFigures& unitCase, nprStressRow& row)
{
  if (stress.Kind == StressCase::Unit)
  {
    unitCase.Reference = frames.Reference;
    unitCase.Buffer = frames.Buffer;
  }
  const nprMask& mask = frames.Mask;
  nprEdgeMetrics own, unit, agreement;
  own.Compute(mask.Pixels.data(), frames.Reference.Pixels.data(), mask.Width, mask.Height);
  unit.Compute(mask.Pixels.data(), unitCase.Reference.Pixels.data(), mask.Width, mask.Height);
  agreement.Compute(
    frames.Reference.Pixels.data(), unitCase.Reference.Pixels.data(), mask.Width, mask.Height);
  row.F1Own = own.F1(1.0);
  row.F1Unit = unit.F1(1.0);
  if (stress.Kind == StressCase::Unit)
  {
    unitCase.F1 = row.F1Unit;
  }
  row.Drift = row.F1Unit - unitCase.F1;
  row.ReferenceF1 = agreement.F1(1.0);
  row.MeanDistanceUnit = unit.MeanSymmetricDistance();
  row.MethodPixels = own.GetMethodPixels();
  row.ReferencePixels = own.GetReferencePixels();
  row.StrayPixels = unit.CountFarMethodPixels(3.0);
  const GBufferFigures& buffer = frames.Buffer;
  row.CoveredPixels = buffer.Covered;
  for (size_t i = 0; i < buffer.Coverage.size() && i < unitCase.Buffer.Coverage.size(); ++i)
  {
    row.CoverageChanged += buffer.Coverage[i] != unitCase.Buffer.Coverage[i] ? 1 : 0;
  }
  row.NonFinitePixels = buffer.NonFinite;
  row.BadDepthPixels = buffer.BadDepth;
}

// With --max-drift: whether the row is outside it (said on stderr).
bool OutsideDrift(
  const nprBenchmarkOptions& options, const std::string& scene, const nprStressRow& row)
{
  if (options.MaxDrift < 0.0 ||
    (std::abs(row.Drift) <= options.MaxDrift && row.NonFinitePixels == 0 &&
      row.BadDepthPixels == 0))
  {
    return false;
  }
  std::cerr << "npr-benchmark: FAILED: " << scene << " " << row.Case << ": F1@1 drift "
            << nprFormat(row.Drift, 4) << " (allowed " << options.MaxDrift << "), "
            << row.NonFinitePixels << " non-finite, " << row.BadDepthPixels
            << " bad-depth pixels\n";
  return true;
}

void PrintCase(const nprBenchmarkStage& stage, const std::string& scene, const nprStressRow& row,
  double caseSeconds, double referenceSeconds)
{
  std::cerr << "npr-benchmark: stress " << scene << " " << row.Case << ": F1@1 "
            << nprFormat(row.F1Own, 3) << " (unit reference " << nprFormat(row.F1Unit, 3)
            << "), stray " << row.StrayPixels << ", non-finite " << row.NonFinitePixels
            << ", bad depth " << row.BadDepthPixels << " (" << nprFormat(caseSeconds, 2)
            << " s; reference " << nprFormat(referenceSeconds, 2) << " s: lines "
            << nprFormat(stage.Reference->GetLinesTime(), 2) << ", locator "
            << nprFormat(stage.Reference->GetLocatorTime(), 2) << ", rays "
            << nprFormat(stage.Reference->GetVisibilityTime(), 2) << ")\n";
}

// One --stress run: the stage, the edge pass at its defaults, the cases, and what they measured.
struct StressRun
{
  explicit StressRun(const nprBenchmarkOptions& options)
    : Options(options)
    , Stage(options.LineWidth)
    , Cases(SelectStressCases(options))
  {
    this->Method.Name = "edges-float";
    this->Pass = this->Stage.MakePass(this->Method);
  }

  const nprBenchmarkOptions& Options;
  nprBenchmarkStage Stage;
  nprBenchmarkMethod Method;
  vtkSmartPointer<vtkNPRPass> Pass;
  std::vector<StressCase> Cases;
  std::vector<nprStressRow> Rows;
  int Failures = 0;
};

// Every case of one scene at the window's size and one camera, each a row; suffix names the
// size and camera in the case where the run has several.
void MeasureCases(StressRun& run, const nprBenchmarkScene& scene, double modelSize,
  const nprBenchmarkCamera& camera, const std::string& suffix)
{
  UnitFigures unitCase;
  for (const StressCase& stress : run.Cases)
  {
    const nprClock::time_point caseStart = nprClock::now();
    nprStressRow row;
    row.Scene = scene.Name;
    row.Case = stress.Name + suffix;
    std::ostringstream detail;
    vtkSmartPointer<vtkPolyData> raw, mesh;
    StressMeshes(scene, stress, modelSize, detail, raw, mesh);
    run.Stage.SetMesh(mesh, raw);
    run.Stage.Activate(nullptr, false);
    nprApplyBenchmarkCamera(run.Stage.Renderer, camera);
    ApplyStressRange(run.Stage, stress, detail, row);
    row.Detail = detail.str();
    const CaseFrames frames = DrawCase(run.Stage, run.Pass, run.Method, row);
    if (run.Options.SaveMasks)
    {
      SaveCaseMasks(run.Options, scene.Name, stress, frames);
    }
    ScoreCase(stress, frames, unitCase, row);
    run.Rows.push_back(row);
    run.Failures += OutsideDrift(run.Options, scene.Name, row) ? 1 : 0;
    PrintCase(run.Stage, scene.Name, row, nprSecondsSince(caseStart), frames.ReferenceSeconds);
  }
}

int WriteStressResults(const nprBenchmarkOptions& options, vtkRenderWindow* window,
  const std::vector<nprStressRow>& rows, double seconds, int failures)
{
  nprBenchmarkInfo info;
  info.Renderer = vtkNPRRenderWindowFactory::GetGLRenderer(window);
  info.Backend = vtkNPRRenderWindowFactory::GetBackendName(window);
  info.Sizes = nprBenchmarkSizesLine(options);
  info.Cameras = nprBenchmarkCameraLine(options.Cameras);
  info.Seconds = seconds;
  nprWriteStressCSV(options.Out + "/stress.csv", rows);
  nprWriteStressMarkdown(options.Out + "/stress.md", rows, info);
  std::cerr << "npr-benchmark: wrote " << options.Out << "/stress.{csv,md} in "
            << nprFormat(info.Seconds, 4) << " s\n";
  if (options.MaxDrift >= 0.0)
  {
    std::cerr << "npr-benchmark: " << failures << " of " << rows.size()
              << " stress rows outside the allowed drift\n";
  }
  return failures ? 1 : 0;
}
}

int nprRunBenchmarkStress(const nprBenchmarkOptions& options)
{
  const nprClock::time_point runStart = nprClock::now();
  const std::vector<nprBenchmarkScene> scenes = nprStartBenchmarkRun(options);
  StressRun run(options);
  for (const nprBenchmarkScene& scene : scenes)
  {
    const double modelSize = nprModelSize(scene.Raw);
    for (const auto& size : options.Sizes)
    {
      run.Stage.Window->SetSize(size.first, size.second);
      for (int c = 0; c < options.Cameras; ++c)
      {
        const nprBenchmarkCamera& camera = nprBenchmarkCameras()[c];
        std::string suffix;
        if (options.Cameras > 1 || options.Sizes.size() > 1)
        {
          suffix = " [" + std::string(camera.Name) + " " + std::to_string(size.first) + "x" +
            std::to_string(size.second) + "]";
        }
        MeasureCases(run, scene, modelSize, camera, suffix);
      }
    }
  }
  return WriteStressResults(
    options, run.Stage.Window, run.Rows, nprSecondsSince(runStart), run.Failures);
}
