// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNPRLineSettings.h"

#include "vtkObjectFactory.h"

vtkStandardNewMacro(vtkNPRLineSettings);

void vtkNPRLineSettings::PrintSettings(ostream& os, vtkIndent indent, const char* angleName) const
{
  os << indent << "Silhouettes: " << this->Silhouettes << "\n";
  os << indent << "Creases: " << this->Creases << "\n";
  os << indent << "Boundaries: " << this->Boundaries << "\n";
  os << indent << "NonManifoldEdges: " << this->NonManifoldEdges << "\n";
  os << indent << angleName << ": " << this->CreaseAngle << "\n";
}

void vtkNPRLineSettings::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  this->PrintSettings(os, indent, "CreaseAngle");
}
