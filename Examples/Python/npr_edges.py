# SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
# SPDX-License-Identifier: BSD-3-Clause
"""Line drawing of one model with vtkNPRPass, rendered headless (EGL, no X server) to a PNG.

    PYTHONPATH=build/lib/python3/dist-packages /usr/bin/python3 Examples/Python/npr_edges.py \
        Testing/Data/cad_part.vtp -o cad_part.png --line-width 2 --silhouette-color 0.8,0,0

Models: whatever vtkNPRModelReader reads (.stl .obj .ply .vtp .vtk .gltf .glb .off).

With --check the script also verifies the result and exits 1 when a check fails, so that it runs
as a test: the image has lines around the object, a second render with nothing changed reuses the
G-buffer and the line image, and the shaded style (no lines) has far fewer dark pixels. The checks
expect dark lines (the default black) on the light surfaces and white background used here.
"""
import argparse
import sys

import vtknpr  # noqa: F401  (first: it imports the VTK modules it needs by itself)
from vtknpr import vtkNPRPass, vtkNPRRenderWindowFactory
from vtkmodules.vtkIOImage import vtkPNGWriter
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (the OpenGL object factory overrides)

from npr_example_common import grab, model_renderer, read_model, rgb, size, view_from

DARK = 60  # a pixel is dark when its brightest channel is below this (0..255)


def parse_arguments():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("model", help="model file")
    parser.add_argument("-o", "--output", required=True, help="PNG to write")
    parser.add_argument("--size", type=size, default=[800, 600], metavar="WxH",
                        help="image size in pixels (default 800x600)")
    parser.add_argument("--line-width", type=float, default=1.5, metavar="PX",
                        help="line width in pixels, 0.5..16 (default 1.5)")
    parser.add_argument("--crease-angle", type=float, default=30.0, metavar="DEG",
                        help="normal angle that makes a crease, 1..179 degrees (default 30)")
    parser.add_argument("--silhouette-color", type=rgb, default=[0.0, 0.0, 0.0], metavar="R,G,B",
                        help="silhouette colour, each part in 0..1 (default 0,0,0)")
    parser.add_argument("--azimuth", type=float, default=30.0, metavar="DEG",
                        help="camera azimuth after the reset (default 30)")
    parser.add_argument("--elevation", type=float, default=30.0, metavar="DEG",
                        help="camera elevation after the reset (default 30)")
    parser.add_argument("--check", action="store_true", help="verify the result; exit 1 on failure")
    return parser.parse_args()


def pixels(image):
    """(width, height, components, bytes) of an 8-bit image."""
    scalars = image.GetPointData().GetScalars()
    width, height, _ = image.GetDimensions()
    return width, height, scalars.GetNumberOfComponents(), memoryview(scalars).cast("B")


def object_box(image):
    """(x0, y0, x1, y1), inclusive: the box of the pixels that are not white background."""
    width, height, components, data = pixels(image)
    xs, ys = [], []
    for y in range(height):
        for x in range(width):
            i = (y * width + x) * components
            if data[i] < 255 or data[i + 1] < 255 or data[i + 2] < 255:
                xs.append(x)
                ys.append(y)
    return (min(xs), min(ys), max(xs), max(ys)) if xs else None


def count_dark(image, box):
    """Number of pixels with every channel below DARK inside box (x0, y0, x1, y1), inclusive."""
    width, _, components, data = pixels(image)
    dark = 0
    for y in range(box[1], box[3] + 1):
        for x in range(box[0], box[2] + 1):
            i = (y * width + x) * components
            if data[i] < DARK and data[i + 1] < DARK and data[i + 2] < DARK:
                dark += 1
    return dark


def main():
    args = parse_arguments()
    model = read_model(args.model, "npr_edges")

    renderer = model_renderer(model, (0.85, 0.82, 0.75))

    # The whole line-drawing chain in one pass; its edge pass takes the tuning.
    npr = vtkNPRPass()
    edges = npr.GetEdgePass()
    edges.SetLineWidth(args.line_width)
    edges.SetCreaseAngle(args.crease_angle)
    edges.SetSilhouetteColor(*args.silhouette_color)
    renderer.SetPass(npr)

    window = vtkNPRRenderWindowFactory.CreateRenderWindow()  # NPR_BACKEND, else EGL: headless
    if window is None:
        sys.exit("npr_edges: error: no headless render window (see Documentation/backends.md)")
    window.SetMultiSamples(0)  # the pass anti-aliases its lines itself
    window.SetSize(*args.size)
    window.AddRenderer(renderer)
    view_from(renderer, args.azimuth, args.elevation)
    window.Render()

    edge_image = grab(window)
    writer = vtkPNGWriter()
    writer.SetFileName(args.output)
    writer.SetInputData(edge_image)
    writer.Write()
    print("wrote %s (%dx%d, %s)" % (args.output, args.size[0], args.size[1],
                                    vtkNPRRenderWindowFactory.GetGLRenderer(window)))
    if not args.check:
        return 0

    failures = []

    def check(ok, text):
        print(("ok      " if ok else "FAILED  ") + text)
        if not ok:
            failures.append(text)

    # An unchanged scene reuses the G-buffer and the line image.
    gbuffer = npr.GetGBufferPass()
    window.Render()
    check(gbuffer.GetNumberOfGeometryDraws() == 1, "two renders, nothing changed: %d G-buffer "
          "draw(s), expected 1" % gbuffer.GetNumberOfGeometryDraws())
    check(edges.GetNumberOfLineImageUpdates() == 1, "two renders, nothing changed: %d line image "
          "update(s), expected 1" % edges.GetNumberOfLineImageUpdates())
    check(gbuffer.GetWritesNormals(), "the G-buffer holds normals (creases are on)")

    # The shaded style: VTK's own opaque step, no G-buffer, no lines.
    draws = gbuffer.GetNumberOfGeometryDraws()
    npr.SetStyleToShaded()
    window.Render()
    shaded_image = grab(window)
    check(gbuffer.GetNumberOfGeometryDraws() == draws, "shaded: no G-buffer draw")

    # Lines around the object. Its outline is a closed curve touching the four sides of its
    # screen box (w x h), so it is at least 2 x sqrt(w^2 + h^2) pixels long (a quadrilateral
    # inscribed in a rectangle has a perimeter of at least twice the diagonal), and a line along
    # it crosses at least 1/sqrt(2) pixel rows or columns per pixel of length, each with a dark
    # core pixel: sqrt(2) x diagonal dark pixels from the outline alone. Asking for one diagonal
    # leaves 30 % of that to anti-aliasing, and ignores every line inside the object.
    box = object_box(shaded_image)
    check(box is not None, "the object is in view")
    if box:
        margin = 3  # lines on the background side of the outline
        box = (max(0, box[0] - margin), max(0, box[1] - margin),
               min(args.size[0] - 1, box[2] + margin), min(args.size[1] - 1, box[3] + margin))
        needed = int(((box[2] - box[0]) ** 2 + (box[3] - box[1]) ** 2) ** 0.5)
        edge_dark = count_dark(edge_image, box)
        check(edge_dark > needed, "edges: %d dark pixels in the object's box %s, more than %d"
              % (edge_dark, box, needed))
        # Without lines, at least the outline's share of dark pixels goes (dark shading stays).
        shaded_dark = count_dark(shaded_image, box)
        check(edge_dark - shaded_dark > needed, "shaded: %d dark pixels, more than %d fewer than "
              "the %d with edges" % (shaded_dark, needed, edge_dark))

    print("%d failed" % len(failures))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
