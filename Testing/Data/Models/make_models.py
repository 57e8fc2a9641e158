#!/usr/bin/env python3
"""Writes the small model files the reader tests use: a unit cube in every supported format,
cubes with NaN vertices, and malformed files. Run it from this folder to regenerate them."""
import base64
import json
import os
import struct

P = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]
QUADS = [(0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7)]
TRIS = [t for q in QUADS for t in ((q[0], q[1], q[2]), (q[0], q[2], q[3]))]


def write(name, text, mode="w"):
    with open(name, mode) as f:
        f.write(text)


def normal(t):
    a, b, c = (P[i] for i in t)
    u = [b[k] - a[k] for k in range(3)]
    v = [c[k] - a[k] for k in range(3)]
    return (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])


# STL, ASCII and binary
lines = ["solid cube"]
for t in TRIS:
    lines.append("  facet normal %g %g %g" % normal(t))
    lines.append("    outer loop")
    lines += ["      vertex %g %g %g" % P[i] for i in t]
    lines += ["    endloop", "  endfacet"]
write("cube.stl", "\n".join(lines + ["endsolid cube", ""]))
binary = b"binary cube".ljust(80, b" ") + struct.pack("<I", len(TRIS))
for t in TRIS:
    binary += struct.pack("<3f", *normal(t))
    for i in t:
        binary += struct.pack("<3f", *P[i])
    binary += b"\0\0"
write("cube_binary.stl", binary, "wb")

# OBJ (1-based), and one with a NaN vertex used by an extra face
obj = ["# unit cube"] + ["v %g %g %g" % p for p in P] + ["f %d %d %d %d" % tuple(i + 1 for i in q) for q in QUADS]
write("cube.obj", "\n".join(obj) + "\n")
write("no_geometry.obj", "# only a comment\n# and another\n")

# PLY: ASCII, binary, truncated binary, face index out of range
header = "ply\nformat %s 1.0\nelement vertex 8\nproperty float x\nproperty float y\nproperty float z\n" \
         "element face 6\nproperty list uchar int vertex_indices\nend_header\n"
write("cube.ply", header % "ascii" + "".join("%g %g %g\n" % p for p in P) +
      "".join("4 %d %d %d %d\n" % q for q in QUADS))
body = b"".join(struct.pack("<3f", *p) for p in P) + b"".join(struct.pack("<B4i", 4, *q) for q in QUADS)
write("cube_binary.ply", (header % "binary_little_endian").encode() + body, "wb")
write("cube_nan.ply", (header % "ascii").replace("vertex 8", "vertex 9").replace("face 6", "face 7") +
      "".join("%g %g %g\n" % p for p in P) + "nan 0 0\n" + "".join("4 %d %d %d %d\n" % q for q in QUADS) + "3 0 1 8\n")
write("truncated.ply", (header % "binary_little_endian").encode() + body[:50], "wb")
write("bad_index.ply", header % "ascii" + "".join("%g %g %g\n" % p for p in P) +
      "".join("4 %d %d %d %d\n" % q for q in QUADS[:5]) + "4 0 1 2 99\n")
# Every triangle with its corners on one line (bounds of area, nothing to draw)
write("zero_area.stl", "solid flat\n" + "".join(
      "facet normal 0 0 1\nouter loop\nvertex %d %d 0\nvertex %d %d 0\nvertex %d %d 0\nendloop\nendfacet\n"
      % (0, y, 1, y, 3, y) for y in range(3)) + "endsolid flat\n")
# Elements without properties (vtkPLY frees memory it never set: heap corruption from about 7 of
# them), and a second vertex element (vtkPLY reads the first of a name)
write("empty_elements.ply", (header % "ascii").replace("end_header", "".join(
      "element extra%d 0\n" % i for i in range(8)) + "end_header") +
      "".join("%g %g %g\n" % p for p in P) + "".join("4 %d %d %d %d\n" % q for q in QUADS))
write("vertex_twice.ply", (header % "ascii").replace("element face", "element vertex 8\nproperty float x\n"
      "property float y\nproperty float z\nelement face") + "".join("%g %g %g\n" % p for p in P) * 2 +
      "".join("4 %d %d %d %d\n" % q for q in QUADS))

# VTK XML polydata and legacy VTK (polydata, and an unstructured hexahedron)
pts = " ".join("%g %g %g" % p for p in P)
conn = " ".join("%d %d %d %d" % q for q in QUADS)
offs = " ".join(str(4 * (i + 1)) for i in range(6))
write("cube.vtp", f"""<?xml version="1.0"?>
<VTKFile type="PolyData" version="0.1" byte_order="LittleEndian">
  <PolyData>
    <Piece NumberOfPoints="8" NumberOfPolys="6">
      <Points><DataArray type="Float32" NumberOfComponents="3" format="ascii">{pts}</DataArray></Points>
      <Polys>
        <DataArray type="Int32" Name="connectivity" format="ascii">{conn}</DataArray>
        <DataArray type="Int32" Name="offsets" format="ascii">{offs}</DataArray>
      </Polys>
    </Piece>
  </PolyData>
</VTKFile>
""")
write("bad.vtp", '<?xml version="1.0"?>\n<VTKFile type="PolyData"><PolyData><Piece NumberOfPoints="8"\n')
# Elements nested 70 deep (VTK's parser overflows its stack some 100,000 deep: refused from 65)
write("deep.vtp", open("cube.vtp").read().replace("<PolyData>", "<PolyData>" + "<a>" * 70, 1))
write("cube.vtk", "# vtk DataFile Version 3.0\ncube\nASCII\nDATASET POLYDATA\nPOINTS 8 float\n" +
      "".join("%g %g %g\n" % p for p in P) + "POLYGONS 6 30\n" + "".join("4 %d %d %d %d\n" % q for q in QUADS))
write("cube_hexahedron.vtk", "# vtk DataFile Version 3.0\nhexahedron\nASCII\nDATASET UNSTRUCTURED_GRID\n"
      "POINTS 8 float\n" + "".join("%g %g %g\n" % p for p in P) + "CELLS 1 9\n8 0 1 2 3 4 5 6 7\nCELL_TYPES 1\n12\n")

# glTF 2.0: one mesh, embedded buffer (.gltf) and binary container (.glb)
positions = b"".join(struct.pack("<3f", *p) for p in P)
indices = b"".join(struct.pack("<3H", *t) for t in TRIS)
blob = positions + indices


def gltf(uri):
    buffer = {"byteLength": len(blob)}
    if uri:
        buffer["uri"] = uri
    return {
        "asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
        "buffers": [buffer],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": len(positions)},
                        {"buffer": 0, "byteOffset": len(positions), "byteLength": len(indices)}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 8, "type": "VEC3",
                       "min": [0, 0, 0], "max": [1, 1, 1]},
                      {"bufferView": 1, "componentType": 5123, "count": len(indices) // 2, "type": "SCALAR"}]}


write("cube.gltf", json.dumps(gltf("data:application/octet-stream;base64," + base64.b64encode(blob).decode()), indent=1))
chunk_json = json.dumps(gltf(None)).encode()
chunk_json += b" " * (-len(chunk_json) % 4)
chunk_bin = blob + b"\0" * (-len(blob) % 4)
glb = struct.pack("<II", len(chunk_json), 0x4E4F534A) + chunk_json + struct.pack("<II", len(chunk_bin), 0x004E4942) + chunk_bin
write("cube.glb", struct.pack("<4sII", b"glTF", 2, 12 + len(glb)) + glb, "wb")
write("bad.gltf", '{"asset": {"version": "2.0"}, "meshes": [\n')

# Geomview OFF: plain, with colours and comments, NaN vertices, and malformed variants
off = "OFF\n8 6 12\n" + "".join("%g %g %g\n" % p for p in P) + "".join("4 %d %d %d %d\n" % q for q in QUADS)
write("cube.off", off)
write("cube_colors.off", "# a cube with per-vertex colours, counts on the keyword line\nCOFF 8 6 0\n" +
      "".join("%g %g %g  %g 0.5 0.25 1\n" % (p + (p[0],)) for p in P) +
      "".join("4 %d %d %d %d  # face\n" % q for q in QUADS))
write("cube_nan.off", "OFF\n9 7 0\n" + "".join("%g %g %g\n" % p for p in P) + "nan 0 inf\n" +
      "".join("4 %d %d %d %d\n" % q for q in QUADS) + "3 0 1 8\n")
write("all_nan.off", "OFF\n3 1 0\nnan 0 0\n0 nan 0\n0 0 inf\n3 0 1 2\n")
write("bad_keyword.off", "OFX\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")
write("bad_count.off", "OFF\n3 one 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")
write("bad_index.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n")
write("bad_number.off", "OFF\n3 1 0\n0 0 0\n1 zero 0\n0 1 0\n3 0 1 2\n")
write("short_face.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1\n")
write("truncated.off", "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")
write("trailing.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n7 7 7\n")
write("binary.off", "OFF BINARY\n")
write("four_d.off", "4OFF\n3 1 0\n0 0 0 1\n1 0 0 1\n0 1 0 1\n3 0 1 2\n")

# Files that are wrong whatever the format
write("empty.stl", "")
write("garbage.stl", bytes(range(256)) * 3, "wb")
write("cube.xyz", "0 0 0\n")

# Hardening cases (Documentation/input.md): each reproduces a crash or a silent blank image of
# npr-render before the checks.
write("short_points.vtk", "# vtk DataFile Version 3.0\nshort\nASCII\nDATASET POLYDATA\nPOINTS 8 float\n"
      "0 0 0\n1 0 0\n1 1 0\nPOLYGONS 1 4\n3 0 1 7\n")
write("bad_index.vtk", cube_vtk := open("cube.vtk").read().replace("4 3 0 4 7", "4 3 0 4 9"))
write("all_nan.obj", "v nan nan nan\nv nan nan nan\nv nan nan nan\nf 1 2 3\n")
write("bad_index.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n")
write("bad_negative_index.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -9\n")
# One face on finite points (drawn), two on NaN/Inf points (dropped with one warning).
write("part_nan.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv nan 0 0\nv 0 inf 0\nf 1 2 3\nf 1 4 5\nf 2 4 5\n")
write("flat.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n")  # every point on one line: nothing to draw
# Silent blank images of npr-render before (issue 36): a cube too small or too large for the
# camera to frame in float, and one point beyond float's range (dropped with its face).
def scaled_cube(scale, extra=""):
    points = "".join("%r %r %r\n" % tuple(scale * c for c in p) for p in P)
    count = 8 + (extra != "")
    return ("# vtk DataFile Version 3.0\nscaled\nASCII\nDATASET POLYDATA\nPOINTS %d double\n%s%s"
            "POLYGONS %d %d\n%s%s" % (count, points, extra, 6 + (extra != ""), 30 + 4 * (extra != ""),
                                      "".join("4 %d %d %d %d\n" % q for q in QUADS),
                                      "3 0 1 8\n" if extra else ""))


write("tiny.vtk", scaled_cube(1e-25))
write("huge.vtk", scaled_cube(1e38))
write("beyond_float.vtk", scaled_cube(1.0, "1e300 0 0\n"))
pieces = f"""<?xml version="1.0"?>
<VTKFile type="PolyData" version="0.1" byte_order="LittleEndian">
  <PolyData>
    <Piece NumberOfPoints="8" NumberOfPolys="6">
      <Points><DataArray type="Float32" NumberOfComponents="3" format="ascii">{pts}</DataArray></Points>
      <Polys>
        <DataArray type="Int32" Name="connectivity" format="ascii">{{conn}}</DataArray>
        <DataArray type="Int32" Name="offsets" format="ascii">{offs}</DataArray>
      </Polys>
    </Piece>
  </PolyData>
</VTKFile>
"""
write("part_bad_index.vtp", pieces.format(conn=conn.rsplit(" ", 1)[0] + " 12"))  # 5 faces drawn
write("bad_index.vtp", pieces.format(conn=" ".join(str(int(i) + 8) for i in conn.split())))


def gltf_file(name, change, uri="data:application/octet-stream;base64," + base64.b64encode(blob).decode()):
    document = gltf(uri)
    change(document)
    write(name, json.dumps(document))


gltf_file("missing_buffer.gltf", lambda d: None, uri="missing_buffer.bin")
write("short_buffer.bin", blob[:100], "wb")
gltf_file("short_buffer.gltf", lambda d: None, uri="short_buffer.bin")
gltf_file("bad_accessor.gltf", lambda d: d["accessors"][0].update(count=9))
gltf_file("bad_indices.gltf", lambda d: d["accessors"][0].update(count=7))
gltf_file("node_cycle.gltf", lambda d: d.update(nodes=[{"mesh": 0, "children": [1]}, {"children": [0]}]))
write("cube_external.bin", blob, "wb")
gltf_file("cube_external.gltf", lambda d: None, uri="cube_external.bin")
write("bad_length.glb", open("cube.glb", "rb").read()[:-4], "wb")
