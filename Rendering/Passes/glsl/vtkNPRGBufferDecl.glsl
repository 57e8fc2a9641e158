// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// Declarations injected into a vtkOpenGLPolyDataMapper fragment shader while vtkNPRGBufferPass
// draws. The pass defines NPR_WRITE_NORMALS, NPR_WRITE_OBJECT_IDS, NPR_HAVE_MAPPER_NORMAL,
// NPR_HAVE_VERTEX_VC and NPR_ENCODING (0 float, 1 half, 2 packed 8-bit, 3 packed 16-bit) before
// this text.
uniform float nprObjectId;
uniform mat4 nprInverseProjection;
uniform vec4 nprViewport; // x, y, 1/width, 1/height of the G-buffer
uniform vec2 nprDepthRange; // packed encodings: the view depths mapped onto 0 and 1
uniform vec2 nprDepthRemap; // NPR_REMAPPED_DEPTH: near, log(far / near)

// View-space position rebuilt from the window position and depth of this fragment.
vec3 nprFragmentPositionVC()
{
  vec4 ndc = vec4(2.0 * (gl_FragCoord.xy - nprViewport.xy) * nprViewport.zw - 1.0,
    2.0 * gl_FragCoord.z - 1.0, 1.0);
  vec4 p = nprInverseProjection * ndc;
  return p.xyz / p.w;
}

// The unit face normal from the derivatives of the view-space position (exact within a
// triangle), turned towards the viewer; (0, 0, 1) where they vanish. The derivatives are made
// unit first: at tiny scales their cross product underflows.
vec3 nprFaceNormal(vec3 positionVC, vec3 toViewer)
{
  vec3 dx = dFdx(positionVC), dy = dFdy(positionVC);
  vec3 n = cross(dx / max(length(dx), 1e-37), dy / max(length(dy), 1e-37));
  return dot(n, n) > 1e-12 ? normalize(n) * sign(dot(n, toViewer) + 1e-30) : vec3(0.0, 0.0, 1.0);
}

//NPR::PackNormal
