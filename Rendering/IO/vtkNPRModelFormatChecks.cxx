// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNPRModelFormatChecks.h"

#include "vtkNPRGLTFChecks.h"
#include "vtkNPRLegacyVTKChecks.h"
#include "vtkNPROBJChecks.h"
#include "vtkNPRPLYChecks.h"
#include "vtkNPRSTLChecks.h"
#include "vtkNPRVTPChecks.h"

std::string vtkNPRModelFormatChecks::Check(
  const std::string& extension, const std::string& fileName, OBJVertices& objVertices)
{
  if (extension == ".ply")
  {
    return vtkNPRPLYChecks::CheckPLY(fileName);
  }
  if (extension == ".stl")
  {
    return vtkNPRSTLChecks::CheckSTL(fileName);
  }
  if (extension == ".obj")
  {
    return vtkNPROBJChecks::CheckOBJ(fileName, objVertices.NonFinite, objVertices.Count);
  }
  if (extension == ".vtp")
  {
    return vtkNPRVTPChecks::CheckVTP(fileName);
  }
  if (extension == ".vtk")
  {
    return vtkNPRLegacyVTKChecks::CheckLegacyVTK(fileName);
  }
  if (extension == ".gltf" || extension == ".glb")
  {
    return vtkNPRGLTFChecks::CheckGLTF(fileName);
  }
  return "";
}
