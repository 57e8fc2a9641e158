// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNPRShaderHook.h"

#include "vtkNPRPassUtilities.h"
#include "vtkNew.h"
#include "vtkObject.h"
#include "vtkOpenGLPolyDataMapper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkProp.h"
#include "vtkShader.h"
#include "vtkShaderProgram.h"

namespace
{
// The cache's last substitutions are protected members of VTK 9.1-9.6; a pointer to member taken
// through a derived class reads them.
struct nprShaderCacheAccess : public vtkOpenGLShaderCache
{
  // VTK 9.1-9.3: vertex, fragment, geometry; later also the tessellation stages. The member's
  // type picks the overload, so no version check.
  using Replace3 = unsigned int (vtkOpenGLShaderCache::*)(std::string&, std::string&, std::string&);
  using Replace5 = unsigned int (vtkOpenGLShaderCache::*)(
    std::string&, std::string&, std::string&, std::string&, std::string&);
  static void Call(vtkOpenGLShaderCache* cache, Replace3 replace, std::string& vertex,
    std::string& fragment, std::string& geometry)
  {
    (cache->*replace)(vertex, fragment, geometry);
  }
  static void Call(vtkOpenGLShaderCache* cache, Replace5 replace, std::string& vertex,
    std::string& fragment, std::string& geometry)
  {
    std::string control, evaluation;
    (cache->*replace)(vertex, fragment, geometry, control, evaluation);
  }
  static void Replace(
    vtkOpenGLShaderCache* cache, std::string& vertex, std::string& fragment, std::string& geometry)
  {
    Call(cache, &nprShaderCacheAccess::ReplaceShaderValues, vertex, fragment, geometry);
  }
};
}

vtkNPRShaderHook::Sources::Sources(const Shaders& shaders)
  : Vertex(shaders.Vertex)
  , Fragment(shaders.Fragment)
{
}

vtkNPRShaderHook::vtkNPRShaderHook(const char* name, const char* implAfter, const char* what)
  : DecTag(std::string("//NPR::") + name + "::Dec")
  , ImplTag(std::string("//NPR::") + name + "::Impl")
  , ImplAfter(implAfter)
  , What(what)
{
}

void vtkNPRShaderHook::InsertTags(
  vtkObject* pass, std::string& fragment, vtkAbstractMapper* mapper) const
{
  if (vtkOpenGLPolyDataMapper::SafeDownCast(mapper))
  {
    vtkNPRInsertAfterShaderTag(
      fragment, this->ImplAfter.c_str(), this->ImplTag.c_str(), pass, "fragment");
    vtkNPRInsertAfterShaderTag(
      fragment, "//VTK::Output::Dec", this->DecTag.c_str(), pass, "fragment");
  }
}

bool vtkNPRShaderHook::IsTagged(const std::string& fragment, vtkAbstractMapper* mapper) const
{
  return vtkOpenGLPolyDataMapper::SafeDownCast(mapper) &&
    fragment.find(this->ImplTag) != std::string::npos;
}

void vtkNPRShaderHook::Fill(
  std::string& fragment, const std::string& dec, const std::string& impl) const
{
  vtkShaderProgram::Substitute(fragment, this->DecTag, dec, false);
  vtkShaderProgram::Substitute(fragment, this->ImplTag, impl, false);
}

bool vtkNPRShaderHook::Apply(vtkObject* pass, vtkProp* prop, const Shaders& shaders,
  const std::string& dec, const std::string& impl)
{
  const Sources before(shaders);
  this->Fill(shaders.Fragment, dec, impl);
  return this->KeepOrRevert(pass, prop, shaders, before);
}

bool vtkNPRShaderHook::KeepOrRevert(
  vtkObject* pass, vtkProp* prop, const Shaders& shaders, const Sources& before)
{
  if (this->Compiles(shaders.Vertex, shaders.Geometry, shaders.Fragment))
  {
    return true;
  }
  shaders.Vertex = before.Vertex;
  shaders.Fragment = before.Fragment;
  this->Fill(shaders.Fragment, "", "");
  vtkProp* userProp = vtkNPRUserProp(prop);
  const std::string name = userProp ? userProp->GetClassName() : "prop";
  if (this->Warned.insert(name).second)
  {
    vtkWarningWithObjectMacro(pass, << this->What << " does not compile with the shader of a "
                                    << name << ": it is drawn without it");
  }
  return false;
}

bool vtkNPRShaderHook::Compiles(
  const std::string& vertex, const std::string& geometry, const std::string& fragment)
{
  if (!this->Window || !this->Window->GetShaderCache())
  {
    return true;
  }
  const std::string key = vertex + '\0' + geometry + '\0' + fragment;
  const auto known = this->Known.find(key);
  if (known != this->Known.end())
  {
    return known->second;
  }
  std::string sources[3] = { vertex, geometry, fragment };
  nprShaderCacheAccess::Replace(this->Window->GetShaderCache(), sources[0], sources[2], sources[1]);
  const vtkShader::Type types[3] = { vtkShader::Vertex, vtkShader::Geometry, vtkShader::Fragment };
  bool compiles = true;
  for (int i = 0; i < 3 && compiles; ++i)
  {
    if (sources[i].empty())
    {
      continue;
    }
    vtkNew<vtkShader> shader;
    shader->SetType(types[i]);
    shader->SetSource(sources[i]);
    compiles = shader->Compile();
    shader->Cleanup();
  }
  this->Known[key] = compiles;
  return compiles;
}

std::string vtkNPRShaderHook::Defines(std::initializer_list<std::pair<const char*, int>> values)
{
  std::string defines;
  for (const auto& value : values)
  {
    defines += std::string("#define ") + value.first + " " + std::to_string(value.second) + "\n";
  }
  return defines;
}
