# SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
# SPDX-License-Identifier: BSD-3-Clause
"""A scientific scene as a technical drawing: isosurfaces written as SVG by vtkNPRDrawingExporter.

    PYTHONPATH=build/lib/python3/dist-packages /usr/bin/python3 \
        Documentation/images/drawing/isosurface_drawing.py -o isosurface.svg [--hidden-lines]
        [--smooth-silhouettes] [--fill-faces face|surface|toon] [--outline] [--annotate]

The field is the density of three Gaussian sources (vtkGaussianSplatter, 130^3 samples), shown by
two isosurfaces (vtkContourFilter): the outer one, at 0.15, cut open by the plane z = 0.3
(vtkClipPolyData), and the inner one, at 0.6, one lobe around each source. The renderer draws
them through vtkNPRPass in the drawing style (hidden lines and smooth silhouettes on request) and
vtkNPRDrawingExporter writes the renderer's lines, with --fill-faces the faces filled under them
(the outer surface light blue, the inner one orange), and with --outline the field's outline box
(its back edges hidden behind the surfaces), and with --annotate the outer surface coloured by
height with its scalar bar, the three sources marked by round points above them and a title (the points as vector
discs, the title as glyph outlines and the scalar bar as an image in the file); the format comes
from the extension (.svg, .pdf, .ps, .eps).
make_images.sh in this folder runs it for drawing.md's pictures.
"""
import argparse
import sys

import vtknpr  # noqa: F401  (first: it imports the VTK modules it needs by itself)
from vtknpr import vtkNPRDrawingExporter, vtkNPRPass, vtkNPRRenderWindowFactory
from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkPlane, vtkPolyData
from vtkmodules.vtkCommonCore import vtkLookupTable
from vtkmodules.vtkCommonDataModel import vtkCellArray
from vtkmodules.vtkFiltersCore import vtkClipPolyData, vtkContourFilter, vtkElevationFilter
from vtkmodules.vtkFiltersModeling import vtkOutlineFilter
from vtkmodules.vtkImagingHybrid import vtkGaussianSplatter
from vtkmodules.vtkRenderingAnnotation import vtkScalarBarActor
from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper, vtkRenderer, vtkTextActor
import vtkmodules.vtkRenderingFreeType  # noqa: F401  (the title's and the scalar bar's text)
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
    parser.add_argument("--annotate", action="store_true",
                        help="colour the outer surface by height, with a scalar bar, points above "
                             "the sources and a title")
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


def annotate(renderer, outer, points):
    """The outer surface coloured by height (z from -2 to 0.3), its scalar bar, the sources
    marked above the surfaces by round points (vertex cells, 10 px) and a title."""
    mapper = outer.GetMapper()
    height = vtkElevationFilter()
    height.SetInputConnection(mapper.GetInputConnection(0, 0))
    height.SetLowPoint(0.0, 0.0, -2.0)
    height.SetHighPoint(0.0, 0.0, 0.3)
    height.SetScalarRange(-2.0, 0.3)
    colours = vtkLookupTable()
    colours.SetHueRange(0.6, 0.45)
    colours.SetSaturationRange(0.25, 0.6)
    colours.SetTableRange(-2.0, 0.3)
    colours.Build()
    mapper.SetInputConnection(height.GetOutputPort())
    mapper.SetLookupTable(colours)
    mapper.SetScalarRange(-2.0, 0.3)
    mapper.ScalarVisibilityOn()
    bar = vtkScalarBarActor()
    bar.SetLookupTable(colours)
    bar.SetTitle("z")
    bar.SetNumberOfLabels(3)
    bar.SetPosition(0.87, 0.1)
    bar.SetWidth(0.11)
    bar.SetHeight(0.6)
    bar.UnconstrainedFontSizeOn()
    for text in (bar.GetTitleTextProperty(), bar.GetLabelTextProperty()):
        text.SetColor(0.1, 0.1, 0.1)
        text.SetFontSize(14)
        text.ShadowOff()
    renderer.AddViewProp(bar)
    above = vtkPoints()  # the sources lie inside the inner surface: marked above it, at z = 1.5
    cells = vtkCellArray()
    for index in range(points.GetNumberOfPoints()):
        x, y, _ = points.GetPoint(index)
        cells.InsertNextCell(1)
        cells.InsertCellPoint(above.InsertNextPoint(x, y, 1.5))
    centres = vtkPolyData()
    centres.SetPoints(above)
    centres.SetVerts(cells)
    marks = vtkActor()
    marks.SetMapper(vtkPolyDataMapper())
    marks.GetMapper().SetInputData(centres)
    marks.GetMapper().ScalarVisibilityOff()
    marks.GetProperty().SetColor(0.75, 0.1, 0.1)
    marks.GetProperty().SetPointSize(10)
    marks.GetProperty().RenderPointsAsSpheresOn()
    renderer.AddActor(marks)
    title = vtkTextActor()
    title.SetInput("Three Gaussian sources: isosurfaces 0.15 and 0.6")
    title.SetPosition(12, 10)
    title.GetTextProperty().SetFontSize(16)
    title.GetTextProperty().SetColor(0.1, 0.1, 0.1)
    renderer.AddViewProp(title)


def isosurface_renderer(azimuth, elevation, outline, annotated=False):
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
    outer = isosurface_actor(field, 0.15, (0.65, 0.8, 0.95), clip_above=0.3)
    renderer.AddActor(outer)
    renderer.AddActor(isosurface_actor(field, 0.6, (1.0, 0.6, 0.25)))
    if annotated:
        annotate(renderer, outer, points)
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
    renderer = isosurface_renderer(args.azimuth, args.elevation, args.outline, args.annotate)
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
          " filled, %d points, %d texts, %d 2D props as an image"
          % (args.output, exporter.GetNumberOfStrokes() - exporter.GetNumberOfStrokes(7)
             - exporter.GetNumberOfStrokes(8), exporter.GetNumberOfStrokes(0),
             lines.GetNumberOfFeatureEdges(), exporter.GetNumberOfFilledFaces(),
             exporter.GetNumberOfStrokes(7), exporter.GetNumberOfTexts(),
             exporter.GetNumberOfImagedOverlays()))
    renderer.SetPass(None)
    npr.ReleaseGraphicsResources(window)
    return 0


if __name__ == "__main__":
    sys.exit(main())
