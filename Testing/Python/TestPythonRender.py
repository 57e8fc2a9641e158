# SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
# SPDX-License-Identifier: BSD-3-Clause
"""The Python wrapping: vtknpr imports with only PYTHONPATH set, has one submodule per VTK module
and every class at its top level, renders headless through the EGL window, reads a model, and
reports unavailable backends as None."""
import argparse
import os
import sys

parser = argparse.ArgumentParser()
parser.add_argument("data")
parser.add_argument("--expect-prefix", help="vtknpr must come from this install prefix")
parser.add_argument("--expect-version", required=True, help="vtknpr.__version__ must be this")
args = parser.parse_args()

import vtknpr  # noqa: E402  (first: it must pull in the VTK modules it needs by itself)
from vtknpr import vtkNPRModelReader, vtkNPRRenderWindowFactory  # noqa: E402
from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper, vtkRenderer  # noqa: E402
from vtkmodules.vtkRenderingCore import vtkWindowToImageFilter  # noqa: E402
import vtkmodules.vtkRenderingOpenGL2  # noqa: E402,F401  (object factory overrides)

# One submodule per VTK module; every class also at the top, as before the modules were split.
import importlib  # noqa: E402
expected = {
    "vtkNPRPasses": ["vtkNPRPass", "vtkNPRGBufferPass", "vtkNPREdgePass", "vtkNPRToonPass",
                     "vtkNPRSketchPass", "vtkNPRInkPass"],
    "vtkNPRLines": ["vtkNPRFeatureLines", "vtkNPRReferenceMask", "vtkNPRShadingNormals"],
    "vtkNPRIO": ["vtkNPRModelReader", "vtkNPROFFReader"],
    "vtkNPRHeadless": ["vtkNPRRenderWindowFactory"],
}
for submodule, classes in expected.items():
    module = importlib.import_module("vtknpr." + submodule)
    for name in classes:
        assert getattr(module, name) is getattr(vtknpr, name), (submodule, name)
headless = importlib.import_module("vtknpr.vtkNPRHeadless")
if hasattr(headless, "vtkNPREGLRenderWindow"):  # VTK 9.1-9.3: the module's own windows
    assert vtknpr.vtkNPROSMesaRenderWindow is headless.vtkNPROSMesaRenderWindow

assert vtknpr.__version__ == args.expect_version, (vtknpr.__version__, args.expect_version)

if args.expect_prefix:
    here = os.path.realpath(vtknpr.__file__)
    assert here.startswith(os.path.realpath(args.expect_prefix)), here

reader = vtkNPRModelReader()
reader.SetFileName(os.path.join(args.data, "rotor.ply"))
reader.Update()
assert reader.GetErrorMessage() == "", reader.GetErrorMessage()
assert reader.GetOutput().GetNumberOfCells() == 4800, reader.GetOutput().GetNumberOfCells()

window = vtkNPRRenderWindowFactory.CreateRenderWindow("egl")
assert window is not None, "no EGL window"
# The module's own EGL window up to VTK 9.3, VTK's from 9.4 on.
assert window.GetClassName() in ("vtkNPREGLRenderWindow", "vtkEGLRenderWindow"), window.GetClassName()
assert vtkNPRRenderWindowFactory.GetBackendName(window) == "egl"
window.SetSize(160, 120)
mapper = vtkPolyDataMapper()
mapper.SetInputConnection(reader.GetOutputPort())
actor = vtkActor()
actor.SetMapper(mapper)
actor.GetProperty().SetColor(0.9, 0.3, 0.1)
renderer = vtkRenderer()
renderer.SetBackground(0, 0, 0)
renderer.AddActor(actor)
window.AddRenderer(renderer)
renderer.ResetCamera()
window.Render()
print("renderer:", vtkNPRRenderWindowFactory.GetGLRenderer(window))
assert vtkNPRRenderWindowFactory.GetGLRenderer(window) != ""

grab = vtkWindowToImageFilter()
grab.SetInput(window)
grab.ReadFrontBufferOff()
grab.Update()
image = grab.GetOutput()
scalars = image.GetPointData().GetScalars()
n = image.GetNumberOfPoints()
lit = [scalars.GetTuple(i) for i in range(n)]
object_pixels = [p for p in lit if max(p[:3]) > 20]
print("object pixels: %d of %d" % (len(object_pixels), n))
assert 0.05 * n < len(object_pixels) < 0.9 * n, len(object_pixels)
assert all(p[0] >= p[2] for p in object_pixels), "the object is not orange-red"
assert max(p[0] for p in object_pixels) - min(p[0] for p in object_pixels) > 60, "no shading"

# Object-space lines and their ground-truth mask from Python: a cube's 12 creases; the mask of
# the rotor for this window has line pixels.
from vtknpr import vtkNPRFeatureLines, vtkNPRReferenceMask  # noqa: E402
from vtkmodules.vtkFiltersSources import vtkCubeSource  # noqa: E402
cube = vtkCubeSource()
lines = vtkNPRFeatureLines()
lines.SetInputConnection(cube.GetOutputPort())
lines.SilhouettesOff()
lines.Update()
assert lines.GetOutput().GetNumberOfLines() == 12, lines.GetOutput().GetNumberOfLines()
mask = vtkNPRReferenceMask()
mask.SetRenderer(renderer)
assert mask.Update()
values = mask.GetMask().GetPointData().GetScalars()
line_pixels = sum(1 for i in range(values.GetNumberOfTuples()) if values.GetValue(i) == 255)
print("reference mask line pixels:", line_pixels)
assert 100 < line_pixels < 0.3 * n, line_pixels

# Unavailable backends are None with a warning, never a crash.
from vtkmodules.vtkCommonCore import vtkObject  # noqa: E402
vtkObject.GlobalWarningDisplayOff()
import vtknpr  # noqa: E402
osmesa = vtkNPRRenderWindowFactory.CreateRenderWindow("osmesa")
if hasattr(vtknpr, "vtkNPROSMesaRenderWindow"):
    assert osmesa is None, "OSMesa from Python needs NPR::OSMesa, which Python is not linked with"
else:  # VTK 9.4+: VTK's OSMesa window where libOSMesa was found, else not in this build
    assert osmesa is None or vtkNPRRenderWindowFactory.GetBackendName(osmesa) == "osmesa"
assert vtkNPRRenderWindowFactory.CreateRenderWindow("nonsense") is None
print("1 passed, 0 failed")
