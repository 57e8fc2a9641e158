// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// Draws the line and point primitives of the opaque props, and the annotations (vtkNPROpaquePass),
// as VTK does, after a G-buffer effect left them out (vtkNPRGBufferPass), depth-tested against the
// effect's depth sprite: they keep their own colours and widths, and hide behind the styled
// surfaces. Polygons are not drawn (their vertices are moved out of the clip volume). Private to
// the module: vtkNPRPass runs it.
#ifndef vtkNPRLinePrimitivesPass_h
#define vtkNPRLinePrimitivesPass_h

#include "vtkNPRPassesModule.h" // for export macro
#include "vtkOpenGLRenderPass.h"

class vtkNPREdgePass;
class vtkNPRGBufferPass;
class vtkNPROpaquePass;

class VTKNPRPASSES_NO_EXPORT vtkNPRLinePrimitivesPass : public vtkOpenGLRenderPass
{
public:
  static vtkNPRLinePrimitivesPass* New();
  vtkTypeMacro(vtkNPRLinePrimitivesPass, vtkOpenGLRenderPass);

  // The pass that draws the props (a vtkOpaquePass); not owned, the façade keeps it.
  vtkRenderPass* DelegatePass = nullptr;
  // Asked whether its last G-buffer left line primitives out; nothing is drawn otherwise.
  vtkNPRGBufferPass* GBufferPass = nullptr;
  // The pass that drew the G-buffer's props, asked whether it left annotations out.
  vtkNPROpaquePass* SurfacePass = nullptr;
  // Its coverage-only mask (the lines alone) gets nothing from here.
  vtkNPREdgePass* EdgePass = nullptr;

  void Render(const vtkRenderState* state) override;
  bool PostReplaceShaderValues(std::string& vertexShader, std::string& geometryShader,
    std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop) override;

protected:
  vtkNPRLinePrimitivesPass() = default;
  ~vtkNPRLinePrimitivesPass() override = default;

private:
  vtkNPRLinePrimitivesPass(const vtkNPRLinePrimitivesPass&) = delete;
  void operator=(const vtkNPRLinePrimitivesPass&) = delete;
};

#endif
