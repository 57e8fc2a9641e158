// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNPRLineBlocks.h"

#include "vtkNPRLineBlocksFS.h"
#include "vtkNPRLineBlocksVS.h"
#include "vtkNPROpenGL.h"
#include "vtkNPRPassUtilities.h"
#include "vtkNPRQuadProgram.h"
#include "vtkNPRRenderTarget.h"
#include "vtkNew.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include <algorithm>

struct vtkNPRLineBlocks::Internals
{
  vtkNPRRenderTarget Target;
  vtkNPRQuadProgram GroupMark;
  vtkNPRQuadProgram BlockMark;
  vtkTextureObject* Groups = nullptr;       // one texel per 4 x 4 pixels: their largest line value
  vtkTextureObject* Blocks = nullptr;       // one texel per block, 1 near a line
  vtkNew<vtkOpenGLVertexArrayObject> Empty; // the block quads have no vertex buffer
  int Grid[2] = { 0, 0 };
  int Rows[2] = { 0, -1 }; // the rows of blocks that meet the rectangle: the rest is not drawn
  int Image[2] = { 0, 0 };
  unsigned long Version = 0;
  int Reach = -1;
  // The programs drawn over the near blocks [1] and the others [0], and their defines: built
  // when the defines change, only bound otherwise.
  vtkShaderProgram* Programs[2] = { nullptr, nullptr };
  std::string Defines[2];
};

vtkNPRLineBlocks::vtkNPRLineBlocks()
  : Internal(new Internals)
{
}

vtkNPRLineBlocks::~vtkNPRLineBlocks()
{
  for (vtkTextureObject* texture : { this->Internal->Groups, this->Internal->Blocks })
  {
    if (texture)
    {
      texture->Delete();
    }
  }
}

bool vtkNPRLineBlocks::Update(vtkOpenGLRenderWindow* window, vtkTextureObject* lines,
  unsigned long version, int reach, const int rect[4])
{
  Internals& internal = *this->Internal;
  const int width = static_cast<int>(lines->GetWidth());
  const int height = static_cast<int>(lines->GetHeight());
  if (internal.Blocks && internal.Version == version && internal.Reach == reach &&
    internal.Image[0] == width && internal.Image[1] == height)
  {
    return true;
  }
  internal.Image[0] = width;
  internal.Image[1] = height;
  internal.Grid[0] = (width + BlockSize - 1) / BlockSize;
  internal.Grid[1] = (height + BlockSize - 1) / BlockSize;
  internal.Rows[0] = std::max(0, rect[1] / BlockSize);
  internal.Rows[1] = std::min(internal.Grid[1] - 1, rect[3] / BlockSize);
  // The 4 x 4 groups' maxima, then the blocks from them: a block's pixels and the reach around
  // them read once each in the first pass, a few dozen groups per block in the second.
  const int groups[2] = { (width + 3) / 4, (height + 3) / 4 };
  const int groupRect[4] = { rect[0] / 4, rect[1] / 4, rect[2] / 4, rect[3] / 4 };
  const int groupReach = (reach + 3) / 4;
  const int blockRect[4] = { std::max(0, groupRect[0] - groupReach) * 4 / BlockSize,
    std::max(0, groupRect[1] - groupReach) * 4 / BlockSize,
    (groupRect[2] + groupReach) * 4 / BlockSize, (groupRect[3] + groupReach) * 4 / BlockSize };
  if (!this->Mark(window, internal.GroupMark, lines, internal.Groups, groups, groupRect, 1, 0) ||
    !this->Mark(window, internal.BlockMark, internal.Groups, internal.Blocks, internal.Grid,
      blockRect, 0, groupReach))
  {
    internal.Reach = -1;
    return false;
  }
  internal.Version = version;
  internal.Reach = reach;
  return true;
}

bool vtkNPRLineBlocks::Mark(vtkOpenGLRenderWindow* window, vtkNPRQuadProgram& mark,
  vtkTextureObject* input, vtkTextureObject*& output, const int size[2], const int rect[4],
  int groups, int reach)
{
  const std::string defines = "#define NPR_BLOCK_SIZE " + std::to_string(BlockSize) +
    "\n#define NPR_GROUPS " + std::to_string(groups) + "\n";
  vtkShaderProgram* program = mark.Ready(window, vtkNPRLineBlocksFS, defines);
  if (!program)
  {
    vtkGenericWarningMacro("vtkNPRLineBlocks: the block marking shader did not compile");
    return false;
  }
  if (!output)
  {
    output = vtkNPRNewTexture(window, vtkTextureObject::Nearest, vtkTextureObject::ClampToEdge);
    output->Allocate2D(size[0], size[1], 1, VTK_UNSIGNED_CHAR);
  }
  output->Resize(size[0], size[1]);
  vtkNPRRenderTarget::Scope target(
    this->Internal->Target, window, { output }, nullptr, size[0], size[1]);
  target.Clear(0.0, 0.0, 0.0, 0.0);
  target.ScissorTo(rect); // the input is zero outside it
  input->Activate();
  program->SetUniformi("lineTexture", input->GetTextureUnit());
  program->SetUniformi("reach", reach);
  mark.Render();
  input->Deactivate();
  return true;
}

vtkShaderProgram* vtkNPRLineBlocks::Ready(
  vtkOpenGLRenderWindow* window, bool near, const std::string& fragment, const std::string& defines)
{
  Internals& internal = *this->Internal;
  vtkShaderProgram*& program = internal.Programs[near ? 1 : 0];
  if (program && internal.Defines[near ? 1 : 0] == defines)
  {
    program = window->GetShaderCache()->ReadyShaderProgram(program);
  }
  else
  {
    std::string source = fragment;
    vtkShaderProgram::Substitute(source, "//NPR::Defines", defines);
    program = window->GetShaderCache()->ReadyShaderProgram(vtkNPRLineBlocksVS, source.c_str(), "");
    internal.Defines[near ? 1 : 0] = defines;
  }
  return program && program->GetCompiled() ? program : nullptr;
}

void vtkNPRLineBlocks::Draw(vtkShaderProgram* program, bool near)
{
  Internals& internal = *this->Internal;
  internal.Blocks->Activate();
  program->SetUniformi("blockTexture", internal.Blocks->GetTextureUnit());
  program->SetUniform2i("gridSize", internal.Grid);
  const float image[2] = { static_cast<float>(internal.Image[0]),
    static_cast<float>(internal.Image[1]) };
  program->SetUniform2f("imageSize", image);
  program->SetUniformi("blockSize", BlockSize);
  program->SetUniformi("drawNear", near ? 1 : 0);
  internal.Empty->Bind();
  const int rows = internal.Rows[1] - internal.Rows[0] + 1;
  if (rows > 0)
  {
    glDrawArrays(
      GL_TRIANGLES, 6 * internal.Grid[0] * internal.Rows[0], 6 * internal.Grid[0] * rows);
  }
  internal.Empty->Release();
  internal.Blocks->Deactivate();
}

void vtkNPRLineBlocks::ReleaseGraphicsResources(vtkWindow* window)
{
  Internals& internal = *this->Internal;
  internal.Target.ReleaseGraphicsResources(window);
  internal.GroupMark.Release(window);
  internal.BlockMark.Release(window);
  internal.Empty->ReleaseGraphicsResources();
  for (vtkTextureObject** texture : { &internal.Groups, &internal.Blocks })
  {
    if (*texture)
    {
      (*texture)->ReleaseGraphicsResources(window);
      (*texture)->Delete();
      *texture = nullptr;
    }
  }
  internal.Reach = -1;
  internal.Programs[0] = internal.Programs[1] = nullptr; // the window's shader cache had them
}
