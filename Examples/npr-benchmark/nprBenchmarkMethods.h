// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// npr-benchmark's line methods: the edge pass at each G-buffer encoding and two threshold
// settings, the ink pass, and object-space feature lines.
#ifndef nprBenchmarkMethods_h
#define nprBenchmarkMethods_h

#include "nprPassSettings.h"

#include <string>
#include <vector>

struct nprBenchmarkMethod
{
  enum Families
  {
    Edges,      // vtkNPRPass, style edges
    Inked,      // vtkNPRPass, style inked
    ObjectLines // vtkNPRFeatureLines over VTK's own chain
  };
  std::string Name;
  Families Family = Edges;
  nprPassSettings Pass; // Edges and Inked; the style is the family's, the line width the run's
  std::string Settings; // for the reader
};

// Every method, in the order of the report.
std::vector<nprBenchmarkMethod> nprAllBenchmarkMethods();

// The methods that names (method names or the families edges, inked, objectlines) select, in
// the order named, each once; all for no names. Throws nprUsageError for an unknown name.
std::vector<nprBenchmarkMethod> nprSelectBenchmarkMethods(const std::vector<std::string>& names);

#endif
