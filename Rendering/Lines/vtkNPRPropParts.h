// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// The parts a prop is drawn as. VTK draws a vtkAssembly or a vtkPropAssembly through its
// assembly paths: the prop at the end of each path, with the matrix composed along it poked in
// for the draw. A vtkLODProp3D draws one of its levels: the actor of the level it drew last (its
// first before it drew), with the LOD prop's matrix. The passes style those parts (and NPR::Lines
// finds their meshes) as the same props added directly.
#ifndef vtkNPRPropParts_h
#define vtkNPRPropParts_h

#include "vtkNPRLinesModule.h" // for export macro

#include <vector> // for the parts

class vtkMatrix4x4;
class vtkProp;

struct vtkNPRPropPart
{
  vtkProp* Prop;
  // The matrix it is drawn with: the path's composed matrix, the prop's own outside an
  // assembly; nullptr for a prop without one. Valid until the assembly changes.
  vtkMatrix4x4* Matrix;
};

// The visible props at the ends of `prop`'s assembly paths (nested assemblies included), in
// VTK's drawing order; `prop` itself when it is no assembly.
VTKNPRLINES_EXPORT std::vector<vtkNPRPropPart> vtkNPRPropParts(vtkProp* prop);

#endif
