// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
//VTK::System::Dec
// vtkNPRInkPass, a frame that draws lines or points: the ink found against the pulled faces in an
// image of its own, put over the frame with its depth (the faces there are at their own depth).
//NPR::Defines
in vec2 texCoord;
uniform sampler2D inkTexture;
uniform sampler2D depthTexture;
//VTK::Output::Dec

void main()
{
  ivec2 q = ivec2(texCoord * vec2(textureSize(inkTexture, 0)));
  vec4 ink = texelFetch(inkTexture, q, 0);
  if (ink.a < 0.75) // background (0) or a face over the ink (a half)
  {
    discard;
  }
  gl_FragData[0] = vec4(ink.rgb, 1.0);
  gl_FragDepth = texelFetch(depthTexture, q, 0).x;
}
