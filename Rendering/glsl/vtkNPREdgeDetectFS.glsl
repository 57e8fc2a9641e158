//VTK::System::Dec
// vtkNPREdgePass, step 1: line pixels from the G-buffer's geometry attachment.
// Output: r = silhouette, g = crease, b = object contour strength (0..1) on the pixels the line
// belongs to. One texel fetch per tap, five taps (a cross): fetches are the cost on llvmpipe.
//NPR::Defines
in vec2 texCoord;
uniform sampler2D geometryTexture; // view depth (> 0, 0 = background), packed normal, id
uniform float silhouetteThreshold; // relative depth step
uniform float creaseAngle;         // radians
uniform float creaseRamp;          // radians: soft ramp around the threshold
//VTK::Output::Dec

vec3 nprUnpackNormal(float code)
{
  vec2 e = vec2(floor(code / 4096.0), mod(code, 4096.0)) / 4095.0 * 2.0 - 1.0;
  vec3 n = vec3(e, 1.0 - abs(e.x) - abs(e.y));
  if (n.z < 0.0)
  {
    n.xy = (1.0 - abs(n.yx)) * vec2(n.x >= 0.0 ? 1.0 : -1.0, n.y >= 0.0 ? 1.0 : -1.0);
  }
  return normalize(n);
}

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
  if (covered0)
  {
#if NPR_PERSPECTIVE
    float a0 = 1.0 / g0.x;
    float a[4];
    for (int k = 0; k < 4; ++k)
    {
      a[k] = g[k].x > 0.0 ? 1.0 / g[k].x : 0.0;
    }
    const float towardsNear = -1.0;
#else
    float a0 = g0.x;
    float a[4];
    for (int k = 0; k < 4; ++k)
    {
      a[k] = g[k].x > 0.0 ? g[k].x : 1e6 * g0.x;
    }
    const float towardsNear = 1.0;
#endif
    // At the image border one neighbour is missing: that axis contributes nothing.
    float lapX = (p.x > 0 && p.x < size.x - 1) ? a[0] + a[1] - 2.0 * a0 : 0.0;
    float lapY = (p.y > 0 && p.y < size.y - 1) ? a[2] + a[3] - 2.0 * a0 : 0.0;
    step2 = towardsNear * (lapX + lapY) / a0;
  }

  float silhouette = 0.0;
#if NPR_SILHOUETTES
  silhouette = smoothstep(silhouetteThreshold, 2.0 * silhouetteThreshold, step2);
#endif

  float crease = 0.0;
#if NPR_CREASES
  if (covered0)
  {
    vec3 n0 = nprUnpackNormal(g0.y);
    for (int k = 0; k < 4; ++k)
    {
      // Not across a depth step from the far side: that line is the nearer surface's silhouette.
      // Both tests are needed: a fold between a steep and a flat face also bends the depth.
      bool farSide = step2 < -silhouetteThreshold && g[k].x < g0.x * (1.0 - 4.0 * silhouetteThreshold);
      bool sameObject = g[k].x > 0.0 && !farSide;
#if NPR_HAVE_OBJECT_IDS
      sameObject = sameObject && g[k].z == g0.z;
#endif
      if (sameObject)
      {
        vec3 nk = nprUnpackNormal(g[k].y);
        // One pixel per crease: the side that faces the viewer more (ties: right and up).
        if (n0.z > nk.z || (n0.z == nk.z && (k == 0 || k == 2)))
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
  float id0 = covered0 ? g0.z : -1.0;
#else
  float id0 = covered0 ? 1.0 : -1.0;
#endif
  float depth0 = covered0 ? g0.x : 3.0e38;
  for (int k = 0; k < 4; ++k)
  {
#if NPR_HAVE_OBJECT_IDS
    float idk = g[k].x > 0.0 ? g[k].z : -1.0;
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
  gl_FragData[0] = vec4(silhouette, crease, contour, 0.0);
}
