// npr-render: renders model files headless into a PNG, with the vtkNPR styles.
// Run `npr-render --help` for the flags; Documentation/cli.md describes them.
#include "nprCameraJson.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkLogger.h"
#include "vtkImageData.h"
#include "vtkImageExtractComponents.h"
#include "vtkNPREdgePass.h"
#include "vtkNPRGBufferPass.h"
#include "vtkNPRInkPass.h"
#include "vtkNPRModelReader.h"
#include "vtkNPRPass.h"
#include "vtkNPRReferenceMask.h"
#include "vtkNPRShadingNormals.h"
#include "vtkNPRSketchPass.h"
#include "vtkNPRToonPass.h"
#include "vtkNPRRenderWindowFactory.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOutputWindow.h"
#include "vtkPNGWriter.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"
#include "vtkWindowToImageFilter.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace
{
const char* const Styles[] = { "shaded", "edges", "toon", "toon+edges", "sketch", "inked" };

struct UsageError : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

// Keeps VTK's multi-line messages off the terminal: npr-render reports one line per problem.
// NPR_VERBOSE=1 prints them as well.
class nprQuietOutputWindow : public vtkOutputWindow
{
public:
  static nprQuietOutputWindow* New();
  vtkTypeMacro(nprQuietOutputWindow, vtkOutputWindow);
  void DisplayErrorText(const char* text) override { this->DisplayText(text); }
  void DisplayWarningText(const char* text) override { this->DisplayText(text); }
  void DisplayGenericWarningText(const char* text) override { this->DisplayText(text); }
  void DisplayText(const char* text) override
  {
    if (text && *text)
    {
      this->Last = Summarise(text);
      if (this->Verbose)
      {
        std::cerr << text;
      }
    }
  }
  // "ERROR: In file, line N\nvtkClass (0x..): message" -> "message"
  static std::string Summarise(std::string text)
  {
    while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back())))
    {
      text.pop_back();
    }
    text.erase(0, text.find_last_of('\n') + 1);
    const size_t colon = text.find("): ");
    if (text.compare(0, 3, "vtk") == 0 && colon != std::string::npos)
    {
      text.erase(0, colon + 3);
    }
    return text;
  }
  std::string Last;
  bool Verbose = false;
};
vtkStandardNewMacro(nprQuietOutputWindow);

struct Options
{
  std::vector<std::string> Models;
  std::string Output;
  int Width = 1024;
  int Height = 768;
  bool SizeGiven = false;
  std::string Style = "shaded";
  double Azimuth = 0.0;
  double Elevation = 0.0;
  double Zoom = 1.0;
  bool CameraMoved = false; // --azimuth, --elevation or --zoom given
  double Background[3] = { 1.0, 1.0, 1.0 };
  std::string CameraIn;
  std::string CameraOut;
  int Frames = 0;
  std::string Backend;

  // --style edges
  bool Silhouettes = true;
  bool Creases = true;
  bool Contours = true;
  double SilhouetteThreshold = 0.005;
  double CreaseAngle = 30.0;
  int ContourSide = vtkNPREdgePass::INSIDE;
  double LineWidth = 1.5;
  double SilhouetteColor[3] = { 0.0, 0.0, 0.0 };
  double CreaseColor[3] = { 0.0, 0.0, 0.0 };
  double ContourColor[3] = { 0.0, 0.0, 0.0 };
  bool AntiAliasing = true;
  std::string Encoding = "float";
  double PackedThreshold = 0.1;
  bool PackedBlur = false;
  std::string EdgeMask;
  std::string ReferenceMask;
  std::vector<std::string> CompareStyles;

  // --style toon, toon+edges (and sketch with --sketch-toon)
  int ToonBands = 3;
  bool ToonPerVertex = false;

  // --style sketch
  double Uncertainty = 3.0;
  int NoiseSeed = 1;
  double NoiseFrequency = 2.0;
  bool Paper = false;
  double PaperColor[3] = { 1.0, 0.98, 0.92 };
  bool SketchToon = false;
};

void PrintHelp()
{
  std::cout <<
    R"(usage: npr-render [options] MODEL [MODEL...]

Renders one scene of the given models headless and writes a PNG.
Models: .stl .obj .ply .vtp .vtk .gltf .glb .off

  -o, --output FILE        PNG to write
  --size WxH               image size in pixels (default 1024x768)
  --style NAME             shaded (default), edges, toon, toon+edges, sketch or inked
  --compare-style LIST     with --frames: also time these styles (comma separated), frames
                           interleaved with the main style's in the same window; print
                           each median and its ratio to the main style's
  --backend NAME           egl, osmesa or x (default: NPR_BACKEND, else egl;
                           osmesa in npr-render-osmesa)
  --azimuth DEG            rotate the camera about the view up after the reset
  --elevation DEG          rotate the camera up or down after the reset
  --zoom FACTOR            zoom (> 1 closer) after the reset
  --background COLOR       r,g,b in 0..1 or #rrggbb (default white)
  --camera-in FILE         use this camera (JSON; its clipping range as given)
  --camera-out FILE        write the camera used (JSON)
  --frames N               time N frames after a warm-up; print one JSON line
  -h, --help               this text

Lines (--style edges, toon+edges and sketch):
  --lines LIST             line types drawn, comma separated: silhouettes, creases,
                           contours, or none (default silhouettes,creases,contours)
  --silhouette-threshold X relative depth step that makes a silhouette (default 0.005)
  --crease-angle DEG       normal angle that makes a crease, 1..179 (default 30)
  --contour-side SIDE      inside, outside or both (default inside)
  --line-width PX          line width in pixels, 0.5..16 (default 1.5)
  --line-color COLOR       colour of every line type (default black)
  --silhouette-color COLOR, --crease-color COLOR, --contour-color COLOR
  --no-antialias           lines without anti-aliasing
  --edge-mask FILE         also write the line coverage alone: white on black, 8-bit
                           grey PNG of the render's size (edges, toon+edges, inked)
  --reference-mask FILE    also write the ground truth of --lines and --crease-angle:
                           the visible object-space lines, white on black, 8-bit grey
                           PNG of the render's size (any style)
  --encoding NAME          how the G-buffer stores depth and normals: float (default),
                           half, packed8 or packed16 (the 1990s packed depth+normal
                           value, lines from its Laplacian)
  --packed-threshold X     packed encodings: Laplacian that makes a line, in units of one
                           component's range, 0.001..4 (default 0.1)
  --packed-blur            packed encodings: blur before the Laplacian (fatter lines)

Inking (--style inked):
  --line-width PX          ink line width in pixels, 0.5..16 (default 1.5)
  --line-color COLOR       ink colour (default black)

Toon shading (--style toon, toon+edges):
  --toon-bands N           number of equal light bands, 1..64 (default 3)
  --toon-per-vertex        light at the vertices, interpolated, then banded (default:
                           per pixel)

Sketch (--style sketch):
  --uncertainty PX         largest displacement of lines and fills in pixels, 0..32
                           (default 3; 0 draws the exact lines on flat colours)
  --noise-seed N           seed of the noise, 0..2147483647 (default 1)
  --noise-frequency F      noise cells per 100 pixels, 0.05..25 (default 2)
  --paper-color COLOR      draw on paper of this colour instead of the background
  --sketch-toon            fill with the toon bands (--toon-bands) instead of flat colours
)";
}

double ParseNumber(const std::string& flag, const std::string& text)
{
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || *end || !std::isfinite(value))
  {
    throw UsageError(flag + " expects a number, got '" + text + "'");
  }
  return value;
}

double ParseRange(const std::string& flag, const std::string& text, double low, double high)
{
  const double value = ParseNumber(flag, text);
  if (value < low || value > high)
  {
    std::ostringstream range;
    range << low << ".." << high;
    throw UsageError(flag + " expects a number in " + range.str() + ", got '" + text + "'");
  }
  return value;
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

void ParseColor(const std::string& flag, const std::string& text, double rgb[3])
{
  if (text.size() == 7 && text[0] == '#' &&
    text.find_first_not_of("0123456789abcdefABCDEF", 1) == std::string::npos)
  {
    for (int i = 0; i < 3; ++i)
    {
      rgb[i] = std::strtol(text.substr(1 + 2 * i, 2).c_str(), nullptr, 16) / 255.0;
    }
    return;
  }
  std::stringstream parts(text);
  std::string part;
  int count = 0;
  while (std::getline(parts, part, ','))
  {
    const double value = count < 3 ? ParseNumber(flag, part) : -1.0;
    if (count >= 3 || value < 0.0 || value > 1.0)
    {
      throw UsageError(flag + " expects r,g,b in 0..1 or #rrggbb, got '" + text + "'");
    }
    rgb[count++] = value;
  }
  if (count != 3)
  {
    throw UsageError(flag + " expects r,g,b in 0..1 or #rrggbb, got '" + text + "'");
  }
}

Options ParseOptions(int argc, char* argv[])
{
  Options options;
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
    else if (arg == "-o" || arg == "--output")
    {
      options.Output = value();
    }
    else if (arg == "--size")
    {
      const std::string text = value();
      const size_t x = text.find('x');
      if (x == std::string::npos)
      {
        throw UsageError("--size expects WxH (e.g. 1024x768), got '" + text + "'");
      }
      options.Width = ParseInteger("--size width", text.substr(0, x), 1, 16384);
      options.Height = ParseInteger("--size height", text.substr(x + 1), 1, 16384);
      options.SizeGiven = true;
    }
    else if (arg == "--style")
    {
      options.Style = value();
      if (std::find(std::begin(Styles), std::end(Styles), options.Style) == std::end(Styles))
      {
        std::string valid;
        for (const char* style : Styles)
        {
          valid += (valid.empty() ? "" : ", ") + std::string(style);
        }
        throw UsageError("unknown style '" + options.Style + "' (valid styles: " + valid + ")");
      }
    }
    else if (arg == "--azimuth")
    {
      options.Azimuth = ParseNumber(arg, value());
      options.CameraMoved = true;
    }
    else if (arg == "--elevation")
    {
      options.Elevation = ParseNumber(arg, value());
      options.CameraMoved = true;
    }
    else if (arg == "--zoom")
    {
      options.Zoom = ParseNumber(arg, value());
      options.CameraMoved = true;
      if (options.Zoom <= 0.0)
      {
        throw UsageError("--zoom expects a positive factor");
      }
    }
    else if (arg == "--background")
    {
      ParseColor(arg, value(), options.Background);
    }
    else if (arg == "--camera-in")
    {
      options.CameraIn = value();
    }
    else if (arg == "--camera-out")
    {
      options.CameraOut = value();
    }
    else if (arg == "--frames")
    {
      options.Frames = ParseInteger(arg, value(), 1, 100000);
    }
    else if (arg == "--backend")
    {
      options.Backend = value();
      if (!vtkNPRRenderWindowFactory::IsKnownBackend(options.Backend.c_str()))
      {
        throw UsageError("unknown backend '" + options.Backend + "' (valid backends: " +
          vtkNPRRenderWindowFactory::GetKnownBackends() + ")");
      }
    }
    else if (arg == "--lines")
    {
      const std::string text = value();
      options.Silhouettes = options.Creases = options.Contours = false;
      std::stringstream parts(text);
      std::string part;
      while (std::getline(parts, part, ','))
      {
        if (part == "silhouettes" || part == "silhouette")
        {
          options.Silhouettes = true;
        }
        else if (part == "creases" || part == "crease")
        {
          options.Creases = true;
        }
        else if (part == "contours" || part == "contour")
        {
          options.Contours = true;
        }
        else if (part != "none")
        {
          throw UsageError("--lines expects silhouettes, creases, contours or none, got '" +
            part + "'");
        }
      }
    }
    else if (arg == "--silhouette-threshold")
    {
      options.SilhouetteThreshold = ParseRange(arg, value(), 1e-5, 1.0);
    }
    else if (arg == "--crease-angle")
    {
      options.CreaseAngle = ParseRange(arg, value(), 1.0, 179.0);
    }
    else if (arg == "--contour-side")
    {
      const std::string side = value();
      const char* const sides[] = { "inside", "outside", "both" };
      const auto found = std::find(std::begin(sides), std::end(sides), side);
      if (found == std::end(sides))
      {
        throw UsageError("--contour-side expects inside, outside or both, got '" + side + "'");
      }
      options.ContourSide = static_cast<int>(found - std::begin(sides));
    }
    else if (arg == "--line-width")
    {
      options.LineWidth = ParseRange(arg, value(), 0.5, 16.0);
    }
    else if (arg == "--line-color")
    {
      ParseColor(arg, value(), options.SilhouetteColor);
      std::copy_n(options.SilhouetteColor, 3, options.CreaseColor);
      std::copy_n(options.SilhouetteColor, 3, options.ContourColor);
    }
    else if (arg == "--silhouette-color")
    {
      ParseColor(arg, value(), options.SilhouetteColor);
    }
    else if (arg == "--crease-color")
    {
      ParseColor(arg, value(), options.CreaseColor);
    }
    else if (arg == "--contour-color")
    {
      ParseColor(arg, value(), options.ContourColor);
    }
    else if (arg == "--no-antialias")
    {
      options.AntiAliasing = false;
    }
    else if (arg == "--compare-style")
    {
      std::stringstream parts(value());
      std::string part;
      while (std::getline(parts, part, ','))
      {
        if (std::find(std::begin(Styles), std::end(Styles), part) == std::end(Styles))
        {
          throw UsageError("unknown style '" + part + "' for --compare-style");
        }
        options.CompareStyles.push_back(part);
      }
    }
    else if (arg == "--edge-mask")
    {
      options.EdgeMask = value();
    }
    else if (arg == "--encoding")
    {
      options.Encoding = value();
      if (vtkNPREdgePass::GetEncodingFromName(options.Encoding.c_str()) < 0)
      {
        throw UsageError(
          "--encoding expects float, half, packed8 or packed16, got '" + options.Encoding + "'");
      }
    }
    else if (arg == "--packed-threshold")
    {
      options.PackedThreshold = ParseRange(arg, value(), 0.001, 4.0);
    }
    else if (arg == "--packed-blur")
    {
      options.PackedBlur = true;
    }
    else if (arg == "--reference-mask")
    {
      options.ReferenceMask = value();
    }
    else if (arg == "--toon-bands")
    {
      options.ToonBands = ParseInteger(arg, value(), 1, 64);
    }
    else if (arg == "--toon-per-vertex")
    {
      options.ToonPerVertex = true;
    }
    else if (arg == "--uncertainty")
    {
      options.Uncertainty = ParseRange(arg, value(), 0.0, 32.0);
    }
    else if (arg == "--noise-seed")
    {
      options.NoiseSeed = ParseInteger(arg, value(), 0, 2147483647);
    }
    else if (arg == "--noise-frequency")
    {
      options.NoiseFrequency = ParseRange(arg, value(), 0.05, 25.0);
    }
    else if (arg == "--paper-color")
    {
      ParseColor(arg, value(), options.PaperColor);
      options.Paper = true;
    }
    else if (arg == "--sketch-toon")
    {
      options.SketchToon = true;
    }
    else if (arg.size() > 1 && arg[0] == '-')
    {
      throw UsageError("unknown option '" + arg + "' (see --help)");
    }
    else
    {
      options.Models.push_back(arg);
    }
  }
  if (options.Models.empty())
  {
    throw UsageError("no model file given (see --help)");
  }
  if (!options.CameraIn.empty() && options.CameraMoved)
  {
    throw UsageError("--azimuth, --elevation and --zoom move the reset camera; they cannot be "
                     "combined with --camera-in");
  }
  if (options.Output.empty() && options.Frames == 0 && options.CameraOut.empty() &&
    options.EdgeMask.empty() && options.ReferenceMask.empty())
  {
    throw UsageError("nothing to do: give -o FILE, --frames N, --edge-mask FILE, "
                     "--reference-mask FILE or --camera-out FILE");
  }
  if (!options.CompareStyles.empty() && options.Frames == 0)
  {
    throw UsageError("--compare-style needs --frames N");
  }
  if (!options.EdgeMask.empty() && options.Style != "edges" && options.Style != "toon+edges" &&
    options.Style != "inked")
  {
    throw UsageError("--edge-mask needs --style edges, toon+edges or inked");
  }
  return options;
}

// Pleasant, distinguishable surface colours for the models of a scene.
const double Palette[][3] = { { 0.85, 0.82, 0.75 }, { 0.55, 0.70, 0.85 }, { 0.90, 0.60, 0.45 },
  { 0.60, 0.80, 0.55 }, { 0.80, 0.65, 0.85 } };

vtkIdType CountTriangles(vtkPolyData* data)
{
  vtkIdType triangles = 0;
  for (vtkCellArray* cells : { data->GetPolys(), data->GetStrips() })
  {
    const vtkIdType connectivity = cells->GetNumberOfConnectivityIds();
    triangles += connectivity - 2 * cells->GetNumberOfCells();
  }
  return triangles;
}

std::string JsonString(const std::string& text)
{
  std::string quoted = "\"";
  for (char c : text)
  {
    if (c == '"' || c == '\\')
    {
      quoted += '\\';
    }
    quoted += (static_cast<unsigned char>(c) < 0x20) ? ' ' : c;
  }
  return quoted + "\"";
}

// Writes the window's colour buffer as a PNG: RGB, or its first channel as 8-bit grey.
void WriteWindowPNG(vtkRenderWindow* window, const std::string& path, bool grey)
{
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ReadFrontBufferOff();
  grab->Update();
  vtkNew<vtkImageExtractComponents> first;
  first->SetInputConnection(grab->GetOutputPort());
  first->SetComponents(0);
  vtkNew<vtkPNGWriter> writer;
  writer->SetFileName(path.c_str());
  writer->SetInputConnection(grey ? first->GetOutputPort() : grab->GetOutputPort());
  writer->Write();
  if (writer->GetErrorCode() != 0)
  {
    throw std::runtime_error(path + ": cannot write the PNG");
  }
}

// The visible object-space lines of what --lines asks for, as a white-on-black 8-bit grey PNG:
// silhouettes and creases as named; contours (object outlines) are silhouettes and boundaries;
// non-manifold edges, where surfaces meet at an angle, go with creases.
void WriteReferenceMask(vtkRenderer* renderer, const Options& options, int width, int height)
{
  vtkNew<vtkNPRReferenceMask> reference;
  reference->SetRenderer(renderer);
  reference->SetSize(width, height);
  reference->SetSilhouettes(options.Silhouettes || options.Contours);
  reference->SetBoundaries(options.Contours);
  reference->SetCreases(options.Creases);
  reference->SetNonManifoldEdges(options.Creases);
  reference->SetCreaseAngle(options.CreaseAngle);
  if (!reference->Update())
  {
    throw std::runtime_error("cannot compute the reference mask");
  }
  vtkNew<vtkPNGWriter> writer;
  writer->SetFileName(options.ReferenceMask.c_str());
  writer->SetInputData(reference->GetMask());
  writer->Write();
  if (writer->GetErrorCode() != 0)
  {
    throw std::runtime_error(options.ReferenceMask + ": cannot write the PNG");
  }
}

vtkSmartPointer<vtkNPRPass> MakePass(const Options& options)
{
  auto pass = vtkSmartPointer<vtkNPRPass>::New();
  pass->SetStyle(vtkNPRPass::GetStyleFromName(options.Style.c_str()));
  vtkNPREdgePass* edges = pass->GetEdgePass();
  edges->SetSilhouettes(options.Silhouettes);
  edges->SetCreases(options.Creases);
  edges->SetContours(options.Contours);
  edges->SetSilhouetteThreshold(options.SilhouetteThreshold);
  edges->SetCreaseAngle(options.CreaseAngle);
  edges->SetContourSide(options.ContourSide);
  edges->SetLineWidth(options.LineWidth);
  edges->SetSilhouetteColor(options.SilhouetteColor);
  edges->SetCreaseColor(options.CreaseColor);
  edges->SetContourColor(options.ContourColor);
  edges->SetAntiAliasing(options.AntiAliasing);
  edges->SetEncoding(vtkNPREdgePass::GetEncodingFromName(options.Encoding.c_str()));
  edges->SetPackedThreshold(options.PackedThreshold);
  edges->SetPackedBlur(options.PackedBlur);
  vtkNPRToonPass* toon = pass->GetToonPass();
  toon->SetNumberOfBands(options.ToonBands);
  toon->SetPerVertex(options.ToonPerVertex);
  vtkNPRSketchPass* sketch = pass->GetSketchPass();
  sketch->SetUncertainty(options.Uncertainty);
  sketch->SetNoiseSeed(static_cast<unsigned int>(options.NoiseSeed));
  sketch->SetNoiseFrequency(options.NoiseFrequency);
  sketch->SetPaper(options.Paper);
  sketch->SetPaperColor(options.PaperColor);
  pass->SetSketchToonShading(options.SketchToon);
  vtkNPRInkPass* ink = pass->GetInkPass();
  ink->SetLineWidth(options.LineWidth);
  ink->SetInkColor(options.SilhouetteColor);
  return pass;
}

int Run(const Options& options, nprQuietOutputWindow* messages)
{
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(options.Background[0], options.Background[1], options.Background[2]);
  // "shaded" is VTK's own chain, untouched: the baseline every style is measured against.
  vtkSmartPointer<vtkNPRPass> pass;
  if (options.Style != "shaded")
  {
    pass = MakePass(options);
    renderer->SetPass(pass);
  }
  vtkIdType triangles = 0;
  for (size_t i = 0; i < options.Models.size(); ++i)
  {
    vtkNew<vtkNPRModelReader> reader;
    reader->SetFileName(options.Models[i].c_str());
    reader->Update();
    if (*reader->GetErrorMessage())
    {
      throw std::runtime_error(reader->GetErrorMessage());
    }
    if (*reader->GetWarningMessage())
    {
      std::cerr << "npr-render: warning: " << reader->GetWarningMessage() << "\n";
    }
    vtkPolyData* model = reader->GetOutput();
    triangles += CountTriangles(model);

    vtkNew<vtkPolyDataMapper> mapper;
    // The file's normals when they are all usable; otherwise smooth shading that keeps sharp
    // (> 30 degree) edges sharp, as CAD users expect, over merged duplicate points.
    vtkNew<vtkNPRShadingNormals> normals;
    normals->SetInputData(model);
    normals->Update();
    mapper->SetInputData(normals->GetOutput());
    // Colours stored in the file (PLY, OFF, VTK) are shown as they are; other arrays are not.
    vtkDataArray* colors = model->GetPointData()->GetScalars()
      ? model->GetPointData()->GetScalars()
      : model->GetCellData()->GetScalars();
    const bool fileColors = vtkUnsignedCharArray::SafeDownCast(colors) &&
      (colors->GetNumberOfComponents() == 3 || colors->GetNumberOfComponents() == 4);
    mapper->SetScalarVisibility(fileColors);
    mapper->SetColorModeToDirectScalars();
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    const double* color = Palette[i % (sizeof(Palette) / sizeof(Palette[0]))];
    actor->GetProperty()->SetColor(color[0], color[1], color[2]);
    actor->GetProperty()->SetSpecular(0.2);
    actor->GetProperty()->SetSpecularPower(30.0);
    renderer->AddActor(actor);
  }

  int width = options.Width, height = options.Height;
  vtkCamera* camera = renderer->GetActiveCamera();
  nprCameraState given;
  if (!options.CameraIn.empty())
  {
    given = nprReadCameraFile(options.CameraIn); // before the window: a bad file fails fast
    if (!options.SizeGiven && given.Size[0] > 0)
    {
      width = given.Size[0];
      height = given.Size[1];
    }
  }

  vtkSmartPointer<vtkRenderWindow> window = vtkSmartPointer<vtkRenderWindow>::Take(
    vtkNPRRenderWindowFactory::CreateRenderWindow(options.Backend.c_str()));
  if (!window)
  {
    throw std::runtime_error(messages->Last);
  }
  window->SetSize(width, height);
  window->AddRenderer(renderer);
  if (!options.CameraIn.empty())
  {
    given.ApplyTo(camera); // clipping range as given
  }
  else
  {
    // After the window exists: the reset fits the scene to its aspect ratio.
    renderer->ResetCamera();
    camera->Azimuth(options.Azimuth);
    camera->Elevation(options.Elevation);
    camera->OrthogonalizeViewUp();
    camera->Zoom(options.Zoom);
    renderer->ResetCameraClippingRange();
  }
  window->Render();

  if (options.Frames > 0)
  {
    // Each timed frame is a real one (the camera is modified, so nothing is reused) and ends
    // with glFinish. With --compare-style the styles alternate frame by frame in this window, so
    // all see the same machine state.
    using Clock = std::chrono::steady_clock;
    // One pass per style; "shaded" is VTK's own chain (no pass).
    std::vector<std::string> styles = { options.Style };
    styles.insert(styles.end(), options.CompareStyles.begin(), options.CompareStyles.end());
    std::vector<vtkSmartPointer<vtkNPRPass>> passes = { pass };
    for (size_t i = 1; i < styles.size(); ++i)
    {
      Options compare = options;
      compare.Style = styles[i];
      passes.push_back(styles[i] == "shaded" ? nullptr : MakePass(compare));
    }
    std::vector<std::vector<double>> times(styles.size());
    for (int i = -1; i < options.Frames; ++i) // frame -1: warm-up of every style
    {
      for (size_t variant = 0; variant < styles.size(); ++variant)
      {
        renderer->SetPass(passes[variant]);
        const Clock::time_point start = Clock::now();
        camera->Modified();
        window->Render();
        window->WaitForCompletion();
        if (i >= 0)
        {
          times[variant].push_back(
            std::chrono::duration<double, std::milli>(Clock::now() - start).count());
        }
      }
    }
    renderer->SetPass(pass);
    auto median = [](std::vector<double> values) {
      std::sort(values.begin(), values.end());
      const size_t n = values.size();
      return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
    };
    auto milliseconds = [](double value) { return nprFormatNumber(std::round(value * 1e3) / 1e3); };
    auto ratio = [](double value) { return nprFormatNumber(std::round(value * 1e3) / 1e3); };
    const std::vector<double>& main = times[0];
    const double mainMedian = median(main);
    std::cout << "{\"style\":" << JsonString(options.Style) << ",\"frames\":" << main.size()
              << ",\"median_ms\":" << milliseconds(mainMedian)
              << ",\"min_ms\":" << milliseconds(*std::min_element(main.begin(), main.end()))
              << ",\"max_ms\":" << milliseconds(*std::max_element(main.begin(), main.end()));
    if (styles.size() > 1)
    {
      // The first compared style as before; every compared style with its time over the main's.
      std::cout << ",\"compare_style\":" << JsonString(styles[1])
                << ",\"compare_median_ms\":" << milliseconds(median(times[1]))
                << ",\"ratio\":" << ratio(mainMedian / median(times[1])) << ",\"compare\":[";
      for (size_t i = 1; i < styles.size(); ++i)
      {
        std::cout << (i > 1 ? "," : "") << "{\"style\":" << JsonString(styles[i])
                  << ",\"median_ms\":" << milliseconds(median(times[i]))
                  << ",\"ratio_to_main\":" << ratio(median(times[i]) / mainMedian) << "}";
      }
      std::cout << "]";
    }
    std::cout << ",\"triangles\":" << triangles
              << ",\"pixels\":" << static_cast<long long>(width) * height
              << ",\"width\":" << width << ",\"height\":" << height
              << ",\"backend\":" << JsonString(vtkNPRRenderWindowFactory::GetBackendName(window))
              << ",\"renderer\":" << JsonString(vtkNPRRenderWindowFactory::GetGLRenderer(window))
              << "}" << std::endl;
  }

  if (!options.Output.empty())
  {
    WriteWindowPNG(window, options.Output, false);
  }
  if (!options.EdgeMask.empty() && options.Style == "inked")
  {
    pass->GetInkPass()->CoverageOnlyOn();
    window->Render();
    WriteWindowPNG(window, options.EdgeMask, true);
    pass->GetInkPass()->CoverageOnlyOff();
  }
  else if (!options.EdgeMask.empty())
  {
    pass->GetEdgePass()->CoverageOnlyOn();
    window->Render(); // the G-buffer and line image are reused: only the composite runs
    WriteWindowPNG(window, options.EdgeMask, true);
    pass->GetEdgePass()->CoverageOnlyOff();
  }
  if (!options.ReferenceMask.empty())
  {
    WriteReferenceMask(renderer, options, width, height); // the camera of the render above
  }
  if (!options.CameraOut.empty())
  {
    nprWriteCameraFile(options.CameraOut, nprCameraState::FromCamera(camera, width, height));
  }
  return 0;
}
}

int main(int argc, char* argv[])
{
  vtkNew<nprQuietOutputWindow> messages;
  const char* verbose = std::getenv("NPR_VERBOSE");
  messages->Verbose = verbose && *verbose && std::strcmp(verbose, "0") != 0;
  vtkOutputWindow::SetInstance(messages);
  if (!messages->Verbose)
  {
    vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF); // VTK logs warnings here too
  }
  int status = 0;
  try
  {
    status = Run(ParseOptions(argc, argv), messages);
  }
  catch (const UsageError& error)
  {
    std::cerr << "npr-render: error: " << error.what() << "\n";
    status = 2;
  }
  catch (const std::exception& error)
  {
    std::cerr << "npr-render: error: " << error.what() << "\n";
    status = 1;
  }
  vtkOutputWindow::SetInstance(nullptr);
  return status;
}
