// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// Draws the opaque props as vtkOpaquePass does, one top-level prop at a time, and says which one
// is being drawn (GetPropBeingDrawn). The passes' shader hooks only see the actor a mapper draws
// for: for a vtkFollower's label, a vtkLODActor or a vtkCubeAxesActor that is an inner actor, not
// the prop the user added. VTK 9.4 added vtkRenderPass::PreRenderProp for this; VTK 9.1-9.3 have
// nothing. With SurfacesOnly it leaves the annotations (vtkNPRIsAnnotation: followers, axes
// actors, image slices) out: a G-buffer effect draws them afterwards, as VTK does; some of them
// (vtkAxesActor) do not pass the passes' property keys on to their inner actors, so no shader hook
// could leave them out of the G-buffer. Private to the module: vtkNPRPass runs it.
#ifndef vtkNPROpaquePass_h
#define vtkNPROpaquePass_h

#include "vtkNPRPassesModule.h" // for export macro
#include "vtkOpaquePass.h"

class vtkProp;

class VTKNPRPASSES_NO_EXPORT vtkNPROpaquePass : public vtkOpaquePass
{
public:
  static vtkNPROpaquePass* New();
  vtkTypeMacro(vtkNPROpaquePass, vtkOpaquePass);

  void Render(const vtkRenderState* state) override;

  // Whether the annotations are left out (default: false, every prop is drawn).
  vtkSetMacro(SurfacesOnly, bool);
  vtkGetMacro(SurfacesOnly, bool);

  // Whether its last Render left an annotation out.
  vtkGetMacro(LeftOutAnnotations, bool);

  void PrintSelf(ostream& os, vtkIndent indent) override;

  // The top-level prop this thread is drawing through a vtkNPROpaquePass, or nullptr outside one.
  static vtkProp* GetPropBeingDrawn();

protected:
  vtkNPROpaquePass() = default;
  ~vtkNPROpaquePass() override = default;

  bool SurfacesOnly = false;
  bool LeftOutAnnotations = false;

private:
  vtkNPROpaquePass(const vtkNPROpaquePass&) = delete;
  void operator=(const vtkNPROpaquePass&) = delete;
};

#endif
