// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// The OBJ check (vtkNPRModelFormatChecks): vtkOBJReader keeps face indices past the vertex count
// and reads "nan" as a number of its own. Private to the module.
#ifndef vtkNPROBJChecks_h
#define vtkNPROBJChecks_h

#include <string>
#include <vector>

namespace vtkNPROBJChecks
{
// Every face, line and point element's vertex, texture and normal indices (1-based, or negative
// from the last vertex so far) in range; every vertex with three numbers. The vertices (0-based,
// in file order) with a NaN or infinite coordinate go to nonFinite, their number to vertices:
// vtkOBJReader does not read such coordinates as they are.
std::string CheckOBJ(
  const std::string& fileName, std::vector<long long>& nonFinite, long long& vertices);
}

#endif
