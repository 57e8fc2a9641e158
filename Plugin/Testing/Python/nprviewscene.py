# SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
# SPDX-License-Identifier: BSD-3-Clause
"""The scene and image helpers shared by the plugin's tests (TestNPRView.py, TestNPRClientServer.py)
and the documentation's screenshot script."""
import argparse
import os

from paraview.simple import Box, ColorBy, Contour, CreateView, Cylinder, Show, Wavelet
from vtkmodules.vtkIOImage import vtkPNGReader
from vtkmodules.util.numpy_support import vtk_to_numpy

SIZE = [400, 300]
STYLES = ["Shaded", "Edges", "Toon", "Toon+Edges", "Sketch", "Inked", "Drawing"]


def plugin_arguments(*extra):
    """Parse --plugin and --output-dir, besides the flags named in extra (each a name and
    add_argument's keywords), and make the output folder."""
    ap = argparse.ArgumentParser()
    ap.add_argument("--plugin", required=True)
    ap.add_argument("--output-dir", required=True)
    for name, options in extra:
        ap.add_argument(name, **options)
    args = ap.parse_args()
    os.makedirs(args.output_dir, exist_ok=True)
    return args


def create_view(size=SIZE):
    """A "Render View (NPR)" of that size on a white background, without the orientation axes."""
    view = CreateView("NPRRenderView")
    view.ViewSize = size
    view.OrientationAxesVisibility = 0
    if hasattr(view, "UseColorPaletteForBackground"):
        view.UseColorPaletteForBackground = 0
    view.Background = [1.0, 1.0, 1.0]
    return view


def create_scene(size=SIZE):
    """A "Render View (NPR)" on a white background showing CAD-like parts (a plate, a pin) and a
    contour of the Wavelet source (split between ranks under MPI). Returns the view and the
    sources by name."""
    view = create_view(size)
    sources = {
        "box": Box(XLength=26, YLength=2, ZLength=22, Center=[0, -12, 0]),
        "cylinder": Cylinder(Resolution=48, Radius=2.5, Height=12, Center=[-14, -5, 6]),
    }
    sources["contour"] = Contour(Input=Wavelet(), ContourBy=["POINTS", "RTData"],
                                 Isosurfaces=[157.0])
    colours = {"box": [0.8, 0.8, 0.85], "cylinder": [0.9, 0.7, 0.4], "contour": [0.5, 0.7, 0.9]}
    for name, source in sources.items():
        display = Show(source, view)
        ColorBy(display, ("POINTS", None))
        display.DiffuseColor = colours[name]
        display.AmbientColor = colours[name]
    view.CameraPosition = [18, 14, 30]
    view.CameraFocalPoint = [-1, -1, 0]
    view.CameraViewUp = [0, 1, 0]
    view.CameraViewAngle = 30
    view.ResetCamera()
    return view, sources


def read_png(path):
    """An RGB image file as an integer array (rows from the bottom, as VTK stores them)."""
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    if image.GetNumberOfPoints() == 0:
        raise RuntimeError("cannot read the image " + path)
    w, h, _ = image.GetDimensions()
    return vtk_to_numpy(image.GetPointData().GetScalars()).reshape(h, w, -1)[..., :3].astype(int)


def dark(img):
    """The number of line-dark pixels."""
    return int((img.sum(axis=2) < 150).sum())
