// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkNPRGeometryPass
 * @brief   The base of the passes that draw the geometry through a delegate with their code in
 *          the mappers' shaders: vtkNPRGBufferPass, vtkNPRToonPass and vtkNPRInkPass.
 *
 * Holds the delegate (normally a vtkOpaquePass), releases its graphics resources with the pass's
 * own, prints it, and starts each Render() the same way (StartRender()): no delegate draws
 * nothing, with a warning; a picking render is handed to the delegate as it is. The shader-stage
 * time (GetShaderStageMTime()) is ShaderStageTime, which a subclass modifies when the code it
 * puts into the mappers' shaders changes.
 *
 * @sa vtkNPRGBufferPass vtkNPRToonPass vtkNPRInkPass
 */
#ifndef vtkNPRGeometryPass_h
#define vtkNPRGeometryPass_h

#include "vtkNPRPassesModule.h" // for export macro
#include "vtkOpenGLRenderPass.h"
#include "vtkTimeStamp.h" // for vtkTimeStamp

class VTKNPRPASSES_EXPORT vtkNPRGeometryPass : public vtkOpenGLRenderPass
{
public:
  vtkTypeMacro(vtkNPRGeometryPass, vtkOpenGLRenderPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The pass that draws the geometry (normally a vtkOpaquePass).
   */
  vtkGetObjectMacro(DelegatePass, vtkRenderPass);
  virtual void SetDelegatePass(vtkRenderPass* pass);
  ///@}

  /**
   * Releases the delegate's resources (a subclass adds its own).
   */
  void ReleaseGraphicsResources(vtkWindow* window) override;

  /**
   * When the code put into the mappers' shaders last changed.
   */
  vtkMTimeType GetShaderStageMTime() override;

protected:
  vtkNPRGeometryPass() = default;
  ~vtkNPRGeometryPass() override;

  /**
   * The start of Render(): clears OpenGL's errors and the count of props drawn; false when
   * Render() is to stop: no delegate (a warning) or a picking render, which the delegate drew.
   * LastRenderWasSelection tells which (unchanged without a delegate).
   */
  bool StartRender(const vtkRenderState* state);

  vtkRenderPass* DelegatePass = nullptr;
  bool LastRenderWasSelection = false;
  vtkTimeStamp ShaderStageTime; // the code in the mappers' shaders changed

private:
  vtkNPRGeometryPass(const vtkNPRGeometryPass&) = delete;
  void operator=(const vtkNPRGeometryPass&) = delete;
};

#endif
