// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNPRGeometryPass.h"

#include "vtkNPRPassUtilities.h"
#include "vtkNPRShaderHook.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"

vtkCxxSetObjectMacro(vtkNPRGeometryPass, DelegatePass, vtkRenderPass);

vtkNPRGeometryPass::vtkNPRGeometryPass(
  const char* hookName, const char* implAfter, const char* what)
  : Hook(new vtkNPRShaderHook(hookName, implAfter, what))
{
}

vtkNPRGeometryPass::~vtkNPRGeometryPass()
{
  this->SetDelegatePass(nullptr);
}

bool vtkNPRGeometryPass::StartRender(const vtkRenderState* state)
{
  vtkOpenGLClearErrorMacro();
  this->NumberOfRenderedProps = 0;
  if (!this->DelegatePass)
  {
    vtkWarningMacro("no delegate pass: nothing drawn");
    return false;
  }
  this->LastRenderWasSelection = vtkNPRRenderSelection(state, this->NumberOfRenderedProps);
  if (this->LastRenderWasSelection)
  {
    return false;
  }
  this->Hook->Window = static_cast<vtkOpenGLRenderWindow*>(state->GetRenderer()->GetRenderWindow());
  return true;
}

bool vtkNPRGeometryPass::PreReplaceShaderValues(
  std::string&, std::string&, std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp*)
{
  this->Hook->InsertTags(this, fragmentShader, mapper);
  return true;
}

bool vtkNPRGeometryPass::PostReplaceShaderValues(std::string& vertexShader,
  std::string& geometryShader, std::string& fragmentShader, vtkAbstractMapper* mapper,
  vtkProp* prop)
{
  if (this->Hook->IsTagged(fragmentShader, mapper))
  {
    this->FillShaderCode(vertexShader, geometryShader, fragmentShader, mapper, prop);
  }
  return true;
}

void vtkNPRGeometryPass::ReleaseGraphicsResources(vtkWindow* window)
{
  if (this->DelegatePass)
  {
    this->DelegatePass->ReleaseGraphicsResources(window);
  }
}

vtkMTimeType vtkNPRGeometryPass::GetShaderStageMTime()
{
  return this->ShaderStageTime.GetMTime();
}

void vtkNPRGeometryPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "DelegatePass: " << this->DelegatePass << "\n";
}
