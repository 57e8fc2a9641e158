// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
//VTK::System::Dec
// vtkNPRDrawingPass: the faces in one colour, the rasterised strokes (premultiplied RGBA) over
// them, and the depth sprite (gl_FragDepth).
//NPR::Defines
in vec2 texCoord;
uniform sampler2D strokeTexture; // premultiplied RGBA, one texel per pixel
uniform sampler2D depthTexture;
uniform ivec2 viewportOrigin; // of the renderer in the window
uniform vec3 faceColor;
//NPR::WindowDepth
//NPR::NearestDepth
//VTK::Output::Dec

void main()
{
  if (texCoord.x < -1.0)
  {
    discard; // never: texCoord is read so that VTK does not warn about an unread input
  }
  ivec2 p = ivec2(gl_FragCoord.xy) - viewportOrigin;
  vec4 stroke = texelFetch(strokeTexture, p, 0);
  float depth = texelFetch(depthTexture, p, 0).r;
  if (depth < 1.0)
  {
    gl_FragData[0] = vec4(faceColor * (1.0 - stroke.a) + stroke.rgb, 1.0);
    gl_FragDepth = nprWindowDepth(depth);
  }
  else
  {
    if (stroke.a <= 0.0)
    {
      discard;
    }
    // Over the window's background (blended: colour not premultiplied, coverage as alpha).
    gl_FragData[0] = vec4(stroke.rgb / stroke.a, stroke.a);
    gl_FragDepth = nprWindowDepth(nprNearestDepth(p));
  }
}
