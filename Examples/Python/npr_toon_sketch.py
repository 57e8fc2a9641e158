# SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
# SPDX-License-Identifier: BSD-3-Clause
"""Toon shading and sketchy drawing of one model with vtkNPRPass, rendered headless to a PNG.

    PYTHONPATH=build/lib/python3/dist-packages /usr/bin/python3 Examples/Python/npr_toon_sketch.py \
        Testing/Data/cad_part.vtp -o cad_part_sketch.png --uncertainty 4 --paper 1,0.98,0.92

Styles: toon (the light in a few flat bands), toon+edges (the bands under the edge pass's lines)
and sketch (flat colours and lines, each displaced by a seeded noise of up to --uncertainty px).

With --check the script also verifies and exits 1 when a check fails, so that it runs as a test:
toon with N bands shows at most N colours on the object, all shades of its colour; the sketch is
the same for the same seed and differs for another; without uncertainty it is exactly toon+edges
with one band and no highlight; an unchanged scene reuses the G-buffer. The checks render scenes
of their own (white, no paper) with --bands, --seed and --uncertainty (3 where it is 0).
"""
import argparse
import sys

import vtknpr  # noqa: F401  (first: it imports the VTK modules it needs by itself)
from vtknpr import vtkNPRPass, vtkNPRRenderWindowFactory
from vtkmodules.vtkIOImage import vtkPNGWriter
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (the OpenGL object factory overrides)

from npr_example_common import grab, model_renderer, read_model, rgb, size, view_from

COLOR = (0.85, 0.55, 0.35)  # no shade of it is the white background, so the object stands out


def parse_arguments():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("model", help="model file")
    parser.add_argument("-o", "--output", required=True, help="PNG to write")
    parser.add_argument("--style", choices=["toon", "toon+edges", "sketch"], default="sketch",
                        help="drawing style (default sketch)")
    parser.add_argument("--bands", type=int, default=3, metavar="N",
                        help="toon bands, 1..64 (default 3)")
    parser.add_argument("--uncertainty", type=float, default=3.0, metavar="PX",
                        help="sketch: largest displacement in pixels, 0..32 (default 3)")
    parser.add_argument("--seed", type=int, default=1, metavar="N",
                        help="sketch: seed of the noise (default 1)")
    parser.add_argument("--paper", type=rgb, metavar="R,G,B",
                        help="sketch: draw on paper of this colour (default: no paper, white)")
    parser.add_argument("--size", type=size, default=[800, 600], metavar="WxH",
                        help="image size in pixels (default 800x600)")
    parser.add_argument("--check", action="store_true", help="verify the result; exit 1 on failure")
    args = parser.parse_args()
    if not 1 <= args.bands <= 64:
        parser.error("argument --bands: %d is not in 1..64" % args.bands)
    return args


class Scene:
    """The model in a headless window of its own, drawn by a vtkNPRPass of the given style."""

    def __init__(self, model, image_size, style):
        self.renderer = model_renderer(model, COLOR)  # no specular: bands of diffuse light only
        self.npr = vtkNPRPass()
        self.npr.SetStyle(vtkNPRPass.GetStyleFromName(style))
        self.renderer.SetPass(self.npr)
        self.window = vtkNPRRenderWindowFactory.CreateRenderWindow()  # NPR_BACKEND, else EGL
        if self.window is None:
            sys.exit("npr_toon_sketch: error: no headless render window "
                     "(see Documentation/backends.md)")
        self.window.SetMultiSamples(0)  # one colour per pixel: multisampling would blend the bands
        self.window.SetSize(*image_size)
        self.window.AddRenderer(self.renderer)
        view_from(self.renderer, 30.0, 30.0)

    def render(self):
        """Renders and returns the frame as a vtkImageData (RGB, read from the back buffer)."""
        self.window.Render()
        return grab(self.window)


def colors(image):
    """The pixels of an 8-bit image as a list of (r, g, b)."""
    scalars = image.GetPointData().GetScalars()
    data = bytes(memoryview(scalars).cast("B"))
    step = scalars.GetNumberOfComponents()
    return list(zip(data[0::step], data[1::step], data[2::step]))


def differing(first, second):
    """Number of pixels that differ between two images of the same size."""
    return sum(a != b for a, b in zip(colors(first), colors(second)))


def run_checks(model, args):
    """The checks of --check, printed one a line; returns the number that failed."""
    failures = []

    def check(ok, text):
        print(("ok      " if ok else "FAILED  ") + text)
        if not ok:
            failures.append(text)

    # 1. Toon: every object pixel is one of the N shades COLOR x Table(I), nothing in between.
    toon = Scene(model, args.size, "toon")
    toon.npr.GetToonPass().SetNumberOfBands(args.bands)
    found = set(colors(toon.render())) - {(255, 255, 255)}  # the object: all but the background
    factor, shades = [0.0, 0.0, 0.0], []
    for k in range(args.bands):  # band k's factor, looked up in the middle of the band
        toon.npr.GetToonPass().GetShade((k + 0.5) / args.bands, factor)
        shades.append([round(255 * c * f) for c, f in zip(COLOR, factor)])
    strays = [c for c in found if all(max(abs(a - b) for a, b in zip(c, s)) > 1 for s in shades)]
    least = min(2, args.bands)  # the model faces several ways: more than one band shows
    check(least <= len(found) <= args.bands, "toon, bands %d: %d distinct colours on the object, "
          "expected %d..%d" % (args.bands, len(found), least, args.bands))
    check(not strays, "toon, bands %d: %d colours are no band's shade (within 1 of 255) %s"
          % (args.bands, len(strays), strays[:3]))

    # 2. The sketch's noise comes from the seed alone: fresh windows and passes, same pixels.
    uncertainty = args.uncertainty or 3.0  # without displacement every seed looks the same

    def sketch(seed):
        scene = Scene(model, args.size, "sketch")
        scene.npr.GetSketchPass().SetUncertainty(uncertainty)
        scene.npr.GetSketchPass().SetNoiseSeed(seed)
        return scene.render()

    first, again, other = sketch(args.seed), sketch(args.seed), sketch(args.seed + 1)
    same, moved = differing(first, again), differing(first, other)
    check(same == 0, "sketch, seed %d twice: %d pixels differ, expected 0" % (args.seed, same))
    check(moved > 0, "sketch, seeds %d and %d (uncertainty %g): %d pixels differ, expected some"
          % (args.seed, args.seed + 1, uncertainty, moved))

    # 3. Without uncertainty the sketch is the edge image of its flat colours, pixel for pixel.
    scene = Scene(model, args.size, "toon+edges")
    scene.npr.GetToonPass().SetNumberOfBands(1)
    scene.npr.GetToonPass().SetSpecular(False)
    edges = scene.render()
    lines = sum(max(c) < 100 for c in colors(edges))
    scene.npr.SetStyleToSketch()
    scene.npr.GetSketchPass().SetUncertainty(0.0)
    flat = differing(edges, scene.render())
    check(flat == 0 and lines > 0, "sketch, uncertainty 0: %d pixels differ from toon+edges with "
          "1 band (%d line pixels), expected 0 (and some lines)" % (flat, lines))

    # 4. An unchanged scene keeps its G-buffer: no geometry draw on the next frame.
    gbuffer = scene.npr.GetGBufferPass()
    draws = gbuffer.GetNumberOfGeometryDraws()
    scene.render()
    after = gbuffer.GetNumberOfGeometryDraws()
    check(after == draws, "sketch, rendered again, nothing changed: %d G-buffer draw(s) after %d, "
          "expected no more" % (after, draws))
    return len(failures)


def main():
    args = parse_arguments()
    model = read_model(args.model, "npr_toon_sketch")

    scene = Scene(model, args.size, args.style)
    scene.npr.GetToonPass().SetNumberOfBands(args.bands)
    sketch = scene.npr.GetSketchPass()
    sketch.SetUncertainty(args.uncertainty)
    sketch.SetNoiseSeed(args.seed)
    sketch.SetPaper(args.paper is not None)
    if args.paper:
        sketch.SetPaperColor(*args.paper)
    writer = vtkPNGWriter()
    writer.SetFileName(args.output)
    writer.SetInputData(scene.render())
    writer.Write()
    print("wrote %s (%s, %dx%d, %s)" % (args.output, args.style, args.size[0], args.size[1],
                                        vtkNPRRenderWindowFactory.GetGLRenderer(scene.window)))
    if not args.check:
        return 0
    failed = run_checks(model, args)
    print("%d failed" % failed)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
