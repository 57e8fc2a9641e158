// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// The PLY check (vtkNPRModelFormatChecks): vtkPLYReader reads past the end of a truncated file
// (and crashes), and takes face indices past the vertex count. Private to the module; the
// header reader also serves vtkNPRBinaryPLY.
#ifndef vtkNPRPLYChecks_h
#define vtkNPRPLYChecks_h

#include <iosfwd>
#include <string>
#include <vector>

namespace vtkNPRPLYChecks
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

// "" for a well-formed file, else what is wrong with it: the header (a vertex element with x, y
// and z, only the lists vtkPLYReader sets up), and the body (every value there, every face index
// naming a vertex, nothing after the last element, an end of line after the last line).
std::string CheckPLY(const std::string& fileName);
}

#endif
