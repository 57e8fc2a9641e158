# SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
# SPDX-License-Identifier: BSD-3-Clause
"""Two scenes as scientists build them, in every vtkNPRPass style, headless, tiled into one PNG.

    PYTHONPATH=build/lib/python3/dist-packages /usr/bin/python3 \
        Examples/Python/npr_scientific_scene.py -o scenes.png

Scene 1: an isosurface of VTK's wavelet source inside its vtkOutlineFilter box. Scene 2: a
superquadric with a vtkCubeAxesActor (grid lines and 3D labels). Each is drawn in the styles
shaded, edges, toon, toon+edges, sketch and inked: one row per style, the two scenes side by side.

With --check the script exits 1 when VTK printed any error or warning in any style, or when a
style changed the look of the line props: the outline box alone (1 px, black, on white) must keep,
within 15 %, the number of dark pixels it has in the shaded style (no lines traced around it), and
the white axes, grid lines and 3D labels of scene 2 must keep, within 10 %, their bright pixels
(no lines traced along them, no toon bands, nothing darkened). It runs as a test on every VTK
release.
"""
import argparse
import sys

import vtknpr  # noqa: F401  (first: it imports the VTK modules it needs by itself)
from vtknpr import vtkNPRPass
from vtkmodules.vtkCommonCore import vtkOutputWindow, vtkStringOutputWindow
from vtkmodules.vtkCommonCore import vtkLookupTable
from vtkmodules.vtkFiltersCore import vtkContourFilter
from vtkmodules.vtkFiltersGeometry import vtkImageDataGeometryFilter
from vtkmodules.vtkFiltersSources import vtkSuperquadricSource
from vtkmodules.vtkImagingCore import vtkExtractVOI, vtkRTAnalyticSource
from vtkmodules.vtkRenderingAnnotation import vtkCubeAxesActor, vtkScalarBarActor
from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper, vtkRenderer, vtkTextActor
import vtkmodules.vtkRenderingFreeType  # noqa: F401  (the axes' label text)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (the OpenGL object factory overrides)

from npr_example_common import headless_window, render_in_pass, write_rows

try:  # VTK 9.1 to 9.3 keep it in FiltersModeling; later releases in FiltersCore
    from vtkmodules.vtkFiltersModeling import vtkOutlineFilter
except ImportError:
    from vtkmodules.vtkFiltersCore import vtkOutlineFilter

STYLES = ["shaded", "edges", "toon", "toon+edges", "sketch", "inked"]


def parse_arguments():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("-o", "--output", required=True, help="PNG to write")
    parser.add_argument("--tile", type=int, default=360, metavar="PX",
                        help="width of one tile in pixels; tiles are 4:3 (default 360)")
    parser.add_argument("--check", action="store_true", help="verify the result; exit 1 on failure")
    return parser.parse_args()


def isosurface_scene(with_surface=True, with_data=False):
    """The wavelet's isosurface at 160 (white) inside its outline box (black, 1 px); with_data
    adds the wavelet's values on the box's back face, colour-mapped, a scalar bar and a title
    (add_colour_mapped_data: the scene of Examples/Python/npr_gallery.py)."""
    wavelet = vtkRTAnalyticSource()
    contour = vtkContourFilter()
    contour.SetInputConnection(wavelet.GetOutputPort())
    contour.SetValue(0, 160.0)
    surface = vtkActor()
    surface.SetMapper(vtkPolyDataMapper())
    surface.GetMapper().SetInputConnection(contour.GetOutputPort())
    surface.GetMapper().ScalarVisibilityOff()
    surface.GetProperty().SetColor(0.85, 0.82, 0.75)
    outline = vtkOutlineFilter()
    outline.SetInputConnection(wavelet.GetOutputPort())
    box = vtkActor()
    box.SetMapper(vtkPolyDataMapper())
    box.GetMapper().SetInputConnection(outline.GetOutputPort())
    box.GetProperty().SetColor(0.0, 0.0, 0.0)
    box.GetProperty().SetLineWidth(1.0)
    renderer = vtkRenderer()
    renderer.SetBackground(1.0, 1.0, 1.0)
    if with_surface:
        renderer.AddActor(surface)
    renderer.AddActor(box)
    if with_data:
        add_colour_mapped_data(renderer, wavelet)
    renderer.ResetCamera()
    renderer.GetActiveCamera().Azimuth(30)
    renderer.GetActiveCamera().Elevation(25)
    renderer.ResetCamera()
    return renderer


def add_colour_mapped_data(renderer, wavelet):
    """The wavelet's values on its lowest z slice (the box's back face from the scene's camera),
    blue to red, a scalar bar and a title, in black for the white background (VTK's default text
    is white)."""
    wavelet.Update()
    low, high = wavelet.GetOutput().GetScalarRange()
    face = vtkExtractVOI()
    face.SetInputConnection(wavelet.GetOutputPort())
    x0, x1, y0, y1, z0, _ = wavelet.GetWholeExtent()
    face.SetVOI(x0, x1, y0, y1, z0, z0)
    surface = vtkImageDataGeometryFilter()
    surface.SetInputConnection(face.GetOutputPort())
    colours = vtkLookupTable()
    colours.SetHueRange(0.667, 0.0)  # blue (low) to red (high)
    colours.SetTableRange(low, high)
    colours.Build()
    data = vtkActor()
    data.SetMapper(vtkPolyDataMapper())
    data.GetMapper().SetInputConnection(surface.GetOutputPort())
    data.GetMapper().SetLookupTable(colours)
    data.GetMapper().SetScalarRange(low, high)
    renderer.AddActor(data)
    bar = vtkScalarBarActor()
    bar.SetLookupTable(colours)
    bar.SetTitle("RTData")
    bar.SetNumberOfLabels(3)
    bar.SetPosition(0.84, 0.12)  # the viewport's right edge, as ParaView places it
    bar.SetWidth(0.14)
    bar.SetHeight(0.7)
    for text in (bar.GetTitleTextProperty(), bar.GetLabelTextProperty()):
        text.SetColor(0.0, 0.0, 0.0)
        text.ShadowOff()
    renderer.AddViewProp(bar)
    title = vtkTextActor()
    title.SetInput("Wavelet: isosurface 160")
    title.GetPositionCoordinate().SetCoordinateSystemToNormalizedViewport()
    title.SetPosition(0.02, 0.03)
    title.GetTextProperty().SetColor(0.0, 0.0, 0.0)
    title.GetTextProperty().SetFontSize(14)
    renderer.AddViewProp(title)


def axes_scene():
    """A superquadric inside white cube axes with grid lines, on a dark background."""
    shape = vtkSuperquadricSource()
    shape.SetPhiRoundness(0.3)
    shape.SetThetaRoundness(0.7)
    shape.SetThetaResolution(48)
    shape.SetPhiResolution(48)
    shape.ToroidalOff()
    actor = vtkActor()
    actor.SetMapper(vtkPolyDataMapper())
    actor.GetMapper().SetInputConnection(shape.GetOutputPort())
    actor.GetProperty().SetColor(0.9, 0.55, 0.3)
    renderer = vtkRenderer()
    renderer.SetBackground(0.1, 0.12, 0.18)
    renderer.AddActor(actor)
    axes = vtkCubeAxesActor()
    shape.Update()
    axes.SetBounds(shape.GetOutput().GetBounds())
    axes.SetCamera(renderer.GetActiveCamera())
    axes.DrawXGridlinesOn()
    axes.DrawYGridlinesOn()
    axes.DrawZGridlinesOn()
    axes.SetGridLineLocation(axes.VTK_GRID_LINES_FURTHEST)
    for index in range(3):
        axes.GetTitleTextProperty(index).SetColor(1.0, 1.0, 1.0)
        axes.GetLabelTextProperty(index).SetColor(1.0, 1.0, 1.0)
    for prop in (axes.GetXAxesLinesProperty(), axes.GetYAxesLinesProperty(),
                 axes.GetZAxesLinesProperty(), axes.GetXAxesGridlinesProperty(),
                 axes.GetYAxesGridlinesProperty(), axes.GetZAxesGridlinesProperty()):
        prop.SetColor(1.0, 1.0, 1.0)
    renderer.AddActor(axes)
    renderer.ResetCamera()
    renderer.GetActiveCamera().Azimuth(35)
    renderer.GetActiveCamera().Elevation(25)
    renderer.GetActiveCamera().Zoom(0.8)
    renderer.ResetCameraClippingRange()
    return renderer


def render(window, renderer, style):
    """The renderer's image in a style (vtkImageData, RGB)."""
    npr = vtkNPRPass()
    npr.SetStyle(vtkNPRPass.GetStyleFromName(style))
    return render_in_pass(window, renderer, npr)


def count(image, test):
    """Pixels whose (r, g, b) satisfy test."""
    scalars = image.GetPointData().GetScalars()
    return sum(1 for i in range(scalars.GetNumberOfTuples()) if test(scalars.GetTuple3(i)))


def main():
    args = parse_arguments()
    messages = vtkStringOutputWindow()
    vtkOutputWindow.SetInstance(messages)
    window = headless_window(args.tile, args.tile * 3 // 4, "npr_scientific_scene")

    rows = []
    black, bright = {}, {}
    for style in STYLES:
        iso = render(window, isosurface_scene(), style)
        axes = render(window, axes_scene(), style)
        # The outline alone, for its width: every style must draw it as VTK does.
        black[style] = count(render(window, isosurface_scene(False), style), lambda p: max(p) < 100)
        bright[style] = count(axes, lambda p: min(p) > 200)
        rows.append([iso, axes])
    write_rows(rows, args.output)
    vtkOutputWindow.SetInstance(None)
    print("npr_scientific_scene: wrote %s (%d styles x 2 scenes)" % (args.output, len(STYLES)))

    if not args.check:
        return 0
    failures = []
    printed = messages.GetOutput().strip()
    if printed:
        failures.append("VTK printed: " + printed)
    for style in STYLES:
        # Dark pixels of the outline alone (its width); bright pixels of scene 2: the grid lines,
        # axes and labels, white on a dark background.
        print("%-10s outline pixels %6d, bright pixels %6d" % (style, black[style], bright[style]))
        if not 0.85 * black["shaded"] <= black[style] <= 1.15 * black["shaded"]:
            failures.append("%s: the outline has %d dark pixels, shaded %d"
                            % (style, black[style], black["shaded"]))
        if not 0.9 * bright["shaded"] <= bright[style] <= 1.1 * bright["shaded"]:
            failures.append("%s: the axes have %d bright pixels, shaded %d"
                            % (style, bright[style], bright["shaded"]))
    if black["shaded"] < 100 or bright["shaded"] < 500:
        failures.append("shaded: too few outline (%d) or axes (%d) pixels"
                        % (black["shaded"], bright["shaded"]))
    for failure in failures:
        print("FAILED: " + failure)
    print("%d passed, %d failed" % (1 if not failures else 0, 1 if failures else 0))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
