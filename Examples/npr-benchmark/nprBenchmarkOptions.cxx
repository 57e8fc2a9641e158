// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nprBenchmarkOptions.h"

#include "nprArguments.h"
#include "nprBenchmarkScale.h"
#include "nprBenchmarkScenes.h"

#include <vtksys/SystemTools.hxx>

#include <algorithm>
#include <stdexcept>

namespace
{
const char* const Help = R"(usage: npr-benchmark --data DIR --out DIR [options]
       npr-benchmark --stress --data DIR --out DIR [options]
       npr-benchmark --coherence --data DIR --out DIR [options]
       npr-benchmark --drawing --data DIR --out DIR [options]
       npr-benchmark --speed --data DIR --out DIR [options]
       npr-benchmark --contours --data DIR --out DIR [options]
       npr-benchmark --scale --data DIR --out DIR [options]

Times every line method against the plain shaded frame and scores its line mask against the
object-space reference mask (precision, recall and F1 at 1 and 2 px, mean symmetric distance).
Writes OUT/results.csv, OUT/results.md and OUT/time_vs_f1.png (plus one plot per size).
With --stress: the edge pass on scaled, translated, near/far-stretched and degenerate versions of
each scene, against the unit case; writes OUT/stress.csv and OUT/stress.md.
With --coherence: how each style's lines follow the surfaces along a pan, an orbit and a dolly
(line pixels carried to the next frame through depth), and the sketch's frame time with surface
against screen noise; writes OUT/coherence.csv and OUT/coherence.md (default scenes cad,bunny,
sizes 640x480,1920x1080).
With --drawing: each scene's technical drawing written as SVG and PDF by a new exporter (time,
size, strokes against feature edges, the files rasterised by rsvg-convert and pdftoppm against the
reference mask), and the drawing style's frame times; writes OUT/drawing.csv and OUT/drawing.md
(default scenes cad,rotor,bunny,isosurface,bunny1m, size 1920x1080).
With --speed: the plain VTK frame, every style, unchanged edges, sketch and drawing frames and
VTK's own passes (vtkSobelGradientMagnitudePass, vtkOutlineGlowPass, vtkSSAOPass, vtkEDLShading,
and vtkPolyDataSilhouette re-extracted every frame), interleaved frame by frame in one window while
the camera turns 1 degree per frame, and vtkNPRFeatureLines per camera change; writes
OUT/speed.csv and OUT/speed.md (default scenes bunny1m,box, sizes 1920x1080,1024x768, 30 frames,
3 runs; --quick: box, 320x240, 2 frames, 1 run).
With --contours: the edge pass on smooth and scanned surfaces and on CAD parts, every line type and
silhouettes alone, with and without its smooth silhouettes, against two truths: the mesh's
silhouette edges and the smooth surface's contour (with the same creases and borders); writes
OUT/contours.csv and OUT/contours.md (default scenes cad,rotor,bunny,isosurface,blobs,knot and the
generated set cone-flange,steep-cone,filleted-cylinder,boss-pocket,bumpy-torus, also seen from 40
degrees above, each set summed up apart; size 1024x768; --quick: knot).
With --scale: the cost against the model's size, on the bunny decimated to 62,500 triangles and
refined by Loop subdivision (binary PLY, made once into the --scale-meshes folder): the wall time
and peak memory of whole programs, each a child process (npr-render in five styles and to SVG,
F3D where installed, a plain VTK program), and of each step in one (read, normals, feature lines,
first and later frames per style, the drawing's strokes), with ns per triangle; writes
OUT/scale.csv, OUT/scale.md, OUT/scale_programs.png and OUT/scale_steps.png (default sizes
1m,4m,16m, 1920x1080, 3 frames; --quick: 62k,250k, 320x240, 2 frames).

  --data DIR         folder of cad_part.vtp, rotor.ply and bunny.ply
  --out DIR          folder for the results (created)
  --dense-mesh FILE  the 1M-triangle scene (default DIR/bunny_1m.ply; the scene is skipped
                     with a warning when it is missing and --scenes does not name it)
  --frames N         timed frames per method and view (default 10; a warm-up frame first)
  --sizes LIST       WxH sizes, comma separated (default 1024x768,1920x1080)
  --scenes LIST      of cad, rotor, bunny, isosurface, blobs, knot, bunny1m, box (default all
                     but box; --stress: cad,bunny) and the generated set cone-flange,
                     steep-cone, filleted-cylinder, boss-pocket, bumpy-torus (--contours)
  --methods LIST     method names, or the families edges, inked, objectlines (default all)
  --cameras N        the first N of the 3 cameras (default 3; --stress: 1)
  --orbit DEG        --contours: instead of the cameras, a turn around each model: azimuth
                     -180 to 180 every DEG degrees (1 to 120) at each camera's elevation
                     (-15, 20, 35); --orbit 10 is 108 views
  --runs N           --speed: repeats of the whole measurement; the median of their medians
                     is reported (default 3); --scale: runs of every size, each figure the
                     median (default 1)
  --line-width PX    line width of every method (default 1.5)
  --quick            one small scene (cad), one camera, 320x240, 2 frames, every method
  --scale-sizes LIST --scale: of 62k, 250k, 1m, 4m, 16m (62,500 triangles times 1, 4, 16, 64,
                     256; default 1m,4m,16m)
  --scale-meshes DIR --scale: the meshes' folder, made where missing (default OUT/meshes)
  --scale-steps FILE the steps of one model in this process, into OUT/steps.csv (what --scale
                     runs as a child for each size)
  --stress-cases LIST  --stress: only the cases whose name contains one of these (comma
                     separated; the unit case always runs), e.g. scale,translate
  --max-drift X      --stress: exit 1 when a case's F1@1 moves more than X from the unit
                     case or a G-buffer pixel is non-finite or out of [near, far]
  --save-masks       also write each reference and method mask as OUT/masks/*.png
  -h, --help         this text
  --version          the program and vtkNPR version
)";

// Which of the options that modes default the command line gave.
struct GivenOptions
{
  bool Frames = false;
  bool Sizes = false;
  bool Cameras = false;
  bool Runs = false;
};

std::vector<std::string> ParseScaleSizes(const std::string& text)
{
  const std::vector<std::string> sizes = nprSplitList(text, true);
  const std::vector<std::string>& names = nprScaleSizeNames();
  for (const std::string& size : sizes)
  {
    if (std::find(names.begin(), names.end(), size) == names.end())
    {
      throw nprUsageError("--scale-sizes: unknown size '" + size + "' (62k, 250k, 1m, 4m, 16m)");
    }
  }
  if (sizes.empty())
  {
    throw nprUsageError("--scale-sizes expects a list of 62k, 250k, 1m, 4m, 16m");
  }
  return sizes;
}

std::vector<std::pair<int, int>> ParseSizes(const std::string& text)
{
  std::vector<std::pair<int, int>> sizes;
  for (const std::string& size : nprSplitList(text, true))
  {
    sizes.push_back(nprParseSize("--sizes", size, 16, 8192, "WxH[,WxH...]"));
  }
  if (sizes.empty())
  {
    throw nprUsageError("--sizes expects WxH[,WxH...]");
  }
  return sizes;
}

std::vector<std::string> ParseScenes(const std::string& text)
{
  const std::vector<std::string> scenes = nprSplitList(text, true);
  const auto& names = nprBenchmarkSceneNames();
  for (const std::string& scene : scenes)
  {
    // box (--speed's small scene) is not among the defaults.
    if (scene != "box" && !nprIsGeneratedScene(scene) &&
      std::find(names.begin(), names.end(), scene) == names.end())
    {
      throw nprUsageError("unknown scene '" + scene +
        "' (cad, rotor, bunny, isosurface, blobs, knot, bunny1m, box, cone-flange, "
        "steep-cone, filleted-cylinder, boss-pocket, bumpy-torus)");
    }
  }
  return scenes;
}

// The options that take a text as it is (--data DIR) or switch something on (--quick).
bool ParseTextOrSwitch(nprArgumentReader& arguments, nprBenchmarkOptions& options)
{
  using Options = nprBenchmarkOptions;
  using Text = std::pair<const char*, std::string Options::*>;
  using Switch = std::pair<const char*, bool Options::*>;
  static const Text texts[] = { { "--data", &Options::Data }, { "--out", &Options::Out },
    { "--dense-mesh", &Options::DenseMesh }, { "--scale-meshes", &Options::ScaleMeshes },
    { "--scale-steps", &Options::ScaleSteps } };
  static const Switch switches[] = { { "--quick", &Options::Quick },
    { "--stress", &Options::Stress }, { "--coherence", &Options::Coherence },
    { "--drawing", &Options::Drawing }, { "--speed", &Options::Speed },
    { "--contours", &Options::Contours }, { "--scale", &Options::Scale },
    { "--save-masks", &Options::SaveMasks } };
  const std::string& arg = arguments.Current();
  for (const auto& text : texts)
  {
    if (arg == text.first)
    {
      options.*text.second = arguments.Value();
      return true;
    }
  }
  for (const auto& on : switches)
  {
    if (arg == on.first)
    {
      options.*on.second = true;
      return true;
    }
  }
  return false;
}

// The options that take a number, each checked against its range.
bool ParseNumber(nprArgumentReader& arguments, nprBenchmarkOptions& options, GivenOptions& given)
{
  const std::string& arg = arguments.Current();
  if (arg == "--frames")
  {
    options.Frames = nprParseInteger(arg, arguments.Value(), 1, 10000);
    given.Frames = true;
  }
  else if (arg == "--cameras")
  {
    options.Cameras =
      nprParseInteger(arg, arguments.Value(), 1, static_cast<int>(nprBenchmarkCameras().size()));
    given.Cameras = true;
  }
  else if (arg == "--orbit")
  {
    options.OrbitStep = nprParseInteger(arg, arguments.Value(), 1, 120);
  }
  else if (arg == "--runs")
  {
    options.Runs = nprParseInteger(arg, arguments.Value(), 1, 100);
    given.Runs = true;
  }
  else if (arg == "--line-width")
  {
    options.LineWidth = nprParseNumberIn(arg, arguments.Value(), 0.5, 16.0);
  }
  else if (arg == "--max-drift")
  {
    options.MaxDrift = nprParseNumberIn(arg, arguments.Value(), 0.0, 1.0);
  }
  else
  {
    return false;
  }
  return true;
}

// The options that take a comma-separated list.
bool ParseList(nprArgumentReader& arguments, nprBenchmarkOptions& options, GivenOptions& given)
{
  const std::string& arg = arguments.Current();
  if (arg == "--sizes")
  {
    options.Sizes = ParseSizes(arguments.Value());
    given.Sizes = true;
  }
  else if (arg == "--scenes")
  {
    options.Scenes = ParseScenes(arguments.Value());
    options.ScenesGiven = true;
  }
  else if (arg == "--methods")
  {
    options.Methods = nprSplitList(arguments.Value(), true);
  }
  else if (arg == "--scale-sizes")
  {
    options.ScaleSizes = ParseScaleSizes(arguments.Value());
  }
  else if (arg == "--stress-cases")
  {
    options.StressCases = nprSplitList(arguments.Value(), true);
  }
  else
  {
    return false;
  }
  return true;
}

// The scenes a mode measures unless --scenes names others.
void DefaultScenes(nprBenchmarkOptions& options, const std::vector<std::string>& scenes)
{
  if (!options.ScenesGiven)
  {
    options.Scenes = scenes;
    options.ScenesGiven = true;
  }
}

// --scale's defaults; its options refused without it.
void ApplyScaleDefaults(nprBenchmarkOptions& options, const GivenOptions& given)
{
  if (!options.Scale)
  {
    if (!options.ScaleSizes.empty() || !options.ScaleMeshes.empty())
    {
      throw nprUsageError("--scale-sizes and --scale-meshes go with --scale");
    }
    if (!options.ScaleSteps.empty() && !given.Sizes)
    {
      options.Sizes = { { 1920, 1080 } };
    }
    return;
  }
  if (options.ScaleSizes.empty())
  {
    options.ScaleSizes = options.Quick ? std::vector<std::string>{ "62k", "250k" }
                                       : std::vector<std::string>{ "1m", "4m", "16m" };
  }
  if (options.ScaleMeshes.empty())
  {
    options.ScaleMeshes = options.Out + "/meshes";
  }
  if (given.Sizes && options.Sizes.size() > 1)
  {
    throw nprUsageError("--scale measures one window size: --sizes WxH");
  }
  if (!given.Sizes && !options.Quick)
  {
    options.Sizes = { { 1920, 1080 } };
  }
  if (!given.Frames && !options.Quick)
  {
    options.Frames = 3;
  }
  options.Runs = given.Runs ? options.Runs : 1;
}

void ApplySpeedDefaults(nprBenchmarkOptions& options, const GivenOptions& given)
{
  DefaultScenes(options,
    options.Quick ? std::vector<std::string>{ "box" }
                  : std::vector<std::string>{ "bunny1m", "box" });
  if (!given.Sizes && !options.Quick)
  {
    options.Sizes = { { 1920, 1080 }, { 1024, 768 } };
  }
  if (!given.Frames && !options.Quick)
  {
    options.Frames = 30;
  }
  if (!given.Runs && options.Quick)
  {
    options.Runs = 1;
  }
}

void ApplyQuickDefaults(nprBenchmarkOptions& options, const GivenOptions& given)
{
  DefaultScenes(options, { options.Contours ? "knot" : "cad" });
  options.Cameras = given.Cameras ? options.Cameras : 1;
  options.Frames = given.Frames ? options.Frames : 2;
  if (!given.Sizes)
  {
    options.Sizes = { { 320, 240 } };
  }
}

void ApplyContoursDefaults(nprBenchmarkOptions& options, const GivenOptions& given)
{
  std::vector<std::string> scenes = { "knot" };
  if (!options.Quick)
  {
    scenes = { "cad", "rotor", "bunny", "isosurface", "blobs", "knot" };
    const std::vector<std::string>& generated = nprBenchmarkGeneratedSceneNames();
    scenes.insert(scenes.end(), generated.begin(), generated.end());
  }
  DefaultScenes(options, scenes);
  if (!given.Sizes && !options.Quick)
  {
    options.Sizes = { { 1024, 768 } };
  }
}

// Each mode's scenes, sizes, frames, runs and cameras where the command line gave none; --speed
// and --quick first, so that a quick run of another mode keeps the quick defaults.
void ApplyModeDefaults(nprBenchmarkOptions& options, const GivenOptions& given)
{
  ApplyScaleDefaults(options, given);
  if (options.Speed)
  {
    ApplySpeedDefaults(options, given);
  }
  if (options.Quick)
  {
    ApplyQuickDefaults(options, given);
  }
  if (options.Coherence)
  {
    DefaultScenes(options, { "cad", "bunny" });
    if (!given.Sizes && !options.Quick)
    {
      options.Sizes = { { 640, 480 }, { 1920, 1080 } };
    }
  }
  if (options.Contours)
  {
    ApplyContoursDefaults(options, given);
  }
  if (options.Drawing && !given.Sizes && !options.Quick)
  {
    options.Sizes = { { 1920, 1080 } };
  }
  if (options.Stress)
  {
    DefaultScenes(options, { "cad", "bunny" });
    options.Cameras = given.Cameras ? options.Cameras : 1;
    if (!given.Sizes && !options.Quick)
    {
      options.Sizes = { { 1024, 768 } };
    }
  }
  if (!options.ScenesGiven)
  {
    options.Scenes = nprBenchmarkSceneNames(); // still not given: a missing bunny1m is skipped
  }
}
}

void nprMakeBenchmarkFolder(const std::string& path)
{
  if (!vtksys::SystemTools::MakeDirectory(path))
  {
    throw std::runtime_error(path + ": cannot create the folder");
  }
}

nprBenchmarkOptions nprParseBenchmarkOptions(int argc, char* argv[])
{
  nprBenchmarkOptions options;
  GivenOptions given;
  nprArgumentReader arguments(argc, argv, Help);
  while (arguments.Next())
  {
    if (!ParseTextOrSwitch(arguments, options) && !ParseNumber(arguments, options, given) &&
      !ParseList(arguments, options, given))
    {
      throw nprUsageError("unknown argument '" + arguments.Current() + "' (see --help)");
    }
  }
  if (options.Data.empty() || options.Out.empty())
  {
    throw nprUsageError("--data DIR and --out DIR are required (see --help)");
  }
  if (options.OrbitStep > 0 && (!options.Contours || given.Cameras))
  {
    throw nprUsageError("--orbit DEG goes with --contours, without --cameras");
  }
  if (options.DenseMesh.empty())
  {
    options.DenseMesh = options.Data + "/bunny_1m.ply";
  }
  ApplyModeDefaults(options, given);
  return options;
}

void nprMakeBenchmarkFolders(const nprBenchmarkOptions& options)
{
  nprMakeBenchmarkFolder(options.Out);
  if (options.SaveMasks)
  {
    nprMakeBenchmarkFolder(options.Out + "/masks");
  }
}

std::string nprBenchmarkSizesLine(const nprBenchmarkOptions& options)
{
  std::string text;
  for (const auto& size : options.Sizes)
  {
    text +=
      (text.empty() ? "" : ", ") + std::to_string(size.first) + "x" + std::to_string(size.second);
  }
  return text;
}
