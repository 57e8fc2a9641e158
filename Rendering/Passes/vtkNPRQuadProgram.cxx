// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNPRQuadProgram.h"

#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderUtilities.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkShaderProgram.h"

vtkNPRQuadProgram::vtkNPRQuadProgram() = default;
vtkNPRQuadProgram::~vtkNPRQuadProgram() = default;

vtkShaderProgram* vtkNPRQuadProgram::Ready(
  vtkOpenGLRenderWindow* window, const std::string& source, const std::string& defines)
{
  if (this->Quad && defines != this->Defines)
  {
    this->Quad.reset();
  }
  if (!this->Quad)
  {
    std::string fragment = source;
    vtkShaderProgram::Substitute(fragment, "//NPR::Defines", defines);
    this->Quad.reset(new vtkOpenGLQuadHelper(window,
      vtkOpenGLRenderUtilities::GetFullScreenQuadVertexShader().c_str(), fragment.c_str(), ""));
    this->Defines = defines;
  }
  else
  {
    window->GetShaderCache()->ReadyShaderProgram(this->Quad->Program);
  }
  vtkShaderProgram* program = this->Quad->Program;
  return program && program->GetCompiled() ? program : nullptr;
}

void vtkNPRQuadProgram::Render()
{
  if (this->Quad)
  {
    this->Quad->Render();
  }
}

void vtkNPRQuadProgram::Release(vtkWindow* window)
{
  if (this->Quad)
  {
    this->Quad->ReleaseGraphicsResources(window);
    this->Quad.reset();
  }
}
