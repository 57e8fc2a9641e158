// npr-benchmark: run time against error of every line method, for a set of scenes and cameras,
// against the object-space reference mask. Documentation/benchmarks.md describes the scenes,
// methods and figures; `npr-benchmark --help` the flags.
#include "nprBenchmarkReport.h"
#include "nprBenchmarkScenes.h"
#include "nprEdgeMetrics.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkImageData.h"
#include "vtkLogger.h"
#include "vtkMapper.h"
#include "vtkNPREdgePass.h"
#include "vtkNPRFeatureLines.h"
#include "vtkNPRGBufferPass.h"
#include "vtkNPRInkPass.h"
#include "vtkNPRPass.h"
#include "vtkNPRReferenceMask.h"
#include "vtkNPRRenderWindowFactory.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOutputWindow.h"
#include "vtkPNGWriter.h"
#include "vtkPixelBufferObject.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkTextureObject.h"
#include "vtkWindowToImageFilter.h"


#include <vtksys/SystemTools.hxx>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace
{
using Clock = std::chrono::steady_clock;

struct UsageError : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

// VTK's messages go to stderr on one line each, or (NPR_VERBOSE=1) in full.
class nprBenchmarkOutputWindow : public vtkOutputWindow
{
public:
  static nprBenchmarkOutputWindow* New();
  vtkTypeMacro(nprBenchmarkOutputWindow, vtkOutputWindow);
  void DisplayText(const char* text) override
  {
    if (!text || !*text)
    {
      return;
    }
    std::string line = text;
    if (!this->Verbose)
    {
      while (!line.empty() && std::isspace(static_cast<unsigned char>(line.back())))
      {
        line.pop_back();
      }
      line.erase(0, line.find_last_of('\n') + 1);
    }
    std::cerr << "npr-benchmark: vtk: " << line << (this->Verbose ? "" : "\n");
  }
  bool Verbose = false;
};
vtkStandardNewMacro(nprBenchmarkOutputWindow);

double Seconds(Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}

double Median(std::vector<double> values)
{
  if (values.empty())
  {
    return 0.0;
  }
  std::sort(values.begin(), values.end());
  const size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

// ---- Methods -----------------------------------------------------------------------------------
enum class Family
{
  Edges,
  Inked,
  ObjectLines
};

struct MethodSpec
{
  std::string Name;
  Family Kind = Family::Edges;
  int Encoding = vtkNPREdgePass::FLOAT;
  double SilhouetteThreshold = 0.005;
  double CreaseAngle = 30.0;
  double PackedThreshold = 0.1;
  std::string Settings;
};

// Every method, in the order of the report. Two threshold settings per G-buffer encoding: the
// pass's defaults and a sensitive one (float, half: smaller depth steps and crease angles;
// packed: half the Laplacian threshold; below that the quantisation noise draws lines).
std::vector<MethodSpec> AllMethods()
{
  std::vector<MethodSpec> methods;
  for (int encoding : { vtkNPREdgePass::FLOAT, vtkNPREdgePass::HALF, vtkNPREdgePass::PACKED8,
         vtkNPREdgePass::PACKED16 })
  {
    const bool packed = encoding == vtkNPREdgePass::PACKED8 || encoding == vtkNPREdgePass::PACKED16;
    for (bool sensitive : { false, true })
    {
      MethodSpec method;
      const std::string name = vtkNPREdgePass::GetEncodingName(encoding);
      method.Name = "edges-" + name + (sensitive ? "-sensitive" : "");
      method.Encoding = encoding;
      std::ostringstream settings;
      settings << name << " G-buffer, ";
      if (packed)
      {
        method.PackedThreshold = sensitive ? 0.05 : 0.1;
        settings << "packed threshold " << method.PackedThreshold;
      }
      else
      {
        method.SilhouetteThreshold = sensitive ? 0.0025 : 0.005;
        method.CreaseAngle = sensitive ? 25.0 : 30.0;
        settings << "silhouette threshold " << method.SilhouetteThreshold << ", crease angle "
                 << method.CreaseAngle;
      }
      method.Settings = settings.str();
      methods.push_back(method);
    }
  }
  MethodSpec inked;
  inked.Name = "inked";
  inked.Kind = Family::Inked;
  inked.Settings = "vtkNPRInkPass: fat back-face wireframe, filled fronts with polygon offset";
  methods.push_back(inked);
  MethodSpec lines;
  lines.Name = "objectlines";
  lines.Kind = Family::ObjectLines;
  lines.Settings = "vtkNPRFeatureLines for the camera every frame, line actor over the shaded "
                   "mesh (coincident-topology polygon offset)";
  methods.push_back(lines);
  return methods;
}

// ---- Options -----------------------------------------------------------------------------------
struct Options
{
  std::string Data;
  std::string Out;
  std::string DenseMesh; // bunny_1m.ply; default DATA/bunny_1m.ply
  int Frames = 10;
  std::vector<std::pair<int, int>> Sizes = { { 1024, 768 }, { 1920, 1080 } };
  std::vector<std::string> Scenes;
  bool ScenesGiven = false;
  std::vector<std::string> Methods;
  int Cameras = 3;
  double LineWidth = 1.5;
  bool Quick = false;
  bool Stress = false;
  std::vector<std::string> StressCases; // name parts; empty: every case
  double MaxDrift = -1.0;               // < 0: report only
  bool SaveMasks = false;
};

void PrintHelp()
{
  std::cout << R"(usage: npr-benchmark --data DIR --out DIR [options]
       npr-benchmark --stress --data DIR --out DIR [options]

Times every line method against the plain shaded frame and scores its line mask against the
object-space reference mask (precision, recall and F1 at 1 and 2 px, mean symmetric distance).
Writes OUT/results.csv, OUT/results.md and OUT/time_vs_f1.png (plus one plot per size).
With --stress: the edge pass on scaled, translated, near/far-stretched and degenerate versions of
each scene, against the unit case; writes OUT/stress.csv and OUT/stress.md.

  --data DIR         folder of cad_part.vtp, rotor.ply and bunny.ply
  --out DIR          folder for the results (created)
  --dense-mesh FILE  the 1M-triangle scene (default DIR/bunny_1m.ply; the scene is skipped
                     with a warning when it is missing and --scenes does not name it)
  --frames N         timed frames per method and view (default 10; a warm-up frame first)
  --sizes LIST       WxH sizes, comma separated (default 1024x768,1920x1080)
  --scenes LIST      of cad, rotor, bunny, isosurface, bunny1m (default all; --stress: cad,bunny)
  --methods LIST     method names, or the families edges, inked, objectlines (default all)
  --cameras N        the first N of the 3 cameras (default 3; --stress: 1)
  --line-width PX    line width of every method (default 1.5)
  --quick            one small scene (cad), one camera, 320x240, 2 frames, every method
  --stress-cases LIST  --stress: only the cases whose name contains one of these (comma
                     separated; the unit case always runs), e.g. scale,translate
  --max-drift X      --stress: exit 1 when a case's F1@1 moves more than X from the unit
                     case or a G-buffer pixel is non-finite or out of [near, far]
  --save-masks       also write each reference and method mask as OUT/masks/*.png
  -h, --help         this text
)";
}

int ParseInteger(const std::string& flag, const std::string& text, int low, int high)
{
  char* end = nullptr;
  const long value = std::strtol(text.c_str(), &end, 10);
  if (text.empty() || *end || value < low || value > high)
  {
    throw UsageError(flag + " expects an integer in " + std::to_string(low) + ".." +
      std::to_string(high) + ", got '" + text + "'");
  }
  return static_cast<int>(value);
}

// A number in [low, high]; range names the range in the message ("0.5..16").
double ParseNumber(
  const std::string& flag, const std::string& text, double low, double high, const char* range)
{
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || *end || !(value >= low && value <= high))
  {
    throw UsageError(flag + " expects a number in " + range + ", got '" + text + "'");
  }
  return value;
}

std::vector<std::string> SplitList(const std::string& text)
{
  std::vector<std::string> parts;
  std::stringstream stream(text);
  std::string part;
  while (std::getline(stream, part, ','))
  {
    if (!part.empty())
    {
      parts.push_back(part);
    }
  }
  return parts;
}

Options ParseOptions(int argc, char* argv[])
{
  Options options;
  bool framesGiven = false, sizesGiven = false, camerasGiven = false;
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc)
      {
        throw UsageError(arg + " needs a value");
      }
      return argv[++i];
    };
    if (arg == "-h" || arg == "--help")
    {
      PrintHelp();
      std::exit(0);
    }
    else if (arg == "--data")
    {
      options.Data = value();
    }
    else if (arg == "--out")
    {
      options.Out = value();
    }
    else if (arg == "--dense-mesh")
    {
      options.DenseMesh = value();
    }
    else if (arg == "--frames")
    {
      options.Frames = ParseInteger(arg, value(), 1, 10000);
      framesGiven = true;
    }
    else if (arg == "--sizes")
    {
      options.Sizes.clear();
      for (const std::string& size : SplitList(value()))
      {
        const size_t x = size.find('x');
        if (x == std::string::npos)
        {
          throw UsageError("--sizes expects WxH[,WxH...], got '" + size + "'");
        }
        options.Sizes.emplace_back(ParseInteger("--sizes width", size.substr(0, x), 16, 8192),
          ParseInteger("--sizes height", size.substr(x + 1), 16, 8192));
      }
      sizesGiven = !options.Sizes.empty();
      if (!sizesGiven)
      {
        throw UsageError("--sizes expects WxH[,WxH...]");
      }
    }
    else if (arg == "--scenes")
    {
      options.Scenes = SplitList(value());
      options.ScenesGiven = true;
      for (const std::string& scene : options.Scenes)
      {
        const auto& names = nprBenchmarkSceneNames();
        if (std::find(names.begin(), names.end(), scene) == names.end())
        {
          throw UsageError("unknown scene '" + scene + "' (cad, rotor, bunny, isosurface, bunny1m)");
        }
      }
    }
    else if (arg == "--methods")
    {
      options.Methods = SplitList(value());
    }
    else if (arg == "--cameras")
    {
      options.Cameras = ParseInteger(arg, value(), 1, static_cast<int>(nprBenchmarkCameras().size()));
      camerasGiven = true;
    }
    else if (arg == "--line-width")
    {
      options.LineWidth = ParseNumber(arg, value(), 0.5, 16.0, "0.5..16");
    }
    else if (arg == "--quick")
    {
      options.Quick = true;
    }
    else if (arg == "--stress")
    {
      options.Stress = true;
    }
    else if (arg == "--stress-cases")
    {
      options.StressCases = SplitList(value());
    }
    else if (arg == "--max-drift")
    {
      options.MaxDrift = ParseNumber(arg, value(), 0.0, 1.0, "0..1");
    }
    else if (arg == "--save-masks")
    {
      options.SaveMasks = true;
    }
    else
    {
      throw UsageError("unknown argument '" + arg + "' (see --help)");
    }
  }
  if (options.Data.empty() || options.Out.empty())
  {
    throw UsageError("--data DIR and --out DIR are required (see --help)");
  }
  if (options.DenseMesh.empty())
  {
    options.DenseMesh = options.Data + "/bunny_1m.ply";
  }
  if (options.Quick)
  {
    if (!options.ScenesGiven)
    {
      options.Scenes = { "cad" };
      options.ScenesGiven = true;
    }
    options.Cameras = camerasGiven ? options.Cameras : 1;
    options.Frames = framesGiven ? options.Frames : 2;
    if (!sizesGiven)
    {
      options.Sizes = { { 320, 240 } };
    }
  }
  if (options.Stress)
  {
    if (!options.ScenesGiven)
    {
      options.Scenes = { "cad", "bunny" };
      options.ScenesGiven = true;
    }
    options.Cameras = camerasGiven ? options.Cameras : 1;
    if (!sizesGiven && !options.Quick)
    {
      options.Sizes = { { 1024, 768 } };
    }
  }
  if (!options.ScenesGiven)
  {
    options.Scenes = nprBenchmarkSceneNames();
  }
  return options;
}

std::vector<MethodSpec> SelectMethods(const Options& options)
{
  const std::vector<MethodSpec> all = AllMethods();
  std::vector<MethodSpec> chosen;
  if (options.Methods.empty())
  {
    chosen = all;
  }
  for (const std::string& name : options.Methods)
  {
    bool found = false;
    for (const MethodSpec& method : all)
    {
      const bool family = (name == "edges" && method.Kind == Family::Edges) ||
        (name == "inked" && method.Kind == Family::Inked) ||
        (name == "objectlines" && method.Kind == Family::ObjectLines);
      if (family || name == method.Name)
      {
        found = true;
        if (std::none_of(chosen.begin(), chosen.end(),
              [&](const MethodSpec& m) { return m.Name == method.Name; }))
        {
          chosen.push_back(method);
        }
      }
    }
    if (!found)
    {
      std::string valid;
      for (const MethodSpec& method : all)
      {
        valid += " " + method.Name;
      }
      throw UsageError("unknown method '" + name + "' (families: edges inked objectlines; methods:" +
        valid + ")");
    }
  }
  return chosen;
}

void MakeDirectory(const std::string& path)
{
  if (!vtksys::SystemTools::MakeDirectory(path))
  {
    throw std::runtime_error(path + ": cannot create the folder");
  }
}

// ---- Masks -------------------------------------------------------------------------------------
struct Mask
{
  int Width = 0;
  int Height = 0;
  std::vector<unsigned char> Pixels; // row 0 = bottom, non-zero = line
};

// The window's first colour channel, thresholded: a line pixel where it is >= 128 (coverage at
// least 50 %).
Mask ReadMask(vtkRenderWindow* window)
{
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();
  grab->ShouldRerenderOff();
  grab->Update();
  vtkImageData* image = grab->GetOutput();
  Mask mask;
  const int* dims = image->GetDimensions();
  mask.Width = dims[0];
  mask.Height = dims[1];
  mask.Pixels.resize(static_cast<size_t>(dims[0]) * dims[1]);
  const auto* rgb = static_cast<const unsigned char*>(image->GetScalarPointer());
  for (size_t i = 0; i < mask.Pixels.size(); ++i)
  {
    mask.Pixels[i] = rgb[3 * i] >= 128 ? 255 : 0;
  }
  return mask;
}

void WriteMaskPNG(const Mask& mask, const std::string& path)
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(mask.Width, mask.Height, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
  std::copy(mask.Pixels.begin(), mask.Pixels.end(),
    static_cast<unsigned char*>(image->GetScalarPointer()));
  vtkNew<vtkPNGWriter> writer;
  writer->SetFileName(path.c_str());
  writer->SetInputData(image);
  writer->Write();
}

// ---- The scene being measured: one window, one renderer, the mesh, the methods' passes ---------
struct Bench
{
  vtkSmartPointer<vtkRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkPolyDataMapper> MeshMapper;
  vtkNew<vtkActor> MeshActor;
  double LineWidth = 1.5;
  vtkNew<vtkNPRFeatureLines> FeatureLines;
  vtkNew<vtkPolyDataMapper> LineMapper;
  vtkNew<vtkActor> LineActor;
  // Kept for the whole run: it builds each mesh's adjacency and occlusion structure once.
  vtkNew<vtkNPRReferenceMask> Reference;
  int DefaultResolve = vtkMapper::GetResolveCoincidentTopology();

  explicit Bench(double lineWidth)
    : LineWidth(lineWidth)
  {
    this->Window =
      vtkSmartPointer<vtkRenderWindow>::Take(vtkNPRRenderWindowFactory::CreateRenderWindow());
    if (!this->Window)
    {
      throw std::runtime_error("no headless render window (see the message above)");
    }
    this->Window->AddRenderer(this->Renderer);
    this->MeshMapper->ScalarVisibilityOff();
    this->MeshActor->SetMapper(this->MeshMapper);
    this->Renderer->AddActor(this->MeshActor);
    this->LineMapper->SetInputConnection(this->FeatureLines->GetOutputPort());
    this->LineMapper->ScalarVisibilityOff();
    this->LineActor->SetMapper(this->LineMapper);
    this->LineActor->GetProperty()->SetLineWidth(static_cast<float>(lineWidth));
    this->LineActor->GetProperty()->LightingOff();
    this->LineActor->VisibilityOff();
    this->Renderer->AddActor(this->LineActor);
    this->ShadeMesh();
    this->Reference->SetRenderer(this->Renderer); // visible actors only: the mesh
  }

  void ShadeMesh()
  {
    vtkProperty* property = this->MeshActor->GetProperty();
    property->SetColor(0.85, 0.82, 0.75); // npr-render's first model colour
    property->SetSpecular(0.2);
    property->SetSpecularPower(30.0);
    property->LightingOn();
    this->LineActor->GetProperty()->SetColor(0.0, 0.0, 0.0);
    this->Renderer->SetBackground(1.0, 1.0, 1.0);
  }

  // The mesh drawn, and the one whose feature lines the object-space method draws (the same
  // surface; the raw one keeps the file's connectivity).
  void SetMesh(vtkPolyData* mesh, vtkPolyData* topology)
  {
    this->MeshMapper->SetInputData(mesh);
    this->FeatureLines->SetInputData(topology);
  }

  vtkCamera* Camera() { return this->Renderer->GetActiveCamera(); }

  // The pass a method renders with (nullptr: VTK's own chain).
  vtkSmartPointer<vtkNPRPass> MakePass(const MethodSpec& method)
  {
    if (method.Kind == Family::ObjectLines)
    {
      return nullptr;
    }
    auto pass = vtkSmartPointer<vtkNPRPass>::New();
    if (method.Kind == Family::Edges)
    {
      pass->SetStyleToEdges();
      vtkNPREdgePass* edges = pass->GetEdgePass();
      edges->SetLineWidth(this->LineWidth);
      edges->SetEncoding(method.Encoding);
      edges->SetSilhouetteThreshold(method.SilhouetteThreshold);
      edges->SetCreaseAngle(method.CreaseAngle);
      edges->SetPackedThreshold(method.PackedThreshold);
    }
    else
    {
      pass->SetStyleToInked();
      pass->GetInkPass()->SetLineWidth(this->LineWidth);
    }
    return pass;
  }

  // Makes the renderer draw this method's frame (pass nullptr and no lines: the shaded frame).
  void Activate(vtkNPRPass* pass, bool objectLines)
  {
    this->Renderer->SetPass(pass);
    this->LineActor->SetVisibility(objectLines);
    // Object-space lines lie on the mesh: VTK's coincident-topology resolution (polygon
    // offset) lets them win the depth test. The other methods draw as users get them, without.
    vtkMapper::SetResolveCoincidentTopology(
      objectLines ? VTK_RESOLVE_POLYGON_OFFSET : this->DefaultResolve);
  }

  // The object-space lines for the current camera (its values are copied: once per frame).
  void UpdateFeatureLines()
  {
    this->FeatureLines->SetCamera(this->Camera());
    this->FeatureLines->Modified(); // the extraction is part of every frame of the method
  }

  // One timed frame: nothing may be reused, and the GPU has finished when it returns.
  double TimedFrame(bool objectLines)
  {
    const Clock::time_point start = Clock::now();
    this->Camera()->Modified();
    if (objectLines)
    {
      this->UpdateFeatureLines();
    }
    this->Window->Render();
    this->Window->WaitForCompletion();
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
  }

  // The method's line mask (white lines on black, thresholded at 50 %).
  Mask MethodMask(const MethodSpec& method, vtkNPRPass* pass)
  {
    Mask mask;
    if (method.Kind == Family::Edges)
    {
      this->Activate(pass, false);
      pass->GetEdgePass()->CoverageOnlyOn();
      this->Window->Render();
      mask = ReadMask(this->Window);
      pass->GetEdgePass()->CoverageOnlyOff();
    }
    else if (method.Kind == Family::Inked)
    {
      this->Activate(pass, false);
      pass->GetInkPass()->CoverageOnlyOn();
      this->Window->Render();
      mask = ReadMask(this->Window);
      pass->GetInkPass()->CoverageOnlyOff();
    }
    else
    {
      // The lines white over the mesh black on black: what the lines leave visible.
      this->Activate(nullptr, true);
      this->UpdateFeatureLines();
      vtkProperty* property = this->MeshActor->GetProperty();
      property->SetColor(0.0, 0.0, 0.0);
      property->LightingOff();
      this->LineActor->GetProperty()->SetColor(1.0, 1.0, 1.0);
      this->Renderer->SetBackground(0.0, 0.0, 0.0);
      this->Window->Render();
      mask = ReadMask(this->Window);
      this->ShadeMesh();
    }
    this->Activate(nullptr, false);
    return mask;
  }

  // The object-space ground truth for the current camera and size (vtkNPRReferenceMask:
  // visible silhouettes, creases above 30 degrees, boundaries and non-manifold edges).
  Mask ReferenceMask()
  {
    this->Activate(nullptr, false);
    if (!this->Reference->Update())
    {
      throw std::runtime_error("vtkNPRReferenceMask failed (see the message above)");
    }
    vtkImageData* image = this->Reference->GetMask();
    Mask mask;
    const int* dims = image->GetDimensions();
    mask.Width = dims[0];
    mask.Height = dims[1];
    const auto* pixels = static_cast<const unsigned char*>(image->GetScalarPointer());
    mask.Pixels.assign(pixels, pixels + static_cast<size_t>(dims[0]) * dims[1]);
    return mask;
  }
};

// ---- The benchmark -----------------------------------------------------------------------------
std::string SceneLines(const std::vector<nprBenchmarkScene>& scenes)
{
  std::ostringstream text;
  for (const nprBenchmarkScene& scene : scenes)
  {
    text << "- " << scene.Name << ": " << scene.Description << ", " << scene.Triangles
         << " triangles\n";
  }
  return text.str();
}

std::string CameraLine(int count)
{
  std::string text;
  for (int i = 0; i < count; ++i)
  {
    const nprBenchmarkCamera& camera = nprBenchmarkCameras()[i];
    std::ostringstream one;
    one << camera.Name << " (azimuth " << camera.Azimuth << ", elevation " << camera.Elevation
        << ")";
    text += (i ? ", " : "") + one.str();
  }
  return text;
}

std::string SizesLine(const Options& options)
{
  std::string text;
  for (const auto& size : options.Sizes)
  {
    text += (text.empty() ? "" : ", ") + std::to_string(size.first) + "x" +
      std::to_string(size.second);
  }
  return text;
}

std::vector<nprBenchmarkScene> LoadScenes(const Options& options)
{
  std::vector<nprBenchmarkScene> scenes;
  for (const std::string& name : options.Scenes)
  {
    const Clock::time_point start = Clock::now();
    try
    {
      scenes.push_back(nprLoadBenchmarkScene(name, options.Data, options.DenseMesh));
    }
    catch (const std::runtime_error& error)
    {
      // The dense mesh is made by the build (target `benchmark`); without it, a default run
      // goes on with the other scenes.
      if (name == "bunny1m" && !options.ScenesGiven)
      {
        std::cerr << "npr-benchmark: warning: scene bunny1m left out: " << error.what() << "\n";
        continue;
      }
      throw;
    }
    std::cerr << "npr-benchmark: scene " << name << ": " << scenes.back().Triangles
              << " triangles, prepared in " << nprFormat(Seconds(start), 3) << " s\n";
  }
  return scenes;
}

int RunBenchmark(const Options& options)
{
  const Clock::time_point runStart = Clock::now();
  const std::vector<MethodSpec> methods = SelectMethods(options);
  if (methods.empty())
  {
    throw std::runtime_error("no method to run");
  }
  MakeDirectory(options.Out);
  if (options.SaveMasks)
  {
    MakeDirectory(options.Out + "/masks");
  }
  const std::vector<nprBenchmarkScene> scenes = LoadScenes(options);

  Bench bench(options.LineWidth);
  std::vector<vtkSmartPointer<vtkNPRPass>> passes;
  for (const MethodSpec& method : methods)
  {
    passes.push_back(bench.MakePass(method));
  }

  std::vector<nprBenchmarkRow> rows;
  const size_t views = scenes.size() * options.Cameras * options.Sizes.size();
  size_t view = 0;
  for (const nprBenchmarkScene& scene : scenes)
  {
    bench.SetMesh(scene.Mesh, scene.Raw);
    for (const auto& size : options.Sizes)
    {
      bench.Window->SetSize(size.first, size.second);
      for (int c = 0; c < options.Cameras; ++c)
      {
        const Clock::time_point viewStart = Clock::now();
        const nprBenchmarkCamera& camera = nprBenchmarkCameras()[c];
        bench.Activate(nullptr, false);
        nprApplyBenchmarkCamera(bench.Renderer, camera);
        bench.Window->Render(); // the camera as drawn, before the reference reads it
        ++view;
        std::cerr << "npr-benchmark: [" << view << "/" << views << "] " << scene.Name << " "
                  << camera.Name << " " << size.first << "x" << size.second << ": reference";
        const Clock::time_point referenceStart = Clock::now();
        const Mask reference = bench.ReferenceMask();
        std::cerr << " " << nprFormat(Seconds(referenceStart), 3) << " s";
        const std::string prefix = options.Out + "/masks/" + scene.Name + "_" + camera.Name + "_" +
          std::to_string(size.first) + "x" + std::to_string(size.second) + "_";
        if (options.SaveMasks)
        {
          WriteMaskPNG(reference, prefix + "reference.png");
        }

        // Frame -1 warms every variant up (shaders, buffers of this size). Then the variants
        // alternate frame by frame: all see the same machine state.
        std::vector<double> shaded;
        std::vector<std::vector<double>> times(methods.size());
        for (int frame = -1; frame < options.Frames; ++frame)
        {
          bench.Activate(nullptr, false);
          const double ms = bench.TimedFrame(false);
          if (frame >= 0)
          {
            shaded.push_back(ms);
          }
          for (size_t m = 0; m < methods.size(); ++m)
          {
            const bool lines = methods[m].Kind == Family::ObjectLines;
            bench.Activate(passes[m], lines);
            const double t = bench.TimedFrame(lines);
            if (frame >= 0)
            {
              times[m].push_back(t);
            }
          }
        }
        const double shadedMedian = Median(shaded);
        std::cerr << ", shaded " << nprFormat(shadedMedian, 3) << " ms";

        for (size_t m = 0; m < methods.size(); ++m)
        {
          const Mask mask = bench.MethodMask(methods[m], passes[m]);
          if (options.SaveMasks)
          {
            WriteMaskPNG(mask, prefix + methods[m].Name + ".png");
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
          row.MedianMs = Median(times[m]);
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
        bench.Activate(nullptr, false);
        std::cerr << "; done in " << nprFormat(Seconds(viewStart), 3) << " s\n";
      }
    }
  }

  nprBenchmarkInfo info;
  info.Renderer = vtkNPRRenderWindowFactory::GetGLRenderer(bench.Window);
  info.Backend = vtkNPRRenderWindowFactory::GetBackendName(bench.Window);
  info.Frames = options.Frames;
  info.Sizes = SizesLine(options);
  info.Scenes = SceneLines(scenes);
  info.Cameras = CameraLine(options.Cameras);
  for (const MethodSpec& method : methods)
  {
    info.Methods += "- " + method.Name + ": " + method.Settings + "\n";
  }
  info.Methods += "\nEvery method draws lines " + nprFormat(options.LineWidth) +
    " px wide. Reference: vtkNPRReferenceMask (visible silhouettes, creases above 30 degrees, "
    "boundary and non-manifold edges, one pixel wide).\n";
  info.Seconds = Seconds(runStart);

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
            << nprFormat(Seconds(runStart), 4) << " s\n";

  const std::string problems = nprCheckBenchmarkRows(rows);
  if (!problems.empty())
  {
    std::cerr << "npr-benchmark: error: figures out of range:\n" << problems;
    return 1;
  }
  return 0;
}

// ---- Stress mode -------------------------------------------------------------------------------
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
    cases.push_back({ std::string("near/far ") + ratio + " (far)", StressCase::FarPlane,
      std::atof(ratio) });
    cases.push_back({ std::string("near/far ") + ratio + " (near)", StressCase::NearPlane,
      std::atof(ratio) });
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

GBufferFigures ReadGBuffer(vtkRenderWindow* window, vtkNPRGBufferPass* gbuffer, double nearPlane,
  double farPlane)
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

int RunStress(const Options& options)
{
  const Clock::time_point runStart = Clock::now();
  MakeDirectory(options.Out);
  if (options.SaveMasks)
  {
    MakeDirectory(options.Out + "/masks");
  }
  const std::vector<nprBenchmarkScene> scenes = LoadScenes(options);
  Bench bench(options.LineWidth);
  MethodSpec method; // edges-float at the pass's defaults
  method.Name = "edges-float";
  vtkSmartPointer<vtkNPRPass> pass = bench.MakePass(method);

  std::vector<nprStressRow> rows;
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
  int failures = 0;
  for (const nprBenchmarkScene& scene : scenes)
  {
    const double modelSize = nprModelSize(scene.Raw);
    for (const auto& size : options.Sizes)
    {
      bench.Window->SetSize(size.first, size.second);
      for (int c = 0; c < options.Cameras; ++c)
      {
        const nprBenchmarkCamera& camera = nprBenchmarkCameras()[c];
        Mask unitReference;
        GBufferFigures unitBuffer;
        double unitF1 = 0.0;
        for (const StressCase& stress : cases)
        {
          const Clock::time_point caseStart = Clock::now();
          nprStressRow row;
          row.Scene = scene.Name;
          row.Case = stress.Name;
          if (options.Cameras > 1 || options.Sizes.size() > 1)
          {
            row.Case += " [" + std::string(camera.Name) + " " + std::to_string(size.first) + "x" +
              std::to_string(size.second) + "]";
          }
          std::ostringstream detail;
          vtkSmartPointer<vtkPolyData> raw = scene.Raw;
          vtkSmartPointer<vtkPolyData> mesh;
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
              raw = nprSoupMesh(scene.Raw);
              detail << "every triangle its own 3 points (" << raw->GetNumberOfPoints()
                     << " points)";
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
          bench.SetMesh(mesh, raw);
          bench.Activate(nullptr, false);
          nprApplyBenchmarkCamera(bench.Renderer, camera);
          double range[2];
          bench.Camera()->GetClippingRange(range);
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
            detail << "clipping range [" << nprFormat(range[0], 3) << ", "
                   << nprFormat(range[1], 3) << "]";
          }
          row.Detail = detail.str();
          bench.Camera()->SetClippingRange(range);
          row.Near = range[0];
          row.Far = range[1];
          bench.Window->Render(); // the camera as drawn, before the reference reads it

          const Clock::time_point referenceStart = Clock::now();
          const Mask reference = bench.ReferenceMask();
          const double referenceSeconds = Seconds(referenceStart);
          bench.Camera()->SetClippingRange(range); // as the user set it, whatever the reference did
          bench.Activate(pass, false);
          bench.TimedFrame(false);
          const GBufferFigures buffer =
            ReadGBuffer(bench.Window, pass->GetGBufferPass(), range[0], range[1]);
          const Mask mask = bench.MethodMask(method, pass);
          bench.Activate(nullptr, false);
          if (stress.Kind == StressCase::Unit)
          {
            unitReference = reference;
            unitBuffer = buffer;
          }
          if (options.SaveMasks)
          {
            std::string name = scene.Name + "_" + stress.Name;
            std::replace_if(name.begin(), name.end(),
              [](char ch) { return !std::isalnum(static_cast<unsigned char>(ch)) && ch != '-'; }, '_');
            WriteMaskPNG(mask, options.Out + "/masks/" + name + ".png");
            WriteMaskPNG(reference, options.Out + "/masks/" + name + "_reference.png");
          }

          nprEdgeMetrics own, unit, agreement;
          own.Compute(mask.Pixels.data(), reference.Pixels.data(), mask.Width, mask.Height);
          unit.Compute(mask.Pixels.data(), unitReference.Pixels.data(), mask.Width, mask.Height);
          agreement.Compute(
            reference.Pixels.data(), unitReference.Pixels.data(), mask.Width, mask.Height);
          row.F1Own = own.F1(1.0);
          row.F1Unit = unit.F1(1.0);
          if (stress.Kind == StressCase::Unit)
          {
            unitF1 = row.F1Unit;
          }
          row.Drift = row.F1Unit - unitF1;
          row.ReferenceF1 = agreement.F1(1.0);
          row.MeanDistanceUnit = unit.MeanSymmetricDistance();
          row.MethodPixels = own.GetMethodPixels();
          row.ReferencePixels = own.GetReferencePixels();
          row.StrayPixels = unit.CountFarMethodPixels(3.0);
          row.CoveredPixels = buffer.Covered;
          for (size_t i = 0; i < buffer.Coverage.size() && i < unitBuffer.Coverage.size(); ++i)
          {
            row.CoverageChanged += buffer.Coverage[i] != unitBuffer.Coverage[i] ? 1 : 0;
          }
          row.NonFinitePixels = buffer.NonFinite;
          row.BadDepthPixels = buffer.BadDepth;
          rows.push_back(row);
          if (options.MaxDrift >= 0.0 &&
            (std::abs(row.Drift) > options.MaxDrift || row.NonFinitePixels > 0 ||
              row.BadDepthPixels > 0))
          {
            std::cerr << "npr-benchmark: FAILED: " << scene.Name << " " << row.Case << ": F1@1 drift "
                      << nprFormat(row.Drift, 4) << " (allowed " << options.MaxDrift << "), "
                      << row.NonFinitePixels << " non-finite, " << row.BadDepthPixels
                      << " bad-depth pixels\n";
            ++failures;
          }
          std::cerr << "npr-benchmark: stress " << scene.Name << " " << row.Case << ": F1@1 "
                    << nprFormat(row.F1Own, 3) << " (unit reference " << nprFormat(row.F1Unit, 3)
                    << "), stray " << row.StrayPixels << ", non-finite " << row.NonFinitePixels
                    << ", bad depth " << row.BadDepthPixels << " ("
                    << nprFormat(Seconds(caseStart), 2) << " s; reference "
                    << nprFormat(referenceSeconds, 2) << " s: lines "
                    << nprFormat(bench.Reference->GetLinesTime(), 2) << ", locator "
                    << nprFormat(bench.Reference->GetLocatorTime(), 2) << ", rays "
                    << nprFormat(bench.Reference->GetVisibilityTime(), 2) << ")\n";
        }
      }
    }
  }

  nprBenchmarkInfo info;
  info.Renderer = vtkNPRRenderWindowFactory::GetGLRenderer(bench.Window);
  info.Backend = vtkNPRRenderWindowFactory::GetBackendName(bench.Window);
  info.Sizes = SizesLine(options);
  info.Cameras = CameraLine(options.Cameras);
  info.Seconds = Seconds(runStart);
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

int main(int argc, char* argv[])
{
  vtkNew<nprBenchmarkOutputWindow> messages;
  const char* verbose = std::getenv("NPR_VERBOSE");
  messages->Verbose = verbose && *verbose && std::strcmp(verbose, "0") != 0;
  vtkOutputWindow::SetInstance(messages);
  if (!messages->Verbose)
  {
    vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  }
  int status = 0;
  try
  {
    const Options options = ParseOptions(argc, argv);
    status = options.Stress ? RunStress(options) : RunBenchmark(options);
  }
  catch (const UsageError& error)
  {
    std::cerr << "npr-benchmark: error: " << error.what() << "\n";
    status = 2;
  }
  catch (const std::exception& error)
  {
    std::cerr << "npr-benchmark: error: " << error.what() << "\n";
    status = 1;
  }
  vtkOutputWindow::SetInstance(nullptr);
  return status;
}
