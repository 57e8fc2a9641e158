// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
//VTK::System::Dec
// vtkNPRGBufferPass, depth-only mode: the geometry attachment (FLOAT encoding: view depth,
// packed octahedral normal) derived from a depth buffer alone, for images whose geometry was not
// drawn by this pass (a composited parallel image, any delegate's output).
// The normal is the cross product of the view-space position's differences to the neighbours;
// of the two one-sided differences along each axis, the one with the smaller depth change is
// taken, so that normals next to a silhouette do not lean across the depth step. Neighbours on
// the background are not used; a pixel with no usable neighbour along an axis faces the viewer.
//NPR::Defines
in vec2 texCoord;
uniform sampler2D depthTexture;
uniform mat4 inverseProjection; // normalised device to view coordinates (GLSL layout)
//VTK::Output::Dec

vec3 positionAt(ivec2 q, ivec2 size, out bool covered)
{
  q = clamp(q, ivec2(0), size - 1);
  float d = texelFetch(depthTexture, q, 0).x;
  covered = d < 1.0;
  vec4 ndc = vec4((vec2(q) + 0.5) / vec2(size) * 2.0 - 1.0, 2.0 * d - 1.0, 1.0);
  vec4 p = inverseProjection * ndc;
  return p.xyz / p.w;
}

// The smaller of the two one-sided differences along one axis (zero when neither is usable).
vec3 difference(vec3 p, ivec2 q, ivec2 step, ivec2 size)
{
  bool coveredA, coveredB;
  vec3 a = positionAt(q + step, size, coveredA) - p;
  vec3 b = p - positionAt(q - step, size, coveredB);
  if (coveredA && (!coveredB || abs(a.z) <= abs(b.z)))
  {
    return a;
  }
  return coveredB ? b : vec3(0.0);
}

//NPR::PackNormal

void main()
{
  ivec2 size = textureSize(depthTexture, 0);
  ivec2 q = ivec2(texCoord * vec2(size));
  bool covered;
  vec3 p = positionAt(q, size, covered);
  if (!covered)
  {
    gl_FragData[0] = vec4(0.0); // background
    return;
  }
  vec3 n = cross(difference(p, q, ivec2(1, 0), size), difference(p, q, ivec2(0, 1), size));
  n = dot(n, n) > 1e-30 ? normalize(n) * sign(dot(n, -p) + 1e-30) : vec3(0.0, 0.0, 1.0);
  gl_FragData[0] = vec4(max(-p.z, 1e-30), nprPackNormal(n), 0.0, 1.0);
}
