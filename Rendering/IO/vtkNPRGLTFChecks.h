// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// Structural checks of glTF 2.0 files (.gltf and .glb) run before vtkGLTFReader, which trusts
// what the JSON says: a buffer whose file is missing or shorter than its byteLength, an accessor
// past the end of its buffer view or an index past the vertex count make it read out of bounds
// (a missing .bin crashes it).
#ifndef vtkNPRGLTFChecks_h
#define vtkNPRGLTFChecks_h

#include <string>

namespace vtkNPRGLTFChecks
{
// "" for a file vtkGLTFReader can read safely, else what is wrong with it (one line). Checks the
// GLB container (magic, version, length, chunks); the JSON (syntax, the arrays and objects the
// reader walks); every buffer (data: URI decoded, external file present, BIN chunk) at least
// its byteLength long; buffer views inside their buffers; accessors inside their buffer views
// with a known component type and type; every index into buffers, bufferViews, accessors,
// meshes, nodes (no cycles), skins, images, samplers and textures in range; primitives with a
// float VEC3 POSITION whose attributes all have its count; and every vertex index of every
// primitive below that count.
std::string CheckGLTF(const std::string& fileName);
}

#endif
