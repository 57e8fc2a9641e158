// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
//VTK::System::Dec
// vtkNPREdgePass, step 2: widens and anti-aliases the line image, composites it over the shaded
// G-buffer colour and writes the depth sprite (gl_FragDepth).
//
// The line image (r silhouettes, g creases, b contours, a suggestive contours) is filtered with a
// separable Gaussian (NPR_TAPS bilinear taps). Across a straight one-pixel line the filtered
// value falls off as P(d) = g(d); the pixel's coverage of a line of
// width w is then 0.5 + (P - P(w/2)) / |P'(w/2)|, which is clamp(w/2 + 0.5 - d, 0, 1) near the
// line's border: a line of the requested width with one pixel of anti-aliasing, and no staircase
// since the filter averages the staircase of the one-pixel line.
//
// Outputs (NPR_OUTPUT): 0 lines over the colour; 1 the coverage alone as grey (an edge mask);
// 2 each type's coverage and the depth the lines are drawn at (for vtkNPRSketchPass).
//NPR::Defines
in vec2 texCoord;
uniform sampler2D lineTexture;  // linear filtering
uniform sampler2D colorTexture;
uniform sampler2D depthTexture;
uniform vec3 taps[NPR_TAPS];    // offset in texels (x, y), weight
uniform vec2 texelSize;
uniform ivec2 viewportOrigin; // of the renderer in the window
uniform vec4 coverageLevel;     // P(w/2) of each type's width w
uniform vec4 coverageSlope;     // |P'(w/2)|
#if NPR_DEPTH_FALLOFF
// The same at NPR_FALLOFF_STEPS width scales from the near clipping plane to the far one, and
// the camera: near, far, 1 for a parallel projection.
uniform vec4 falloffLevels[NPR_FALLOFF_STEPS];
uniform vec4 falloffSlopes[NPR_FALLOFF_STEPS];
uniform vec3 falloffCamera;
#endif
//NPR::LineColor
//NPR::WindowDepth
//NPR::NearestDepth
//VTK::Output::Dec

#if NPR_DEPTH_FALLOFF
// Where a window depth lies between the clipping planes, 0 at the near one to 1 at the far one,
// linear in the distance.
float nprFalloffPosition(float window)
{
  float n = falloffCamera.x;
  float f = falloffCamera.y;
  float t = window;
  if (falloffCamera.z < 0.5)
  {
    float distance = 2.0 * f * n / ((f + n) - (2.0 * window - 1.0) * (f - n));
    t = (distance - n) / (f - n);
  }
  return clamp(t, 0.0, 1.0) * float(NPR_FALLOFF_STEPS - 1);
}
#endif

void main()
{
  vec4 coverage = vec4(0.0);
  if (texCoord.x < -1.0)
  {
    discard; // never: texCoord is read so that VTK does not warn about an unread input
  }
  ivec2 p = ivec2(gl_FragCoord.xy) - viewportOrigin;
#if NPR_LINES
  // The taps from the pixel's centre as its window position gives it, not from texCoord: the
  // same value whether the full-screen quad or vtkNPRLineBlocks' block quads are drawn.
  vec2 centre = vec2(p) + 0.5;
  vec4 lines = vec4(0.0);
  for (int i = 0; i < NPR_TAPS; ++i)
  {
    lines += taps[i].z * texture(lineTexture, (centre + taps[i].xy) * texelSize);
  }
#endif
  float depth = texelFetch(depthTexture, p, 0).r;
#if NPR_LINES
  vec4 level = coverageLevel;
  vec4 slope = coverageSlope;
#if NPR_DEPTH_FALLOFF
  // The width at this pixel's depth (a background pixel's: its line's surface's).
  if (max(max(lines.r, lines.g), max(lines.b, lines.a)) > 0.0)
  {
    float stored = depth < 1.0 ? depth : nprNearestDepth(p);
    float x = nprFalloffPosition(nprWindowDepth(stored));
    int i = min(int(x), NPR_FALLOFF_STEPS - 2);
    level = mix(falloffLevels[i], falloffLevels[i + 1], x - float(i));
    slope = mix(falloffSlopes[i], falloffSlopes[i + 1], x - float(i));
  }
#endif
#if NPR_ANTIALIAS
  coverage = clamp(0.5 + (lines - level) / slope, 0.0, 1.0);
#else
  coverage = step(level, lines);
#endif
#endif
#if !NPR_LINES && NPR_OUTPUT == 0
  if (depth >= 1.0)
  {
    // Background and no line: nothing to write. (No saving on llvmpipe, which runs the code after
    // a discard even for a block of pixels that all took it; what it spares is the background's
    // branch below, compiled out.)
    discard;
  }
#endif
  float anyLine = max(max(coverage.r, coverage.g), max(coverage.b, coverage.a));
  bool onLine = anyLine > 0.0;
#if NPR_OUTPUT == 1
  gl_FragData[0] = vec4(vec3(anyLine), 1.0);
  gl_FragDepth = nprWindowDepth(depth);
#elif NPR_OUTPUT == 2
  // Suggestive contours go with the silhouettes: the sketch has three line types.
  gl_FragData[0] = vec4(max(coverage.r, coverage.a), coverage.gb,
    depth < 1.0 || !onLine ? depth : nprNearestDepth(p));
#else
  if (depth < 1.0)
  {
    // On a surface.
    gl_FragData[0] = vec4(nprLinesOver(texelFetch(colorTexture, p, 0).rgb, coverage), 1.0);
    gl_FragDepth = nprWindowDepth(depth);
  }
#if NPR_LINES
  else
  {
    // Background: only the parts of wide or anti-aliased lines that reach past a surface, blended
    // over the window's background at the depth of the nearest surface they belong to.
    if (!onLine)
    {
      discard;
    }
    ivec2 surface = nprNearestSurface(p);
#if NPR_SURFACE_SHADE
    gl_FragData[0] =
      nprLinesAlone(coverage, nprLineColors(texelFetch(colorTexture, surface, 0).rgb));
#else
    gl_FragData[0] = nprLinesAlone(coverage);
#endif
    gl_FragDepth = nprWindowDepth(texelFetch(depthTexture, surface, 0).r);
  }
#endif
#endif
}
