// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// A full-screen quad program of one of the module's fragment shaders, compiled for a set of
// compile-time defines (llvmpipe runs both sides of uniform branches, so variants are compiled
// rather than switched by uniforms). Private to the module's passes.
#ifndef vtkNPRQuadProgram_h
#define vtkNPRQuadProgram_h

#include <memory> // for std::unique_ptr
#include <string> // for std::string

class vtkOpenGLQuadHelper;
class vtkOpenGLRenderWindow;
class vtkShaderProgram;
class vtkWindow;

struct vtkNPRQuadProgram
{
  vtkNPRQuadProgram();
  ~vtkNPRQuadProgram();

  /**
   * Builds the program (the source's "//NPR::Defines" replaced by defines) when there is none
   * or the defines changed, binds it, and returns it; null when it did not compile.
   */
  vtkShaderProgram* Ready(
    vtkOpenGLRenderWindow* window, const std::string& source, const std::string& defines);

  /**
   * Draws the quad with the program made ready last.
   */
  void Render();

  void Release(vtkWindow* window);

private:
  std::unique_ptr<vtkOpenGLQuadHelper> Quad;
  std::string Defines;
};

#endif
