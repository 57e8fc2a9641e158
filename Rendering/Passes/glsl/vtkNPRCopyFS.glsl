// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
//VTK::System::Dec
// vtkNPRGBufferPass, depth-only mode: puts the captured image (colour and depth) back into the
// framebuffer the pass was called with, as its delegate would have left it.
//NPR::Defines
in vec2 texCoord;
uniform sampler2D colorTexture;
uniform sampler2D depthTexture;
//VTK::Output::Dec

void main()
{
  ivec2 q = ivec2(texCoord * vec2(textureSize(colorTexture, 0)));
  gl_FragData[0] = texelFetch(colorTexture, q, 0);
  gl_FragDepth = texelFetch(depthTexture, q, 0).x;
}
