// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// vtkNPRToonPass: the light reaching a surface, shared by the vertex (per-vertex toon) and the
// fragment shaders. Lights are set by the pass from the renderer's switched-on lights, in view
// coordinates, as VTK's own lighting sees them. Their number (NPR_TOON_LIGHTS) and whether any
// is positional (NPR_TOON_POSITIONAL) are compiled in: a loop over a uniform count costs llvmpipe
// as much again as the whole shaded frame.
uniform vec4 nprToonLightPosition[NPR_TOON_LIGHT_ARRAY];    // w = 0: direction towards the light; 1: position
uniform float nprToonLightIntensity[NPR_TOON_LIGHT_ARRAY];  // intensity x luminance of the colour
#if NPR_TOON_POSITIONAL
uniform vec4 nprToonLightSpot[NPR_TOON_LIGHT_ARRAY];        // xyz: direction the light shines in; w: cos(cone), -2 for no cone
uniform vec4 nprToonLightAttenuation[NPR_TOON_LIGHT_ARRAY]; // constant, linear, quadratic; w: spot exponent
#endif

// x: sum of intensity x attenuation x max(0, n.l); y: the same for the Phong specular term.
vec2 nprToonLight(vec3 n, vec3 p, float specularPower)
{
  vec2 sum = vec2(0.0);
  vec3 toEye = normalize(-p);
  for (int i = 0; i < NPR_TOON_LIGHTS; ++i)
  {
    vec3 l = nprToonLightPosition[i].xyz;
    float attenuation = 1.0;
#if NPR_TOON_POSITIONAL
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
#endif
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
