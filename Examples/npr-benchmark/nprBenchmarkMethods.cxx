// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nprBenchmarkMethods.h"

#include "nprArguments.h"

#include <algorithm>
#include <sstream>

// Two threshold settings per G-buffer encoding: the pass's defaults and a sensitive one (float,
// half: smaller depth steps and crease angles; packed: half the Laplacian threshold; below that
// the quantisation noise draws lines).
std::vector<nprBenchmarkMethod> nprAllBenchmarkMethods()
{
  std::vector<nprBenchmarkMethod> methods;
  for (int encoding : { vtkNPREdgePass::FLOAT, vtkNPREdgePass::HALF, vtkNPREdgePass::PACKED8,
         vtkNPREdgePass::PACKED16 })
  {
    const bool packed = encoding == vtkNPREdgePass::PACKED8 || encoding == vtkNPREdgePass::PACKED16;
    for (bool sensitive : { false, true })
    {
      nprBenchmarkMethod method;
      const std::string name = vtkNPREdgePass::GetEncodingName(encoding);
      method.Name = "edges-" + name + (sensitive ? "-sensitive" : "");
      method.Pass.Encoding = encoding;
      std::ostringstream settings;
      settings << name << " G-buffer, ";
      if (packed)
      {
        method.Pass.PackedThreshold = sensitive ? 0.05 : 0.1;
        settings << "packed threshold " << method.Pass.PackedThreshold;
      }
      else
      {
        method.Pass.SilhouetteThreshold = sensitive ? 0.0025 : 0.005;
        method.Pass.CreaseAngle = sensitive ? 25.0 : 30.0;
        settings << "silhouette threshold " << method.Pass.SilhouetteThreshold << ", crease angle "
                 << method.Pass.CreaseAngle;
      }
      method.Settings = settings.str();
      methods.push_back(method);
    }
  }
  nprBenchmarkMethod inked;
  inked.Name = "inked";
  inked.Family = nprBenchmarkMethod::Inked;
  inked.Settings = "vtkNPRInkPass: fat back-face wireframe, filled fronts with polygon offset";
  methods.push_back(inked);
  nprBenchmarkMethod lines;
  lines.Name = "objectlines";
  lines.Family = nprBenchmarkMethod::ObjectLines;
  lines.Settings = "vtkNPRFeatureLines for the camera every frame, line actor over the shaded "
                   "mesh (coincident-topology polygon offset)";
  methods.push_back(lines);
  return methods;
}

std::vector<nprBenchmarkMethod> nprSelectBenchmarkMethods(const std::vector<std::string>& names)
{
  const std::vector<nprBenchmarkMethod> all = nprAllBenchmarkMethods();
  std::vector<nprBenchmarkMethod> chosen;
  if (names.empty())
  {
    chosen = all;
  }
  for (const std::string& name : names)
  {
    bool found = false;
    for (const nprBenchmarkMethod& method : all)
    {
      const bool family = (name == "edges" && method.Family == nprBenchmarkMethod::Edges) ||
        (name == "inked" && method.Family == nprBenchmarkMethod::Inked) ||
        (name == "objectlines" && method.Family == nprBenchmarkMethod::ObjectLines);
      if (family || name == method.Name)
      {
        found = true;
        if (std::none_of(chosen.begin(), chosen.end(),
              [&](const nprBenchmarkMethod& m) { return m.Name == method.Name; }))
        {
          chosen.push_back(method);
        }
      }
    }
    if (!found)
    {
      std::string valid;
      for (const nprBenchmarkMethod& method : all)
      {
        valid += " " + method.Name;
      }
      throw nprUsageError(
        "unknown method '" + name + "' (families: edges inked objectlines; methods:" + valid + ")");
    }
  }
  return chosen;
}
