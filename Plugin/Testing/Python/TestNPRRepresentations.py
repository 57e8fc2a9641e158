# SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
# SPDX-License-Identifier: BSD-3-Clause
"""pvbatch test of ParaView's representations in every style of "Render View (NPR)": Surface With
Edges, Points, Point Gaussian with opacity by array, Wireframe, Feature Edges, Slice, Volume, a
translucent surface and a selection. Each case is rendered in every style and checked by what
that representation must still show: its own colour (the mesh edges, the points, the selection
highlight), the red object behind it (translucency), or its pixels at all (slice, volume), and
no error or warning from VTK or ParaView; and the names ParaView registers the view under.
Fails by exception (pvbatch then exits non-zero).

  pvbatch TestNPRRepresentations.py --plugin NPRView.so --output-dir DIR
"""
import os
import sys

from paraview.simple import *  # noqa: F401,F403
from vtkmodules.vtkCommonCore import vtkOutputWindow, vtkStringOutputWindow

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from nprviewscene import STYLES, create_view, plugin_arguments, read_png  # noqa: E402

args = plugin_arguments()
LoadPlugin(args.plugin, ns=globals())
SIZE = [320, 240]

# VTK's and ParaView's messages while a case renders. Only then: pvbatch prints the script's own
# output and tracebacks through the output window too.
messages = [vtkStringOutputWindow()]  # a new one for each case
console = vtkOutputWindow.GetInstance()

view = create_view(SIZE)


def colour_pixels(img, rgb, tolerance=60):
    """Pixels within tolerance of rgb (0..255) in every channel."""
    return int((abs(img - rgb).max(axis=2) <= tolerance).sum())


def redder_than_shaded(img):
    """Pixels where the red object shows (red clearly above green and blue)."""
    return int(((img[..., 0] - img[..., 1:].max(axis=2)) > 60).sum())


def solid(source, colour, representation="Surface"):
    display = Show(source, view)
    ColorBy(display, ("POINTS", None))
    display.SetRepresentationType(representation)
    display.DiffuseColor = colour
    display.AmbientColor = colour
    return display


def red_box_behind():
    solid(Box(XLength=3, YLength=3, ZLength=0.2, Center=[0, 0, -1.5]), [1, 0, 0])


def case_surface_with_edges():
    display = solid(Sphere(ThetaResolution=16, PhiResolution=12), [0.8, 0.8, 0.8],
                    "Surface With Edges")
    display.EdgeColor = [1, 0, 0]
    return lambda img, style: ("red mesh edges", colour_pixels(img, [255, 0, 0], 90), 150)


def case_points():
    display = solid(Sphere(ThetaResolution=24, PhiResolution=16), [0, 0, 1], "Points")
    display.PointSize = 4
    return lambda img, style: ("blue points", colour_pixels(img, [0, 0, 255], 90), 300)


def case_point_gaussian():
    red_box_behind()
    points = Sphere(ThetaResolution=24, PhiResolution=16, Radius=0.8)
    elevation = Elevation(Input=points, LowPoint=[0, -1, 0], HighPoint=[0, 1, 0])
    display = Show(elevation, view)
    display.SetRepresentationType("Point Gaussian")
    ColorBy(display, ("POINTS", None))
    display.DiffuseColor = [0, 0, 1]
    display.GaussianRadius = 0.12
    display.OpacityByArray = 1
    display.OpacityArray = ["POINTS", "Elevation"]
    display.OpacityTransferFunction.Points = [0, 0.15, 0.5, 0, 1, 0.15, 0.5, 0]
    return lambda img, style: ("red box seen through the splats", redder_than_shaded(img), None)


def case_wireframe():
    solid(Sphere(ThetaResolution=16, PhiResolution=12), [0, 0.6, 0], "Wireframe")
    return lambda img, style: ("green wireframe", colour_pixels(img, [0, 153, 0], 80), 300)


def case_feature_edges():
    solid(Box(XLength=1.5, YLength=1, ZLength=1), [0, 0.6, 0], "Feature Edges")
    return lambda img, style: ("green feature edges", colour_pixels(img, [0, 153, 0], 80), 150)


def case_slice():
    display = Show(Wavelet(), view)
    display.SetRepresentationType("Slice")
    ColorBy(display, ("POINTS", "RTData"))
    return lambda img, style: ("coloured slice", int((abs(img - 255).max(axis=2) > 40).sum()),
                               5000)


def case_volume():
    display = Show(Wavelet(), view)
    display.SetRepresentationType("Volume")
    ColorBy(display, ("POINTS", "RTData"))
    return lambda img, style: ("volume", int((abs(img - 255).max(axis=2) > 20).sum()), 5000)


def case_translucent():
    red_box_behind()
    display = solid(Sphere(ThetaResolution=32, PhiResolution=24, Radius=0.9), [0.2, 0.4, 1])
    display.Opacity = 0.4
    return lambda img, style: ("red box seen through the surface", redder_than_shaded(img), None)


def case_selection():
    sphere = Sphere(ThetaResolution=16, PhiResolution=12)
    solid(sphere, [0.8, 0.8, 0.8])
    SetActiveSource(sphere)
    SelectIDs(IDs=sum([[0, cell] for cell in range(60)], []), FieldType="CELL", Source=sphere)
    selection = GetDisplayProperties(sphere, view)
    colour = [1.0, 0.0, 1.0]
    if hasattr(selection, "SelectionColor"):
        selection.SelectionColor = colour
    # Half of what the shaded view shows (the styles' own lines cover some), 300 in the sketch
    # (its displaced depth sprite hides part of it: Documentation/toon-sketch.md). The inked style
    # showed it only at the outline before it drew such frames in three steps.
    return lambda img, style: ("magenta selection", colour_pixels(img, [255, 0, 255], 90),
                               300 if style == "Sketch" else None)


CASES = [case_surface_with_edges, case_points, case_point_gaussian, case_wireframe,
         case_feature_edges, case_slice, case_volume, case_translucent, case_selection]
failures = []
# The drawing style paints faces white and draws the meshes' lines (Documentation/drawing.md):
# the colours these cases check are not part of it.
DRAWING_WHITE = {"point_gaussian": "the red box behind the splats is white too",
                 "slice": "an image slice has no mesh lines to draw",
                 "translucent": "the red box behind the surface is white too"}


def check(condition, message):
    print(("ok    " if condition else "FAIL  ") + message)
    if not condition:
        failures.append(message)


def clear_view():
    for source in list(GetSources().values()):
        ClearSelection(source)
    for source in list(GetSources().values()):
        Delete(source)


def render(name, style):
    view.Style = STYLES.index(style)
    path = os.path.join(args.output_dir, "%s-%s.png" % (name, style.lower().replace("+", "-")))
    vtkOutputWindow.SetInstance(messages[0])
    try:
        Render(view)
        SaveScreenshot(path, view, ImageResolution=SIZE)
    finally:
        vtkOutputWindow.SetInstance(console)
    return read_png(path)


for make_case in CASES:
    name = make_case.__name__[len("case_"):]
    measure = make_case()
    view.ResetCamera()
    messages[0] = vtkStringOutputWindow()
    shaded = None
    for style in STYLES:
        img = render(name, style)
        if style == "Drawing" and name in DRAWING_WHITE:
            print("skip  %s, Drawing: the drawing paints every face white (%s)"
                  % (name, DRAWING_WHITE[name]))
            continue
        what, value, minimum = measure(img, style)
        if style == "Shaded":
            shaded = value
        bound = minimum if minimum is not None else max(1, shaded // 2)
        check(value >= bound, "%s, %s: %d pixels of the %s (at least %d; Shaded %d)"
              % (name, style, value, what, bound, shaded))
    log = messages[0].GetOutput()
    check("ERROR" not in log.upper() and "WARNING" not in log.upper(),
          "%s: no error or warning in any style%s" % (name, "" if not log else ": " + log[:400]))
    clear_view()

# The names scripts find views by (Documentation/paraview.md, "Scripts, traces and saved states").
check(FindView("RenderViewNPR1") == view, "the first NPR view is registered as RenderViewNPR1")
named = CreateView("NPRRenderView", registrationName="RenderView1")
check(FindView("RenderView1") == named, "an NPR view created as RenderView1 is found by that name")

if failures:
    raise RuntimeError("%d checks failed: %s" % (len(failures), "; ".join(failures)))
print("all %d cases passed in every style" % len(CASES))
