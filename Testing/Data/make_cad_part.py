#!/usr/bin/python3
"""Writes cad_part.vtp: a machined-looking part built from VTK sources (a base plate, a boss, a
flanged ring, a block with a pin through it and a chamfered wedge) for the line tests, the
documentation and the benchmark. Run with /usr/bin/python3 (Debian's VTK) from this folder."""
import math

from vtkmodules.vtkCommonCore import vtkIntArray
from vtkmodules.vtkFiltersCore import vtkAppendPolyData, vtkCleanPolyData, vtkTriangleFilter
from vtkmodules.vtkFiltersGeneral import vtkTransformPolyDataFilter
from vtkmodules.vtkFiltersModeling import vtkLinearExtrusionFilter
from vtkmodules.vtkFiltersSources import vtkCubeSource, vtkCylinderSource, vtkDiskSource
from vtkmodules.vtkCommonTransforms import vtkTransform
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter
from vtkmodules.vtkCommonDataModel import vtkPolyData, vtkCellArray
from vtkmodules.vtkCommonCore import vtkPoints


def placed(source, translate=(0, 0, 0), rotate=None):
    transform = vtkTransform()
    transform.Translate(*translate)
    if rotate:
        transform.RotateWXYZ(*rotate)
    moved = vtkTransformPolyDataFilter()
    moved.SetTransform(transform)
    moved.SetInputConnection(source.GetOutputPort())
    return moved


def box(x, y, z, center):
    cube = vtkCubeSource()
    cube.SetXLength(x)
    cube.SetYLength(y)
    cube.SetZLength(z)
    return placed(cube, center)


def cylinder(radius, height, center, rotate=None, resolution=48):
    cyl = vtkCylinderSource()  # axis along y
    cyl.SetRadius(radius)
    cyl.SetHeight(height)
    cyl.SetResolution(resolution)
    return placed(cyl, center, rotate)


def ring(inner, outer, height, center):
    disk = vtkDiskSource()
    disk.SetInnerRadius(inner)
    disk.SetOuterRadius(outer)
    disk.SetCircumferentialResolution(64)
    disk.SetRadialResolution(1)
    extrude = vtkLinearExtrusionFilter()
    extrude.SetInputConnection(disk.GetOutputPort())
    extrude.SetExtrusionTypeToVectorExtrusion()
    extrude.SetVector(0, 0, height)
    extrude.CappingOn()
    return placed(extrude, center, (-90, 1, 0, 0))


def wedge(center):
    points = vtkPoints()
    for x, y in ((0, 0), (1.2, 0), (0, 0.8)):
        points.InsertNextPoint(x, y, 0)
    polygon = vtkCellArray()
    polygon.InsertNextCell(3, (0, 1, 2))
    triangle = vtkPolyData()
    triangle.SetPoints(points)
    triangle.SetPolys(polygon)
    extrude = vtkLinearExtrusionFilter()
    extrude.SetInputData(triangle)
    extrude.SetExtrusionTypeToVectorExtrusion()
    extrude.SetVector(0, 0, 1.0)
    extrude.CappingOn()
    return placed(extrude, center)


parts = [
    box(4.0, 0.4, 3.0, (0, 0, 0)),                       # base plate
    cylinder(0.55, 1.0, (-1.1, 0.7, 0.6)),               # boss
    ring(0.35, 0.7, 0.5, (0.9, 0.2, 0.7)),               # flanged ring
    box(1.2, 0.9, 0.8, (0.6, 0.65, -0.9)),               # block
    cylinder(0.18, 1.6, (0.6, 0.7, -0.9), (90, 1, 0, 0), 32),  # pin through the block
    wedge((-1.8, 0.2, -1.3)),                            # chamfered wedge
]
append = vtkAppendPolyData()
for index, part in enumerate(parts):
    part.Update()
    data = vtkPolyData()
    data.ShallowCopy(part.GetOutput())
    data.GetPointData().Initialize()  # normals are computed by the renderer's user
    ids = vtkIntArray()
    ids.SetName("part")
    ids.SetNumberOfTuples(data.GetNumberOfCells())
    ids.Fill(index)
    data.GetCellData().Initialize()
    data.GetCellData().AddArray(ids)
    append.AddInputData(data)
triangles = vtkTriangleFilter()
triangles.SetInputConnection(append.GetOutputPort())
clean = vtkCleanPolyData()
clean.SetInputConnection(triangles.GetOutputPort())
writer = vtkXMLPolyDataWriter()
writer.SetInputConnection(clean.GetOutputPort())
writer.SetFileName("cad_part.vtp")
writer.SetDataModeToBinary()
writer.Write()
clean.Update()
print("cad_part.vtp:", clean.GetOutput().GetNumberOfCells(), "triangles")
