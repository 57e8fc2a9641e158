// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNPRPropParts.h"

#include "vtkAssemblyNode.h"
#include "vtkAssemblyPath.h"
#include "vtkProp.h"

std::vector<vtkNPRPropPart> vtkNPRPropParts(vtkProp* prop)
{
  std::vector<vtkNPRPropPart> parts;
  prop->InitPathTraversal();
  while (vtkAssemblyPath* path = prop->GetNextPath())
  {
    vtkAssemblyNode* last = path->GetLastNode();
    vtkProp* part = last->GetViewProp();
    if (part->GetVisibility())
    {
      // A node without a matrix (the prop itself, a vtkPropAssembly's part) leaves the prop's own.
      parts.push_back({ part, last->GetMatrix() ? last->GetMatrix() : part->GetMatrix() });
    }
  }
  return parts;
}
