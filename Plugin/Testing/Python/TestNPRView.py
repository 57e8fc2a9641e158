# SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
# SPDX-License-Identifier: BSD-3-Clause
"""pvbatch test of the NPR plugin: load it, create "Render View (NPR)", show CAD-like sources and
a contour of the Wavelet source, render every style, check pixels numerically and compare with
the committed baselines. Fails by exception (pvbatch then exits non-zero).

  pvbatch TestNPRView.py --plugin NPRView.so --output-dir DIR [--baseline-dir DIR] [--mpi]

Serial: each style with the full G-buffer (baseline <style>.png), and the line styles with
ForceDepthOnly (baseline <style>-depth.png). With --mpi (mpiexec -n 2): the images come from IceT's
composited depth and must match the serial depth-only baselines within MPI_TOLERANCE.
"""
import os
import re
import sys

from paraview.simple import *  # noqa: F401,F403
from paraview import servermanager

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from nprviewscene import SIZE, STYLES, create_scene, dark, plugin_arguments, read_png  # noqa: E402

args = plugin_arguments(("--baseline-dir", {}), ("--mpi", {"action": "store_true"}),
                        ("--make-baselines", {"action": "store_true"}))

# Regression threshold of vtkTesting (as VTK's image tests) for baselines made on Mesa llvmpipe.
THRESHOLD = 10
# The parallel images against the serial depth-only ones: at most this fraction of pixels may
# differ by more than 48 (of 255) in a channel. IceT's composited depth equals the serial depth
# except for rounding, so only a few line pixels along grazing surfaces may flip.
MPI_TOLERANCE = 0.002

LoadPlugin(args.plugin, ns=globals())
pm = servermanager.vtkProcessModule.GetProcessModule()
ranks = pm.GetNumberOfLocalPartitions()
if args.mpi and ranks < 2:
    raise RuntimeError("--mpi given but running on %d rank(s)" % ranks)

view, sources = create_scene()
box, cylinder, contour = sources["box"], sources["cylinder"], sources["contour"]

LINE_STYLES = ["Edges", "Toon+Edges", "Sketch"]


def render(style, depth_only, suffix=""):
    view.Style = STYLES.index(style)
    view.ForceDepthOnly = 1 if depth_only else 0
    Render(view)
    name = style.lower().replace("+", "-") + ("-depth" if depth_only else "") + suffix
    path = os.path.join(args.output_dir, name + ".png")
    SaveScreenshot(path, view, ImageResolution=SIZE)
    return name, path, read_png(path)


failures = []


def check(condition, message):
    print(("ok    " if condition else "FAIL  ") + message)
    if not condition:
        failures.append(message)


def compare_baseline(name, path):
    if not args.baseline_dir:
        return
    base = os.path.join(args.baseline_dir, name + ".png")
    if not os.path.exists(base):
        check(args.make_baselines, "baseline %s exists" % base)
        return
    from vtkmodules.vtkTestingRendering import vtkTesting
    testing = vtkTesting()
    for a in ("-V", base, "-T", args.output_dir):
        testing.AddArgument(a)
    check(testing.RegressionTest(path, THRESHOLD) == vtkTesting.PASSED,
          "%s matches its baseline" % name)


if not args.mpi:
    images = {}
    for style in STYLES:
        name, path, img = render(style, False)
        images[style] = img
        compare_baseline(name, path)
    shaded = images["Shaded"]
    covered = int((shaded.sum(axis=2) < 760).sum())
    print("covered pixels", covered, "dark pixels:", {s: dark(i) for s, i in images.items()})
    check(covered > 20000, "the scene covers the view")
    check(dark(images["Edges"]) > dark(shaded) + 3000, "edges draws lines")
    check(dark(images["Toon+Edges"]) > dark(images["Toon"]) + 1500, "toon+edges draws lines")
    check(dark(images["Inked"]) > dark(shaded) + 1500, "inked draws outlines")
    check(dark(images["Sketch"]) > dark(shaded) + 1500, "sketch draws lines")
    mask = shaded.sum(axis=2) < 760

    def levels(img):
        return len(set(map(tuple, img[mask].reshape(-1, 3) // 4)))
    check(levels(images["Toon"]) < 0.7 * levels(shaded),
          "toon has fewer shades than shaded (%d < %d)" % (levels(images["Toon"]), levels(shaded)))
    check(int((abs(images["Sketch"] - images["Edges"]).sum(axis=2) > 60).sum()) > 2000,
          "sketch differs from edges")
    # Drawing: white faces and the meshes' own lines; hidden lines, in grey, on request.
    def grey(img):
        mean = img.sum(axis=2) / 3.0
        return int(((mean > 80) & (mean < 200) & (img.max(axis=2) - img.min(axis=2) < 8)).sum())
    drawing = images["Drawing"]
    view.DrawingHiddenLines = 1
    _, _, hidden = render("Drawing", False, "-hidden")
    view.DrawingHiddenLines = 0
    white = float((drawing[mask].min(axis=1) >= 250).mean())
    print("drawing: %.3f of the covered pixels white, %d dark; grey pixels %d, with hidden lines %d"
          % (white, dark(drawing), grey(drawing), grey(hidden)))
    shaded_white = float((shaded[mask].min(axis=1) >= 250).mean())
    check(white > 0.5 and shaded_white < 0.1,
          "drawing: the faces are white (%.3f, shaded %.3f)" % (white, shaded_white))
    check(dark(drawing) > 1500, "drawing draws lines")
    check(grey(hidden) > grey(drawing) + 500, "drawing: hidden lines appear in grey")
    # Suggestive contours in red (their own colour) on the edges style; smooth silhouettes and
    # creases from the face normals are accepted and still draw lines.
    view.SuggestiveContours = 1
    view.SuggestiveContourColor = [1, 0, 0]
    view.SuggestiveContourThreshold = 0.001  # the wavelet's isosurface has shallow valleys
    _, _, suggestive = render("Edges", False, "-suggestive")
    view.SuggestiveContours = 0
    view.SuggestiveContourThreshold = 0.01
    red = int(((suggestive[:, :, 0] > 150) & (suggestive[:, :, 1] < 80)).sum())
    print("suggestive contours: %d red pixels" % red)
    check(red > 20, "the view draws suggestive contours in their colour")
    view.SmoothSilhouettes = 1
    view.FaceCreases = 1
    _, _, options = render("Edges", False, "-smooth")
    view.SmoothSilhouettes = 0
    view.FaceCreases = 0
    check(dark(options) > dark(shaded) + 3000, "edges with smooth silhouettes draws lines")
    # The view's lines as a vector file (vtkNPRDrawingExporter through the view's command).
    svg = os.path.join(args.output_dir, "drawing.svg")
    if os.path.exists(svg):
        os.remove(svg)
    view.Style = STYLES.index("Drawing")
    view.DrawingHiddenLines = 1
    view.DrawingFileName = svg
    view.SMProxy.UpdateVTKObjects()
    view.SMProxy.InvokeCommand("ExportDrawing")
    view.DrawingHiddenLines = 0
    text = open(svg).read() if os.path.exists(svg) else ""
    print("drawing.svg: %d bytes, %d paths" % (len(text), text.count("<path")))
    check(text.count("<path") > 20 and '<g class="npr-hidden">' in text and
          '<g class="npr-silhouette">' in text and "<image" not in text,
          "ExportDrawing writes the SVG with its groups, hidden lines and no raster")
    # With DrawingFillFaces: the faces as filled paths under the same strokes.
    view.DrawingFillFaces = 1
    view.SMProxy.UpdateVTKObjects()
    view.SMProxy.InvokeCommand("ExportDrawing")
    view.DrawingFillFaces = 0
    filled = open(svg).read() if os.path.exists(svg) else ""
    print("drawing.svg with faces: %d paths" % filled.count("<path"))
    white = re.findall(r'fill(?::|=")rgb\(100%, ?100%, ?100%\)', filled)  # Cairo 1.16, 1.18
    check(len(white) > 10 and '<g class="npr-silhouette">' in filled,
          "ExportDrawing with DrawingFillFaces writes white filled faces under the strokes")
    # Lines from depth only (what MPI gives): silhouettes and creases remain.
    for style in LINE_STYLES:
        name, path, img = render(style, True)
        compare_baseline(name, path)
        if style == "Edges":
            check(dark(img) > dark(shaded) + 2000, "depth-only edges draws lines")
else:
    for style in LINE_STYLES:
        name, path, img = render(style, False)
        if pm.GetPartitionId() != 0:
            continue
        base = os.path.join(args.baseline_dir, name + "-depth.png")
        ref = read_png(base)
        differing = float((abs(img - ref).max(axis=2) > 48).mean())
        print("%s: %.5f of the pixels differ from the serial depth-only image (dark %d vs %d)"
              % (style, differing, dark(img), dark(ref)))
        check(differing <= MPI_TOLERANCE, "%s under MPI matches the serial depth-only image" % style)
        if style == "Edges":
            edges_mpi, edges_serial = img, ref
    # Toon shading is applied to each rank's piece inside IceT: as in one process.
    name, path, img = render("Toon", False)
    if pm.GetPartitionId() == 0:
        ref = read_png(os.path.join(args.baseline_dir, "toon.png"))
        differing = float((abs(img - ref).max(axis=2) > 48).mean())
        print("Toon: %.5f of the pixels differ from the serial image" % differing)
        check(differing <= MPI_TOLERANCE, "Toon under MPI matches the serial image")
    for style in ("Shaded", "Inked"):
        render(style, False)

    # Where the ranks' pieces of the contour meet on screen: the contour coloured flat by rank.
    # ParaView 5.12 replaced ProcessIdScalars (removed in 5.14) by ProcessIds.
    if "ProcessIds" in globals():
        ranks_source, ranks_array = ProcessIds(Input=contour), "PointProcessIds"
    else:
        ranks_source, ranks_array = ProcessIdScalars(Input=contour), "ProcessId"
    camera = [list(view.CameraPosition), list(view.CameraFocalPoint), list(view.CameraViewUp),
              view.CameraViewAngle]
    for source in (box, cylinder, contour):
        Hide(source, view)
    ranks_display = Show(ranks_source, view)
    # Show() may reset the camera: the border must be found in the edges images' view.
    view.CameraPosition, view.CameraFocalPoint, view.CameraViewUp, view.CameraViewAngle = camera
    ColorBy(ranks_display, ("POINTS", ranks_array))
    ranks_lut = GetColorTransferFunction(ranks_array)
    ranks_lut.RGBPoints = [0.0, 1.0, 0.0, 0.0, 1.0, 0.0, 0.0, 1.0]
    ranks_lut.AutomaticRescaleRangeMode = "Never"
    ranks_lut.RescaleTransferFunction(0.0, 1.0)
    ranks_display.Ambient = 1.0
    ranks_display.Diffuse = 0.0
    ranks_display.Specular = 0.0
    _, _, ranks_img = render("Shaded", False)
    if pm.GetPartitionId() == 0:
        import numpy as np
        covered = ranks_img.sum(axis=2) < 700
        rank = ranks_img[..., 0] > ranks_img[..., 2]
        border = np.zeros(covered.shape, bool)
        for axis in (0, 1):
            a = [slice(None)] * 2
            b = [slice(None)] * 2
            a[axis], b[axis] = slice(1, None), slice(None, -1)
            meet = covered[tuple(a)] & covered[tuple(b)] & (rank[tuple(a)] != rank[tuple(b)])
            border[tuple(a)] |= meet
            border[tuple(b)] |= meet

        def grow(mask, r):
            out = mask.copy()
            for dy in range(-r, r + 1):
                for dx in range(-r, r + 1):
                    out |= np.roll(np.roll(mask, dy, axis=0), dx, axis=1)
            return out
        near_border = grow(border, 3)
        line_mpi = edges_mpi.sum(axis=2) < 150
        line_serial = grow(edges_serial.sum(axis=2) < 150, 1)
        extra = int((line_mpi & ~line_serial & near_border).sum())
        print("rank border: %d pixels; line pixels within 3 px of it: %d under MPI, %d of them "
              "not on a serial line" % (int(border.sum()), int((line_mpi & near_border).sum()), extra))
        check(border.sum() > 100, "the ranks' pieces meet in the view (%d border pixels)" % border.sum())
        check(extra <= 0.02 * border.sum(), "no lines along the border between the ranks' pieces")

if failures:
    raise RuntimeError("FAIL: " + "; ".join(failures))
print("PASS")
