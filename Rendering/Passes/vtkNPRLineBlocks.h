// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// The blocks of a line image that a line can reach, and a program's fragments drawn over those
// blocks alone or over the others. A composite whose line code runs only near lines pays for it
// where lines are: the blocks' quads are rasterised, nothing else, whereas a discard or a branch
// in a full-screen pass still runs the code for every pixel on a software renderer (llvmpipe).
// Private to NPR::Passes.
//
// @code
// blocks.Update(window, lineTexture, lineImageVersion, reach, contentRectangle);
// vtkShaderProgram* program = blocks.Ready(window, true, fragmentSource, defines);
// // ... the program's own textures and uniforms ...
// blocks.Draw(program, true); // only the blocks marked near a line
// @endcode
#ifndef vtkNPRLineBlocks_h
#define vtkNPRLineBlocks_h

#include <memory> // for std::unique_ptr
#include <string> // for std::string

class vtkOpenGLRenderWindow;
struct vtkNPRQuadProgram;
class vtkShaderProgram;
class vtkTextureObject;
class vtkWindow;

class vtkNPRLineBlocks
{
public:
  static constexpr int BlockSize = 16; // pixels

  vtkNPRLineBlocks();
  ~vtkNPRLineBlocks();
  vtkNPRLineBlocks(const vtkNPRLineBlocks&) = delete;
  vtkNPRLineBlocks& operator=(const vtkNPRLineBlocks&) = delete;

  /**
   * Marks each block of `lines` with a texel (any channel above zero) within `reach` pixels of it,
   * looking only at the blocks that meet `rect` (x0, y0, x1, y1, inclusive; the line image is
   * zero outside it). Nothing to do when the image's update count and the reach are those of the
   * last call. False where the marking shader did not compile (reported).
   */
  bool Update(vtkOpenGLRenderWindow* window, vtkTextureObject* lines, unsigned long version,
    int reach, const int rect[4]);

  /**
   * Binds the program drawn over the blocks near a line (near) or over the others: a fragment
   * shader with its "//NPR::Defines" replaced by defines, built (the window's shader cache keeps
   * it) when the defines are not those of the last call. Null where it did not compile.
   */
  vtkShaderProgram* Ready(vtkOpenGLRenderWindow* window, bool near, const std::string& fragment,
    const std::string& defines);

  /**
   * Draws the bound program over the blocks near a line (near) or over the others, in the
   * viewport as set (the blocks divide it as they divide the line image), the rows of blocks
   * that meet the rectangle of the last Update() only.
   */
  void Draw(vtkShaderProgram* program, bool near);

  void ReleaseGraphicsResources(vtkWindow* window);

private:
  // One marking pass (glsl/vtkNPRLineBlocksFS.glsl) from input into output, made size[0] x
  // size[1], over rect of output.
  bool Mark(vtkOpenGLRenderWindow* window, vtkNPRQuadProgram& mark, vtkTextureObject* input,
    vtkTextureObject*& output, const int size[2], const int rect[4], int groups, int reach);

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
