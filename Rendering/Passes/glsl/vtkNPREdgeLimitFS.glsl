// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
//VTK::System::Dec
// vtkNPREdgePass, step 1b (MaximumLineFraction): lines no wider than a fraction of the object they
// lie on. The object is what the lines outline: from a line pixel, each of the two axes and two
// diagonals is walked both ways over the covered pixels of the same id until the next outline
// (silhouette or contour) beyond the pixel's own, and the second shortest of these chords is the
// object's width there. Creases do not end a chord: a CAD face stays the object it is part of.
//
// A line pixel of a narrower object gets a value s < 1 that makes the composite draw its line
// narrower: the composite's Gaussian turns a one-pixel line of value s into a line as wide as
// where s P(d) meets P's level at the full width w, so a width x < w takes
// s = exp(-(w^2 - x^2) / (8 sigma^2)); below one pixel s falls linearly to the value at which the
// anti-aliased line leaves no coverage at all.
//NPR::Defines
in vec2 texCoord;
uniform sampler2D lineTexture;     // the detection's one-pixel lines (r, g, b, a: the types)
uniform sampler2D geometryTexture; // view depth (> 0 where covered) and the object ids
uniform vec4 widthLimitWidths;     // each type's width the composite draws, pixels
uniform float widthLimitFraction;  // the largest share of the object's width one line may take
uniform float widthLimitExponent;  // 1 / (8 sigma^2) of the composite's Gaussian
uniform vec4 widthLimitVanishing;  // each type's value at which its line leaves no coverage
uniform int widthLimitPixels;      // objects this wide or wider keep the full width
//VTK::Output::Dec

bool nprSameObject(vec4 g, vec4 g0)
{
#if NPR_HAVE_OBJECT_IDS
  return g.x > 0.0 && g[NPR_ID_CHANNEL] == g0[NPR_ID_CHANNEL];
#else
  return g.x > 0.0;
#endif
}

bool nprOutline(vec4 lines)
{
  return lines.r > 0.0 || lines.b > 0.0;
}

// How many pixels on from p along dir the object of p goes, at most limit: the last one counted is
// the first outline pixel after two that are none. A single pixel off the outline does not count:
// a walk nearly along a slanted outline leaves its staircase and meets it again a step later. Past
// the image's border the object goes on (in a tiled render, into the next tile).
int nprObjectRun(ivec2 p, ivec2 dir, ivec2 size, vec4 g0, int offLine, int limit)
{
  int run = 0;
  for (int i = 1; i <= limit; ++i)
  {
    ivec2 q = p + i * dir;
    if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, size)))
    {
      run = limit;
      break;
    }
    if (!nprSameObject(texelFetch(geometryTexture, q, 0), g0))
    {
      break;
    }
    run = i;
    bool outline = nprOutline(texelFetch(lineTexture, q, 0));
    if (outline && offLine >= 2)
    {
      break;
    }
    offLine = outline ? 0 : offLine + 1;
  }
  return run;
}

// The object's width through p in pixels, as far as widthLimitPixels: the second shortest of its
// chords through p along the two axes and the two diagonals. On a band (a tube, a wire) the two
// chords nearest its cross direction are 1 to 1.41 times its width; at the outline of a wide
// convex object the chord along the outline leaves the object after a few pixels, but no other.
float nprObjectWidth(ivec2 p, ivec2 size, vec4 g0, int offLine)
{
  const ivec2 directions[4] = ivec2[4](ivec2(1, 0), ivec2(0, 1), ivec2(1, 1), ivec2(1, -1));
  const float lengths[4] = float[4](1.0, 1.0, 1.41421356, 1.41421356);
  float shortest = float(widthLimitPixels);
  float second = shortest;
  for (int k = 0; k < 4; ++k)
  {
    int limit = int(ceil(second / lengths[k])) - 1;
    int forward = nprObjectRun(p, directions[k], size, g0, offLine, limit);
    int backward = nprObjectRun(p, -directions[k], size, g0, offLine, limit - forward);
    float chord = float(forward + backward + 1) * lengths[k];
    second = min(second, max(shortest, chord));
    shortest = min(shortest, chord);
  }
  return second;
}

// The factors on a line pixel's values (r, g, b, a: the types) that make the composite draw each
// type's line min(its width, widthLimitFraction x object width) wide.
vec4 nprWidthFactors(float objectWidth)
{
  vec4 width = min(widthLimitWidths, vec4(widthLimitFraction * objectWidth));
  vec4 full = widthLimitWidths * widthLimitWidths;
  vec4 onePixel = min(vec4(1.0), widthLimitWidths);
  vec4 narrower = exp(-(full - width * width) * widthLimitExponent);
  vec4 atOnePixel = exp(-(full - onePixel * onePixel) * widthLimitExponent);
  vec4 belowOnePixel = mix(widthLimitVanishing, atOnePixel, width / onePixel);
  return mix(belowOnePixel, narrower, greaterThanEqual(width, onePixel));
}

void main()
{
  ivec2 size = textureSize(lineTexture, 0);
  ivec2 p = ivec2(texCoord * vec2(size)); // this pass draws the whole line image
  vec4 lines = texelFetch(lineTexture, p, 0);
  vec4 g0 = texelFetch(geometryTexture, p, 0);
  if (g0.x > 0.0 && any(greaterThan(lines, vec4(0.0))))
  {
    vec4 factors = nprWidthFactors(nprObjectWidth(p, size, g0, nprOutline(lines) ? 0 : 2));
    if (any(lessThan(factors, vec4(1.0))))
    {
      // Too narrow for full-width lines: its outline only, one line per pixel. Lines of several
      // types on one pixel darken it together far more than each one's width allows, and creases
      // inside a thin object crowd its outline (on a stream tube a few pixels wide the shading
      // normals turn by more than the crease angle from one pixel to the next).
      lines = factors * (lines.r > 0.0 ? vec4(lines.r, 0.0, 0.0, 0.0) : vec4(0.0, 0.0, lines.b, 0.0));
    }
  }
  gl_FragData[0] = lines;
}
