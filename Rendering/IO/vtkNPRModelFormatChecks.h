// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// Structural checks run before VTK's own readers, which trust their input: vtkPLYReader reads
// past the end of a truncated file (and crashes), vtkSTLReader takes any bytes as binary STL,
// vtkOBJReader keeps face indices past the vertex count and reads "nan" as a number of its own,
// vtkDataSetReader fills a short POINTS section with zeros after a warning no observer sees.
// One checker per format (vtkNPRPLYChecks, vtkNPRSTLChecks, vtkNPROBJChecks,
// vtkNPRLegacyVTKChecks, vtkNPRVTPChecks, vtkNPRGLTFChecks); this picks the file's. Private to
// the module.
#ifndef vtkNPRModelFormatChecks_h
#define vtkNPRModelFormatChecks_h

#include <string>
#include <vector>

namespace vtkNPRModelFormatChecks
{
// An OBJ file's vertices with a NaN or infinite coordinate (0-based), and how many it has.
struct OBJVertices
{
  std::vector<long long> NonFinite;
  long long Count = 0;
};

// The check of the format `extension` names (lower case, with its dot): "" for a well-formed file
// (or a format without a check), else what is wrong with it. An OBJ file's vertices go to
// objVertices.
std::string Check(
  const std::string& extension, const std::string& fileName, OBJVertices& objVertices);
}

#endif
