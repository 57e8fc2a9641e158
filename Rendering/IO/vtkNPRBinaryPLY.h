// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// The common binary PLY layout read at the speed of the disk, into what vtkPLYReader makes of it.
//
// Scans and exporters write one layout almost always: a little-endian body with a vertex element
// (x, y, z as float or double, optionally nx, ny, nz and red, green, blue, alpha as uchar, other
// scalar properties ignored) followed by a face element whose only property is its list of
// vertex indices. vtkPLYReader reads it value by value through a generic property table (2.4 s
// for 4.8M triangles on this project's machine); here the vertices are converted row by row and
// the faces copied into the cell array's own storage. The output is vtkPLYReader's, value for
// value: float points, "Normals" (float) as the normals, "RGB" or "RGBA" (unsigned char) as
// the point scalars, the faces as polygons in file order.
//
// Any other layout (big-endian or ASCII, texture coordinates, face colours or intensity, other
// elements, a face of more than 255 vertices, which vtkPLYReader's count wraps) is left to
// vtkPLYReader. It checks what vtkNPRPLYChecks::CheckPLY checks of such a file as it
// reads (every value there, every face index naming a vertex), so a file it reads needs no check
// before; one it refuses goes to CheckPLY, which says what is wrong.
// Private to the module: vtkNPRModelReader's PLY path.
#ifndef vtkNPRBinaryPLY_h
#define vtkNPRBinaryPLY_h

#include <string>

class vtkPolyData;

namespace vtkNPRBinaryPLY
{
// Reads fileName into output and returns true; false (output untouched) for a layout it leaves to
// vtkPLYReader, a file that ends early or a face index past the vertices.
bool Read(const std::string& fileName, vtkPolyData* output);
}

#endif
