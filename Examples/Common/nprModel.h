// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// A model as the command-line programs draw it: read with vtkNPRModelReader, shaded with
// vtkNPRShadingNormals' normals, in one of a few surface colours.
#ifndef nprModel_h
#define nprModel_h

#include "vtkSmartPointer.h"

#include <cstddef>
#include <string>

class nprProgress;
class vtkPolyData;
class vtkProperty;
class vtkRenderer;

// Reads a model file (any format vtkNPRModelReader knows). Throws std::runtime_error with the
// reader's one-line message; a warning (such as points dropped) goes to warning when given.
vtkSmartPointer<vtkPolyData> nprReadModel(const std::string& path, std::string* warning = nullptr);

// The mesh to draw: the file's normals when they are all usable; otherwise smooth shading that
// keeps sharp (> 30 degree) edges sharp, as CAD users expect, over merged duplicate points.
vtkSmartPointer<vtkPolyData> nprPrepareMesh(vtkPolyData* raw);

// Triangles of the polygons and strips (a polygon of n points counts n - 2).
long long nprCountTriangles(vtkPolyData* mesh);

// The surface of the index-th model of a scene: pleasant, distinguishable colours, a little
// specular.
void nprApplyModelLook(vtkProperty* property, size_t index);

// Reads the index-th model of a scene and adds it to renderer: the prepared mesh, in its file's
// colours when it has them, else in nprApplyModelLook's. A reader warning is printed on stderr as
// "PROGRAM: warning: ...". Returns the model's triangles. Reading and preparing are reported
// to progress when given (and long).
long long nprAddModel(vtkRenderer* renderer, const std::string& path, size_t index,
  const std::string& program, nprProgress* progress = nullptr);

#endif
