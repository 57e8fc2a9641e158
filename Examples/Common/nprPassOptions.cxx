// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nprPassOptions.h"

#include "nprArguments.h"
#include "nprPassSettings.h"

#include "vtkNPREdgePass.h"
#include "vtkNPRPass.h"

#include <algorithm>
#include <cctype>
#include <iterator>
#include <utility>
#include <vector>

const char* const nprPassOptionsHelp = R"(Style:
  --style NAME             shaded (default), edges, toon, toon+edges, sketch, inked or
                           drawing

Lines (--style edges, toon+edges, sketch and drawing):
  --lines LIST             line types drawn, comma separated: silhouettes, creases,
                           contours, suggestive (suggestive contours), or none (default
                           silhouettes,creases,contours)
  --silhouette-threshold X relative depth step that makes a silhouette (default 0.005)
  --smooth-silhouettes     silhouettes also where the shading normal turns away between
                           two pixels (the smooth surface's contour)
  --crease-angle DEG       normal angle that makes a crease, 1..179 (default 30)
  --face-creases           creases between the faces' own normals instead of the shading
                           normals (the mesh's creases, for CAD parts)
  --suggestive-threshold X strength of a suggestive contour, 0.0001..1 (default 0.01)
  --contour-side SIDE      inside, outside or both (default inside)
  --line-width PX          line width in pixels, 0.5..16 (default 1.5)
  --silhouette-width PX    width of the silhouettes (and the drawing's boundaries), 0..16
                           (default 0; 0 is --line-width)
  --crease-width PX        width of the creases (and the drawing's non-manifold edges), 0..16
                           (default 0; 0 is --line-width)
  --contour-width PX       width of the object contours, 0..16 (default 0; 0 is --line-width)
  --suggestive-width PX    width of the suggestive contours, 0..16 (default 0; 0 is
                           --line-width)
  --max-line-fraction F    largest share of an object's width one of its lines may take,
                           0..1 (default 0; 0 is no limit, 0.1 suits stream tubes)
  --depth-falloff          line widths fall off with depth: --near-line-scale times each
                           kind's width at the near clipping plane, --far-line-scale at
                           the far one (the scene's depth)
  --near-line-scale F      width scale of the nearest lines, 0.1..4 (default 1.5)
  --far-line-scale F       width scale of the farthest lines, 0.1..4 (default 0.5)
  --surface-line-shade F   lines over a surface in its own colour times F, 0..1 (default 0;
                           0 keeps the lines' own colours, 0.5 suits colour-mapped data)
  --line-color COLOR       colour of every line type: a name (red, navy, ...), r,g,b in
                           0..1 or #rrggbb (default black)
  --silhouette-color COLOR, --crease-color COLOR, --contour-color COLOR,
  --suggestive-color COLOR
  --no-antialias           lines without anti-aliasing
  --encoding NAME          how the G-buffer stores depth and normals: float (default),
                           half, packed8 or packed16 (the 1990s packed depth+normal
                           value, lines from its Laplacian)
  --packed-threshold X     packed encodings: Laplacian that makes a line, in units of one
                           component's range, 0.001..4 (default 0.1)
  --packed-blur            packed encodings: blur before the Laplacian (fatter lines)

Inking (--style inked):
  --line-width PX          ink line width in pixels, 0.5..16 (default 1.5)
  --line-color COLOR       ink colour (default black)

Technical drawing (--style drawing: white faces, exact lines from the meshes; --lines,
--crease-angle, --line-width and the colours apply):
  --hidden-lines           also draw the hidden lines, dashed (6 px on, 4 off at 72 DPI),
                           0.6 times as wide, in grey
  --taper PX               visible strokes grow from nothing at an open end to their width
                           over PX pixels at 72 DPI, 0..200 (default 0; 0 is no taper)
  --curvature-width F      visible strokes up to 1 + F times as wide where they bend,
                           0..4 (default 0)

Toon shading (--style toon, toon+edges):
  --toon-bands N           number of equal light bands, 1..64 (default 3)
  --toon-per-vertex        light at the vertices, interpolated, then banded (default:
                           per pixel)

Sketch (--style sketch):
  --uncertainty PX         largest displacement of lines and fills in pixels, 0..32
                           (default 3; 0 draws the exact lines on flat colours)
  --noise-seed N           seed of the noise, 0..2147483647 (default 1)
  --noise-frequency F      noise cells per 100 pixels, 0.05..25 (default 2)
  --noise-space SPACE      surface (the wobble stays on the surfaces as the camera moves) or
                           screen (fixed to the pixels) (default surface)
  --paper-color COLOR      draw on paper of this colour instead of the background
  --sketch-toon            fill with the toon bands (--toon-bands) instead of flat colours
)";

bool nprIsStyleName(const std::string& name)
{
  return vtkNPRPass::GetStyleFromName(name.c_str()) >= 0;
}

std::string nprStyleFromText(const std::string& flag, const std::string& text)
{
  std::string name; // lower case without spaces: "Toon + Edges" -> "toon+edges"
  for (char c : text)
  {
    if (c != ' ')
    {
      name += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    }
  }
  if (!nprIsStyleName(name))
  {
    throw nprUsageError("unknown style '" + text + "'" + (flag == "--style" ? "" : " for " + flag) +
      " (valid styles: " + nprStyleNames() + ")");
  }
  return name;
}

std::string nprStyleNames()
{
  std::string names;
  for (int style = vtkNPRPass::SHADED; style <= vtkNPRPass::DRAWING; ++style)
  {
    names += (names.empty() ? "" : ", ") + std::string(vtkNPRPass::GetStyleName(style));
  }
  return names;
}

namespace
{
// The flags that set a number in a range, a switch, or one line type's colour, and the setting each
// sets.
struct RangeFlag
{
  const char* Flag;
  double nprPassSettings::*Setting;
  double Minimum, Maximum;
};
const RangeFlag RangeFlags[] = {
  { "--silhouette-threshold", &nprPassSettings::SilhouetteThreshold, 1e-5, 1.0 },
  { "--crease-angle", &nprPassSettings::CreaseAngle, 1.0, 179.0 },
  { "--suggestive-threshold", &nprPassSettings::SuggestiveContourThreshold, 1e-4, 1.0 },
  { "--line-width", &nprPassSettings::LineWidth, 0.5, 16.0 },
  { "--silhouette-width", &nprPassSettings::SilhouetteLineWidth, 0.0, 16.0 },
  { "--crease-width", &nprPassSettings::CreaseLineWidth, 0.0, 16.0 },
  { "--contour-width", &nprPassSettings::ContourLineWidth, 0.0, 16.0 },
  { "--suggestive-width", &nprPassSettings::SuggestiveContourLineWidth, 0.0, 16.0 },
  { "--max-line-fraction", &nprPassSettings::MaximumLineFraction, 0.0, 1.0 },
  { "--surface-line-shade", &nprPassSettings::SurfaceLineShade, 0.0, 1.0 },
  { "--near-line-scale", &nprPassSettings::NearLineScale, 0.1, 4.0 },
  { "--far-line-scale", &nprPassSettings::FarLineScale, 0.1, 4.0 },
  { "--taper", &nprPassSettings::TaperLength, 0.0, 200.0 },
  { "--curvature-width", &nprPassSettings::CurvatureWidth, 0.0, 4.0 },
  { "--packed-threshold", &nprPassSettings::PackedThreshold, 0.001, 4.0 },
  { "--uncertainty", &nprPassSettings::Uncertainty, 0.0, 32.0 },
  { "--noise-frequency", &nprPassSettings::NoiseFrequency, 0.05, 25.0 },
};
struct SwitchFlag
{
  const char* Flag;
  bool nprPassSettings::*Setting;
  bool Value;
};
const SwitchFlag SwitchFlags[] = {
  { "--smooth-silhouettes", &nprPassSettings::SmoothSilhouettes, true },
  { "--face-creases", &nprPassSettings::FaceCreases, true },
  { "--no-antialias", &nprPassSettings::AntiAliasing, false },
  { "--packed-blur", &nprPassSettings::PackedBlur, true },
  { "--toon-per-vertex", &nprPassSettings::ToonPerVertex, true },
  { "--hidden-lines", &nprPassSettings::HiddenLines, true },
  { "--depth-falloff", &nprPassSettings::DepthFalloff, true },
  { "--sketch-toon", &nprPassSettings::SketchToon, true },
};
const std::pair<const char*, double (nprPassSettings::*)[3]> ColorFlags[] = {
  { "--silhouette-color", &nprPassSettings::SilhouetteColor },
  { "--crease-color", &nprPassSettings::CreaseColor },
  { "--contour-color", &nprPassSettings::ContourColor },
  { "--suggestive-color", &nprPassSettings::SuggestiveContourColor },
};

// A flag of the tables above; false for any other.
bool ParseTableFlag(const std::string& arg, nprArgumentReader& arguments, nprPassSettings& pass)
{
  for (const RangeFlag& flag : RangeFlags)
  {
    if (arg == flag.Flag)
    {
      pass.*flag.Setting = nprParseRange(arg, arguments.Value(), flag.Minimum, flag.Maximum);
      return true;
    }
  }
  for (const SwitchFlag& flag : SwitchFlags)
  {
    if (arg == flag.Flag)
    {
      pass.*flag.Setting = flag.Value;
      return true;
    }
  }
  for (const auto& flag : ColorFlags)
  {
    if (arg == flag.first)
    {
      nprParseColor(arg, arguments.Value(), pass.*flag.second);
      return true;
    }
  }
  return false;
}

// --lines: the line types drawn.
void ParseLineTypes(const std::string& list, nprPassSettings& pass)
{
  pass.Silhouettes = pass.Creases = pass.Contours = pass.SuggestiveContours = false;
  for (const std::string& part : nprSplitList(list))
  {
    if (part == "silhouettes" || part == "silhouette")
    {
      pass.Silhouettes = true;
    }
    else if (part == "creases" || part == "crease")
    {
      pass.Creases = true;
    }
    else if (part == "contours" || part == "contour")
    {
      pass.Contours = true;
    }
    else if (part == "suggestive")
    {
      pass.SuggestiveContours = true;
    }
    else if (part != "none")
    {
      throw nprUsageError("--lines expects silhouettes, creases, contours, suggestive or none, "
                          "got '" +
        part + "'");
    }
  }
}

// The flags of one of several names: an index into names, or a usage error listing them.
int ParseChoice(const std::string& arg, const std::string& value,
  const std::vector<std::string>& names, const char* expected)
{
  const auto found = std::find(names.begin(), names.end(), value);
  if (found == names.end())
  {
    throw nprUsageError(arg + " expects " + expected + ", got '" + value + "'");
  }
  return static_cast<int>(found - names.begin());
}

// The flags the tables leave out; false for a flag that is none of the pass's.
bool ParseOtherFlag(const std::string& arg, nprArgumentReader& arguments, nprPassSettings& pass)
{
  if (arg == "--style")
  {
    pass.Style = nprStyleFromText(arg, arguments.Value());
  }
  else if (arg == "--lines")
  {
    ParseLineTypes(arguments.Value(), pass);
  }
  else if (arg == "--contour-side")
  {
    pass.ContourSide = ParseChoice(
      arg, arguments.Value(), { "inside", "outside", "both" }, "inside, outside or both");
  }
  else if (arg == "--line-color")
  {
    nprParseColor(arg, arguments.Value(), pass.SilhouetteColor);
    std::copy_n(pass.SilhouetteColor, 3, pass.CreaseColor);
    std::copy_n(pass.SilhouetteColor, 3, pass.ContourColor);
    std::copy_n(pass.SilhouetteColor, 3, pass.SuggestiveContourColor);
  }
  else if (arg == "--encoding")
  {
    const std::string encoding = arguments.Value();
    pass.Encoding = vtkNPREdgePass::GetEncodingFromName(encoding.c_str());
    if (pass.Encoding < 0)
    {
      throw nprUsageError(
        "--encoding expects float, half, packed8 or packed16, got '" + encoding + "'");
    }
  }
  else if (arg == "--toon-bands")
  {
    pass.ToonBands = nprParseInteger(arg, arguments.Value(), 1, 64);
  }
  else if (arg == "--noise-seed")
  {
    pass.NoiseSeed = nprParseInteger(arg, arguments.Value(), 0, 2147483647);
  }
  else if (arg == "--noise-space")
  {
    pass.NoiseSpace =
      ParseChoice(arg, arguments.Value(), { "surface", "screen" }, "surface or screen") == 1
      ? vtkNPRSketchPass::SCREEN
      : vtkNPRSketchPass::SURFACE;
  }
  else if (arg == "--paper-color")
  {
    nprParseColor(arg, arguments.Value(), pass.PaperColor);
    pass.Paper = true;
  }
  else
  {
    return false;
  }
  return true;
}
}

bool nprParsePassOption(nprArgumentReader& arguments, nprPassSettings& pass)
{
  const std::string& arg = arguments.Current();
  if (!ParseTableFlag(arg, arguments, pass) && !ParseOtherFlag(arg, arguments, pass))
  {
    return false;
  }
  pass.GivenFlags.insert(arg);
  return true;
}

namespace
{
constexpr unsigned StyleBit(int style)
{
  return 1u << style;
}
// The styles that find lines in the image (vtkNPREdgePass), and those that draw any lines.
constexpr unsigned ImageLines =
  StyleBit(vtkNPRPass::EDGES) | StyleBit(vtkNPRPass::TOON_EDGES) | StyleBit(vtkNPRPass::SKETCH);
constexpr unsigned Strokes = ImageLines | StyleBit(vtkNPRPass::DRAWING);
constexpr unsigned Toon =
  StyleBit(vtkNPRPass::TOON) | StyleBit(vtkNPRPass::TOON_EDGES) | StyleBit(vtkNPRPass::SKETCH);

// Which styles use each flag of the styles (the sketch uses the toon flags with --sketch-toon).
struct FlagScope
{
  const char* Flag;
  unsigned Styles;
};
const FlagScope FlagScopes[] = { { "--lines", Strokes }, { "--crease-angle", Strokes },
  { "--silhouette-threshold", ImageLines }, { "--smooth-silhouettes", Strokes },
  { "--face-creases", ImageLines }, { "--max-line-fraction", ImageLines },
  { "--surface-line-shade", ImageLines }, { "--suggestive-threshold", ImageLines },
  { "--suggestive-color", ImageLines }, { "--contour-side", ImageLines },
  { "--contour-color", ImageLines }, { "--no-antialias", ImageLines }, { "--encoding", ImageLines },
  { "--packed-threshold", ImageLines }, { "--packed-blur", ImageLines },
  { "--silhouette-color", Strokes }, { "--crease-color", Strokes },
  { "--silhouette-width", Strokes }, { "--crease-width", Strokes },
  { "--contour-width", ImageLines }, { "--suggestive-width", ImageLines },
  { "--line-width", Strokes | StyleBit(vtkNPRPass::INKED) },
  { "--line-color", Strokes | StyleBit(vtkNPRPass::INKED) }, { "--toon-bands", Toon },
  { "--toon-per-vertex", Toon }, { "--sketch-toon", StyleBit(vtkNPRPass::SKETCH) },
  { "--uncertainty", StyleBit(vtkNPRPass::SKETCH) },
  { "--noise-seed", StyleBit(vtkNPRPass::SKETCH) },
  { "--noise-frequency", StyleBit(vtkNPRPass::SKETCH) },
  { "--noise-space", StyleBit(vtkNPRPass::SKETCH) },
  { "--paper-color", StyleBit(vtkNPRPass::SKETCH) },
  { "--hidden-lines", StyleBit(vtkNPRPass::DRAWING) }, { "--taper", StyleBit(vtkNPRPass::DRAWING) },
  { "--curvature-width", StyleBit(vtkNPRPass::DRAWING) }, { "--depth-falloff", Strokes },
  { "--near-line-scale", Strokes }, { "--far-line-scale", Strokes } };

// "edges, toon+edges or sketch"
std::string StyleList(unsigned styles)
{
  std::vector<std::string> names;
  for (int style = vtkNPRPass::SHADED; style <= vtkNPRPass::DRAWING; ++style)
  {
    if (styles & StyleBit(style))
    {
      names.emplace_back(vtkNPRPass::GetStyleName(style));
    }
  }
  std::string list;
  for (size_t i = 0; i < names.size(); ++i)
  {
    list += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i];
  }
  return list;
}

bool IsPacked(int encoding)
{
  return encoding == vtkNPREdgePass::PACKED8 || encoding == vtkNPREdgePass::PACKED16;
}

// A flag that none of the drawing styles uses.
void WarnUnusedFlags(const nprPassSettings& pass, unsigned drawn, const std::set<std::string>& also,
  std::vector<std::string>& warnings)
{
  for (const FlagScope& scope : FlagScopes)
  {
    if (pass.GivenFlags.count(scope.Flag) && !(scope.Styles & drawn) && !also.count(scope.Flag))
    {
      warnings.push_back(std::string(scope.Flag) + " applies to --style " +
        StyleList(scope.Styles) + "; ignored with --style " + StyleList(drawn));
    }
  }
}

// A flag that another flag turns off.
void WarnOverriddenFlags(
  const nprPassSettings& pass, unsigned drawn, std::vector<std::string>& warnings)
{
  const bool packed = IsPacked(pass.Encoding);
  auto given = [&](const char* flag) { return pass.GivenFlags.count(flag) > 0; };
  for (const char* flag : { "--packed-threshold", "--packed-blur" })
  {
    if (given(flag) && !packed && (drawn & ImageLines))
    {
      warnings.push_back(std::string(flag) + " applies only with --encoding packed8 or packed16");
    }
  }
  for (const char* flag : { "--suggestive-threshold", "--suggestive-color" })
  {
    if (given(flag) && !pass.SuggestiveContours)
    {
      warnings.push_back(std::string(flag) + " has no effect: --lines has no suggestive");
    }
  }
  if ((given("--toon-bands") || given("--toon-per-vertex")) && !pass.SketchToon &&
    (drawn & Toon) == StyleBit(vtkNPRPass::SKETCH))
  {
    warnings.push_back("the toon flags apply to the sketch only with --sketch-toon");
  }
}

// Combinations that cannot draw what they ask for.
void RefuseImpossible(const nprPassSettings& pass, unsigned drawn)
{
  const std::string encoding = vtkNPREdgePass::GetEncodingName(pass.Encoding);
  if ((drawn & ImageLines) && pass.FaceCreases && pass.Encoding != vtkNPREdgePass::FLOAT)
  {
    throw nprUsageError("--face-creases needs --encoding float (only it keeps the faces' "
                        "normals), not " +
      encoding);
  }
  const bool packed = IsPacked(pass.Encoding);
  if ((drawn & ImageLines) && packed && (pass.SmoothSilhouettes || pass.SuggestiveContours))
  {
    throw nprUsageError(
      std::string(pass.SmoothSilhouettes ? "--smooth-silhouettes" : "--lines suggestive") +
      " needs --encoding float or half: the packed encodings find no line types");
  }
  if (drawn == StyleBit(vtkNPRPass::DRAWING) && !pass.Silhouettes && !pass.Creases)
  {
    throw nprUsageError("--style drawing draws silhouettes (with boundaries) and creases; "
                        "the --lines given leave it nothing to draw");
  }
}
}

std::vector<std::string> nprCheckPassOptions(const nprPassSettings& pass,
  const std::vector<std::string>& styles, const std::set<std::string>& alsoUsed)
{
  unsigned drawn = 0;
  for (const std::string& style : styles)
  {
    drawn |= StyleBit(vtkNPRPass::GetStyleFromName(style.c_str()));
  }
  RefuseImpossible(pass, drawn);
  std::vector<std::string> warnings;
  WarnUnusedFlags(pass, drawn, alsoUsed, warnings);
  WarnOverriddenFlags(pass, drawn, warnings);
  if ((drawn & Strokes) == StyleBit(vtkNPRPass::DRAWING) &&
    (pass.Contours || pass.SuggestiveContours) && pass.GivenFlags.count("--lines"))
  {
    warnings.push_back("--style drawing draws no contours or suggestive contours (only "
                       "silhouettes, boundaries and creases)");
  }
  return warnings;
}
