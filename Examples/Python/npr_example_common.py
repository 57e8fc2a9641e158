# SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
# SPDX-License-Identifier: BSD-3-Clause
"""What the Python examples share: the single-model ones' (npr_edges.py, npr_toon_sketch.py)
argument types, the model with npr-render's normals and its renderer; and for all, the rendered
frame read back, and one frame of a scene in a pass (npr_scientific_scene.py, npr_stream_tubes.py)."""
import sys

import vtknpr  # noqa: F401  (first: it imports the VTK modules it needs by itself)
from vtknpr import vtkNPRModelReader, vtkNPRRenderWindowFactory
from vtkmodules.vtkCommonCore import vtkObject
from vtkmodules.vtkFiltersCore import vtkImageAppend, vtkPolyDataNormals
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import (vtkActor, vtkPolyDataMapper, vtkRenderer,
                                         vtkWindowToImageFilter)


def size(text):
    """'WxH' -> [W, H]"""
    width, height = (int(part) for part in text.split("x"))
    if width < 1 or height < 1:
        raise ValueError(text)
    return [width, height]


def rgb(text):
    """'r,g,b' with each part in 0..1 -> [r, g, b]"""
    parts = [float(part) for part in text.split(",")]
    if len(parts) != 3 or not all(0.0 <= part <= 1.0 for part in parts):
        raise ValueError(text)
    return parts


def read_model(file_name, program):
    """The model, with normals computed as npr-render does when the file has none; exits with
    the reader's message, after the program's name, when it cannot be read."""
    reader = vtkNPRModelReader()
    reader.SetFileName(file_name)
    vtkObject.GlobalWarningDisplayOff()  # the reader's one-line message is reported below
    reader.Update()
    vtkObject.GlobalWarningDisplayOn()
    if reader.GetErrorMessage():
        sys.exit(program + ": error: " + reader.GetErrorMessage())
    model = reader.GetOutput()
    if model.GetPointData().GetNormals() or model.GetNumberOfPolys() + model.GetNumberOfStrips() == 0:
        return model
    normals = vtkPolyDataNormals()  # smooth shading that keeps edges over 30 degrees sharp
    normals.SetInputData(model)
    normals.SetFeatureAngle(30.0)
    normals.SplittingOn()
    normals.ConsistencyOff()
    normals.Update()
    return normals.GetOutput()


def model_renderer(model, color):
    """A renderer on white with one actor: the model in one colour (its scalars ignored) and no
    specular, so that the shades come from the diffuse light alone."""
    mapper = vtkPolyDataMapper()
    mapper.SetInputData(model)
    mapper.ScalarVisibilityOff()
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetColor(*color)
    renderer = vtkRenderer()
    renderer.SetBackground(1.0, 1.0, 1.0)
    renderer.AddActor(actor)
    return renderer


def grab(window):
    """The image last rendered into the window (RGB, from the back buffer), a new one each call."""
    grabber = vtkWindowToImageFilter()
    grabber.SetInput(window)
    grabber.ReadFrontBufferOff()
    grabber.ShouldRerenderOff()  # the frame as rendered: no extra render
    grabber.Update()
    return grabber.GetOutput()  # a new output per grabber: no copy needed


def headless_window(width, height, program):
    """A headless render window of that size, multisampling off; exits with an error after the
    program's name when there is none."""
    window = vtkNPRRenderWindowFactory.CreateRenderWindow()
    if window is None:
        sys.exit(program + ": error: no headless render window")
    window.SetSize(width, height)
    window.SetMultiSamples(0)
    return window


def write_rows(rows, file_name):
    """Stacks the rows (lists of images of one height, the first row at the top) into one PNG."""
    stacked = vtkImageAppend()
    stacked.SetAppendAxis(1)
    for images in reversed(rows):  # an image's rows run bottom up
        row = vtkImageAppend()
        row.SetAppendAxis(0)
        for image in images:
            row.AddInputData(image)
        row.Update()
        stacked.AddInputData(row.GetOutput())
    stacked.Update()
    writer = vtkPNGWriter()
    writer.SetFileName(file_name)
    writer.SetInputData(stacked.GetOutput())
    writer.Write()


def render_in_pass(window, renderer, npr):
    """The renderer's image (RGB) in one frame drawn by the pass npr: the renderer is in the
    window for that frame only, and the pass lets go of its resources after it, so that a scene
    can be drawn again in another pass."""
    renderer.SetPass(npr)
    window.AddRenderer(renderer)
    window.Render()
    image = grab(window)
    window.RemoveRenderer(renderer)
    renderer.SetPass(None)
    npr.ReleaseGraphicsResources(window)
    return image


def view_from(renderer, azimuth, elevation):
    """Fits the camera to the scene (once the window exists: the reset fits its aspect ratio),
    then turns it by azimuth and elevation degrees."""
    renderer.ResetCamera()
    camera = renderer.GetActiveCamera()
    camera.Azimuth(azimuth)
    camera.Elevation(elevation)
    camera.OrthogonalizeViewUp()
    renderer.ResetCameraClippingRange()
