// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNPRLinePrimitivesPass.h"

#include "vtkNPREdgePass.h"
#include "vtkNPRGBufferPass.h"
#include "vtkNPROpaquePass.h"
#include "vtkNPRPassUtilities.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLPolyDataMapper.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"

vtkStandardNewMacro(vtkNPRLinePrimitivesPass);

void vtkNPRLinePrimitivesPass::Render(const vtkRenderState* state)
{
  this->NumberOfRenderedProps = 0;
  const bool leftOut = (this->GBufferPass && this->GBufferPass->GetHasLinePrimitives()) ||
    (this->SurfacePass && this->SurfacePass->GetLeftOutAnnotations());
  if (!this->DelegatePass || !leftOut || state->GetRenderer()->GetSelector() ||
    (this->EdgePass && this->EdgePass->GetCoverageOnly()))
  {
    return; // a picking render draws everything in the G-buffer pass
  }
  this->PreRender(state);
  this->DelegatePass->Render(state);
  this->NumberOfRenderedProps = this->DelegatePass->GetNumberOfRenderedProps();
  this->PostRender(state);
}

bool vtkNPRLinePrimitivesPass::PostReplaceShaderValues(
  std::string& vertexShader, std::string&, std::string&, vtkAbstractMapper* mapper, vtkProp* prop)
{
  if (!vtkOpenGLPolyDataMapper::SafeDownCast(mapper) || vtkNPRKeepsOwnLook(mapper, prop))
  {
    return true;
  }
  // Polygons were drawn in the G-buffer: every vertex at one point beyond the far plane, nothing
  // rasterised. The point still depends on the position VTK computed, or the compiler drops the
  // attributes it came from, which the mapper then fails to set (a vtkGlyph3DMapper's per-glyph
  // matrix, GCMCMatrix: "Error setting 'GCMCMatrix' in shader VAO").
  const std::string::size_type end = vertexShader.rfind('}');
  if (end != std::string::npos)
  {
    vertexShader.insert(
      end, "  gl_Position = vec4(0.0, 0.0, 2.0, 1.0) * (abs(gl_Position.w) + 1.0);\n");
  }
  return true;
}
