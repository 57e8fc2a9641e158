// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// vtkNPREdgePass and vtkNPRSketchPass: the colour of lines given each type's coverage
// (r silhouettes, g creases, b contours, a suggestive contours). Creases are drawn first, then
// contours and suggestive contours, silhouettes on top. The includer defines NPR_SURFACE_SHADE:
// 1 when the lines over a surface take its own colour darkened (vtkNPREdgePass::SurfaceLineShade).
uniform vec3 silhouetteColor;
uniform vec3 creaseColor;
uniform vec3 contourColor;
uniform vec3 suggestiveColor;
#if NPR_SURFACE_SHADE
uniform float surfaceLineShade; // the lines' colour over a surface: the surface's times this
#endif

// The colours set for each type, as the columns r, g, b, a of the coverage name them.
mat4x3 nprSetLineColors()
{
  return mat4x3(silhouetteColor, creaseColor, contourColor, suggestiveColor);
}

// The colours of the lines over a surface of this colour.
mat4x3 nprLineColors(vec3 surface)
{
#if NPR_SURFACE_SHADE
  vec3 shade = surfaceLineShade * surface;
  return mat4x3(shade, shade, shade, shade);
#else
  return nprSetLineColors();
#endif
}

// Lines of the given colours over an opaque colour.
vec3 nprLinesOver(vec3 color, vec4 coverage, mat4x3 lineColors)
{
  color = mix(color, lineColors[1], coverage.g);
  color = mix(color, lineColors[2], coverage.b);
  color = mix(color, lineColors[3], coverage.a);
  return mix(color, lineColors[0], coverage.r);
}

// Lines over a surface of this colour.
vec3 nprLinesOver(vec3 color, vec4 coverage)
{
  return nprLinesOver(color, coverage, nprLineColors(color));
}

vec3 nprLinesOver(vec3 color, vec3 coverage)
{
  return nprLinesOver(color, vec4(coverage, 0.0));
}

// Lines over nothing: their colour and total coverage (alpha), not premultiplied.
vec4 nprLinesAlone(vec4 coverage, mat4x3 lineColors)
{
  vec4 color = vec4(lineColors[1], 1.0) * coverage.g;
  color = mix(color, vec4(lineColors[2], 1.0), coverage.b);
  color = mix(color, vec4(lineColors[3], 1.0), coverage.a);
  color = mix(color, vec4(lineColors[0], 1.0), coverage.r);
  return vec4(color.rgb / max(color.a, 1e-6), color.a);
}

vec4 nprLinesAlone(vec4 coverage)
{
  return nprLinesAlone(coverage, nprSetLineColors());
}

vec4 nprLinesAlone(vec3 coverage)
{
  return nprLinesAlone(vec4(coverage, 0.0));
}
