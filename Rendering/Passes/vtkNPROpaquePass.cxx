// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNPROpaquePass.h"

#include "vtkNPRPassUtilities.h"
#include "vtkObjectFactory.h"
#include "vtkProp.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"

vtkStandardNewMacro(vtkNPROpaquePass);

namespace
{
// Per thread: each thread renders its own context, and the hooks run inside the prop's draw.
thread_local vtkProp* PropBeingDrawn = nullptr;

class ScopedPropBeingDrawn
{
public:
  explicit ScopedPropBeingDrawn(vtkProp* prop)
    : Previous(PropBeingDrawn)
  {
    PropBeingDrawn = prop;
  }
  ~ScopedPropBeingDrawn() { PropBeingDrawn = this->Previous; }
  ScopedPropBeingDrawn(const ScopedPropBeingDrawn&) = delete;
  ScopedPropBeingDrawn& operator=(const ScopedPropBeingDrawn&) = delete;

private:
  vtkProp* Previous;
};
}

vtkProp* vtkNPROpaquePass::GetPropBeingDrawn()
{
  return PropBeingDrawn;
}

void vtkNPROpaquePass::Render(const vtkRenderState* state)
{
  // vtkDefaultPass::RenderFilteredOpaqueGeometry (unchanged from VTK 9.1 to 9.6), with the prop
  // recorded around its draw and the annotations left out on request.
  this->NumberOfRenderedProps = 0;
  this->LeftOutAnnotations = false;
  for (int i = 0; i < state->GetPropArrayCount(); ++i)
  {
    vtkProp* prop = state->GetPropArray()[i];
    if (this->SurfacesOnly && vtkNPRIsAnnotation(prop))
    {
      this->LeftOutAnnotations = true;
    }
    else if (prop->HasKeys(state->GetRequiredKeys()))
    {
      const ScopedPropBeingDrawn scope(prop);
      this->NumberOfRenderedProps +=
        prop->RenderFilteredOpaqueGeometry(state->GetRenderer(), state->GetRequiredKeys());
    }
  }
}

void vtkNPROpaquePass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SurfacesOnly: " << this->SurfacesOnly << "\n";
  os << indent << "LeftOutAnnotations: " << this->LeftOutAnnotations << "\n";
}
