//VTK::System::Dec
// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// nprOneFetchPass: each pixel of the scene's image copied by one fetch, no filtering, no math.

in vec2 texCoord; // the full-screen quad's, at pixel centres
uniform sampler2D source;

//VTK::Output::Dec

void main()
{
  gl_FragData[0] = texelFetch(source, ivec2(texCoord * vec2(textureSize(source, 0))), 0);
}
