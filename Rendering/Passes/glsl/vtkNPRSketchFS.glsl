// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
//VTK::System::Dec
// vtkNPRSketchPass: lines and surfaces looked up through noise-displaced coordinates, merged on
// the surface colour or the paper, with the smaller of the two displaced depths as the depth
// sprite. Every lookup is a texelFetch with the filtering done here, so that with screen noise
// the displacement of each pixel is exactly what vtkNPRSketchPass::GetDisplacement() computes.
//NPR::Defines
in vec2 texCoord; // unused (pixels come from gl_FragCoord) but read: VTK warns about unread inputs
uniform sampler2D colorTexture;    // the G-buffer's colour (flat colours)
uniform sampler2D depthTexture;    // the G-buffer's depth
uniform sampler2D coverageTexture; // r, g, b: coverage of each line type; a: the lines' depth
uniform ivec2 coverageLow;         // the texels written, corners included: no line elsewhere
uniform ivec2 coverageHigh;
uniform ivec2 viewportOrigin;      // of the renderer in the window
#if NPR_SURFACE_NOISE
uniform sampler2D noiseTexture;    // the surface noise of each block of pixels (xy)
uniform float noiseBlock;          // pixels of a block on each side
uniform vec2 blockShift;           // the first block starts this many pixels before the texture
#else
uniform sampler2D noiseTexture;    // 256 x 256 tile, xy: noise vector
uniform float noiseScale;          // noise texels per pixel
uniform ivec2 tileOffset;          // of this tile in the renderer's whole image (tiled renders)
#endif
uniform vec4 edgeDisplacement;     // uncertainty x edge matrix, row major
uniform vec4 surfaceDisplacement;  // uncertainty x surface matrix, row major
uniform vec3 paperColor;
//NPR::LineColor
//NPR::AcrossTiles
//NPR::WindowDepth
//VTK::Output::Dec

bool nprInside(ivec2 texel, ivec2 size)
{
  return all(greaterThanEqual(texel, ivec2(0))) && all(lessThan(texel, size));
}

// Bilinear mix of the xy of four texels: i and j the lower and upper corners, f the weights.
vec2 nprBilinear(sampler2D tile, ivec2 i, ivec2 j, vec2 f)
{
  vec2 n00 = texelFetch(tile, i, 0).xy;
  vec2 n10 = texelFetch(tile, ivec2(j.x, i.y), 0).xy;
  vec2 n01 = texelFetch(tile, ivec2(i.x, j.y), 0).xy;
  vec2 n11 = texelFetch(tile, j, 0).xy;
  return mix(mix(n00, n10, f.x), mix(n01, n11, f.x), f.y);
}

#if NPR_SURFACE_NOISE
// The noise field of vtkNPRSketchNoiseFS (one texel per block), interpolated bilinearly.
vec2 nprNoise(vec2 pixel)
{
  ivec2 last = textureSize(noiseTexture, 0) - 1;
  vec2 t = (pixel + blockShift + 0.5) / noiseBlock - 0.5;
  vec2 cell = floor(t);
  return nprBilinear(noiseTexture, clamp(ivec2(cell), ivec2(0), last),
    clamp(ivec2(cell) + 1, ivec2(0), last), t - cell);
}
#else
// The screen noise's tile, wrapped around, in the pixels of the renderer's whole image.
vec2 nprNoise(vec2 pixel)
{
  vec2 t = (pixel + vec2(tileOffset) + 0.5) * noiseScale - 0.5;
  vec2 cell = floor(t);
  ivec2 i = ivec2(cell) & 255;
  return nprBilinear(noiseTexture, i, (i + 1) & 255, t - cell);
}
#endif

vec2 nprTimes(vec4 m, vec2 v)
{
  return vec2(m.x * v.x + m.y * v.y, m.z * v.x + m.w * v.y);
}

vec4 nprCoverageAt(ivec2 texel, ivec2 size)
{
  texel = nprAcrossTiles(texel, size);
  bool written =
    all(greaterThanEqual(texel, coverageLow)) && all(lessThanEqual(texel, coverageHigh));
  return written ? texelFetch(coverageTexture, texel, 0) : vec4(0.0, 0.0, 0.0, 1.0);
}

void main()
{
  if (texCoord.x < -1.0)
  {
    discard; // never: see texCoord
  }
  ivec2 size = textureSize(depthTexture, 0);
  vec2 pixel = vec2(ivec2(gl_FragCoord.xy) - viewportOrigin);
  vec2 noise = nprNoise(pixel);

  // Surfaces: nearest texel at the displaced position.
  ivec2 surfaceTexel =
    nprAcrossTiles(ivec2(floor(pixel + 0.5 + nprTimes(surfaceDisplacement, noise))), size);
  float surfaceDepth = 1.0;
  vec3 surfaceColor = vec3(0.0);
  if (nprInside(surfaceTexel, size))
  {
    surfaceDepth = texelFetch(depthTexture, surfaceTexel, 0).r;
    surfaceColor = texelFetch(colorTexture, surfaceTexel, 0).rgb;
  }

  // Lines: bilinear coverage at the displaced position, the depth of its nearest texel.
  vec2 lineAt = pixel + 0.5 + nprTimes(edgeDisplacement, noise);
  vec2 t = lineAt - 0.5;
  vec2 corner = floor(t);
  vec2 f = t - corner;
  ivec2 i = ivec2(corner);
  vec4 c00 = nprCoverageAt(i, size);
  vec4 c10 = nprCoverageAt(i + ivec2(1, 0), size);
  vec4 c01 = nprCoverageAt(i + ivec2(0, 1), size);
  vec4 c11 = nprCoverageAt(i + ivec2(1, 1), size);
  vec3 coverage = mix(mix(c00.rgb, c10.rgb, f.x), mix(c01.rgb, c11.rgb, f.x), f.y);
  ivec2 nearest = ivec2(floor(lineAt)) - i; // 0 or 1 on each axis
  float lineDepth = nearest.y == 0 ? (nearest.x == 0 ? c00.a : c10.a) : (nearest.x == 0 ? c01.a : c11.a);

  float depth = min(surfaceDepth, lineDepth);
  bool onLine = max(coverage.r, max(coverage.g, coverage.b)) > 0.0;
  if (surfaceDepth < 1.0)
  {
    gl_FragData[0] = vec4(nprLinesOver(surfaceColor, coverage), 1.0);
  }
  else
  {
#if NPR_PAPER
    // On the paper the lines keep their own colours.
    gl_FragData[0] = vec4(nprLinesOver(paperColor, vec4(coverage, 0.0), nprSetLineColors()), 1.0);
#else
    if (onLine)
    {
      gl_FragData[0] = nprLinesAlone(coverage);
    }
    else if (depth < 1.0)
    {
      gl_FragData[0] = vec4(0.0); // the depth sprite only: the background shows
    }
    else
    {
      discard;
    }
#endif
  }
  gl_FragDepth = nprWindowDepth(depth);
}
