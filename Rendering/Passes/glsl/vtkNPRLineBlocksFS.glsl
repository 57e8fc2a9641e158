// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
//VTK::System::Dec
// vtkNPRLineBlocks, step 1 in two passes. NPR_GROUPS 1: each texel the largest line value of a
// 4 x 4 group of the line image's texels (exact: a maximum of 8-bit values is one). NPR_GROUPS 0:
// one texel per block of NPR_BLOCK_SIZE x NPR_BLOCK_SIZE pixels, 1 where a group within `reach`
// groups of the block holds a line value above zero (a composite pixel there may be covered), 0
// elsewhere. Loop bounds are the same for every pixel: a software renderer runs one loop for a
// whole group of pixels.
//NPR::Defines
in vec2 texCoord;
uniform sampler2D lineTexture; // NPR_GROUPS 1: the line image; 0: the groups' maxima
uniform int reach;             // groups
//VTK::Output::Dec

void main()
{
  ivec2 size = textureSize(lineTexture, 0);
  float found = texCoord.x < -1.0 ? 1.0 : 0.0; // texCoord read: VTK warns about an unread input
#if NPR_GROUPS
  ivec2 first = ivec2(gl_FragCoord.xy) * 4;
  for (int j = 0; j < 4; ++j)
  {
    for (int i = 0; i < 4; ++i)
    {
      vec4 v = texelFetch(lineTexture, min(first + ivec2(i, j), size - 1), 0);
      found = max(found, max(max(v.r, v.g), max(v.b, v.a)));
    }
  }
  gl_FragData[0] = vec4(found, 0.0, 0.0, 1.0);
#else
  const int groups = NPR_BLOCK_SIZE / 4;
  ivec2 first = ivec2(gl_FragCoord.xy) * groups - ivec2(reach);
  int span = groups + 2 * reach;
  for (int j = 0; j < span; ++j)
  {
    for (int i = 0; i < span; ++i)
    {
      found = max(found, texelFetch(lineTexture, clamp(first + ivec2(i, j), ivec2(0), size - 1), 0).r);
    }
  }
  gl_FragData[0] = vec4(found > 0.0 ? 1.0 : 0.0, 0.0, 0.0, 1.0);
#endif
}
