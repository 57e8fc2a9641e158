// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// vtkNPREdgePass and vtkNPRSketchPass: the colour of lines given each type's coverage
// (r silhouettes, g creases, b contours, a suggestive contours). Creases are drawn first, then
// contours and suggestive contours, silhouettes on top.
uniform vec3 silhouetteColor;
uniform vec3 creaseColor;
uniform vec3 contourColor;
uniform vec3 suggestiveColor;

// Lines over an opaque colour.
vec3 nprLinesOver(vec3 color, vec4 coverage)
{
  color = mix(color, creaseColor, coverage.g);
  color = mix(color, contourColor, coverage.b);
  color = mix(color, suggestiveColor, coverage.a);
  return mix(color, silhouetteColor, coverage.r);
}

vec3 nprLinesOver(vec3 color, vec3 coverage)
{
  return nprLinesOver(color, vec4(coverage, 0.0));
}

// Lines over nothing: their colour and total coverage (alpha), not premultiplied.
vec4 nprLinesAlone(vec4 coverage)
{
  vec4 color = vec4(creaseColor, 1.0) * coverage.g;
  color = mix(color, vec4(contourColor, 1.0), coverage.b);
  color = mix(color, vec4(suggestiveColor, 1.0), coverage.a);
  color = mix(color, vec4(silhouetteColor, 1.0), coverage.r);
  return vec4(color.rgb / max(color.a, 1e-6), color.a);
}

vec4 nprLinesAlone(vec3 coverage)
{
  return nprLinesAlone(vec4(coverage, 0.0));
}
