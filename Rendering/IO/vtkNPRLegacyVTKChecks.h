// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// The legacy VTK check (vtkNPRModelFormatChecks): vtkDataSetReader fills a short POINTS section
// with zeros after a warning no observer sees, and keeps cells whose point indices name no point.
// Private to the module.
#ifndef vtkNPRLegacyVTKChecks_h
#define vtkNPRLegacyVTKChecks_h

#include <string>

namespace vtkNPRLegacyVTKChecks
{
// Legacy VTK (ASCII or binary, file versions up to 5.1): the header, and for POINTS and the cell
// sections (VERTICES, LINES, POLYGONS, TRIANGLE_STRIPS, CELLS, CELL_TYPES) that the file holds
// every value the section declares and that every cell's point index names a point. "" for a
// well-formed file, else what is wrong with it.
std::string CheckLegacyVTK(const std::string& fileName);
}

#endif
