// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNPREdgeEffectPass.h"

#include "vtkNPREdgePass.h"
#include "vtkNPRGBufferPass.h"
#include "vtkObjectFactory.h"

vtkCxxSetObjectMacro(vtkNPREdgeEffectPass, EdgePass, vtkNPREdgePass);

vtkNPREdgeEffectPass::~vtkNPREdgeEffectPass()
{
  this->SetEdgePass(nullptr);
}

vtkNPRGBufferPass* vtkNPREdgeEffectPass::GetGBuffer()
{
  vtkNPRGBufferPass* gbuffer = this->EdgePass ? this->EdgePass->GetGBufferPass() : nullptr;
  if (!gbuffer)
  {
    vtkWarningMacro("no edge pass with a G-buffer: nothing drawn");
  }
  return gbuffer;
}

void vtkNPREdgeEffectPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "EdgePass: " << this->EdgePass << "\n";
}
