// vtkNPRToonPass: the light reaching a surface, shared by the vertex (per-vertex toon) and the
// fragment shaders. Lights are set by the pass from the renderer's switched-on lights, in view
// coordinates, as VTK's own lighting sees them.
#define NPR_TOON_MAX_LIGHTS 8
uniform int nprToonLightCount;
uniform vec4 nprToonLightPosition[NPR_TOON_MAX_LIGHTS];    // w = 0: direction towards the light; 1: position
uniform vec4 nprToonLightSpot[NPR_TOON_MAX_LIGHTS];        // xyz: direction the light shines in; w: cos(cone), -2 for no cone
uniform vec4 nprToonLightAttenuation[NPR_TOON_MAX_LIGHTS]; // constant, linear, quadratic; w: spot exponent
uniform float nprToonLightIntensity[NPR_TOON_MAX_LIGHTS];  // intensity x luminance of the colour

// x: sum of intensity x attenuation x max(0, n.l); y: the same for the Phong specular term.
vec2 nprToonLight(vec3 n, vec3 p, float specularPower)
{
  vec2 sum = vec2(0.0);
  vec3 toEye = normalize(-p);
  for (int i = 0; i < nprToonLightCount; ++i)
  {
    vec3 l = nprToonLightPosition[i].xyz;
    float attenuation = 1.0;
    if (nprToonLightPosition[i].w != 0.0)
    {
      vec3 toLight = nprToonLightPosition[i].xyz - p;
      float distance = length(toLight);
      l = toLight / max(distance, 1e-30);
      vec3 k = nprToonLightAttenuation[i].xyz;
      attenuation = 1.0 / max(k.x + k.y * distance + k.z * distance * distance, 1e-30);
      if (nprToonLightSpot[i].w > -1.5)
      {
        float coneDot = dot(-l, nprToonLightSpot[i].xyz);
        attenuation = coneDot >= nprToonLightSpot[i].w
          ? attenuation * pow(max(coneDot, 0.0), nprToonLightAttenuation[i].w)
          : 0.0;
      }
    }
    float diffuse = max(0.0, dot(n, l));
    sum.x += nprToonLightIntensity[i] * attenuation * diffuse;
    if (diffuse > 0.0)
    {
      sum.y += nprToonLightIntensity[i] * attenuation *
        pow(max(0.0, dot(reflect(-l, n), toEye)), specularPower);
    }
  }
  return sum;
}
