# SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
# SPDX-License-Identifier: BSD-3-Clause
"""Stream tubes coloured by a scalar in the line styles: the lines keep the colours visible.

    PYTHONPATH=build/lib/python3/dist-packages /usr/bin/python3 \\
        Examples/Python/npr_stream_tubes.py -o tubes.png

Two scenes as flow visualisations build them: a few stream tubes a few pixels wide seeded along a
line (as VTK's OfficeTube example), and a crowd of them seeded in a ball (as ParaView's
disk_out_ref stream tubes), coloured by a pressure-like scalar. Each is drawn shaded; in the edges
style with the default settings; with vtkNPREdgePass's MaximumLineFraction at 0.1 (each line at
most a tenth of the width of the tube it lies on); with that and SurfaceLineShade at 0.5 (the
lines in a darker shade of the tube's own colour); and in the toon+edges and sketch styles with
both: one row each.

With --check the script exits 1 unless:
- with both settings, in every line style and both scenes, at most 10 % of the tubes' pixels turn
  near-black (every channel under 64) that are not near-black in the shaded image;
- with the width limit alone, less than 0.2 times as many of the few tubes' pixels do as with
  the default settings, and less than 0.6 times as many in the crowd;
- with the default settings more than 40 % of the few tubes' pixels do (what the settings mend);
- the lines stay: with both settings, at least a third as many pixels are darkened by a tenth or
  more as with the default settings.
It runs as a test on every VTK release.
"""
import argparse
import math
import sys

import vtknpr  # noqa: F401  (first: it imports the VTK modules it needs by itself)
from vtknpr import vtkNPRPass
from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkImageData, vtkPolyData
from vtkmodules.vtkFiltersCore import vtkTubeFilter
from vtkmodules.vtkFiltersFlowPaths import vtkStreamTracer
from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper, vtkRenderer
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (the OpenGL object factory overrides)

from npr_example_common import headless_window, render_in_pass, write_rows

# The settings that keep the data visible: vtkNPREdgePass's MaximumLineFraction and
# SurfaceLineShade.
LIMIT = 0.1
SHADE = 0.5
# (style, MaximumLineFraction, SurfaceLineShade), one row each
RENDERINGS = [("shaded", 0.0, 0.0), ("edges", 0.0, 0.0), ("edges", LIMIT, 0.0),
              ("edges", LIMIT, SHADE), ("toon+edges", LIMIT, SHADE), ("sketch", LIMIT, SHADE)]
NEAR_BLACK = 64  # every channel below this


def parse_arguments():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("-o", "--output", required=True, help="PNG to write")
    parser.add_argument("--size", default="640x480", help="size of one tile (default 640x480)")
    parser.add_argument("--check", action="store_true", help="verify the result; exit 1 on failure")
    return parser.parse_args()


def swirl():
    """A vortex on a 41^3 grid: vectors 'velocity' and a scalar 'pressure'. (Computed here, not by
    vtkArrayCalculator: its expression parser throws C++ exceptions internally, which a Python
    under AddressSanitizer cannot take.)"""
    grid = vtkImageData()
    grid.SetDimensions(41, 41, 41)
    grid.SetOrigin(-1, -1, -1)
    grid.SetSpacing(0.05, 0.05, 0.05)
    velocity = vtkDoubleArray()
    velocity.SetName("velocity")
    velocity.SetNumberOfComponents(3)
    velocity.SetNumberOfTuples(grid.GetNumberOfPoints())
    pressure = vtkDoubleArray()
    pressure.SetName("pressure")
    pressure.SetNumberOfTuples(grid.GetNumberOfPoints())
    for i in range(grid.GetNumberOfPoints()):
        x, y, z = grid.GetPoint(i)
        velocity.SetTuple3(i, -y + 0.3 * x * z, x + 0.3 * y * z, 0.4 - 0.5 * (x * x + y * y))
        pressure.SetValue(i, x * x + y * y - z)
    grid.GetPointData().AddArray(velocity)
    grid.GetPointData().AddArray(pressure)
    return grid


def stream_tubes(crowd):
    """A renderer with the stream tubes: a few along a line, or a crowd from a ball of seeds."""
    seeds = vtkPolyData()
    seeds.SetPoints(vtkPoints())
    if crowd:
        # 80 points spread evenly through a ball (a golden-angle spiral, radii by cube root).
        for i in range(80):
            t = (i + 0.5) / 80.0
            r = 0.7 * t ** (1.0 / 3.0)
            z = 1.0 - 2.0 * ((i * 0.618034) % 1.0)
            ring = math.sqrt(max(0.0, 1.0 - z * z))
            angle = 2.399963 * i
            seeds.GetPoints().InsertNextPoint(
                r * ring * math.cos(angle), r * ring * math.sin(angle), -0.5 + r * z)
        radius = 0.02
    else:
        for i in range(9):
            t = i / 8.0
            seeds.GetPoints().InsertNextPoint(0.1 + 0.7 * t, -0.8 + 0.9 * t, -0.6)
        radius = 0.012
    tracer = vtkStreamTracer()
    tracer.SetInputData(swirl())
    tracer.SetSourceData(seeds)
    tracer.SetInputArrayToProcess(0, 0, 0, 0, "velocity")
    tracer.SetMaximumPropagation(8)
    tracer.SetIntegrationDirectionToBoth()
    tubes = vtkTubeFilter()
    tubes.SetInputConnection(tracer.GetOutputPort())
    tubes.SetRadius(radius)
    tubes.SetNumberOfSides(8)
    tubes.Update()
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(tubes.GetOutputPort())
    mapper.SetScalarModeToUsePointFieldData()
    mapper.SelectColorArray("pressure")
    mapper.SetScalarRange(tubes.GetOutput().GetPointData().GetArray("pressure").GetRange())
    actor = vtkActor()
    actor.SetMapper(mapper)
    renderer = vtkRenderer()
    renderer.SetBackground(1, 1, 1)
    renderer.AddActor(actor)
    renderer.ResetCamera()
    renderer.GetActiveCamera().Elevation(-50)
    renderer.ResetCamera()
    return renderer


def render(window, renderer, style, fraction=0.0, shade=0.0):
    """The renderer's image in a style (vtkImageData, RGB)."""
    npr = vtkNPRPass()
    npr.SetStyle(vtkNPRPass.GetStyleFromName(style))
    npr.GetEdgePass().SetMaximumLineFraction(fraction)
    npr.GetEdgePass().SetSurfaceLineShade(shade)
    return render_in_pass(window, renderer, npr)


def line_pixels(shaded, styled):
    """(tube pixels, those near-black in styled but not in shaded, those darker in styled by a
    tenth or more of their brightest channel: the lines drawn over the tubes). Tube pixels are those
    not white in the shaded image."""
    before = bytes(memoryview(shaded.GetPointData().GetScalars()))
    after = bytes(memoryview(styled.GetPointData().GetScalars()))
    tube = turned = darker = 0
    for i in range(0, len(before), 3):
        pixel = before[i:i + 3]
        if pixel == b"\xff\xff\xff":
            continue
        tube += 1
        brightest, now = max(pixel), max(after[i:i + 3])
        if now < NEAR_BLACK <= brightest:
            turned += 1
        if now < 0.9 * brightest:
            darker += 1
    return tube, turned, darker


def main():
    args = parse_arguments()
    width, height = (int(v) for v in args.size.split("x"))
    window = headless_window(width, height, "npr_stream_tubes")
    shares = {}
    scenes = {"few": stream_tubes(False), "crowd": stream_tubes(True)}
    rows = []
    for setting in RENDERINGS:
        rows.append([])
        for scene, renderer in scenes.items():
            image = render(window, renderer, *setting)
            shaded = render(window, renderer, "shaded")
            shares[setting + (scene,)] = line_pixels(shaded, image)
            rows[-1].append(image)
    write_rows(rows, args.output)
    print("npr_stream_tubes: wrote %s (%d renderings x 2 scenes)" % (args.output, len(RENDERINGS)))
    return check(shares) if args.check else 0


def check(shares):
    """Exit status of --check: 0, or 1 with the failures printed."""
    def share(style, fraction, shade, scene):
        tube, turned, _ = shares[(style, fraction, shade, scene)]
        return turned / max(tube, 1)

    failures = []
    for (style, fraction, shade, scene), (tube, turned, darker) in shares.items():
        name = "%s, limit %g, shade %g" % (style, fraction, shade)
        print("%-30s %-5s tube pixels %7d, newly near-black %5.1f %%, darkened %6d"
              % (name, scene, tube, 100.0 * turned / max(tube, 1), darker))
        if tube < 2000:
            failures.append("%s %s: only %d tube pixels" % (name, scene, tube))
        if fraction and shade and turned > 0.10 * tube:
            failures.append("%s %s: %.1f %% of the tube pixels turn near-black (at most 10 %%)"
                            % (name, scene, 100.0 * turned / tube))
    for scene, ratio in (("few", 0.2), ("crowd", 0.6)):
        if share("edges", LIMIT, 0.0, scene) >= ratio * share("edges", 0.0, 0.0, scene):
            failures.append("%s: the width limit alone should leave less than %g times the "
                            "near-black pixels of the default settings" % (scene, ratio))
    if share("edges", 0.0, 0.0, "few") <= 0.40:
        failures.append("few: the default settings leave only %.1f %% near-black: the scene no "
                        "longer shows the problem" % (100.0 * share("edges", 0.0, 0.0, "few")))
    for scene in scenes_of(shares):
        kept = shares[("edges", LIMIT, SHADE, scene)][2]
        before = shares[("edges", 0.0, 0.0, scene)][2]
        if 3 * kept < before:
            failures.append("%s: with both settings %d pixels show lines, with the defaults %d: "
                            "the lines must stay" % (scene, kept, before))
    for failure in failures:
        print("npr_stream_tubes: FAILED: " + failure)
    return 1 if failures else 0


def scenes_of(shares):
    return sorted(set(key[-1] for key in shares))


if __name__ == "__main__":
    sys.exit(main())
