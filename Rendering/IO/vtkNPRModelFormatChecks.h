// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// Structural checks run before VTK's own readers, which trust their input: vtkPLYReader reads
// past the end of a truncated file (and crashes), vtkSTLReader takes any bytes as binary STL,
// vtkOBJReader keeps face indices past the vertex count and reads "nan" as a number of its own,
// vtkDataSetReader fills a short POINTS section with zeros after a warning no observer sees.
// Each returns "" for a well-formed file, else what is wrong with it (glTF: vtkNPRGLTFChecks).
#ifndef vtkNPRModelFormatChecks_h
#define vtkNPRModelFormatChecks_h

#include <iosfwd>
#include <string>
#include <vector>

namespace vtkNPRModelFormatChecks
{
// A PLY header's property: a scalar, or a list (CountSize > 0).
struct PLYProperty
{
  std::string Name;
  int Size = 0;      // bytes of the value, or of each list item
  int CountSize = 0; // bytes of a list's count; 0 for a scalar property
  bool Signed = false;
  bool Float = false;
};

struct PLYElement
{
  std::string Name;
  long long Count = 0;
  std::vector<PLYProperty> Properties;
};

// Reads a PLY header up to end_header, leaving in at the body: "" or what is wrong with it.
std::string ReadPLYHeader(std::istream& in, std::string& format, std::vector<PLYElement>& elements);

std::string CheckPLY(const std::string& fileName);
std::string CheckSTL(const std::string& fileName);

// Every face, line and point element's vertex, texture and normal indices (1-based, or negative
// from the last vertex so far) in range; every vertex with three numbers. The vertices (0-based,
// in file order) with a NaN or infinite coordinate go to nonFinite, their number to vertices:
// vtkOBJReader does not read such coordinates as they are.
std::string CheckOBJ(
  const std::string& fileName, std::vector<long long>& nonFinite, long long& vertices);

// Legacy VTK (ASCII or binary, file versions up to 5.1): the header, and for POINTS and the cell
// sections (VERTICES, LINES, POLYGONS, TRIANGLE_STRIPS, CELLS, CELL_TYPES) that the file holds
// every value the section declares and that every cell's point index names a point.
std::string CheckLegacyVTK(const std::string& fileName);

// VTK XML polydata: the piece's counts and every appended raw array's header (byte count, or
// the blocks of a compressed array) within what the file can hold. vtkXMLPolyDataReader
// allocates what they say before it reads: a mutated size asks for terabytes.
std::string CheckVTP(const std::string& fileName);
}

#endif
