# SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
# SPDX-License-Identifier: BSD-3-Clause
"""Examples/Python/npr_gallery.py at a small panel size, its PNGs read back and checked.

    TestGallery.py npr_gallery.py DATA_DIR OUT_DIR

Every file is written at the size its grid implies; in each, the 7 style panels (row by row from
the top left, in vtkNPRPass's order of styles) show something, each differs from every other
outside the labels (no style missing or twice), edges has more dark line pixels than shaded, each
label's corner has dark text, the same pixels over every subject (drawn over the style), and the
scientific scene's panels have their scalar bar. VTK prints no error or warning.
"""
import os
import subprocess
import sys

import vtknpr  # noqa: F401
from vtknpr import vtkNPRPass
from vtkmodules.vtkIOImage import vtkPNGReader

# The library's styles, not the script's list: a style the script leaves out is caught.
STYLES = [vtkNPRPass.GetStyleName(style) for style in range(vtkNPRPass.DRAWING + 1)]
PANEL, STRIP, COLUMNS = (160, 120), (120, 100), 4
LABEL_BAND = 0.2  # the top of a panel holds its label (the script's font: height / 13, >= 10 px)
# Pixels inside every label's opaque box at these panel sizes (10 px text from (3, 1) on): the
# first letters of the style's name, and nothing of the scene.
LABEL_CORNER = (5, 2, 20, 8)
failures = []


def check(condition, message):
    print(("ok      " if condition else "FAILED  ") + message)
    if not condition:
        failures.append(message)


class Image:
    """An RGB(A) PNG as bytes, addressed from the top left as it is viewed."""

    def __init__(self, file_name):
        reader = vtkPNGReader()
        reader.SetFileName(file_name)
        reader.Update()
        image = reader.GetOutput()
        self.width, self.height, _ = image.GetDimensions()
        self.components = image.GetNumberOfScalarComponents()
        self.data = bytes(memoryview(image.GetPointData().GetScalars()))

    def pixels(self, x0, y0, x1, y1):
        """The (r, g, b) of the rectangle [x0, x1) x [y0, y1), top-left origin."""
        c = self.components
        for y in range(y0, y1):
            row = (self.height - 1 - y) * self.width  # VTK's rows run bottom up
            for x in range(x0, x1):
                yield self.data[(row + x) * c:(row + x) * c + 3]


def panel_origin(index, panel, columns):
    """The top left pixel of the index-th panel, row by row from the top left."""
    return (index % columns) * panel[0], (index // columns) * panel[1]


def panel_box(index, panel, columns, top=0.0, left=0.0, right=1.0, bottom=1.0):
    """The part [left, right) x [top, bottom) (fractions) of the index-th panel, in pixels."""
    x, y = panel_origin(index, panel, columns)
    return (x + int(left * panel[0]), y + int(top * panel[1]),
            x + int(right * panel[0]), y + int(bottom * panel[1]))


def count(image, box, test):
    return sum(1 for p in image.pixels(*box) if test(p))


def differing(image, box_a, box_b):
    """The fraction of pixels of two equal boxes that differ by more than 24 in a channel."""
    pairs = zip(image.pixels(*box_a), image.pixels(*box_b))
    total = (box_a[2] - box_a[0]) * (box_a[3] - box_a[1])
    return sum(1 for a, b in pairs if max(abs(u - v) for u, v in zip(a, b)) > 24) / total


def dark(p):
    return max(p) < 60


def coloured(p):
    return max(p) - min(p) > 80


def check_styles(name, image, panel, columns):
    rows = -(-len(STYLES) // columns)
    size = (panel[0] * columns, panel[1] * rows)
    check((image.width, image.height) == size, "%s: %dx%d pixels, %d x %d panels of %dx%d"
          % (name, image.width, image.height, columns, rows, panel[0], panel[1]))
    if (image.width, image.height) != size:
        return
    scenes = [panel_box(i, panel, columns, top=LABEL_BAND) for i in range(len(STYLES))]
    area = (scenes[0][2] - scenes[0][0]) * (scenes[0][3] - scenes[0][1])
    for style, box in zip(STYLES, scenes):
        drawn = count(image, box, lambda p: min(p) < 235) / area
        check(drawn > 0.02,
              "%s %s: %.1f %% of the panel drawn (> 2 %%)" % (name, style, 100 * drawn))
    for i in range(len(STYLES)):
        for j in range(i + 1, len(STYLES)):
            fraction = differing(image, scenes[i], scenes[j])
            check(fraction > 0.005, "%s: %s and %s differ in %.1f %% of the pixels (> 0.5 %%)"
                  % (name, STYLES[i], STYLES[j], 100 * fraction))
    lines = [count(image, scenes[STYLES.index(style)], dark) for style in ("shaded", "edges")]
    check(lines[1] > lines[0] + 0.01 * area,
          "%s: edges has %d dark pixels, shaded %d (+1 %% of the panel)"
          % (name, lines[1], lines[0]))


def label_corner(image, index, panel, columns):
    x, y = panel_origin(index, panel, columns)
    box = (x + LABEL_CORNER[0], y + LABEL_CORNER[1], x + LABEL_CORNER[2], y + LABEL_CORNER[3])
    return list(image.pixels(*box))


def check_labels(images):
    """Dark text in each label's corner, the same pixels over every subject: VTK draws the
    label on its opaque box over whatever the style made of the scene."""
    for index, style in enumerate(STYLES):
        corners = {name: label_corner(images[name], index, PANEL, COLUMNS)
                   for name in ("gallery_cad", "gallery_scan", "gallery_science")}
        corners["styles"] = label_corner(images["styles"], index, STRIP, len(STYLES))
        for name, corner in corners.items():
            text = sum(1 for p in corner if dark(p))
            check(text >= 8, "%s %s: %d dark text pixels in the label's corner (>= 8)"
                  % (name, style, text))
        check(corners["gallery_cad"] == corners["gallery_scan"] == corners["gallery_science"],
              "%s: the label's corner is the same over the three subjects" % style)


def check_scalar_bar(image):
    """The bar's colours in the panel's right strip, where the colour-mapped data does not reach."""
    for index, style in enumerate(STYLES):
        box = panel_box(index, PANEL, COLUMNS, left=0.86, right=0.97, top=0.25, bottom=0.8)
        fraction = count(image, box, coloured) / ((box[2] - box[0]) * (box[3] - box[1]))
        check(fraction > 0.1, "science %s: %.0f %% coloured pixels where the scalar bar is"
              " (> 10 %%)" % (style, 100 * fraction))


def main():
    script, data, out = sys.argv[1:4]
    run = subprocess.run([sys.executable, script, "--out", out, "--data", data,
                          "--size", "%dx%d" % PANEL, "--strip-size", "%dx%d" % STRIP,
                          "--columns", str(COLUMNS)],
                         stdout=subprocess.PIPE, stderr=subprocess.STDOUT, universal_newlines=True)
    print(run.stdout)
    check(run.returncode == 0, "npr_gallery.py exits 0 (%d)" % run.returncode)
    check("ERROR" not in run.stdout and "Warning" not in run.stdout,
          "VTK printed no error or warning")
    images = {}
    for name in ("gallery_cad", "gallery_scan", "gallery_science", "styles"):
        path = os.path.join(out, name + ".png")
        check(os.path.isfile(path), "%s written" % path)
        if os.path.isfile(path):
            images[name] = Image(path)
    if failures:
        return 1
    for name in ("gallery_cad", "gallery_scan", "gallery_science"):
        check_styles(name, images[name], PANEL, COLUMNS)
    check_styles("styles", images["styles"], STRIP, len(STYLES))
    check_labels(images)
    check_scalar_bar(images["gallery_science"])
    print("%d failed" % len(failures))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
