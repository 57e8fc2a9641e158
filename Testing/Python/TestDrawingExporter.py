# SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
# SPDX-License-Identifier: BSD-3-Clause
"""vtkNPRDrawingExporter from Python: reachable from vtknpr (and its vtkNPRPasses submodule),
writes an SVG of the CAD part with one <path> per stroke and the class groups, and reports an
unknown extension as an error naming the supported ones."""
import argparse
import os

parser = argparse.ArgumentParser()
parser.add_argument("data")
parser.add_argument("out")
args = parser.parse_args()

import vtknpr  # noqa: E402
from vtknpr import vtkNPRDrawingExporter, vtkNPRModelReader, vtkNPRPass  # noqa: E402
from vtknpr import vtkNPRRenderWindowFactory  # noqa: E402
from vtkmodules.vtkCommonCore import vtkOutputWindow  # noqa: E402
from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper, vtkRenderer  # noqa: E402
import vtkmodules.vtkRenderingOpenGL2  # noqa: E402,F401

assert vtknpr.vtkNPRPasses.vtkNPRDrawingExporter is vtkNPRDrawingExporter

window = vtkNPRRenderWindowFactory.CreateRenderWindow(None)
assert window is not None, "no headless window"
window.SetMultiSamples(0)
window.SetSize(400, 300)
renderer = vtkRenderer()
renderer.SetBackground(1, 1, 1)
npr = vtkNPRPass()
npr.SetStyleToEdges()
renderer.SetPass(npr)
window.AddRenderer(renderer)
reader = vtkNPRModelReader()
reader.SetFileName(os.path.join(args.data, "cad_part.vtp"))
mapper = vtkPolyDataMapper()
mapper.SetInputConnection(reader.GetOutputPort())
actor = vtkActor()
actor.SetMapper(mapper)
renderer.AddActor(actor)
renderer.ResetCamera()
renderer.GetActiveCamera().Azimuth(30)
renderer.GetActiveCamera().Elevation(30)
renderer.GetActiveCamera().OrthogonalizeViewUp()
renderer.ResetCameraClippingRange()
window.Render()

os.makedirs(args.out, exist_ok=True)
path = os.path.join(args.out, "python_drawing.svg")
exporter = vtkNPRDrawingExporter()
exporter.SetRenderWindow(window)
exporter.SetFileName(path)
assert exporter.Write(), exporter.GetErrorMessage()
svg = open(path).read()
strokes = exporter.GetNumberOfStrokes()
# Chained: far fewer strokes than feature edges.
assert 10 < strokes < exporter.GetDrawingLines().GetNumberOfFeatureEdges() / 4, strokes
assert svg.count("<path") == strokes, (svg.count("<path"), strokes)
assert exporter.GetDrawingLines().GetStrokes().GetNumberOfLines() == strokes
assert '<g class="npr-silhouette">' in svg and '<g class="npr-crease">' in svg
assert exporter.GetImageEmbedded() and "<image" in svg  # the edges style: the image under the lines
print("%s: %d strokes, %d bytes" % (path, strokes, len(svg)))

vtkOutputWindow.GetInstance().SetDisplayModeToNever()  # the expected error below
exporter.SetFileName(os.path.join(args.out, "python_drawing.png"))
assert not exporter.Write()
assert ".svg, .pdf, .ps, .eps" in exporter.GetErrorMessage(), exporter.GetErrorMessage()
assert not os.path.exists(os.path.join(args.out, "python_drawing.png"))
print("PASSED")
