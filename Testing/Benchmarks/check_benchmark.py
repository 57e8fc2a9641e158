#!/usr/bin/python3
# SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
# SPDX-License-Identifier: BSD-3-Clause
"""Smoke test of npr-benchmark: runs it with --quick (alone, or with --stress, --coherence,
--drawing, --speed, --contours or --scale) and checks that the files are written and that every figure is sane (F1 in [0, 1], no NaN, positive times).

usage: check_benchmark.py --npr-benchmark EXE --data DIR --out DIR
       [--stress | --coherence | --drawing | --speed | --contours | --scale]"""
import argparse
import csv
import math
import os
import shutil
import subprocess
import sys

failures = []


def check(condition, message):
    if not condition:
        failures.append(message)
        print("check failed: " + message, file=sys.stderr)


def number(row, key):
    text = row[key]
    try:
        value = float(text)
    except ValueError:
        check(False, "%s is not a number: %r" % (key, text))
        return float("nan")
    check(math.isfinite(value), "%s is not finite: %r in %s" % (key, text, row))
    return value


def check_png(path):
    check(os.path.isfile(path), path + " missing")
    if os.path.isfile(path):
        with open(path, "rb") as f:
            check(f.read(8) == b"\x89PNG\r\n\x1a\n", path + " is not a PNG")
        check(os.path.getsize(path) > 5000, path + " is nearly empty")


def read_csv(path):
    check(os.path.isfile(path), path + " missing")
    if not os.path.isfile(path):
        return []
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def check_benchmark(out):
    rows = read_csv(os.path.join(out, "results.csv"))
    check(len(rows) >= 2, "results.csv has %d rows" % len(rows))
    methods = {row["method"] for row in rows}
    check("edges-float" in methods, "edges-float missing from " + str(sorted(methods)))
    for row in rows:
        for key in ("precision_1px", "recall_1px", "f1_1px", "precision_2px", "recall_2px",
                    "f1_2px"):
            value = number(row, key)
            check(0.0 <= value <= 1.0, "%s out of [0, 1]: %s" % (key, row))
        check(number(row, "f1_2px") >= number(row, "f1_1px"), "F1@2 < F1@1: %s" % row)
        check(number(row, "mean_distance_px") >= 0.0, "negative distance: %s" % row)
        check(number(row, "median_ms") > 0.0 and number(row, "ratio_to_shaded") > 0.0,
              "times: %s" % row)
        check(int(row["reference_pixels"]) > 0 and int(row["method_pixels"]) > 0,
              "an empty mask: %s" % row)
    # The float edge pass finds the CAD part's lines: a broken mask reader would not.
    for row in rows:
        if row["method"] == "edges-float":
            check(number(row, "f1_2px") > 0.5, "edges-float F1@2 %s" % row["f1_2px"])
    md = open(os.path.join(out, "results.md")).read() if os.path.isfile(
        os.path.join(out, "results.md")) else ""
    check("| method | size |" in md and "edges-float" in md, "results.md has no table")
    check("nan" not in md.lower().replace("nanosecond", ""), "results.md has a NaN")
    check_png(os.path.join(out, "time_vs_f1.png"))


def check_stress(out):
    rows = read_csv(os.path.join(out, "stress.csv"))
    cases = {row["case"] for row in rows}
    for case in ("unit", "scale 1e-6", "scale 1e6", "translate 1e7", "near/far 1e6 (near)",
                 "slivers", "duplicate vertices", "zero normals", "NaN points"):
        check(case in cases, "stress case %r missing from %s" % (case, sorted(cases)))
    for row in rows:
        for key in ("f1_1px_own_reference", "f1_1px_unit_reference", "reference_f1_vs_unit"):
            value = number(row, key)
            check(0.0 <= value <= 1.0, "%s out of [0, 1]: %s" % (key, row))
        for key in ("stray_pixels", "coverage_changed", "nonfinite_pixels", "bad_depth_pixels"):
            check(int(row[key]) >= 0, "%s: %s" % (key, row))
        if row["case"] == "unit":
            check(number(row, "drift") == 0.0, "unit drift: %s" % row)
            check(number(row, "f1_1px_own_reference") > 0.5, "unit F1: %s" % row)
    check(os.path.isfile(os.path.join(out, "stress.md")), "stress.md missing")


def check_coherence(out):
    rows = read_csv(os.path.join(out, "coherence.csv"))
    paths = {row["path"] for row in rows}
    styles = {row["style"] for row in rows}
    check(paths == {"pan 20 px", "orbit 1 deg", "dolly 2 %"}, "camera paths: %s" % sorted(paths))
    check({"edges", "sketch, surface noise", "sketch, screen noise", "inked"} <= styles,
          "styles: %s" % sorted(styles))
    for row in rows:
        for key in ("landed", "landed_exactly", "appeared", "vanished"):
            value = number(row, key)
            check(0.0 <= value <= 1.0, "%s out of [0, 1]: %s" % (key, row))
        if row["path"] == "pan 20 px":
            check(0.0 <= number(row, "pan_iou") <= 1.0, "pan IoU: %s" % row)
        # Edges follow a pan exactly, and so does the sketch with surface noise.
        if row["path"] == "pan 20 px" and row["style"] in ("edges", "sketch, surface noise"):
            check(number(row, "pan_iou") > 0.95, "%s pan IoU: %s" % (row["style"], row))
    costs = read_csv(os.path.join(out, "coherence_cost.csv"))
    check(len(costs) >= 1, "coherence_cost.csv has %d rows" % len(costs))
    for row in costs:
        check(number(row, "sketch_screen_ms") > 0.0 and number(row, "sketch_surface_ms") > 0.0,
              "times: %s" % row)
    md = os.path.join(out, "coherence.md")
    check(os.path.isfile(md) and "| camera path |" in open(md).read(), "coherence.md has no table")


def check_drawing(out):
    rows = read_csv(os.path.join(out, "drawing.csv"))
    check({(row["format"], row["hidden_lines"]) for row in rows} ==
          {("svg", "0"), ("svg", "1"), ("pdf", "0"), ("pdf", "1")},
          "drawing.csv: SVG and PDF, with and without hidden lines")
    for row in rows:
        check(number(row, "seconds") > 0.0 and int(row["bytes"]) > 0, "time and size: %s" % row)
        # Strokes chain the edges: fewer strokes than feature edges.
        check(0 < int(row["strokes"]) < int(row["feature_edges"]), "strokes: %s" % row)
        path = os.path.join(out, "drawing_%s_%s%s.%s" % (row["scene"], row["size"],
                                                          "_hidden" if row["hidden_lines"] == "1"
                                                          else "", row["format"]))
        check(os.path.isfile(path), "%s missing" % path)
        # Rasterised by rsvg-convert and pdftoppm (where installed): the reference's lines.
        f1 = number(row, "f1_at_1")
        if row["hidden_lines"] == "0" and f1 >= 0.0:
            check(f1 >= 0.98, "F1@1 of the %s: %s" % (row["format"], row))
    styles = read_csv(os.path.join(out, "drawing_style.csv"))
    check(len(styles) >= 1, "drawing_style.csv has %d rows" % len(styles))
    for row in styles:
        check(all(number(row, key) > 0.0 for key in ("shaded_ms", "first_ms", "moved_ms",
                                                       "unchanged_ms")), "times: %s" % row)
    md = os.path.join(out, "drawing.md")
    check(os.path.isfile(md) and "| hidden lines |" in open(md).read(), "drawing.md has no table")


SPEED_METHODS = (
    "plain VTK frame", "vtkNPRPass edges", "vtkNPRPass toon+edges", "vtkNPRPass sketch",
    "vtkNPRPass toon", "vtkNPRPass inked", "vtkNPRPass drawing",
    "vtkNPRPass edges, silhouettes only", "vtkNPRPass edges, every line type off",
    "vtkNPRPass edges, composite over every pixel",
    "vtkNPRPass edges, surfaces copied by a shader",
    "vtkNPRPass sketch, line coverage over every pixel",
    "vtkNPRGBufferPass alone (drawn, not shown)",
    "render steps into a texture, one full-screen fetch",
    "vtkNPRPass edges, creases from face normals", "vtkNPRPass edges, smooth silhouettes on",
    "vtkNPRPass edges, suggestive contours on", "vtkNPRPass inked, 1 px wireframe",
    "vtkNPRPass edges, unchanged frame drawn again",
    "vtkNPRPass sketch, unchanged frame drawn again",
    "vtkNPRPass drawing, unchanged frame drawn again", "vtkSobelGradientMagnitudePass",
    "vtkOutlineGlowPass", "vtkSSAOPass", "vtkEDLShading",
    "vtkPolyDataSilhouette re-extracted + surface", "vtkNPRFeatureLines re-extracted + surface",
    "vtkNPRFeatureLines per camera change (SetCamera + Update)")


def check_speed(out):
    rows = read_csv(os.path.join(out, "speed.csv"))
    methods = {row["method"] for row in rows}
    for method in SPEED_METHODS:
        check(method in methods, "speed.csv: %r missing" % method)
    check({row["scene"] for row in rows} == {"box"}, "speed.csv: the box only with --quick")
    for row in rows:
        check(number(row, "median_ms") > 0.0, "time: %s" % row)
    md = os.path.join(out, "speed.md")
    text = open(md).read() if os.path.isfile(md) else ""
    check("| method | median (ms) | ratio to plain |" in text, "speed.md has no table")
    check("| GPU (ms) | GPU over plain (ms) |" in text, "speed.md has no GPU-time columns")
    check("| over plain, lowest to highest run (ms) |" in text, "speed.md has no run spread")
    check(all(row.get("gpu_median_ms") not in (None, "") for row in rows),
          "speed.csv lacks gpu_median_ms")
    check(all(method in text for method in SPEED_METHODS), "speed.md lacks a method")
    check("nan" not in text.lower(), "speed.md has a NaN")


def check_contours(out):
    rows = read_csv(os.path.join(out, "contours.csv"))
    pairs = {(row["method"], row["truth"]) for row in rows}
    expected = {(m, t) for m in ("lines", "lines-smooth", "outline", "outline-smooth")
                for t in ("mesh", "smooth")}
    check(pairs == expected, "contours.csv: methods and truths %s" % sorted(pairs))
    check({row["scene"] for row in rows} == {"knot"}, "contours.csv: the knot only with --quick")
    for row in rows:
        for key in ("precision_1px", "recall_1px", "f1_1px"):
            value = number(row, key)
            check(0.0 <= value <= 1.0, "%s out of [0, 1]: %s" % (key, row))
        check(int(row["truth_pixels"]) > 100, "an empty truth: %s" % row)
        # The knot's tube outlines: every line found, nothing else (measured 0.99 and above).
        check(number(row, "f1_1px") >= 0.95, "F1@1 of the knot: %s" % row)
    md = os.path.join(out, "contours.md")
    check(os.path.isfile(md) and "| scene | kind | method | truth |" in open(md).read(),
          "contours.md has no table")
    check({row["set"] for row in rows} == {"repository"}, "contours.csv: the knot's set")
    # Each set summed up apart: the knot, smooth, its outline against the smooth contour.
    check("| repository | smooth | outline | smooth | 1 |" in open(md).read(),
          "contours.md: no summary of the repository's set")


def check_contours_orbit(args):
    """--orbit turns the camera around the model: 360/DEG azimuths at each of the three
    elevations, every view scored; it goes only with --contours and without --cameras."""
    out = args.out + "-orbit"
    shutil.rmtree(out, ignore_errors=True)
    command = [args.npr_benchmark, "--quick", "--contours", "--orbit", "120", "--data", args.data,
               "--out", out]
    print(" ".join(command))
    check(subprocess.run(command).returncode == 0, "--contours --orbit 120 failed")
    rows = read_csv(os.path.join(out, "contours.csv"))
    cameras = sorted({row["camera"] for row in rows})
    expected = sorted("a%de%d" % (azimuth, elevation) for azimuth in (-180, -60, 60)
                      for elevation in (20, 35, -15))
    check(cameras == expected, "--orbit 120 cameras: %s" % cameras)
    check(len(rows) == 9 * 8, "--orbit 120: %d rows, not 9 views x 8" % len(rows))
    text = open(os.path.join(out, "contours.md")).read()
    check("(9 views)" in text and "| 9/9 |" in text, "contours.md: the orbit's views not counted")
    for bad in (["--orbit", "10"], ["--contours", "--cameras", "2", "--orbit", "10"],
                ["--contours", "--orbit", "0"]):
        result = subprocess.run([args.npr_benchmark, "--data", args.data, "--out", out] + bad,
                                stderr=subprocess.PIPE, text=True)
        check(result.returncode == 2 and "--orbit" in result.stderr,
              "%s accepted or unclear: %d %s" % (bad, result.returncode, result.stderr))


def check_speed_methods(args):
    """--methods picks methods (the plain frame always comes first); an unknown name is an error."""
    out = args.out + "-methods"
    shutil.rmtree(out, ignore_errors=True)
    command = [args.npr_benchmark, "--quick", "--speed", "--data", args.data, "--out", out,
               "--methods", "edges,unchanged"]
    print(" ".join(command))
    check(subprocess.run(command).returncode == 0, "--speed --methods edges,unchanged failed")
    methods = [row["method"] for row in read_csv(os.path.join(out, "speed.csv"))]
    check(methods == ["plain VTK frame", "vtkNPRPass edges",
                      "vtkNPRPass edges, unchanged frame drawn again"],
          "--methods edges,unchanged gave %s" % methods)
    result = subprocess.run(command[:-1] + ["edges,nonsense"], stderr=subprocess.PIPE, text=True)
    check(result.returncode != 0 and "unknown method 'nonsense'" in result.stderr,
          "an unknown --speed method was accepted: %d %s" % (result.returncode, result.stderr))


SCALE_OURS = (
    "npr-render --style shaded", "npr-render --style edges", "npr-render --style sketch",
    "npr-render --style toon+edges", "npr-render --style drawing",
    "npr-render --style drawing -o x.svg",
    "plain VTK: vtkPLYReader, vtkPolyDataNormals, render, PNG")
SCALE_F3D = ("F3D --output", "F3D --output --edges")
# Each step with its parts: (step, parts that need not be logged, parts always measured).
SCALE_STEPS = (
    ("read (vtkNPRModelReader)", ("vtkNPRModelReader: validate", "vtkNPRModelReader: read",
                                  "vtkNPRModelReader: check points"), ()),
    ("shading normals (vtkNPRShadingNormals)", ("vtkNPRShadingNormals: merge",
                                                "vtkNPRShadingNormals: normals"), ()),
    ("feature lines: first update (adjacency)", (), ()),
    ("feature lines per camera change", (), ()),
    ("first frame: shaded (mesh upload)", (), ()), ("later frames: shaded", (), ()),
    ("first frame: edges", (), ()), ("later frames: edges", (), ()),
    ("first frame: sketch", (), ()), ("later frames: sketch", (), ()),
    ("first frame: toon+edges", (), ()), ("later frames: toon+edges", (), ()),
    ("first frame: drawing", (), ("drawing: first stroke update",)),
    ("later frames: drawing", (), ("drawing: stroke update per camera change",)))
SCALE_SIZES = {"62k": 62500, "250k": 250000}


def ply_faces(path):
    """The face count of a PLY header, and whether the file is binary."""
    with open(path, "rb") as f:
        header = f.read(1000).split(b"end_header")[0].decode("ascii", "replace")
    faces = [int(line.split()[2]) for line in header.splitlines()
             if line.startswith("element face")]
    return (faces[0] if faces else -1), "format binary" in header


def check_scale_row(row, triangles, part=False):
    """A measured row: a positive time, ns per triangle from it, a peak (not for parts)."""
    check(row["status"] == "", "%s %s: %s" % (row["size"], row["name"], row["status"]))
    if row["status"]:
        return 0.0
    seconds = number(row, "seconds")
    check(seconds > 0.0, "time: %s" % row)
    ns = number(row, "ns_per_triangle")
    check(abs(ns - 1e9 * seconds / triangles) <= 1e-3 * ns, "ns per triangle: %s" % row)
    if part:
        check(row["peak_mb"] == "", "a part with a peak of its own: %s" % row)
    else:
        check(number(row, "peak_mb") > 0.0, "peak memory: %s" % row)
        if row["kind"] == "step":
            check(number(row, "added_mb") >= 0.0, "added memory: %s" % row)
    return seconds


def check_scale(out):
    rows = read_csv(os.path.join(out, "scale.csv"))
    found = {(row["size"], row["kind"], row["name"]): row for row in rows}
    check({row["size"] for row in rows} == set(SCALE_SIZES), "scale.csv: sizes %s" %
          sorted({row["size"] for row in rows}))
    for size, triangles in SCALE_SIZES.items():
        faces, binary = ply_faces(os.path.join(out, "meshes", "bunny_%s.ply" % size))
        check(faces == triangles and binary, "meshes/bunny_%s.ply: %d faces" % (size, faces))
        for name in SCALE_OURS + SCALE_F3D:
            row = found.get((size, "program", name))
            check(row is not None, "scale.csv: %s %r missing" % (size, name))
            # F3D may be missing or without a display: said in the status, never an error.
            if row and (name not in SCALE_F3D or row["status"] == ""):
                check(int(row["triangles"]) == triangles, "triangles: %s" % row)
                check_scale_row(row, triangles)
        for step, logged, parts in SCALE_STEPS:
            row = found.get((size, "step", step))
            check(row is not None, "scale.csv: %s %r missing" % (size, step))
            whole = check_scale_row(row, triangles) if row else 0.0
            # A part lies within its step (the timer-log events appear once they are logged).
            for part in logged + parts:
                row = found.get((size, "step", part))
                check(row is not None, "scale.csv: %s %r missing" % (size, part))
                if row and (part in parts or row["status"] != "n/a"):
                    check(check_scale_row(row, triangles, True) <= whole,
                          "%s %s longer than its step" % (size, part))
    md = os.path.join(out, "scale.md")
    text = open(md).read() if os.path.isfile(md) else ""
    check("| program | 62k s | 62k MB | 250k s | 250k MB |" in text, "scale.md: no program table")
    check("| step | 62k ms | 62k MB | 250k ms | 250k MB |" in text, "scale.md: no step table")
    check(all(name in text for name in SCALE_OURS + SCALE_F3D), "scale.md lacks a program")
    check("nan" not in text.lower(), "scale.md has a NaN")
    for plot in ("scale_programs.png", "scale_steps.png"):
        check_png(os.path.join(out, plot))


def check_scale_options(args):
    """Bad --scale options are refused with status 2 and a message that names the option."""
    for bad, flag in ((["--scale", "--scale-sizes", "3m"], "--scale-sizes"),
                      (["--scale", "--scale-sizes", ""], "--scale-sizes"),
                      (["--scale-sizes", "1m"], "--scale-sizes"),
                      (["--scale-meshes", args.out], "--scale-meshes"),
                      (["--scale", "--scale-meshes"], "--scale-meshes"),
                      (["--scale", "--sizes", "640x480,320x240"], "--sizes")):
        result = subprocess.run([args.npr_benchmark, "--data", args.data, "--out", args.out +
                                 "-refused"] + bad, stderr=subprocess.PIPE, text=True)
        check(result.returncode == 2 and flag in result.stderr,
              "%s accepted or unclear: %d %s" % (bad, result.returncode, result.stderr))


# npr-benchmark's modes, each an option of its own passed on as it is (none: the default run).
MODES = ("stress", "coherence", "drawing", "speed", "contours", "scale")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--npr-benchmark", required=True)
    parser.add_argument("--data", required=True)
    parser.add_argument("--out", required=True)
    mode = parser.add_mutually_exclusive_group()
    for name in MODES:
        mode.add_argument("--" + name, action="store_true")
    args = parser.parse_args()
    shutil.rmtree(args.out, ignore_errors=True)
    command = [args.npr_benchmark, "--quick", "--data", args.data, "--out", args.out]
    command += ["--" + name for name in MODES if getattr(args, name)]
    print(" ".join(command))
    result = subprocess.run(command)
    check(result.returncode == 0, "npr-benchmark exited with %d" % result.returncode)
    if args.stress:
        check_stress(args.out)
    elif args.coherence:
        check_coherence(args.out)
    elif args.drawing:
        check_drawing(args.out)
    elif args.speed:
        check_speed(args.out)
        check_speed_methods(args)
    elif args.contours:
        check_contours(args.out)
        check_contours_orbit(args)
    elif args.scale:
        check_scale(args.out)
        check_scale_options(args)
    else:
        check_benchmark(args.out)
    print("FAILED (%d failed checks)" % len(failures) if failures else "PASSED")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
