#!/usr/bin/env python3
# SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
# SPDX-License-Identifier: BSD-3-Clause
"""F1@1 of the drawing style's silhouettes against the visible smooth contours.

    /usr/bin/python3 Examples/npr-benchmark/measure_drawing_silhouettes.py \\
        --npr-render build/bin/npr-render MODEL [MODEL ...]

For each model and view (three), npr-render writes the drawing (silhouettes and boundaries,
1 px lines) as SVG with the mesh silhouettes and with --smooth-silhouettes, and the reference
mask of the visible smooth contours and boundaries (--reference-mask with --smooth-silhouettes;
--lines silhouettes,contours asks both for the boundaries, so npr-render warns that the drawing
has no object contours). rsvg-convert
rasterises each SVG; its line pixels (red under 160) are compared with the mask: precision,
recall and F1 at a tolerance of one pixel (nprEdgeMetrics' definitions). Prints a Markdown table.
"""
import argparse
import os
import subprocess
import sys
import tempfile

import vtk

VIEWS = [(35, 25), (155, 10), (275, -30)]  # azimuth, elevation


def pixels(path, dark):
    """The set of (x, y) line pixels of a PNG: dark ones, or non-zero ones of a mask."""
    reader = vtk.vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    width, height, _ = image.GetDimensions()
    scalars = image.GetPointData().GetScalars()
    components = scalars.GetNumberOfComponents()
    found = set()
    for i in range(width * height):
        value = scalars.GetComponent(i, 0)
        if (value < 160 and (components < 4 or scalars.GetComponent(i, 3) > 0)) if dark else value > 0:
            found.add((i % width, i // width))
    return found


def within_one(point, others):
    x, y = point
    return any(p in others for p in ((x, y), (x + 1, y), (x - 1, y), (x, y + 1), (x, y - 1)))


def f1(method, reference):
    precision = sum(within_one(p, reference) for p in method) / len(method) if method else 1.0
    recall = sum(within_one(p, method) for p in reference) / len(reference) if reference else 1.0
    return (2 * precision * recall / (precision + recall) if precision + recall else 0.0,
            precision, recall)


def run(command):
    result = subprocess.run(command, capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit("measure_drawing_silhouettes: %s failed: %s" % (command[0], result.stderr.strip()))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--npr-render", default="build/bin/npr-render")
    parser.add_argument("--size", default="1024x768")
    parser.add_argument("models", nargs="+")
    args = parser.parse_args()
    width, height = (int(v) for v in args.size.split("x"))
    print("| model | view | mesh silhouettes F1@1 (P / R) | smooth silhouettes F1@1 (P / R) |")
    print("|---|---|---|---|")
    totals = {False: [], True: []}
    with tempfile.TemporaryDirectory() as folder:
        for model in args.models:
            for azimuth, elevation in VIEWS:
                common = [args.npr_render, model, "--size", args.size, "--azimuth", str(azimuth),
                          "--elevation", str(elevation), "--style", "drawing", "--lines",
                          "silhouettes,contours", "--line-width", "1"]
                truth = os.path.join(folder, "truth.png")
                cells = []
                for smooth in (False, True):
                    svg, png = os.path.join(folder, "d.svg"), os.path.join(folder, "d.png")
                    extra = ["--smooth-silhouettes", "--reference-mask", truth] if smooth else []
                    run(common + extra + ["-o", svg])
                    run(["rsvg-convert", "-w", str(width), "-h", str(height), svg, "-o", png])
                    cells.append((smooth, pixels(png, True)))
                reference = pixels(truth, False)
                row = []
                for smooth, drawn in cells:
                    score = f1(drawn, reference)
                    totals[smooth].append(score[0])
                    row.append("%.3f (%.3f / %.3f)" % score)
                print("| %s | %d, %d | %s | %s |" % (os.path.basename(model), azimuth, elevation, *row))
    print("| mean | | %.3f | %.3f |" % tuple(sum(v) / len(v) for v in (totals[False], totals[True])))


if __name__ == "__main__":
    main()
