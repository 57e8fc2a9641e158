// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// Draws the mesh edges of the actors that show them (vtkProperty::EdgeVisibilityOn, ParaView's
// "Surface With Edges") as a wireframe in the edge colour and line width, depth-tested against
// what the pass before it left (the drawing's depth sprite): the drawing paints faces in one
// colour and would lose the edges VTK draws into them. Each such actor (an assembly's parts too,
// with their path's matrix) gets a companion actor of its own mapper class (a shallow copy) in
// the wireframe representation, kept between frames, so
// that neither the user's actor nor its mapper is touched (their shaders and buffers stay as they
// are). Private to the module: vtkNPRPass runs it after vtkNPRDrawingPass.
#ifndef vtkNPRMeshEdgesPass_h
#define vtkNPRMeshEdgesPass_h

#include "vtkNPRPassesModule.h" // for export macro
#include "vtkRenderPass.h"

#include <memory> // for std::unique_ptr

class vtkActor;

class VTKNPRPASSES_NO_EXPORT vtkNPRMeshEdgesPass : public vtkRenderPass
{
public:
  static vtkNPRMeshEdgesPass* New();
  vtkTypeMacro(vtkNPRMeshEdgesPass, vtkRenderPass);

  void Render(const vtkRenderState* state) override;
  void ReleaseGraphicsResources(vtkWindow* window) override;

  // Whether the actor's mesh edges are drawn here: visible, opaque, a surface with its edges on.
  static bool ShowsMeshEdges(vtkActor* actor);

protected:
  vtkNPRMeshEdgesPass();
  ~vtkNPRMeshEdgesPass() override;

private:
  vtkNPRMeshEdgesPass(const vtkNPRMeshEdgesPass&) = delete;
  void operator=(const vtkNPRMeshEdgesPass&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
