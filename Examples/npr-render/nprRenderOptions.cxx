// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nprRenderOptions.h"

#include "nprArguments.h"
#include "nprOrbit.h"
#include "nprPassOptions.h"
#include "nprWindowImage.h"

#include "vtkNPRDrawingExporter.h"
#include "vtkNPRDrawingSheet.h"
#include "vtkNPRRenderWindowFactory.h"

#include <algorithm>
#include <iostream>
#include <set>

namespace
{
// Flags that the chosen styles do not use, one warning each on stderr.
void WarnAboutFlags(const nprRenderOptions& options)
{
  std::vector<std::string> styles = { options.Pass.Style };
  styles.insert(styles.end(), options.CompareStyles.begin(), options.CompareStyles.end());
  std::set<std::string> alsoUsed; // the reference mask is made of --lines and --crease-angle
  if (!options.ReferenceMask.empty())
  {
    alsoUsed = { "--lines", "--crease-angle" };
  }
  for (const std::string& warning : nprCheckPassOptions(options.Pass, styles, alsoUsed))
  {
    std::cerr << "npr-render: warning: " << warning << "\n";
  }
}

// The drawing sheet's flags; false for another flag.
bool ParseSheetOption(nprArgumentReader& arguments, nprRenderOptions& options)
{
  const std::string& arg = arguments.Current();
  if (arg == "--sheet")
  {
    options.Sheet = arguments.Value();
    for (const std::string& view : nprSplitList(options.Sheet))
    {
      if (!vtkNPRDrawingSheet::IsViewName(view.c_str()))
      {
        throw nprUsageError("--sheet: unknown view '" + view +
          "' (views: " + vtkNPRDrawingSheet::GetViewNames() + ")");
      }
    }
  }
  else if (arg == "--sheet-paper")
  {
    options.SheetPaper = arguments.Value();
    if (vtkNPRDrawingSheet::GetPaperSizeFromName(options.SheetPaper.c_str()) < 0)
    {
      throw nprUsageError("--sheet-paper " + options.SheetPaper + ": not A4, A3 or letter");
    }
  }
  else if (arg == "--sheet-angle")
  {
    const std::string angle = arguments.Value();
    if (angle != "first" && angle != "third")
    {
      throw nprUsageError("--sheet-angle " + angle + ": not first or third");
    }
    options.SheetThirdAngle = angle == "third";
  }
  else if (arg == "--sheet-margin")
  {
    options.SheetMargin = nprParseRange(arg, arguments.Value(), 0.0, 50.0);
  }
  else
  {
    return false;
  }
  options.SheetFlags.insert(arg);
  return true;
}

// A sheet is the drawing style's, written as a vector file; its flags need --sheet.
void CheckSheetOptions(nprRenderOptions& options)
{
  if (options.Sheet.empty())
  {
    if (!options.SheetFlags.empty())
    {
      throw nprUsageError(*options.SheetFlags.begin() + " needs --sheet VIEWS");
    }
    return;
  }
  if (!nprIsDrawingFile(options.Output))
  {
    throw nprUsageError(std::string("--sheet needs -o FILE with the extension ") +
      vtkNPRDrawingExporter::GetSupportedExtensions());
  }
  if (options.Orbit > 0 || options.Frames > 0 || !options.EdgeMask.empty())
  {
    throw nprUsageError("--sheet cannot be combined with --orbit, --frames or --edge-mask");
  }
  if (options.Pass.GivenFlags.count("--style") && options.Pass.Style != "drawing")
  {
    throw nprUsageError(
      "--sheet draws the drawing style: leave out --style or give --style drawing");
  }
  options.Pass.Style = "drawing";
}

// The vector drawing's filled faces; false for another flag.
bool ParseFillOption(nprArgumentReader& arguments, nprRenderOptions& options)
{
  const std::string& arg = arguments.Current();
  if (arg == "--fill-faces")
  {
    options.FillFaces = true;
    return true;
  }
  if (arg == "--fill-colors")
  {
    const std::string colors = arguments.Value();
    const char* const names[] = { "face", "surface", "toon" }; // FillColorModes' order
    const auto found = std::find(std::begin(names), std::end(names), colors);
    if (found == std::end(names))
    {
      throw nprUsageError("--fill-colors " + colors + ": not face, surface or toon");
    }
    options.FillColors = static_cast<int>(found - std::begin(names));
    options.FillColorsGiven = true;
    return true;
  }
  return false;
}

// Filled faces are written into a vector drawing or sheet, and their colours need them.
void CheckFillOptions(const nprRenderOptions& options)
{
  if (options.FillColorsGiven && !options.FillFaces)
  {
    throw nprUsageError("--fill-colors needs --fill-faces");
  }
  if (options.FillFaces && !nprIsDrawingFile(options.Output))
  {
    throw nprUsageError(std::string("--fill-faces needs -o FILE with the extension ") +
      vtkNPRDrawingExporter::GetSupportedExtensions());
  }
}

const char* const Usage = R"(usage: npr-render [options] MODEL [MODEL...]

Renders one scene of the given models headless and writes a PNG, or a vector drawing
of its lines (SVG, PDF, PostScript).
Models: .stl .obj .ply .vtp .vtk .gltf .glb .off

  -o, --output FILE        the image to write, by its extension: .png, or the lines as
                           a vector drawing .svg, .pdf, .ps or .eps (1 pixel = 1 point,
                           over the image unless --style drawing); with --orbit:
                           frames or a video
  --size WxH               image size in pixels (default 1024x768)
  --compare-style LIST     with --frames: also time these styles (names as --style, comma
                           separated), frames
                           interleaved with the main style's in the same window; print
                           each median and its ratio to the main style's
  --backend NAME           egl, osmesa or x (default: NPR_BACKEND, else egl;
                           osmesa in npr-render-osmesa)
  --background COLOR       a colour name, r,g,b in 0..1 or #rrggbb (default white)
  --camera-in FILE         use this camera (JSON; its clipping range as given)
  --camera-out FILE        write the camera used (JSON)
  --frames N               time N frames after a warm-up; print one JSON line
  --orbit N                write N frames of the camera turning about the view up through
                           the focal point: -o NAME.png writes NAME_0001.png..., -o NAME.ogv
                           an Ogg Theora video, -o NAME.mp4 an MP4 (the ffmpeg program),
                           -o NAME.avi an AVI (VTK's FFMPEG writer, where VTK has it)
  --orbit-degrees DEG      the whole turn of --orbit, -3600..3600 (default 360: a loop)
  --fps RATE               frames per second of a video, 1..120 (default 25)
  --edge-mask FILE         also write the line coverage alone: white on black, 8-bit
                           grey PNG of the render's size (edges, toon+edges, inked)
  --reference-mask FILE    also write the ground truth of --lines and --crease-angle:
                           the visible object-space lines, white on black, 8-bit grey
                           PNG of the render's size (any style)
  --fill-faces             with a vector -o: the visible faces as filled regions under
                           the lines, back to front (the render's picture, as shapes)
  --fill-colors COLORS     face (default: the drawing style's face colour), surface (each
                           model's own colour, flat and unlit) or toon (those colours in
                           the toon bands of the lights, flat per face)
  --sheet VIEWS            write a drawing sheet to -o (.svg, .pdf, .ps, .eps): these
                           views of the scene on one page, one scale, with their names
                           (comma separated: iso, front, top, right, left, back, bottom);
                           the drawing style's lines (--hidden-lines and the line flags)
  --sheet-paper NAME       A4 (default), A3 or letter, landscape
  --sheet-angle ANGLE      first (default: the top view under the front view, the right
                           view to its left) or third (top above, right to the right)
  --sheet-margin MM        the page's margins in millimetres, 0..50 (default 10)
  --quiet                  no progress lines (otherwise each step that takes over a
                           second, such as reading a large model, prints one on stderr)
  -h, --help               this text
  --version                the program and vtkNPR version

)";

// The options of what npr-render writes and how it times: -o, --frames, --orbit and the others
// that npr-view does not take.
bool ParseOutputOption(nprArgumentReader& arguments, nprRenderOptions& options)
{
  const std::string& arg = arguments.Current();
  if (arg == "-o" || arg == "--output")
  {
    options.Output = arguments.Value();
  }
  else if (arg == "--camera-out")
  {
    options.CameraOut = arguments.Value();
  }
  else if (arg == "--quiet")
  {
    options.Quiet = true;
  }
  else if (arg == "--frames")
  {
    options.Frames = nprParseInteger(arg, arguments.Value(), 1, 100000);
  }
  else if (arg == "--orbit")
  {
    options.Orbit = nprParseInteger(arg, arguments.Value(), 1, 100000);
  }
  else if (arg == "--orbit-degrees")
  {
    options.OrbitDegrees = nprParseRange(arg, arguments.Value(), -3600.0, 3600.0);
  }
  else if (arg == "--fps")
  {
    options.Rate = nprParseRange(arg, arguments.Value(), 1.0, 120.0);
  }
  else if (arg == "--backend")
  {
    options.Backend = arguments.Value();
    if (!vtkNPRRenderWindowFactory::IsKnownBackend(options.Backend.c_str()))
    {
      throw nprUsageError("unknown backend '" + options.Backend +
        "' (valid backends: " + vtkNPRRenderWindowFactory::GetKnownBackends() + ")");
    }
  }
  else if (arg == "--compare-style")
  {
    for (const std::string& part : nprSplitList(arguments.Value()))
    {
      options.CompareStyles.push_back(nprStyleFromText(arg, part));
    }
  }
  else if (arg == "--edge-mask")
  {
    options.EdgeMask = arguments.Value();
  }
  else if (arg == "--reference-mask")
  {
    options.ReferenceMask = arguments.Value();
  }
  else
  {
    return false;
  }
  return true;
}

// -o's extension against --orbit, and that the command has something to write or time.
void CheckOutputOptions(const nprRenderOptions& options)
{
  const std::string outputKind = nprOrbitOutputKind(options.Output);
  if (options.Orbit > 0)
  {
    if (options.Output.empty() || outputKind.empty())
    {
      throw nprUsageError(
        "--orbit needs -o NAME.png (numbered frames), NAME.ogv, NAME.mp4 or NAME.avi");
    }
    if (options.Frames > 0 || !options.EdgeMask.empty() || !options.ReferenceMask.empty())
    {
      throw nprUsageError("--orbit cannot be combined with --frames, --edge-mask or "
                          "--reference-mask");
    }
  }
  else if (!outputKind.empty() && outputKind != "png")
  {
    throw nprUsageError("-o " + options.Output + ": a video needs --orbit N");
  }
  else if (!options.Output.empty() && outputKind.empty() && !nprIsDrawingFile(options.Output))
  {
    throw nprUsageError("-o " + options.Output + ": unknown extension (supported: " +
      nprOutputExtensions() + "; with --orbit: .png, .ogv, .mp4, .avi)");
  }
  if (options.Output.empty() && options.Frames == 0 && options.CameraOut.empty() &&
    options.EdgeMask.empty() && options.ReferenceMask.empty())
  {
    throw nprUsageError("nothing to do: give -o FILE, --frames N, --edge-mask FILE, "
                        "--reference-mask FILE or --camera-out FILE");
  }
  if (!options.CompareStyles.empty() && options.Frames == 0)
  {
    throw nprUsageError("--compare-style needs --frames N");
  }
  const std::string& style = options.Pass.Style;
  if (!options.EdgeMask.empty() && style != "edges" && style != "toon+edges" && style != "inked")
  {
    throw nprUsageError("--edge-mask needs --style edges, toon+edges or inked");
  }
}
}

nprRenderOptions nprParseRenderOptions(int argc, char* argv[])
{
  nprRenderOptions options;
  static const std::string help = std::string(Usage) + "Camera (not with --camera-in):\n" +
    nprCameraOptionsHelp + "\n" + nprPassOptionsHelp;
  nprArgumentReader arguments(argc, argv, help.c_str());
  while (arguments.Next())
  {
    // --style and the flags of the styles; the models, the frame and the camera; the drawing
    // sheet; the filled faces; what is written and timed.
    if (!nprParsePassOption(arguments, options.Pass) && !nprParseSceneOption(arguments, options) &&
      !ParseSheetOption(arguments, options) && !ParseFillOption(arguments, options) &&
      !ParseOutputOption(arguments, options))
    {
      throw nprUsageError("unknown option '" + arguments.Current() + "' (see --help)");
    }
  }
  nprCheckSceneOptions(options);
  CheckSheetOptions(options);
  CheckFillOptions(options);
  CheckOutputOptions(options);
  WarnAboutFlags(options);
  return options;
}
