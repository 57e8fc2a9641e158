# SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
# SPDX-License-Identifier: BSD-3-Clause
"""PyVista programs run as clients of vtknpr.pyvista (run_examples.py), none needing a download.

Two kinds, each a function that builds a pyvista.Plotter and calls show(), as a user's script does:
- PyVista's own demos, shipped in the python3-pyvista package (pyvista/demos/demos.py), called
  unchanged;
- scenes written for this project after topics of PyVista's example gallery (the gallery's
  scripts are not packaged by Debian), on PyVista's bundled data sets and generated data.

The runner turns the style on in every renderer of each plotter when show() is called.
"""
import numpy as np
import pyvista as pv
from pyvista import demos, examples

# name -> (where it comes from, function)
CORPUS = {}


def client(name, source):
    def register(function):
        CORPUS[name] = (source, function)
        return function
    return register


def show_outlined(plotter, data):
    """Shows the plotter with the data set's outline in black, as the gallery frames its data."""
    plotter.add_mesh(data.outline(), color="black")
    plotter.show()


# ---- PyVista's own demos, unchanged ------------------------------------------------------------
CORPUS["demo_glyphs"] = ("pyvista.demos.plot_glyphs (supertoroid glyphs, scalars)",
                         lambda: demos.plot_glyphs(2))
CORPUS["demo_ants_plane"] = ("pyvista.demos.plot_ants_plane (meshes, scalars, text, scalar bar)",
                             demos.plot_ants_plane)
CORPUS["demo_beam"] = ("pyvista.demos.plot_beam (hexahedral beam, scalars, camera, text)",
                       demos.plot_beam)
CORPUS["demo_orientation"] = ("pyvista.demos.orientation_plotter (a cube with labelled faces)",
                              lambda: demos.orientation_plotter().show())


# ---- Gallery topics, on bundled or generated data ------------------------------------------------
@client("isosurfaces", "gallery topic: contouring (examples.load_uniform, bundled)")
def isosurfaces():
    grid = examples.load_uniform()
    plotter = pv.Plotter()
    plotter.add_mesh(grid.outline(), color="black")
    plotter.add_mesh(grid.contour(5, scalars="Spatial Point Data"), smooth_shading=True,
                     cmap="viridis")
    plotter.show()


@client("glyphs", "gallery topic: plotting glyphs (vectors on a sphere, generated)")
def glyphs():
    sphere = pv.Sphere(radius=1.0, theta_resolution=12, phi_resolution=12)
    sphere["vectors"] = sphere.points * 0.3
    arrows = sphere.glyph(orient="vectors", scale=False, factor=0.25)
    plotter = pv.Plotter()
    plotter.add_mesh(sphere, color="white")
    plotter.add_mesh(arrows, color="tomato")
    plotter.show()


@client("streamlines", "gallery topic: streamlines (a swirl on a generated grid)")
def streamlines():
    grid = pv.ImageData(dimensions=(20, 20, 20), spacing=(0.1, 0.1, 0.1), origin=(-1, -1, -1))
    x, y, z = grid.points.T
    grid["vectors"] = np.column_stack((-y, x, 0.2 * np.ones_like(z)))
    # Seeds on a ring (PyVista's random point-cloud seeds would change the image run to run).
    angles = np.linspace(0.0, 2.0 * np.pi, 12, endpoint=False)
    seeds = pv.PolyData(np.column_stack((0.6 * np.cos(angles), 0.6 * np.sin(angles),
                                         np.full_like(angles, -0.8))))
    lines = grid.streamlines_from_source(seeds, vectors="vectors")
    plotter = pv.Plotter()
    plotter.add_mesh(lines, line_width=2, color="navy")
    plotter.add_mesh(lines.tube(radius=0.02), color="orange")
    plotter.add_mesh(grid.outline(), color="grey")
    plotter.show()


@client("clipping", "gallery topic: clipping with a plane (examples.load_hexbeam, bundled)")
def clipping():
    beam = examples.load_hexbeam()
    plotter = pv.Plotter()
    plotter.add_mesh(beam.clip(normal="x", origin=beam.center), show_edges=True,
                     scalars="sample_cell_scalars")
    show_outlined(plotter, beam)


@client("volume", "gallery topic: volume rendering (examples.load_channels, bundled)")
def volume():
    channels = examples.load_channels()
    plotter = pv.Plotter()
    plotter.add_volume(channels, cmap="viridis", opacity="linear")
    above = np.array(channels.center) + (0.0, 0.0, 60.0)  # a surface clear of the volume
    plotter.add_mesh(pv.Sphere(radius=40, center=above), color="white")
    show_outlined(plotter, channels)


@client("point_cloud", "gallery topic: point clouds (the ant's vertices, bundled)")
def point_cloud():
    ant = examples.load_ant()
    plotter = pv.Plotter()
    plotter.add_points(ant.points, color="purple", point_size=4)
    plotter.add_mesh(ant.translate((30, 0, 0), inplace=False), color="tan")
    plotter.show()


@client("subplots", "gallery topic: multi-window plots (examples.load_airplane, load_nut, bundled)")
def subplots():
    plotter = pv.Plotter(shape=(1, 2))
    plotter.subplot(0, 0)
    plotter.add_mesh(examples.load_airplane(), color="lightblue")
    plotter.add_text("airplane", font_size=10)
    plotter.subplot(0, 1)
    plotter.add_mesh(examples.load_nut(), color="goldenrod", smooth_shading=True)
    plotter.add_text("nut", font_size=10)
    plotter.show()


@client("text", "gallery topic: labels and text (point labels, 2D text, generated)")
def text():
    cube = pv.Cube()
    plotter = pv.Plotter()
    plotter.add_mesh(cube, color="lightgrey")
    plotter.add_point_labels(cube.points[:4], ["a", "b", "c", "d"], point_size=8, font_size=14)
    plotter.add_text("corners", position="upper_left")
    plotter.show_bounds(color="black")
    plotter.show()


@client("scalar_bar", "gallery topic: scalar bars (elevation of generated hills)")
def scalar_bar():
    hills = pv.ParametricRandomHills(random_seed=2).elevation()
    plotter = pv.Plotter()
    plotter.add_mesh(hills, scalars="Elevation", cmap="terrain",
                     scalar_bar_args={"title": "Elevation", "vertical": True})
    plotter.show()
