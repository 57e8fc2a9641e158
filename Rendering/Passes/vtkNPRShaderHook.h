// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// The steps a pass takes to add its code to VTK's poly-data fragment shader, written once: two tags
// of its own, //NPR::<Name>::Dec after //VTK::Output::Dec and //NPR::<Name>::Impl after a VTK tag
// of its choice, inserted in PreReplaceShaderValues and filled in PostReplaceShaderValues, once
// VTK's code is in place. The filled shaders are tried before VTK uses them (VTK 9.1 crashes on a
// shader that does not compile): compiled as VTK's shader cache would (results kept per source),
// and put back as they were, with a warning once per prop class, when they do not compile, so that
// the prop is drawn as VTK draws it. Private to the module.
#ifndef vtkNPRShaderHook_h
#define vtkNPRShaderHook_h

#include <initializer_list> // for the defines
#include <set>              // for std::set
#include <string>           // for std::string
#include <unordered_map>    // for std::unordered_map
#include <utility>          // for std::pair

class vtkAbstractMapper;
class vtkObject;
class vtkOpenGLRenderWindow;
class vtkProp;

class vtkNPRShaderHook
{
public:
  // A program's stages as a hook gets them; no hook changes the geometry shader (the ink pass
  // leaves VTK's mesh-edges shader out of its wireframe draw before the hooks run).
  struct Shaders
  {
    std::string& Vertex;
    const std::string& Geometry;
    std::string& Fragment;
  };

  // The sources a pass started from: what a shader that does not compile goes back to.
  struct Sources
  {
    explicit Sources(const Shaders& shaders);
    std::string Vertex;
    std::string Fragment;
  };

  // `name` makes the tags; the Impl tag goes after `implAfter`; `what` names the effect in the
  // warning ("toon shading").
  vtkNPRShaderHook(const char* name, const char* implAfter, const char* what);

  // The window of the frame being drawn (whose context the hooks run in). Without one, every
  // shader is taken to compile.
  vtkOpenGLRenderWindow* Window = nullptr;

  // PreReplaceShaderValues: the tags into the fragment shader of a vtkOpenGLPolyDataMapper. A
  // missing VTK tag is reported by `pass` (vtkNPRInsertAfterShaderTag).
  void InsertTags(vtkObject* pass, std::string& fragment, vtkAbstractMapper* mapper) const;

  // PostReplaceShaderValues: whether `fragment` has the tags to fill in.
  bool IsTagged(const std::string& fragment, vtkAbstractMapper* mapper) const;

  // Puts `dec` and `impl` in place of the tags, untried: for code that needs no check (nothing,
  // a discard).
  void Fill(std::string& fragment, const std::string& dec, const std::string& impl) const;

  // Fills the tags in and tries the result (KeepOrRevert). Returns whether it was kept.
  bool Apply(vtkObject* pass, vtkProp* prop, const Shaders& shaders, const std::string& dec,
    const std::string& impl);

  // Keeps the shaders a pass filled in when they compile. Otherwise puts back `before` (with the
  // tags emptied) and warns once per prop class, through `pass`, that the effect could not be
  // applied: the prop is drawn as VTK draws it. Returns whether the pass's code was kept.
  bool KeepOrRevert(vtkObject* pass, vtkProp* prop, const Shaders& shaders, const Sources& before);

  // Whether the three stages compile (an empty geometry shader is none). Without a window, true.
  bool Compiles(
    const std::string& vertex, const std::string& geometry, const std::string& fragment);

  // "#define NAME value\n" for each pair, in order: the settings compiled into a pass's code.
  static std::string Defines(std::initializer_list<std::pair<const char*, int>> values);

private:
  const std::string DecTag;
  const std::string ImplTag;
  const std::string ImplAfter;
  const std::string What;
  std::unordered_map<std::string, bool> Known;
  std::set<std::string> Warned;
};

#endif
