// Declarations injected into a vtkOpenGLPolyDataMapper fragment shader while vtkNPRGBufferPass
// draws. The pass defines NPR_WRITE_NORMALS, NPR_WRITE_OBJECT_IDS, NPR_HAVE_MAPPER_NORMAL and
// NPR_HAVE_VERTEX_VC before this text.
uniform float nprObjectId;
uniform mat4 nprInverseProjection;
uniform vec4 nprViewport; // x, y, 1/width, 1/height of the G-buffer

// View-space position rebuilt from the window position and depth of this fragment.
vec3 nprFragmentPositionVC()
{
  vec4 ndc = vec4(2.0 * (gl_FragCoord.xy - nprViewport.xy) * nprViewport.zw - 1.0,
    2.0 * gl_FragCoord.z - 1.0, 1.0);
  vec4 p = nprInverseProjection * ndc;
  return p.xyz / p.w;
}

// Octahedral encoding, each coordinate quantised to 12 bits and both packed into one float
// (an integer below 2^24, exact in 32-bit float): about 0.05 degree resolution.
float nprPackNormal(vec3 n)
{
  n /= abs(n.x) + abs(n.y) + abs(n.z);
  vec2 e = n.xy;
  if (n.z < 0.0)
  {
    e = (1.0 - abs(n.yx)) * vec2(n.x >= 0.0 ? 1.0 : -1.0, n.y >= 0.0 ? 1.0 : -1.0);
  }
  e = floor((e * 0.5 + 0.5) * 4095.0 + 0.5);
  return e.x * 4096.0 + e.y;
}
