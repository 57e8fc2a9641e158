# SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
# SPDX-License-Identifier: BSD-3-Clause
"""Installed python3-vtknpr and vtknpr-tools (Utilities/check-packages.sh, in a clean chroot):

  check_vtknpr.py python VERSION        vtknpr imports from the system's Python with no
                                        PYTHONPATH, has VERSION, and renders a cube through
                                        vtkNPRPass (edges) headless: its 9 visible edges drawn
  check_vtknpr.py image PNG             npr-render's image of the CAD part has dark lines on a
                                        white background
Exits non-zero with the reason on failure."""
import sys


def line_pixels(image, threshold=60):
    scalars = image.GetPointData().GetScalars()
    components = scalars.GetNumberOfComponents()
    count = 0
    for i in range(image.GetNumberOfPoints()):
        if max(scalars.GetComponent(i, c) for c in range(min(3, components))) < threshold:
            count += 1
    return count, image.GetNumberOfPoints()


def check_python(version):
    import vtknpr
    from vtknpr import vtkNPRPass, vtkNPRRenderWindowFactory
    from vtkmodules.vtkFiltersSources import vtkCubeSource
    from vtkmodules.vtkRenderingCore import (vtkActor, vtkPolyDataMapper, vtkRenderer,
                                             vtkWindowToImageFilter)
    import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (object factory overrides)

    assert vtknpr.__version__ == version, (vtknpr.__version__, version)
    assert vtknpr.__file__.startswith("/usr/lib/python3"), vtknpr.__file__
    window = vtkNPRRenderWindowFactory.CreateRenderWindow("egl")
    assert window is not None, "no EGL window"
    window.SetSize(320, 240)
    window.SetMultiSamples(0)
    cube = vtkCubeSource()
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(cube.GetOutputPort())
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetColor(1, 1, 1)
    actor.GetProperty().SetAmbient(1)
    actor.GetProperty().SetDiffuse(0)
    renderer = vtkRenderer()
    renderer.SetBackground(1, 1, 1)
    renderer.AddActor(actor)
    renderer.GetActiveCamera().Azimuth(30)
    renderer.GetActiveCamera().Elevation(30)
    renderer.ResetCamera()
    window.AddRenderer(renderer)

    def grab():
        window.Render()
        capture = vtkWindowToImageFilter()
        capture.SetInput(window)
        capture.ReadFrontBufferOff()
        capture.Update()
        return line_pixels(capture.GetOutput())

    plain, total = grab()
    npr = vtkNPRPass()
    npr.SetStyleToEdges()
    renderer.SetPass(npr)
    edges, _ = grab()
    print("vtkNPRPass on %s: %d line pixels of %d (%d without the pass)"
          % (vtkNPRRenderWindowFactory.GetGLRenderer(window), edges, total, plain))
    # A white cube on white: nothing dark without the pass; its 9 visible edges with it.
    assert plain == 0, plain
    assert 300 < edges < 0.2 * total, edges


def check_image(path):
    from vtkmodules.vtkIOImage import vtkPNGReader
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    assert image.GetNumberOfPoints() > 0, "not a PNG image: " + path
    lines, total = line_pixels(image)
    print("%s: %d line pixels of %d" % (path, lines, total))
    assert 500 < lines < 0.3 * total, lines


if __name__ == "__main__":
    if len(sys.argv) != 3 or sys.argv[1] not in ("python", "image"):
        sys.exit(__doc__)
    if sys.argv[1] == "python":
        check_python(sys.argv[2])
    else:
        check_image(sys.argv[2])
    print("passed")
