# SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
# SPDX-License-Identifier: BSD-3-Clause
"""vtkNPRGBufferPass's depth-only mode in plain VTK: any delegate (here a whole
vtkRenderStepsPass) draws colour and depth, the G-buffer's depth and normals are derived from the
depth buffer, and vtkNPREdgePass draws silhouettes and creases from them. The lines must cover
about the same pixels as with the full G-buffer (vtkNPRPass, edges style).

The passes run in a bare vtkSequencePass, with no camera pass above them to set the viewport, as
ParaView's image-processing slot calls them: the composites must set their own viewport."""
import sys

import vtknpr  # noqa: F401
from vtknpr import (vtkNPREdgePass, vtkNPRGBufferPass, vtkNPRModelReader, vtkNPRPass,
                    vtkNPRRenderWindowFactory)
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import (vtkActor, vtkPolyDataMapper, vtkRenderer,
                                         vtkWindowToImageFilter)
from vtkmodules.vtkRenderingOpenGL2 import (vtkRenderPassCollection, vtkRenderStepsPass,
                                            vtkSequencePass)

reader = vtkNPRModelReader()
reader.SetFileName(sys.argv[1] + "/cad_part.vtp")
mapper = vtkPolyDataMapper()
mapper.SetInputConnection(reader.GetOutputPort())
actor = vtkActor()
actor.SetMapper(mapper)
actor.GetProperty().SetColor(0.8, 0.8, 0.8)
window = vtkNPRRenderWindowFactory.CreateRenderWindow("egl")
window.SetSize(320, 240)
window.SetMultiSamples(0)
renderer = vtkRenderer()
renderer.SetBackground(1, 1, 1)
renderer.AddActor(actor)
window.AddRenderer(renderer)
renderer.ResetCamera()
renderer.GetActiveCamera().Azimuth(30)
renderer.GetActiveCamera().Elevation(25)
renderer.ResetCamera()


def dark_pixels(name):
    window.Render()
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ReadFrontBufferOff()
    grab.ShouldRerenderOff()  # the frame as rendered
    grab.Update()
    if len(sys.argv) > 2:  # an output folder: keep the images
        writer = vtkPNGWriter()
        writer.SetFileName("%s/depth_only_%s.png" % (sys.argv[2], name))
        writer.SetInputConnection(grab.GetOutputPort())
        writer.Write()
    scalars = grab.GetOutput().GetPointData().GetScalars()
    n = grab.GetOutput().GetNumberOfPoints()
    return set(i for i in range(n) if sum(scalars.GetTuple(i)[:3]) < 150)


full = vtkNPRPass()
full.SetStyleToEdges()
renderer.SetPass(full)
reference = dark_pixels("full")

gbuffer = vtkNPRGBufferPass()
gbuffer.SetDepthOnly(True)
gbuffer.SetDelegatePass(vtkRenderStepsPass())
edges = vtkNPREdgePass()
edges.SetGBufferPass(gbuffer)
passes = vtkRenderPassCollection()
passes.AddItem(gbuffer)
passes.AddItem(edges)
sequence = vtkSequencePass()
sequence.SetPasses(passes)
renderer.SetPass(sequence)
# Nothing clears the window between the passes' frames here (as in ParaView): a frame with the
# model nearer leaves nearer depths behind, which the next frame's copy must replace.
camera = renderer.GetActiveCamera()
camera.Dolly(1.6)
renderer.ResetCameraClippingRange()
window.Render()
camera.Dolly(1.0 / 1.6)
renderer.ResetCameraClippingRange()
depth_only = dark_pixels("depth")
assert gbuffer.GetWritesNormals() and not gbuffer.GetWritesObjectIds()

def near(pixels):
    """The pixels and their 8 neighbours."""
    grown = set()
    for i in pixels:
        for dy in (-320, 0, 320):
            for dx in (-1, 0, 1):
                grown.add(i + dy + dx)
    return grown


precision = len(depth_only & near(reference)) / max(1, len(depth_only))
recall = len(reference & near(depth_only)) / max(1, len(reference))
print("line pixels: full G-buffer %d, depth-only %d; %.3f of the depth-only ones lie near a "
      "full-G-buffer line, %.3f of those near a depth-only one"
      % (len(reference), len(depth_only), precision, recall))
assert len(reference) > 500, len(reference)
assert 0.6 * len(reference) < len(depth_only) < 1.6 * len(reference), len(depth_only)
assert precision > 0.9, precision
assert recall > 0.9, recall
