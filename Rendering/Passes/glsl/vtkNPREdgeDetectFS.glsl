// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
//VTK::System::Dec
// vtkNPREdgePass, step 1: line pixels from the G-buffer's geometry attachment.
// Output: r = silhouette, g = crease, b = object contour, a = suggestive contour strength (0..1)
// on the pixels the line belongs to. One texel fetch per tap, five taps (a cross): fetches are
// the cost on llvmpipe. NPR_ENCODING says how the G-buffer stores the geometry
// (vtkNPRGBufferPass::GeometryEncoding): 0 float (depth, 12-bit octahedral normal packed in one
// float, id, the face normal packed likewise), 1 half (depth / far, octahedral normal in two
// channels, id), 2 and 3 the packed 8- and 16-bit depth+normal value.
//NPR::Defines
in vec2 texCoord;
uniform sampler2D geometryTexture; // view depth (> 0, 0 = background), normal, id
uniform float silhouetteThreshold; // relative depth step
uniform float creaseAngle;         // radians
uniform float creaseRamp;          // radians: soft ramp around the threshold
uniform float packedThreshold;     // packed: Laplacian, in units of one component's range
uniform float packedUnit;          // packed: a texel value in units of one component's range
uniform float suggestiveThreshold; // second difference of n.v over one pixel
uniform vec3 viewRayOrigin; // view space: the ray through pixel (0, 0)'s centre (the direction of
uniform vec3 viewRayPerPixelX; // projection for a parallel view), and its change per pixel
uniform vec3 viewRayPerPixelY;
#if !NPR_PERSPECTIVE
uniform vec3 viewPixelStepX; // parallel view: the step between neighbouring pixels' points
uniform vec3 viewPixelStepY;
#endif
//VTK::Output::Dec

#if NPR_ENCODING >= 2
// The packed buffer of the 1990s engines: one value mixes depth and normal, so one Laplacian
// finds every line, of no particular type (reported as silhouettes). Its magnitude is taken, so a
// step gives a line on both of its sides, as it did then. NPR_PACKED_BLUR smooths the value with
// a 3x3 binomial kernel first (a 5x5 kernel in all): fatter lines, fewer from quantisation.
float nprPackedAt(ivec2 q, ivec2 size)
{
  return texelFetch(geometryTexture, clamp(q, ivec2(0), size - 1), 0).x;
}

void main()
{
  ivec2 size = textureSize(geometryTexture, 0);
  ivec2 p = ivec2(texCoord * vec2(size));
#if NPR_PACKED_BLUR
  float v[25];
  for (int j = 0; j < 5; ++j)
  {
    for (int i = 0; i < 5; ++i)
    {
      v[5 * j + i] = nprPackedAt(p + ivec2(i - 2, j - 2), size);
    }
  }
  // Blurred value at the centre (c) and its four neighbours, from the 3x3 around each.
  float blurred[5];
  const ivec2 centres[5] = ivec2[5](ivec2(2, 2), ivec2(3, 2), ivec2(1, 2), ivec2(2, 3), ivec2(2, 1));
  for (int k = 0; k < 5; ++k)
  {
    ivec2 c = centres[k];
    float sum = 0.0;
    for (int j = -1; j <= 1; ++j)
    {
      for (int i = -1; i <= 1; ++i)
      {
        float w = (i == 0 ? 2.0 : 1.0) * (j == 0 ? 2.0 : 1.0);
        sum += w * v[5 * (c.y + j) + c.x + i];
      }
    }
    blurred[k] = sum / 16.0;
  }
  float laplacian = 4.0 * blurred[0] - blurred[1] - blurred[2] - blurred[3] - blurred[4];
#else
  float laplacian = 4.0 * nprPackedAt(p, size) - nprPackedAt(p + ivec2(1, 0), size) -
    nprPackedAt(p - ivec2(1, 0), size) - nprPackedAt(p + ivec2(0, 1), size) -
    nprPackedAt(p - ivec2(0, 1), size);
#endif
  float response = abs(laplacian) * packedUnit;
  float line = smoothstep(packedThreshold, 1.5 * packedThreshold, response);
  gl_FragData[0] = vec4(line, 0.0, 0.0, 0.0);
}
#else

#if NPR_ENCODING == 1
#define NPR_NORMAL(g) nprUnpackOctahedral(g.yz)
#define NPR_FACE_NORMAL(g) nprUnpackOctahedral(g.yz) // half: the interpolated normal only
#define NPR_ID(g) g.w
#else
#define NPR_NORMAL(g) nprUnpackNormal(g.y)
#if NPR_HAVE_FACE_NORMALS
#define NPR_FACE_NORMAL(g) nprUnpackNormal(g.w)
#else
#define NPR_FACE_NORMAL(g) nprUnpackNormal(g.y)
#endif
#define NPR_ID(g) g.z
#endif

vec3 nprUnpackOctahedral(vec2 e)
{
  vec3 n = vec3(e, 1.0 - abs(e.x) - abs(e.y));
  if (n.z < 0.0)
  {
    n.xy = (1.0 - abs(n.yx)) * vec2(n.x >= 0.0 ? 1.0 : -1.0, n.y >= 0.0 ? 1.0 : -1.0);
  }
  return normalize(n);
}

// The view-space direction from the eye through pixel q's centre (parallel: of projection).
vec3 nprViewRay(ivec2 q)
{
  return viewRayOrigin + float(q.x) * viewRayPerPixelX + float(q.y) * viewRayPerPixelY;
}

// The depth operator's quantity, affine in screen space on planes: 1/z for perspective, z for
// parallel projection. Background (depth 0) is farthest: 0, or a million times depth0.
float nprAffineDepth(float depth, float depth0)
{
#if NPR_PERSPECTIVE
  return depth > 0.0 ? 1.0 / depth : 0.0;
#else
  return depth > 0.0 ? depth : 1e6 * depth0;
#endif
}

vec3 nprUnpackNormal(float code)
{
  return nprUnpackOctahedral(vec2(floor(code / 4096.0), mod(code, 4096.0)) / 4095.0 * 2.0 - 1.0);
}

#if NPR_CREASES
// Whether a crease runs between pixel p and its neighbour p + d that lies farther by more than a
// step's margin, so that the neighbour leaves the line out as a step's far side (main, below).
// At a concave crease whose nearer face is seen nearly edge-on (a cone rising from a flange,
// seen from a little above its slope) the depth jumps by as much across one pixel as at a step;
// but the planes of the two faces (their normals through their depths) cross between the two
// pixels' centres, where at a step the nearer surface's plane stays in front at both. a0, aD: the
// affine depths (1/z for perspective, z for a parallel view).
bool nprCreaseBeyondStep(ivec2 p, ivec2 d, float depth0, float depthD, float a0, float aD,
  vec3 n0, vec3 nD)
{
  if (depth0 >= depthD * (1.0 - 4.0 * silhouetteThreshold))
  {
    return false;
  }
  // This surface against the neighbour's plane at p (here), then this plane against the
  // neighbour's surface at p + d (there).
#if NPR_PERSPECTIVE
  // On a plane through a point of affine depth a at ray r, the affine depth at ray r' is
  // a (n.r') / (n.r).
  vec3 ray0 = nprViewRay(p);
  vec3 rayD = nprViewRay(p + d);
  float here = a0 - aD * dot(nD, ray0) / dot(nD, rayD);
  float there = a0 * dot(n0, rayD) / dot(n0, ray0) - aD;
#else
  // Parallel rays along -z: a plane of normal n through view depth z at one pixel has view depth
  // z + (n.xy . s) / n.z at the pixel a view-space step s away.
  vec2 s = (float(d.x) * viewPixelStepX + float(d.y) * viewPixelStepY).xy;
  float here = a0 - (aD - dot(nD.xy, s) / nD.z);
  float there = a0 + dot(n0.xy, s) / n0.z - aD;
#endif
  return here * there <= 0.0;
}
#endif

void main()
{
  ivec2 size = textureSize(geometryTexture, 0);
  ivec2 p = ivec2(texCoord * vec2(size)); // this pass draws the whole G-buffer
  vec4 g0 = texelFetch(geometryTexture, p, 0);
  vec4 g[4];
  g[0] = texelFetch(geometryTexture, ivec2(min(p.x + 1, size.x - 1), p.y), 0);
  g[1] = texelFetch(geometryTexture, ivec2(max(p.x - 1, 0), p.y), 0);
  g[2] = texelFetch(geometryTexture, ivec2(p.x, min(p.y + 1, size.y - 1)), 0);
  g[3] = texelFetch(geometryTexture, ivec2(p.x, max(p.y - 1, 0)), 0);
  bool covered0 = g0.x > 0.0;

  // Second-order depth operator (Saito & Takahashi), relative to this pixel's depth. It is taken
  // on 1/z for perspective and on z for parallel projection, the quantity that is affine in
  // screen space, so that it vanishes on planes at any slant (no lines on grazing faces). Its
  // sign says which side of a step this pixel is on: positive = the nearer side.
  float step2 = 0.0;
  float a0 = 1.0;
  float a[4] = float[4](0.0, 0.0, 0.0, 0.0);
  float lapX = 0.0;
  float lapY = 0.0;
#if NPR_PERSPECTIVE
  const float towardsNear = -1.0;
#else
  const float towardsNear = 1.0;
#endif
  if (covered0)
  {
    a0 = nprAffineDepth(g0.x, g0.x);
    for (int k = 0; k < 4; ++k)
    {
      a[k] = nprAffineDepth(g[k].x, g0.x);
    }
    // At the image border one neighbour is missing: that axis contributes nothing.
    lapX = (p.x > 0 && p.x < size.x - 1) ? a[0] + a[1] - 2.0 * a0 : 0.0;
    lapY = (p.y > 0 && p.y < size.y - 1) ? a[2] + a[3] - 2.0 * a0 : 0.0;
    step2 = towardsNear * (lapX + lapY) / a0;
  }

  float silhouette = 0.0;
#if NPR_SILHOUETTES
  silhouette = smoothstep(silhouetteThreshold, 2.0 * silhouetteThreshold, step2);
  if (silhouette > 0.0)
  {
    // A step or a kink? A surface that folds away seen nearly edge-on (a shallow crease, a fold
    // past a contour's ending) bends the depth as much as a step does. Along the axis that bends
    // most, towards the farther neighbour, the second difference one pixel further on tells
    // them apart: past a step it has the opposite sign (the far side's own bend), past a kink
    // between the two pixels it has the same sign or none. One more fetch, on line pixels only.
    // towardsNear * a grows with the distance (-1/z or z); the background is farthest.
    bool alongX = towardsNear * lapX >= towardsNear * lapY;
    float aPlus = alongX ? a[0] : a[2];
    float aMinus = alongX ? a[1] : a[3];
    bool farIsMinus = towardsNear * aMinus > towardsNear * aPlus;
    float aFar = farIsMinus ? aMinus : aPlus;
    ivec2 beyond = p + (farIsMinus ? -2 : 2) * (alongX ? ivec2(1, 0) : ivec2(0, 1));
    if (all(greaterThanEqual(beyond, ivec2(0))) && all(lessThan(beyond, size)))
    {
      float aBeyond = nprAffineDepth(texelFetch(geometryTexture, beyond, 0).x, g0.x);
      float bendBeyond = towardsNear * (aBeyond + a0 - 2.0 * aFar) / a0;
      silhouette = bendBeyond < -silhouetteThreshold ? silhouette : 0.0;
    }
  }
#endif

#if NPR_FACING
  // n.v, the cosine between the interpolated normal and the direction to the eye, at the five
  // taps. Its zero set is the contour of the smooth surface the normals describe; its minima
  // along the view direction are the suggestive contours.
  const ivec2 offsets[4] = ivec2[4](ivec2(1, 0), ivec2(-1, 0), ivec2(0, 1), ivec2(0, -1));
  // The rays of neighbouring pixels have all but the same length: divided by this pixel's,
  // one square root instead of five.
  vec3 ray0 = nprViewRay(p);
  float rayScale = inversesqrt(dot(ray0, ray0));
  float facing0 = covered0 ? -dot(NPR_NORMAL(g0), ray0) * rayScale : 0.0;
  // The neighbours' n.v only where this pixel can hold a line: a sign change drawn here needs
  // |n.v| below a half on both sides or a turn of the normal by over 60 degrees within a pixel
  // (a crease); suggestive contours need them everywhere.
  float facing[4] = float[4](facing0, facing0, facing0, facing0);
#if !NPR_SUGGESTIVE
  if (covered0 && abs(facing0) < 0.5)
#endif
  {
    for (int k = 0; k < 4; ++k)
    {
      facing[k] = -dot(NPR_NORMAL(g[k]), nprViewRay(p + offsets[k])) * rayScale;
    }
  }
  bool ofObject[4]; // the neighbour is covered, by this pixel's object
  for (int k = 0; k < 4; ++k)
  {
    ofObject[k] = covered0 && g[k].x > 0.0;
#if NPR_HAVE_OBJECT_IDS
    ofObject[k] = ofObject[k] && NPR_ID(g[k]) == NPR_ID(g0);
#endif
  }
  // The taps clamped at the image border repeat this pixel: they are no neighbours.
  bool inside[4] = bool[4](p.x < size.x - 1, p.x > 0, p.y < size.y - 1, p.y > 0);
#endif

#if NPR_SMOOTH_SILHOUETTES
  if (covered0)
  {
    for (int k = 0; k < 4; ++k)
    {
      bool line = false;
      if (ofObject[k] && inside[k] && (facing0 > 0.0) != (facing[k] > 0.0))
      {
        // n.v changes sign between this pixel and its neighbour: the contour runs between
        // them. Drawn on the pixel nearer the zero (ties: the front-facing one).
        float t = facing0 / (facing0 - facing[k]);
        line = facing0 > 0.0 ? t <= 0.5 : t < 0.5;
      }
      silhouette = line ? 1.0 : silhouette;
    }
  }
#endif
  float suggestive = 0.0;
#if NPR_SUGGESTIVE
  // Suggestive contours (DeCarlo et al. 2003): where n.v, positive, has a minimum along the view
  // direction projected onto the surface. In the image that direction is the one in which the
  // surface recedes: the gradient of depth. The second derivative of n.v along it must exceed the
  // threshold (its strength) and the first derivative vanish within half a pixel.
  if (covered0 && facing0 > 0.0 && ofObject[0] && ofObject[1] && ofObject[2] &&
    ofObject[3] && inside[0] && inside[1] && inside[2] && inside[3] &&
    abs(step2) <= silhouetteThreshold)
  {
    vec2 recede = vec2(g[0].x - g[1].x, g[2].x - g[3].x);
    float recedeLength = length(recede);
    if (recedeLength > 0.0)
    {
      vec2 w = recede / recedeLength;
      float first = 0.5 * (w.x * (facing[0] - facing[1]) + w.y * (facing[2] - facing[3]));
      float second = w.x * w.x * (facing[0] + facing[1] - 2.0 * facing0) +
        w.y * w.y * (facing[2] + facing[3] - 2.0 * facing0);
      if (second > 0.0 && abs(first) <= 0.5 * second)
      {
        suggestive = smoothstep(suggestiveThreshold, 2.0 * suggestiveThreshold, second);
      }
    }
  }
#endif

  float crease = 0.0;
#if NPR_CREASES
  if (covered0)
  {
    // Between the faces' own normals (float encoding): the mesh's creases, also where the
    // shading normals are averaged across an edge sharper than the angle.
    vec3 n0 = NPR_FACE_NORMAL(g0);
    const ivec2 steps[4] = ivec2[4](ivec2(1, 0), ivec2(-1, 0), ivec2(0, 1), ivec2(0, -1));
    for (int k = 0; k < 4; ++k)
    {
      // Not across a depth step from the far side: that line is the nearer surface's silhouette.
      // Both tests are needed: a fold between a steep and a flat face also bends the depth.
      bool farSide = step2 < -silhouetteThreshold && g[k].x < g0.x * (1.0 - 4.0 * silhouetteThreshold);
      bool sameObject = g[k].x > 0.0 && !farSide;
#if NPR_HAVE_OBJECT_IDS
      sameObject = sameObject && NPR_ID(g[k]) == NPR_ID(g0);
#endif
      if (sameObject)
      {
        vec3 nk = NPR_FACE_NORMAL(g[k]);
        // One pixel per crease: the side that faces the viewer more (ties: right and up), or
        // this side where the other is a step's far side across the crease (left out above).
        if (n0.z > nk.z || (n0.z == nk.z && (k == 0 || k == 2)) ||
          nprCreaseBeyondStep(p, steps[k], g0.x, g[k].x, a0, a[k], n0, nk))
        {
          float angle = acos(clamp(dot(n0, nk), -1.0, 1.0));
          crease = max(crease, smoothstep(creaseAngle - creaseRamp, creaseAngle + creaseRamp, angle));
        }
      }
    }
  }
#endif

  float contour = 0.0;
#if NPR_CONTOURS
  // Object contours: the id changes (or, with one object, coverage changes). The nearer side is
  // "inside" the object in front; background is farthest.
#if NPR_HAVE_OBJECT_IDS
  float id0 = covered0 ? NPR_ID(g0) : -1.0;
#else
  float id0 = covered0 ? 1.0 : -1.0;
#endif
  float depth0 = covered0 ? g0.x : 3.0e38;
  for (int k = 0; k < 4; ++k)
  {
#if NPR_HAVE_OBJECT_IDS
    float idk = g[k].x > 0.0 ? NPR_ID(g[k]) : -1.0;
#else
    float idk = g[k].x > 0.0 ? 1.0 : -1.0;
#endif
    if (idk != id0)
    {
      float depthk = g[k].x > 0.0 ? g[k].x : 3.0e38;
      // Objects touching or passing through each other (a depth step below the silhouette
      // threshold): the larger id counts as nearer, so the line keeps to one side.
      bool nearer = abs(depth0 - depthk) <= silhouetteThreshold * min(depth0, depthk)
        ? id0 > idk : depth0 < depthk;
#if NPR_CONTOUR_SIDE == 0
      contour = nearer ? 1.0 : contour;
#elif NPR_CONTOUR_SIDE == 1
      contour = nearer ? contour : 1.0;
#else
      contour = 1.0;
#endif
    }
  }
#endif
  gl_FragData[0] = vec4(silhouette, crease, contour, suggestive);
}
#endif
