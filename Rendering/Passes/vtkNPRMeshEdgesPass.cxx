// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNPRMeshEdgesPass.h"

#include "vtkActor.h"
#include "vtkMapper.h"
#include "vtkMatrix4x4.h"
#include "vtkNPROpenGL.h"
#include "vtkNPRPassUtilities.h"
#include "vtkNPRPropParts.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkWeakPointer.h"

#include <algorithm>
#include <cstring>
#include <map>
#include <utility>

vtkStandardNewMacro(vtkNPRMeshEdgesPass);

namespace
{
// The fraction of the depth range the edges are drawn nearer by: about what VTK's coincident
// topology offset moves lines (units -4: 6.4e-5), times a few for wide lines on slanted faces.
constexpr double EdgeDepthPull = 5e-4;

// The mapper's settings and input onto the companion's. A vtkPolyDataMapper's own copy: in VTK
// 9.1 vtkOpenGLPolyDataMapper::ShallowCopy also copies the deprecated shader-code settings, with
// a deprecation warning for each (ParaView's output window would show them every time).
void nprCopyMapper(vtkMapper* from, vtkMapper* to)
{
  if (auto* polyDataMapper = vtkPolyDataMapper::SafeDownCast(to))
  {
    polyDataMapper->vtkPolyDataMapper::ShallowCopy(from);
  }
  else
  {
    to->ShallowCopy(from);
  }
}

// The wireframe companion of one user actor, and what it was last copied from.
struct nprEdgeCompanion
{
  vtkWeakPointer<vtkActor> Source;
  vtkSmartPointer<vtkActor> Actor;
  vtkMTimeType MapperTime = 0;
  vtkMTimeType PropertyTime = 0;

  // Brings the companion up to date with its actor, drawn with `matrix` (the actor's own, or its
  // assembly path's); copies only what changed, so that an unchanged actor leaves the
  // companion's shaders and buffers as they are.
  void Update(vtkActor* source, vtkMatrix4x4* matrix)
  {
    vtkMapper* mapper = source->GetMapper();
    if (!this->Actor || strcmp(this->Actor->GetMapper()->GetClassName(), mapper->GetClassName()))
    {
      this->Actor = vtkSmartPointer<vtkActor>::New();
      this->Actor->SetMapper(vtkSmartPointer<vtkMapper>::Take(mapper->NewInstance()));
      this->MapperTime = this->PropertyTime = 0;
    }
    if (mapper->GetMTime() != this->MapperTime)
    {
      nprCopyMapper(mapper, this->Actor->GetMapper());
      this->Actor->GetMapper()->ScalarVisibilityOff(); // the edge colour, as VTK draws edges
      this->MapperTime = mapper->GetMTime();
    }
    vtkProperty* from = source->GetProperty();
    if (from->GetMTime() != this->PropertyTime)
    {
      vtkProperty* to = this->Actor->GetProperty();
      to->SetRepresentationToWireframe();
      to->LightingOff();
      to->SetColor(from->GetEdgeColor());
      // VTK 9.1-9.3 draw a mesh edge as a band a line width wide, smoothed over a pixel on each
      // side: as wide as an aliased line one pixel wider.
      to->SetLineWidth(from->GetLineWidth() + 1.0f);
      this->PropertyTime = from->GetMTime();
    }
    vtkMatrix4x4* own = this->Actor->GetUserMatrix();
    if (!own ||
      !std::equal(&matrix->Element[0][0], &matrix->Element[0][0] + 16, &own->Element[0][0]))
    {
      vtkNew<vtkMatrix4x4> copy;
      copy->DeepCopy(matrix);
      this->Actor->SetUserMatrix(copy);
    }
  }
};
}

struct vtkNPRMeshEdgesPass::Internals
{
  // By top-level prop and part (the actor itself, or an assembly's part actor).
  std::map<std::pair<vtkProp*, vtkActor*>, nprEdgeCompanion> Companions;
};

vtkNPRMeshEdgesPass::vtkNPRMeshEdgesPass()
  : Internal(new Internals)
{
}

vtkNPRMeshEdgesPass::~vtkNPRMeshEdgesPass() = default;

bool vtkNPRMeshEdgesPass::ShowsMeshEdges(vtkActor* actor)
{
  vtkProperty* property = actor ? actor->GetProperty() : nullptr;
  return property && actor->GetVisibility() && actor->GetMapper() &&
    vtkNPRDrawsMeshEdges(property) && actor->HasOpaqueGeometry();
}

void vtkNPRMeshEdgesPass::Render(const vtkRenderState* state)
{
  this->NumberOfRenderedProps = 0;
  vtkRenderer* renderer = state->GetRenderer();
  auto& companions = this->Internal->Companions;
  for (auto it = companions.begin(); it != companions.end();) // forget deleted actors
  {
    it = it->second.Source ? std::next(it) : companions.erase(it);
  }
  if (renderer->GetSelector())
  {
    return; // a picking render picks the surfaces, not their edges
  }
  // The lines lie on the faces whose depth the sprite holds: drawn a little nearer (the depth
  // range shortened by EdgeDepthPull at its far end), they pass the depth test all along instead
  // of every other pixel, and stay hidden behind other faces. vtkOpenGLState does not track it.
  float range[2] = { 0.0f, 1.0f };
  glGetFloatv(GL_DEPTH_RANGE, range);
  glDepthRange(range[0], range[0] + (range[1] - range[0]) * (1.0 - EdgeDepthPull));
  for (int i = 0; i < state->GetPropArrayCount(); ++i)
  {
    vtkProp* prop = state->GetPropArray()[i];
    for (const vtkNPRPropPart& part : vtkNPRPropParts(prop))
    {
      auto* actor = vtkActor::SafeDownCast(part.Prop);
      if (!ShowsMeshEdges(actor))
      {
        continue;
      }
      nprEdgeCompanion& companion = companions[{ prop, actor }];
      companion.Source = actor;
      companion.Update(actor, part.Matrix); // an actor's part always has one
      this->NumberOfRenderedProps += companion.Actor->RenderOpaqueGeometry(renderer);
    }
  }
  glDepthRange(range[0], range[1]);
}

void vtkNPRMeshEdgesPass::ReleaseGraphicsResources(vtkWindow* window)
{
  for (auto& entry : this->Internal->Companions)
  {
    if (entry.second.Actor)
    {
      entry.second.Actor->ReleaseGraphicsResources(window);
    }
  }
}
