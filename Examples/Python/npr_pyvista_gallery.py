# SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
# SPDX-License-Identifier: BSD-3-Clause
"""The six vtkNPR styles on a PyVista scene, tiled into one PNG (the gallery of pyvista.md).

    PYTHONPATH=build/lib/python3/dist-packages python3 Examples/Python/npr_pyvista_gallery.py \\
        -o gallery.png

The scene is PyVista's bundled hexahedral beam, bent, coloured by its displacement, clipped,
with its outline and an isosurface of a generated field beside it: the kind of figure a
scientist makes with PyVista. Needs PyVista (Debian 13 and later: python3-pyvista).
"""
import argparse
import sys

import numpy as np
import pyvista as pv
from pyvista import examples

from vtknpr.pyvista import STYLES, enable_npr


def scene(plotter):
    beam = examples.load_hexbeam()
    displacement = beam.points[:, 2] ** 3 / 250
    beam.points[:, 1] += displacement
    beam["displacement"] = displacement
    clipped = beam.clip(normal="x", origin=beam.center)
    plotter.add_mesh(clipped, scalars="displacement", cmap="coolwarm", show_scalar_bar=False)
    plotter.add_mesh(beam.outline(), color="black")
    field = pv.ImageData(dimensions=(40, 40, 40), spacing=(0.05, 0.05, 0.05),
                         origin=(-2.5, -1.0, 0.0))
    x, y, z = field.points.T
    field["f"] = np.sin(4 * x) * np.cos(4 * y) + z
    plotter.add_mesh(field.contour([1.2]), color="wheat", smooth_shading=True)
    plotter.view_isometric()
    plotter.reset_camera()
    plotter.camera.zoom(0.95)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("-o", "--output", required=True, help="PNG to write")
    parser.add_argument("--tile", type=int, default=320, help="tile width in pixels")
    args = parser.parse_args()
    pv.OFF_SCREEN = True
    tiles = []
    for style in STYLES:
        plotter = pv.Plotter(off_screen=True, window_size=[args.tile, args.tile * 3 // 4])
        plotter.set_background("white")
        scene(plotter)
        enable_npr(plotter, style, line_width=1.5)
        plotter.add_text(style, font_size=9, color="black")
        plotter.render()
        tiles.append(np.array(plotter.screenshot(return_img=True)))
        plotter.close()
    rows = [np.concatenate(tiles[i:i + 3], axis=1) for i in (0, 3)]
    image = np.concatenate(rows, axis=0)
    grid = pv.ImageData(dimensions=(image.shape[1], image.shape[0], 1))
    grid.point_data["rgb"] = np.ascontiguousarray(image[::-1]).reshape(-1, 3)
    from vtkmodules.vtkIOImage import vtkPNGWriter
    writer = vtkPNGWriter()
    writer.SetFileName(args.output)
    writer.SetInputData(grid)
    writer.Write()
    print("npr_pyvista_gallery: wrote %s (%d styles)" % (args.output, len(STYLES)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
