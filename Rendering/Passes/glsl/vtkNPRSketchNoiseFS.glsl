// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
//VTK::System::Dec
// vtkNPRSketchPass, surface noise: the noise of the surface point seen at the centre of each
// block of noiseBlock x noiseBlock pixels (the sketch interpolates it bilinearly; the noise
// varies over tens of pixels, and this pass then runs on one pixel in noiseBlock^2).
//NPR::Defines
in vec2 texCoord; // unused (pixels come from gl_FragCoord) but read: VTK warns about unread inputs
uniform sampler2D depthTexture;    // the G-buffer's depth
uniform sampler3D noiseTexture;    // xy: the noise vector, zw: the same at half the frequency
uniform float noiseCells;          // lattice cells of the xy noise across the tile
uniform mat4 deviceToView;         // inverse projection
uniform mat4 viewToNoise;          // view to world, relative to the noise's anchor
uniform float pixelFootprint;      // size of a pixel in view units, at view depth 1 (perspective)
uniform float cellPixels;          // wanted size of a noise cell in pixels
uniform float noiseReach;          // how far off the surface a pixel looks for it, in pixels
uniform float noiseBlock;          // pixels of a block on each side
uniform vec2 blockShift;           // the first block starts this many pixels before the texture
//NPR::WindowDepth
//NPR::AcrossTiles
//VTK::Output::Dec

bool nprInside(ivec2 texel, ivec2 size)
{
  return all(greaterThanEqual(texel, ivec2(0))) && all(lessThan(texel, size));
}

vec3 nprViewPosition(vec2 pixel, float stored, vec2 size)
{
  vec2 ndc = (pixel + 0.5) / size * 2.0 - 1.0;
#if NPR_REMAPPED_DEPTH
  // Log depth (perspective only): the point of the pixel's ray at that view depth.
  vec4 near = deviceToView * vec4(ndc, -1.0, 1.0);
  vec3 onNear = near.xyz / near.w;
  return onNear * (nprDepthRemap.x * exp(stored * nprDepthRemap.y) / -onNear.z);
#else
  vec4 view = deviceToView * vec4(ndc, stored * 2.0 - 1.0, 1.0);
  return view.xyz / view.w;
#endif
}

// The surface point's noise: two octaves a factor 2 apart, chosen and blended by the pixel size
// there, so that a cell keeps its size on screen within a factor of two under any zoom.
vec2 nprSurfaceNoise(vec3 view)
{
#if NPR_PERSPECTIVE
  float footprint = pixelFootprint * max(-view.z, 1e-30);
#else
  float footprint = pixelFootprint;
#endif
  float level = log2(max(footprint * cellPixels, 1e-30));
  float octave = floor(level);
  float t = level - octave;
  vec3 at = (viewToNoise * vec4(view, 1.0)).xyz * (exp2(-octave) / noiseCells);
  vec4 octaves = texture(noiseTexture, at) * 2.0 - 1.0; // stored as v / 2 + 1/2
  vec2 fine = octaves.xy;
  vec2 coarse = octaves.zw;
  // Blended independent noises keep their spread when divided by this; clamped to |n| <= 1.
  vec2 n = mix(fine, coarse, t) / sqrt(t * t + (1.0 - t) * (1.0 - t));
  float length2 = dot(n, n);
  return length2 > 1.0 ? n * inversesqrt(length2) : n;
}

vec2 nprNoise(vec2 pixel, ivec2 size)
{
  float stored = texelFetch(depthTexture, ivec2(pixel), 0).r;
  if (stored >= 1.0)
  {
    // Off the surface: the farthest surface within reach (along a silhouette, the rim's depth).
    const vec2 directions[8] = vec2[8](vec2(1.0, 0.0), vec2(0.70710678, 0.70710678),
      vec2(0.0, 1.0), vec2(-0.70710678, 0.70710678), vec2(-1.0, 0.0),
      vec2(-0.70710678, -0.70710678), vec2(0.0, -1.0), vec2(0.70710678, -0.70710678));
    stored = -1.0;
    for (int k = 0; k < 8; ++k)
    {
      ivec2 tap = nprAcrossTiles(ivec2(floor(pixel + 0.5 + noiseReach * directions[k])), size);
      float tapDepth = nprInside(tap, size) ? texelFetch(depthTexture, tap, 0).r : 1.0;
      stored = tapDepth < 1.0 ? max(stored, tapDepth) : stored;
    }
    if (stored < 0.0)
    {
      return vec2(0.0); // no surface near: no line near either
    }
  }
  return nprSurfaceNoise(nprViewPosition(pixel, stored, vec2(size)));
}

void main()
{
  if (texCoord.x < -1.0)
  {
    discard; // never: see texCoord
  }
  ivec2 size = textureSize(depthTexture, 0);
  vec2 pixel =
    clamp((floor(gl_FragCoord.xy) + 0.5) * noiseBlock - 0.5 - blockShift, vec2(0.0), vec2(size - 1));
  gl_FragData[0] = vec4(nprNoise(floor(pixel + 0.5), size), 0.0, 1.0);
}
