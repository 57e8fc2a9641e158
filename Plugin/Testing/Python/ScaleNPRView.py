# SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
# SPDX-License-Identifier: BSD-3-Clause
"""pvbatch benchmark of the NPR view at scale: a contour of a large Wavelet source shown at
1920x1080 in ParaView's plain Render View (the baseline, before and after), and in every style of
the NPR view. Prints, and with --output writes, a table: per view and style the first frame
after switching to it, the mean of the later frames (the camera turned 1 degree a frame), and
every rank's peak and current resident memory; also the triangle count (summed over the ranks)
and the time of the source and of the contour. Meant for mpiexec -n 2 (any number of ranks works).

  mpiexec -n 2 pvbatch --force-offscreen-rendering ScaleNPRView.py --plugin NPRView.so
      [--size small|full | --extent N] [--iso V] [--view-size WxH] [--frames N]
      [--output DIR [--check]]

--size full (--extent 544) gives 20.1M triangles at the default iso value; small (the default,
--extent 24) 39K. --check fails (non-zero exit) unless the contour has triangles, the table has a
row per view and rank with every rank's memory, every image is drawn, the line styles draw lines,
Shaded matches the plain view and the other styles differ from it. No timing decides anything.
"""
import argparse
import builtins
import csv
import json
import math
import os
import sys
import time

from paraview.simple import *  # noqa: F401,F403
from paraview import servermanager

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from nprviewscene import STYLES, dark, read_png  # noqa: E402

# Half-widths of the Wavelet's WholeExtent ([-N, N] on each axis). At iso 157 the contour has
# about 68 N^2 triangles (measured at N = 10 to 80 with ParaView 5.11); 544 gives 20.0M.
SIZES = {"small": 24, "full": 544}
PLAIN, PLAIN_AGAIN = "Render View", "Render View again"


def positive_int(text):
    try:
        value = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError("not an integer: %r" % text)
    if value < 1:
        raise argparse.ArgumentTypeError("must be at least 1: %r" % text)
    return value


ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
ap.add_argument("--plugin", required=True, help="the plugin, NPRView.so")
group = ap.add_mutually_exclusive_group()
group.add_argument("--size", choices=sorted(SIZES), help="small (smoke test) or full (20M)")
group.add_argument("--extent", type=positive_int, metavar="N",
                   help="the Wavelet's WholeExtent is [-N, N] on each axis")
ap.add_argument("--iso", type=float, default=157.0, help="the contour's value of RTData")
ap.add_argument("--view-size", default="1920x1080", metavar="WxH", help="default 1920x1080")
ap.add_argument("--frames", type=positive_int, default=10,
                help="later frames timed per view and style (default 10)")
ap.add_argument("--output", metavar="DIR", help="write scale.json, scale.csv and a PNG per style")
ap.add_argument("--check", action="store_true", help="assert the images and the table")
args = ap.parse_args()
extent = args.extent or SIZES[args.size or "small"]
try:
    VIEW_SIZE = [int(v) for v in args.view_size.lower().split("x")]
    if len(VIEW_SIZE) != 2 or builtins.min(VIEW_SIZE) < 16:
        raise ValueError
except ValueError:
    ap.error("--view-size: expected WxH of at least 16x16, got %r" % args.view_size)
if args.check and not args.output:
    ap.error("--check needs --output (it checks the files written)")
if not os.path.isfile(args.plugin):
    ap.error("--plugin: no such file: %s" % args.plugin)
if args.output:
    os.makedirs(args.output, exist_ok=True)

LoadPlugin(args.plugin, ns=globals())
ranks = servermanager.vtkProcessModule.GetProcessModule().GetNumberOfLocalPartitions()

# Memory per rank. In pvbatch only rank 0 runs this script; the others serve its pipeline. A
# Programmable Source runs on every rank, so each rank reads its own /proc/self/status there
# (VmHWM, the peak resident set, and VmRSS, the current one) into a one-point polydata, and
# Fetch appends the ranks' points on rank 0. This needs no MPI in Python, no --symmetric and no
# guess at the other processes' ids, and works whatever launches the ranks and on several hosts.
# With reset, each rank first writes 5 to /proc/self/clear_refs (Linux 4.0 and later), which
# sets its peak to its current resident set, so that a row's peak is the peak while that view or
# style rendered; where the write is refused the peaks are those since the process started
# (the table's peak_reset column says which).
MEMORY_SCRIPT = """
from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray
from vtkmodules.vtkParallelCore import vtkMultiProcessController
reset = 0.0
if RESET:
    try:
        with open("/proc/self/clear_refs", "w") as f:
            f.write("5")
        reset = 1.0
    except OSError:
        pass
kb = {}
with open("/proc/self/status") as f:
    for line in f:
        key, _, value = line.partition(":")
        if key in ("VmHWM", "VmRSS"):
            kb[key] = float(value.split()[0])
controller = vtkMultiProcessController.GetGlobalController()
values = {"Rank": controller.GetLocalProcessId() if controller else 0,
          "VmHWM": kb.get("VmHWM", -1.0), "VmRSS": kb.get("VmRSS", -1.0), "Reset": reset}
output = self.GetOutput()
points = vtkPoints()
points.InsertNextPoint(0.0, 0.0, 0.0)
output.SetPoints(points)
verts = vtkCellArray()
verts.InsertNextCell(1)
verts.InsertCellPoint(0)
output.SetVerts(verts)
for name, value in values.items():
    array = vtkDoubleArray()
    array.SetName(name)
    array.InsertNextValue(value)
    output.GetPointData().AddArray(array)
"""
memory_source = ProgrammableSource(OutputDataSetType="vtkPolyData")
memory_calls = [0]


def memory(reset=False):
    """Every rank's [peak, current resident memory in MiB, whether its peak was reset], by rank;
    reset: restart the peaks."""
    memory_calls[0] += 1  # a new script text makes the source run again
    memory_source.Script = "RESET = %d  # call %d\n" % (reset, memory_calls[0]) + MEMORY_SCRIPT
    memory_source.UpdatePipeline()
    data = servermanager.Fetch(memory_source)
    pd = data.GetPointData()
    out = {}
    for i in range(data.GetNumberOfPoints()):
        rank = int(pd.GetArray("Rank").GetValue(i))
        out[rank] = [pd.GetArray("VmHWM").GetValue(i) / 1024.0,
                     pd.GetArray("VmRSS").GetValue(i) / 1024.0,
                     bool(pd.GetArray("Reset").GetValue(i))]
    return out


def memory_since(started):
    """memory(), each rank's flag telling whether the memory(reset=True) that gave started could
    reset its peak."""
    return {rank: values[:2] + [started[rank][2]] for rank, values in memory().items()}


def timed(function):
    start = time.perf_counter()
    function()
    return 1000.0 * (time.perf_counter() - start)


rows = []
steps = {}

# The source and the contour, each timed apart. UpdatePipeline returns when rank 0 is done; the
# data information that follows is gathered from every rank, so the time covers them all.
started = memory(reset=True)
wavelet = Wavelet(WholeExtent=[-extent, extent] * 3)
steps["source_ms"] = timed(lambda: (wavelet.UpdatePipeline(),
                                    wavelet.GetDataInformation().GetNumberOfPoints()))
contour = Contour(Input=wavelet, ContourBy=["POINTS", "RTData"], Isosurfaces=[args.iso])
steps["contour_ms"] = timed(lambda: (contour.UpdatePipeline(),
                                     contour.GetDataInformation().GetNumberOfPoints()))
steps["memory"] = memory_since(started)
version = servermanager.vtkSMProxyManager.GetParaViewSourceVersion()
triangles = contour.GetDataInformation().GetNumberOfCells()
contour_points = contour.GetDataInformation().GetNumberOfPoints()
print("ParaView %s, %d rank(s); Wavelet [-%d, %d]^3 (%d points): %.0f ms; contour at %g: "
      "%d triangles, %d points, %.0f ms" % (
          version, ranks, extent, extent, (2 * extent + 1) ** 3,
          steps["source_ms"], args.iso, triangles, contour_points,
          steps["contour_ms"]))
sys.stdout.flush()


def setup(view):
    view.ViewSize = VIEW_SIZE
    view.OrientationAxesVisibility = 0
    if hasattr(view, "UseColorPaletteForBackground"):
        view.UseColorPaletteForBackground = 0
    view.Background = [1.0, 1.0, 1.0]
    display = Show(contour, view)
    ColorBy(display, ("POINTS", None))
    display.DiffuseColor = [0.5, 0.7, 0.9]
    display.AmbientColor = [0.5, 0.7, 0.9]
    # The whole contour in view, from the direction of the tests' scene (set here, not by
    # ResetCamera: the camera is restored from these values before every row).
    direction = [19.0, 15.0, 30.0]
    norm = math.sqrt(direction[0] ** 2 + direction[1] ** 2 + direction[2] ** 2)
    distance = 1.25 * extent / math.sin(math.radians(15.0))
    view.CameraFocalPoint = [0.0, 0.0, 0.0]
    view.CameraPosition = [distance * d / norm for d in direction]
    view.CameraViewUp = [0.0, 1.0, 0.0]
    view.CameraViewAngle = 30
    return [list(view.CameraPosition), list(view.CameraFocalPoint), list(view.CameraViewUp)]


def turn(view, degrees):
    """The camera turned about the view up through the focal point."""
    position, focus, up = view.CameraPosition, view.CameraFocalPoint, view.CameraViewUp
    offset = [p - f for p, f in zip(position, focus)]
    along = offset[0] * up[0] + offset[1] * up[1] + offset[2] * up[2]
    radial = [o - along * u for o, u in zip(offset, up)]
    side = [up[1] * radial[2] - up[2] * radial[1], up[2] * radial[0] - up[0] * radial[2],
            up[0] * radial[1] - up[1] * radial[0]]
    c, s = math.cos(math.radians(degrees)), math.sin(math.radians(degrees))
    view.CameraPosition = [f + along * u + c * r + s * w
                           for f, u, r, w in zip(focus, up, radial, side)]


def measure(view, name, camera, set_style=None):
    """One row: the first frame (after set_style), the mean of the later frames, memory."""
    view.CameraPosition, view.CameraFocalPoint, view.CameraViewUp = camera
    started = memory(reset=True)
    if set_style:
        set_style()
    first = timed(lambda: Render(view))
    later = []
    for _ in range(args.frames):
        turn(view, 1.0)
        later.append(timed(lambda: Render(view)))
    # (paraview.simple's star import brings numpy_interface's sum, min, max and all)
    row = {"view": name, "first_ms": first, "later_ms": builtins.sum(later) / len(later),
           "later_min_ms": builtins.min(later), "later_max_ms": builtins.max(later),
           "memory": memory_since(started)}
    if args.output:
        view.CameraPosition, view.CameraFocalPoint, view.CameraViewUp = camera
        row["image"] = os.path.join(args.output, name.lower().replace("+", "-").replace(" ", "-")
                                    + ".png")
        SaveScreenshot(row["image"], view, ImageResolution=VIEW_SIZE)
    rows.append(row)
    mem = "; ".join("rank %d %.0f/%.0f MiB" % (r, m[0], m[1])
                    for r, m in sorted(row["memory"].items()))
    print("%-12s first %8.1f ms, later %8.1f ms (%d frames); peak/current %s" % (
        name, first, row["later_ms"], args.frames, mem))
    sys.stdout.flush()


def measure_plain(name):
    """ParaView's own render view; its first frame includes the upload of the geometry. It is
    deleted afterwards, so that it holds no memory while another view renders."""
    plain = CreateView("RenderView")
    measure(plain, name, setup(plain))
    Delete(plain)


# The plain view before and after the NPR view: on a shared machine the two show how much the
# load changed during the run. The ratios are to the mean of their later frames.
measure_plain(PLAIN)

# The NPR view, shown in the last style of the loop so that every style's first frame follows a
# switch; its first frame after Show (with the upload) is timed apart.
npr = CreateView("NPRRenderView")
order = STYLES[1:] + STYLES[:1]
npr.Style = STYLES.index(order[-1])
camera = setup(npr)
steps["npr_show_ms"] = timed(lambda: Render(npr))
for style in order:
    measure(npr, style, camera, lambda: setattr(npr, "Style", STYLES.index(style)))
Delete(npr)
measure_plain(PLAIN_AGAIN)

plain_rows = [row for row in rows if row["view"] in (PLAIN, PLAIN_AGAIN)]
steps["plain_frame_ms"] = builtins.sum(row["later_ms"] for row in plain_rows) / len(plain_rows)
for row in rows:
    row["first_ratio"] = row["first_ms"] / steps["plain_frame_ms"]
    row["later_ratio"] = row["later_ms"] / steps["plain_frame_ms"]
plain_row = rows[0]
print("\n| View / style | First frame (ms) | x plain | Later frames (ms) | x plain | "
      "Fastest (ms) | " + " | ".join("Peak rank %d (MiB)" % r for r in sorted(plain_row["memory"]))
      + " |")
print("|---|---:|---:|---:|---:|---:|" + "---:|" * len(plain_row["memory"]))
for row in rows:
    print("| %s | %.0f | %.2f | %.0f | %.2f | %.0f | %s |" % (
        row["view"], row["first_ms"], row["first_ratio"], row["later_ms"], row["later_ratio"],
        row["later_min_ms"], " | ".join("%.0f" % m[0] for _, m in sorted(row["memory"].items()))))
print("x plain: to a frame of the plain view, %.0f ms (the mean of its later frames in both rows)"
      % steps["plain_frame_ms"])
print("source %.0f ms, contour %.0f ms (peak/current %s); NPR view's first frame after Show "
      "%.0f ms (x %.2f)" % (steps["source_ms"], steps["contour_ms"],
                            "; ".join("rank %d %.0f/%.0f MiB" % (r, m[0], m[1])
                                      for r, m in sorted(steps["memory"].items())),
                            steps["npr_show_ms"], steps["npr_show_ms"] / steps["plain_frame_ms"]))

failures = []


def check(condition, message):
    print(("ok    " if condition else "FAIL  ") + message)
    if not condition:
        failures.append(message)


if args.output:
    table = os.path.join(args.output, "scale.csv")
    with open(table, "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(["view", "first_ms", "first_ratio", "later_ms", "later_ratio",
                         "later_min_ms", "rank", "peak_mib", "current_mib", "peak_reset"])
        for row in rows:
            for rank, (peak, current, reset) in sorted(row["memory"].items()):
                writer.writerow([row["view"], "%.1f" % row["first_ms"], "%.3f" % row["first_ratio"],
                                 "%.1f" % row["later_ms"], "%.3f" % row["later_ratio"],
                                 "%.1f" % row["later_min_ms"], rank,
                                 "%.1f" % peak, "%.1f" % current, int(reset)])
    with open(os.path.join(args.output, "scale.json"), "w") as f:
        json.dump({"paraview": version, "ranks": ranks, "extent": extent,
                   "iso": args.iso, "triangles": triangles, "points": contour_points,
                   "view_size": VIEW_SIZE, "frames": args.frames, "steps": steps, "rows": rows},
                  f, indent=1, default=str)
    print("wrote", table)

if args.check:
    check(triangles > 0, "the contour has triangles (%d)" % triangles)
    # The table as written: a row per view and rank, every rank's memory above 0.
    with open(os.path.join(args.output, "scale.csv")) as f:
        written = list(csv.DictReader(f))
    views = [r["view"] for r in written]
    check(sorted(set(views)) == sorted([PLAIN, PLAIN_AGAIN] + STYLES) and
          builtins.all(views.count(v) == ranks for v in set(views)),
          "the table has one row per view and rank (%d rows, %d ranks)" % (len(written), ranks))
    check(builtins.all(float(r["peak_mib"]) > 0 and float(r["current_mib"]) > 0
                       for r in written) and
          sorted(set(int(r["rank"]) for r in written)) == list(range(ranks)),
          "every rank's peak and current memory are above 0")
    images = {row["view"]: read_png(row["image"]) for row in rows}
    base = images[PLAIN]
    covered = int((base.sum(axis=2) < 760).sum())
    print("covered pixels %d; dark pixels %s" % (covered, {v: dark(i) for v, i in images.items()}))
    check(covered > 0.05 * VIEW_SIZE[0] * VIEW_SIZE[1], "the contour covers the plain view")
    for view, img in images.items():
        drawn = int((img.sum(axis=2) < 760).sum())
        check(drawn > 0.5 * covered, "%s: the image is drawn (%d non-white pixels)" % (view, drawn))
        if view in (PLAIN, PLAIN_AGAIN):
            continue
        # The NPR view's Shaded style is ParaView's image; every other style changes it.
        differing = int((abs(img - base).max(axis=2) > 48).sum())
        if view == "Shaded":
            check(differing <= 0.001 * covered,
                  "Shaded matches the plain view (%d pixels differ)" % differing)
        else:
            check(differing > 0.01 * covered,
                  "%s differs from the plain view (%d pixels)" % (view, differing))
        if view not in ("Shaded", "Toon"):
            check(dark(img) > dark(base) + 0.01 * covered,
                  "%s draws lines (%d dark pixels, plain %d)" % (view, dark(img), dark(base)))

if failures:
    raise RuntimeError("FAIL: " + "; ".join(failures))
print("PASS" if args.check else "done")
