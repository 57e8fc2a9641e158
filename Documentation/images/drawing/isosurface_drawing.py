# SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
# SPDX-License-Identifier: BSD-3-Clause
"""A scientific scene as a technical drawing: isosurfaces written as SVG by vtkNPRDrawingExporter.

    PYTHONPATH=build/lib/python3/dist-packages /usr/bin/python3 \
        Documentation/images/drawing/isosurface_drawing.py -o isosurface.svg [--hidden-lines]
        [--smooth-silhouettes] [--fill-faces face|surface|toon] [--outline]

The field is the density of three Gaussian sources (vtkGaussianSplatter, 130^3 samples), shown by
two isosurfaces (vtkContourFilter): the outer one, at 0.15, cut open by the plane z = 0.3
(vtkClipPolyData), and the inner one, at 0.6, one lobe around each source. The renderer draws
them through vtkNPRPass in the drawing style (hidden lines and smooth silhouettes on request) and
vtkNPRDrawingExporter writes the renderer's lines, with --fill-faces the faces filled under them
(the outer surface light blue, the inner one orange), and with --outline the field's outline box
(its back edges hidden behind the surfaces); the format comes from the extension (.svg, .pdf,
.ps, .eps).
make_images.sh in this folder runs it for drawing.md's pictures.
"""
import argparse
import sys

import vtknpr  # noqa: F401  (first: it imports the VTK modules it needs by itself)
from vtknpr import vtkNPRDrawingExporter, vtkNPRPass, vtkNPRRenderWindowFactory
from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkPlane, vtkPolyData
from vtkmodules.vtkFiltersCore import vtkClipPolyData, vtkContourFilter
from vtkmodules.vtkFiltersModeling import vtkOutlineFilter
from vtkmodules.vtkImagingHybrid import vtkGaussianSplatter
from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper, vtkRenderer
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (the OpenGL object factory overrides)


def parse_arguments():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("-o", "--output", required=True, help="drawing to write (.svg, .pdf, .ps, .eps)")
    parser.add_argument("--size", default="640x480", help="image size WxH in pixels (= points)")
    parser.add_argument("--hidden-lines", action="store_true", help="also draw the hidden lines, dashed")
    parser.add_argument("--smooth-silhouettes", action="store_true",
                        help="silhouettes as the smooth contours of the isosurfaces' normals")
    parser.add_argument("--fill-faces", choices=("face", "surface", "toon"),
                        help="fill the faces under the lines, in these colours")
    parser.add_argument("--outline", action="store_true", help="draw the field's outline box")
    parser.add_argument("--azimuth", type=float, default=20.0)
    parser.add_argument("--elevation", type=float, default=35.0)
    return parser.parse_args()


def isosurface_actor(field, level, color, clip_above=None):
    """The isosurface of `field` at `level`, without its part above z = clip_above if given."""
    contour = vtkContourFilter()
    contour.SetInputConnection(field.GetOutputPort())
    contour.SetValue(0, level)
    contour.ComputeScalarsOff()
    port = contour.GetOutputPort()
    if clip_above is not None:
        plane = vtkPlane()
        plane.SetOrigin(0.0, 0.0, clip_above)
        plane.SetNormal(0.0, 0.0, 1.0)
        clip = vtkClipPolyData()
        clip.SetInputConnection(port)
        clip.SetClipFunction(plane)
        clip.InsideOutOn()  # keep z <= clip_above
        port = clip.GetOutputPort()
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(port)
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetColor(*color)
    return actor


def outline_actor(field):
    outline = vtkOutlineFilter()
    outline.SetInputConnection(field.GetOutputPort())
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(outline.GetOutputPort())
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetColor(0.1, 0.2, 0.5)
    return actor


def isosurface_renderer(azimuth, elevation, outline):
    sources = vtkPoints()
    weights = vtkDoubleArray()
    for x, y, weight in ((-1.3, -0.7, 1.0), (1.3, -0.7, 1.0), (0.0, 1.3, 0.8)):
        sources.InsertNextPoint(x, y, 0.0)
        weights.InsertNextValue(weight)
    points = vtkPolyData()
    points.SetPoints(sources)
    points.GetPointData().SetScalars(weights)
    field = vtkGaussianSplatter()  # weight x exp(-5 (r / R)^2) summed over the sources
    field.SetInputData(points)
    field.SetModelBounds(-4, 4, -4, 4, -4, 4)
    field.SetSampleDimensions(130, 130, 130)
    field.SetRadius(0.4)  # R, as a fraction of the bounds' diagonal
    field.ScalarWarpingOn()
    field.NormalWarpingOff()
    field.CappingOff()
    renderer = vtkRenderer()
    renderer.SetBackground(1.0, 1.0, 1.0)
    renderer.AddActor(isosurface_actor(field, 0.15, (0.65, 0.8, 0.95), clip_above=0.3))
    renderer.AddActor(isosurface_actor(field, 0.6, (1.0, 0.6, 0.25)))
    if outline:
        renderer.AddActor(outline_actor(field))
    renderer.ResetCamera()
    renderer.GetActiveCamera().Azimuth(azimuth)
    renderer.GetActiveCamera().Elevation(elevation)
    renderer.GetActiveCamera().OrthogonalizeViewUp()
    renderer.ResetCamera()
    return renderer


def main():
    args = parse_arguments()
    width, height = (int(v) for v in args.size.split("x"))
    window = vtkNPRRenderWindowFactory.CreateRenderWindow()
    if window is None:
        sys.exit("isosurface_drawing: error: no headless render window")
    window.SetSize(width, height)
    renderer = isosurface_renderer(args.azimuth, args.elevation, args.outline)
    window.AddRenderer(renderer)
    npr = vtkNPRPass()
    npr.SetStyleToDrawing()
    npr.SetHiddenLines(args.hidden_lines)
    npr.GetEdgePass().SetSmoothSilhouettes(args.smooth_silhouettes)
    renderer.SetPass(npr)
    window.Render()

    exporter = vtkNPRDrawingExporter()
    exporter.SetRenderWindow(window)
    exporter.SetFileName(args.output)
    if args.fill_faces:
        exporter.FillFacesOn()
        exporter.SetFillColors({"face": vtkNPRDrawingExporter.FACE_COLOR,
                                "surface": vtkNPRDrawingExporter.SURFACE_COLORS,
                                "toon": vtkNPRDrawingExporter.TOON_BANDS}[args.fill_faces])
    if not exporter.Write():
        sys.exit("isosurface_drawing: error: " + exporter.GetErrorMessage())
    lines = exporter.GetDrawingLines()
    print("isosurface_drawing: wrote %s: %d strokes (%d hidden) from %d feature edges, %d faces"
          " filled" % (args.output, exporter.GetNumberOfStrokes(), exporter.GetNumberOfStrokes(0),
                       lines.GetNumberOfFeatureEdges(), exporter.GetNumberOfFilledFaces()))
    renderer.SetPass(None)
    npr.ReleaseGraphicsResources(window)
    return 0


if __name__ == "__main__":
    sys.exit(main())
