#!/usr/bin/env python3
"""Writes the fuzz seeds that Testing/Data/Models lacks: richer files of each format (normals,
texture coordinates, lines and points, binary legacy VTK 5.1, appended binary VTP, a glTF node
hierarchy with a material and an external .bin) into seeds/. The plain unit cubes there are
copies of Testing/Data/Models files. Run it with /usr/bin/python3 (VTK's bindings)."""
import json
import os
import struct

from vtkmodules.vtkFiltersSources import vtkSphereSource
from vtkmodules.vtkFiltersCore import vtkPolyDataNormals
from vtkmodules.vtkIOLegacy import vtkPolyDataWriter
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter
from vtkmodules.vtkIOPLY import vtkPLYWriter

os.chdir(os.path.join(os.path.dirname(os.path.abspath(__file__)), "seeds"))
sphere = vtkSphereSource()
sphere.SetThetaResolution(6)
sphere.SetPhiResolution(4)
normals = vtkPolyDataNormals()
normals.SetInputConnection(sphere.GetOutputPort())
normals.Update()
mesh = normals.GetOutput()

for name, binary in (("sphere_binary.vtk", True), ("sphere.vtk", False)):
    writer = vtkPolyDataWriter()
    writer.SetInputData(mesh)
    writer.SetFileName(name)
    writer.SetFileTypeToBinary() if binary else writer.SetFileTypeToASCII()
    writer.Write()
writer = vtkXMLPolyDataWriter()
writer.SetInputData(mesh)
writer.SetFileName("sphere_appended.vtp")
writer.SetDataModeToAppended()
writer.EncodeAppendedDataOff()
writer.Write()
writer = vtkPLYWriter()
writer.SetInputData(mesh)
writer.SetFileName("sphere_binary.ply")
writer.SetFileTypeToBinary()
writer.Write()

with open("triangle_metadata.vtk", "w") as f:  # a METADATA block between sections
    f.write("# vtk DataFile Version 5.1\ntriangle\nASCII\nDATASET POLYDATA\nPOINTS 3 float\n"
            "0 0 0 1 0 0 0 1 0\nMETADATA\nINFORMATION 0\n\nPOLYGONS 2 3\nOFFSETS vtktypeint64\n0 3\n"
            "CONNECTIVITY vtktypeint64\n0 1 2\n")
with open("square_vt_vn.obj", "w") as f:
    f.write("# a square with texture coordinates and normals, a line and points\n"
            "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
            "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvn 0 0 1\n"
            "g square\nf 1/1/1 2/2/1 3/3/1\nf -4/-4/-1 -2/-2/-1 -1/-1/-1\n"
            "l 1 3\np 2 4\n")

# glTF: two nodes (a parent and a child), normals and texture coordinates, a material, an
# external buffer.
P = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)]
N = [(0, 0, 1)] * 4
T = [(0, 0), (1, 0), (1, 1), (0, 1)]
I = [0, 1, 2, 0, 2, 3]
blob = b"".join(struct.pack("<3f", *p) for p in P) + b"".join(struct.pack("<3f", *n) for n in N) + \
    b"".join(struct.pack("<2f", *t) for t in T) + b"".join(struct.pack("<I", i) for i in I)
with open("square_nodes.bin", "wb") as f:
    f.write(blob)
document = {
    "asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
    "nodes": [{"children": [1], "translation": [0, 0, 1]}, {"mesh": 0, "scale": [2, 2, 2]}],
    "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2},
                                "indices": 3, "material": 0, "mode": 4}]}],
    "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.2, 0.2, 1]}}],
    "buffers": [{"byteLength": len(blob), "uri": "square_nodes.bin"}],
    "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 96, "byteStride": 12},
                    {"buffer": 0, "byteOffset": 96, "byteLength": 32},
                    {"buffer": 0, "byteOffset": 128, "byteLength": 24}],
    "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3",
                   "min": [0, 0, 0], "max": [1, 1, 0]},
                  {"bufferView": 0, "byteOffset": 48, "componentType": 5126, "count": 4, "type": "VEC3"},
                  {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC2"},
                  {"bufferView": 2, "componentType": 5125, "count": 6, "type": "SCALAR"}]}
with open("square_nodes.gltf", "w") as f:
    json.dump(document, f)
