// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNPRPropParts.h"

#include "vtkAbstractMapper3D.h"
#include "vtkActor.h"
#include "vtkAssemblyNode.h"
#include "vtkAssemblyPath.h"
#include "vtkLODProp3D.h"
#include "vtkMapper.h"
#include "vtkNew.h"
#include "vtkProp.h"
#include "vtkPropCollection.h"

namespace
{
// The actor of the level a vtkLODProp3D drew last (its first actor before it drew; the LOD prop
// itself when that level is no actor: a volume or an image). VTK draws it with the LOD prop's
// matrix.
vtkProp* nprDrawnLevel(vtkLODProp3D* lod)
{
  vtkNew<vtkPropCollection> actors;
  lod->GetActors(actors);
  const int id = lod->GetLastRenderedLODID();
  vtkAbstractMapper3D* drawn = id >= 0 ? lod->GetLODMapper(id) : nullptr;
  actors->InitTraversal();
  while (vtkProp* level = actors->GetNextProp())
  {
    auto* actor = vtkActor::SafeDownCast(level);
    if (actor && (!drawn || static_cast<vtkAbstractMapper3D*>(actor->GetMapper()) == drawn))
    {
      return actor;
    }
  }
  return lod;
}
}

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
      vtkMatrix4x4* matrix = last->GetMatrix() ? last->GetMatrix() : part->GetMatrix();
      if (auto* lod = vtkLODProp3D::SafeDownCast(part))
      {
        part = nprDrawnLevel(lod);
      }
      parts.push_back({ part, matrix });
    }
  }
  return parts;
}
