# SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
# SPDX-License-Identifier: BSD-3-Clause
"""Runs the PyVista programs of corpus.py with vtknpr.pyvista.enable_npr added, in one style.

    run_examples.py STYLE [--output DIR]

Each program runs twice, off screen: as PyVista draws it, then with enable_npr(renderer, STYLE)
in every renderer of its plotter when it calls show(). Fails when VTK, PyVista or Python warn or
report an error, and when the styled image does not differ from PyVista's where surfaces are
(more than 0.1 % of the pixels; for "shaded", at most 0.5 %: that style is VTK's own look, but
the anti-aliased edges of text glyphs blend a little differently under any render pass).
Exits 77 (a skipped test) when PyVista is not installed.
"""
import argparse
import os
import sys
import warnings

try:
    import pyvista as pv
except ImportError:
    print("run_examples: PyVista is not installed for %s: skipped" % sys.executable)
    sys.exit(77)

import numpy as np
from vtkmodules.vtkCommonCore import vtkOutputWindow, vtkStringOutputWindow
from vtkmodules.vtkIOImage import vtkPNGWriter

import vtknpr  # noqa: F401
from vtknpr.pyvista import STYLES, enable_npr

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from corpus import CORPUS  # noqa: E402


class Capture:
    """Replaces Plotter.show: turns the style on, renders, keeps the image, closes."""

    def __init__(self):
        self.style = None
        self.images = []
        self.original = pv.Plotter.show
        capture = self

        def show(plotter, *args, **kwargs):
            for unused in ("screenshot", "interactive_update", "return_viewer"):
                kwargs.pop(unused, None)
            kwargs["auto_close"] = False
            if capture.style is not None:
                for renderer in plotter.renderers:
                    enable_npr(renderer, capture.style)
            capture.original(plotter, *args, **kwargs)
            plotter.render()
            capture.images.append(np.array(plotter.screenshot(return_img=True)))
            plotter.close()

        pv.Plotter.show = show

    def run(self, function, style):
        self.style = style
        self.images = []
        function()
        return self.images


def write_png(rgb, path):
    """An RGB array (rows top down, as PyVista's screenshots) as a PNG."""
    image = pv.ImageData(dimensions=(rgb.shape[1], rgb.shape[0], 1))
    image.point_data["rgb"] = np.ascontiguousarray(rgb[::-1]).reshape(-1, 3).astype(np.uint8)
    writer = vtkPNGWriter()
    writer.SetFileName(path)
    writer.SetInputData(image)
    writer.Write()


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("style", choices=STYLES)
    parser.add_argument("--output", help="folder for the images (unstyled and styled side by side)")
    parser.add_argument("--only", nargs="*", help="names of programs to run (default: all)")
    args = parser.parse_args()

    pv.OFF_SCREEN = True
    pv.global_theme.window_size = [400, 300]
    messages = vtkStringOutputWindow()
    vtkOutputWindow.SetInstance(messages)
    capture = Capture()
    failures, passed = [], 0
    for name, (source, function) in CORPUS.items():
        if args.only and name not in args.only:
            continue
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            plain = capture.run(function, None)
            styled = capture.run(function, args.style)
        problems = ["warning: %s" % w.message for w in caught]
        printed = messages.GetOutput().strip()
        messages = vtkStringOutputWindow()  # a fresh one per program
        vtkOutputWindow.SetInstance(messages)
        if printed:
            problems.append("VTK printed: " + printed[:400])
        if len(plain) != 1 or len(styled) != 1:
            problems.append("%d and %d images shown, expected 1" % (len(plain), len(styled)))
        else:
            a, b = plain[0].astype(int), styled[0].astype(int)
            differing = float((np.abs(a - b).sum(axis=2) > 30).mean())
            if args.style == "shaded":
                # Text glyphs' anti-aliased edges blend a little differently under any render pass.
                ok = differing <= 0.005
            else:
                ok = differing > 0.001
            print("%-16s %-10s %5.1f %% of the pixels differ from PyVista's image"
                  % (name, args.style, 100.0 * differing))
            if not ok:
                problems.append("%.2f %% of the pixels differ" % (100.0 * differing))
            if args.output:
                os.makedirs(args.output, exist_ok=True)
                side = np.concatenate((plain[0], styled[0]), axis=1)
                write_png(side, os.path.join(
                    args.output, "%s-%s.png" % (name, args.style.replace("+", "-"))))
        if problems:
            failures.append("%s (%s): %s" % (name, source, "; ".join(problems)))
        else:
            passed += 1
    vtkOutputWindow.SetInstance(None)
    for failure in failures:
        print("FAILED: " + failure)
    print("%d passed, %d failed (PyVista %s, style %s)"
          % (passed, len(failures), pv.__version__, args.style))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
