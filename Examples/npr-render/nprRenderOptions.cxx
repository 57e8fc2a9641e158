// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nprRenderOptions.h"

#include "nprArguments.h"
#include "nprOrbit.h"

#include "vtkNPREdgePass.h"
#include "vtkNPRRenderWindowFactory.h"

#include <algorithm>
#include <iterator>

namespace
{
const char* const Styles[] = { "shaded", "edges", "toon", "toon+edges", "sketch", "inked" };

const char* const Help = R"(usage: npr-render [options] MODEL [MODEL...]

Renders one scene of the given models headless and writes a PNG.
Models: .stl .obj .ply .vtp .vtk .gltf .glb .off

  -o, --output FILE        PNG to write (with --orbit: frames or a video)
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
  --orbit N                write N frames of the camera turning about the view up through
                           the focal point: -o NAME.png writes NAME_0001.png..., -o NAME.ogv
                           an Ogg Theora video, -o NAME.mp4 an MP4 (VTK's FFMPEG writer, or
                           the ffmpeg program)
  --orbit-degrees DEG      the whole turn of --orbit, -3600..3600 (default 360: a loop)
  --fps RATE               frames per second of a video, 1..120 (default 25)
  -h, --help               this text
  --version                the program and vtkNPR version

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
  --noise-space SPACE      surface (the wobble stays on the surfaces as the camera moves) or
                           screen (fixed to the pixels) (default surface)
  --paper-color COLOR      draw on paper of this colour instead of the background
  --sketch-toon            fill with the toon bands (--toon-bands) instead of flat colours
)";
}

nprRenderOptions nprParseRenderOptions(int argc, char* argv[])
{
  nprRenderOptions options;
  nprPassSettings& pass = options.Pass;
  nprArgumentReader arguments(argc, argv, Help);
  while (arguments.Next())
  {
    const std::string& arg = arguments.Current();
    if (arg == "-o" || arg == "--output")
    {
      options.Output = arguments.Value();
    }
    else if (arg == "--size")
    {
      const auto size = nprParseSize("--size", arguments.Value(), 1, 16384, "WxH (e.g. 1024x768)");
      options.Width = size.first;
      options.Height = size.second;
      options.SizeGiven = true;
    }
    else if (arg == "--style")
    {
      pass.Style = arguments.Value();
      if (std::find(std::begin(Styles), std::end(Styles), pass.Style) == std::end(Styles))
      {
        std::string valid;
        for (const char* style : Styles)
        {
          valid += (valid.empty() ? "" : ", ") + std::string(style);
        }
        throw nprUsageError("unknown style '" + pass.Style + "' (valid styles: " + valid + ")");
      }
    }
    else if (arg == "--azimuth")
    {
      options.Azimuth = nprParseNumber(arg, arguments.Value());
      options.CameraMoved = true;
    }
    else if (arg == "--elevation")
    {
      options.Elevation = nprParseNumber(arg, arguments.Value());
      options.CameraMoved = true;
    }
    else if (arg == "--zoom")
    {
      options.Zoom = nprParseNumber(arg, arguments.Value());
      options.CameraMoved = true;
      if (options.Zoom <= 0.0)
      {
        throw nprUsageError("--zoom expects a positive factor");
      }
    }
    else if (arg == "--background")
    {
      nprParseColor(arg, arguments.Value(), options.Background);
    }
    else if (arg == "--camera-in")
    {
      options.CameraIn = arguments.Value();
    }
    else if (arg == "--camera-out")
    {
      options.CameraOut = arguments.Value();
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
    else if (arg == "--lines")
    {
      const std::vector<std::string> parts = nprSplitList(arguments.Value());
      pass.Silhouettes = pass.Creases = pass.Contours = false;
      for (const std::string& part : parts)
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
        else if (part != "none")
        {
          throw nprUsageError(
            "--lines expects silhouettes, creases, contours or none, got '" + part + "'");
        }
      }
    }
    else if (arg == "--silhouette-threshold")
    {
      pass.SilhouetteThreshold = nprParseRange(arg, arguments.Value(), 1e-5, 1.0);
    }
    else if (arg == "--crease-angle")
    {
      pass.CreaseAngle = nprParseRange(arg, arguments.Value(), 1.0, 179.0);
    }
    else if (arg == "--contour-side")
    {
      const std::string side = arguments.Value();
      const char* const sides[] = { "inside", "outside", "both" };
      const auto found = std::find(std::begin(sides), std::end(sides), side);
      if (found == std::end(sides))
      {
        throw nprUsageError("--contour-side expects inside, outside or both, got '" + side + "'");
      }
      pass.ContourSide = static_cast<int>(found - std::begin(sides));
    }
    else if (arg == "--line-width")
    {
      pass.LineWidth = nprParseRange(arg, arguments.Value(), 0.5, 16.0);
    }
    else if (arg == "--line-color")
    {
      nprParseColor(arg, arguments.Value(), pass.SilhouetteColor);
      std::copy_n(pass.SilhouetteColor, 3, pass.CreaseColor);
      std::copy_n(pass.SilhouetteColor, 3, pass.ContourColor);
    }
    else if (arg == "--silhouette-color")
    {
      nprParseColor(arg, arguments.Value(), pass.SilhouetteColor);
    }
    else if (arg == "--crease-color")
    {
      nprParseColor(arg, arguments.Value(), pass.CreaseColor);
    }
    else if (arg == "--contour-color")
    {
      nprParseColor(arg, arguments.Value(), pass.ContourColor);
    }
    else if (arg == "--no-antialias")
    {
      pass.AntiAliasing = false;
    }
    else if (arg == "--compare-style")
    {
      for (const std::string& part : nprSplitList(arguments.Value()))
      {
        if (std::find(std::begin(Styles), std::end(Styles), part) == std::end(Styles))
        {
          throw nprUsageError("unknown style '" + part + "' for --compare-style");
        }
        options.CompareStyles.push_back(part);
      }
    }
    else if (arg == "--edge-mask")
    {
      options.EdgeMask = arguments.Value();
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
    else if (arg == "--packed-threshold")
    {
      pass.PackedThreshold = nprParseRange(arg, arguments.Value(), 0.001, 4.0);
    }
    else if (arg == "--packed-blur")
    {
      pass.PackedBlur = true;
    }
    else if (arg == "--reference-mask")
    {
      options.ReferenceMask = arguments.Value();
    }
    else if (arg == "--toon-bands")
    {
      pass.ToonBands = nprParseInteger(arg, arguments.Value(), 1, 64);
    }
    else if (arg == "--toon-per-vertex")
    {
      pass.ToonPerVertex = true;
    }
    else if (arg == "--uncertainty")
    {
      pass.Uncertainty = nprParseRange(arg, arguments.Value(), 0.0, 32.0);
    }
    else if (arg == "--noise-seed")
    {
      pass.NoiseSeed = nprParseInteger(arg, arguments.Value(), 0, 2147483647);
    }
    else if (arg == "--noise-space")
    {
      const std::string space = arguments.Value();
      if (space != "surface" && space != "screen")
      {
        throw nprUsageError("--noise-space expects surface or screen, got '" + space + "'");
      }
      pass.NoiseSpace = space == "screen" ? vtkNPRSketchPass::SCREEN : vtkNPRSketchPass::SURFACE;
    }
    else if (arg == "--noise-frequency")
    {
      pass.NoiseFrequency = nprParseRange(arg, arguments.Value(), 0.05, 25.0);
    }
    else if (arg == "--paper-color")
    {
      nprParseColor(arg, arguments.Value(), pass.PaperColor);
      pass.Paper = true;
    }
    else if (arg == "--sketch-toon")
    {
      pass.SketchToon = true;
    }
    else if (arg.size() > 1 && arg[0] == '-')
    {
      throw nprUsageError("unknown option '" + arg + "' (see --help)");
    }
    else
    {
      options.Models.push_back(arg);
    }
  }
  if (options.Models.empty())
  {
    throw nprUsageError("no model file given (see --help)");
  }
  if (!options.CameraIn.empty() && options.CameraMoved)
  {
    throw nprUsageError("--azimuth, --elevation and --zoom move the reset camera; they cannot be "
                        "combined with --camera-in");
  }
  const std::string outputKind = nprOrbitOutputKind(options.Output);
  if (options.Orbit > 0)
  {
    if (options.Output.empty() || outputKind.empty())
    {
      throw nprUsageError("--orbit needs -o NAME.png (numbered frames), NAME.ogv or NAME.mp4");
    }
    if (options.Frames > 0 || !options.EdgeMask.empty() || !options.ReferenceMask.empty())
    {
      throw nprUsageError("--orbit cannot be combined with --frames, --edge-mask or "
                          "--reference-mask");
    }
  }
  else if (outputKind == "ogv" || outputKind == "mp4")
  {
    throw nprUsageError("-o " + options.Output + ": a video needs --orbit N");
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
  if (!options.EdgeMask.empty() && pass.Style != "edges" && pass.Style != "toon+edges" &&
    pass.Style != "inked")
  {
    throw nprUsageError("--edge-mask needs --style edges, toon+edges or inked");
  }
  return options;
}
