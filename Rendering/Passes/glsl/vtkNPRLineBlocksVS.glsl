// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
//VTK::System::Dec
// vtkNPRLineBlocks, step 2: two triangles per block of the image, drawn without vertex buffers
// (vertex i belongs to block i / 6). A block of the kind drawn (drawNear: those marked near a
// line, or the others) covers its pixels; the corners of any other block lie outside the clip
// volume, so that none of its pixels is rasterised at all: the fragment shader runs only over the
// blocks drawn.
uniform sampler2D blockTexture; // r: 1 near a line
uniform ivec2 gridSize;         // blocks across and up
uniform vec2 imageSize;         // pixels of the image the blocks divide
uniform int blockSize;          // pixels
uniform int drawNear;           // 1: the blocks near a line; 0: the others
out vec2 texCoord;              // as the full-screen quad gives it

void main()
{
  const ivec2 corners[6] =
    ivec2[6](ivec2(0, 0), ivec2(1, 0), ivec2(1, 1), ivec2(0, 0), ivec2(1, 1), ivec2(0, 1));
  int index = gl_VertexID / 6;
  ivec2 block = ivec2(index % gridSize.x, index / gridSize.x);
  bool near = texelFetch(blockTexture, block, 0).r > 0.5;
  vec2 pixel = min(vec2((block + corners[gl_VertexID - 6 * index]) * blockSize), imageSize);
  texCoord = pixel / imageSize;
  vec4 outside = vec4(2.0, 2.0, 2.0, 1.0);
  gl_Position = near == (drawNear == 1) ? vec4(2.0 * texCoord - 1.0, 0.0, 1.0) : outside;
}
