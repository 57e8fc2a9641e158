// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNPRToonPass.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMath.h"
#include "vtkNPROpenGL.h"
#include "vtkNPRPassUtilities.h"
#include "vtkNPRShaderHook.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLPolyDataMapper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkProperty.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkScalarsToColors.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkTransform.h"

#include "vtkNPRToonDecl.h"
#include "vtkNPRToonImpl.h"
#include "vtkNPRToonLighting.h"
#include "vtkNPRToonVertexDecl.h"
#include "vtkNPRToonVertexImpl.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace
{
// Samples of a user table: enough that a table's own entries stay distinct bands.
constexpr int UserTableSamples = 256;
}

struct vtkNPRToonPass::Internals
{
  vtkTextureObject* TableTexture = nullptr;
  std::vector<float> TableValues; // RGBA per entry, what the texture holds
  vtkMTimeType TableTime = 0;     // of the pass (bands, table) when the texture was made
  // Lights of this frame, in the layout of the shader's uniforms.
  int LightCount = 0;
  bool AnyPositional = false;
  float Position[MaximumNumberOfLights][4];
  float Spot[MaximumNumberOfLights][4];
  float Attenuation[MaximumNumberOfLights][4];
  float Intensity[MaximumNumberOfLights];
  bool WarnedAboutLights = false;
  std::string ShaderSettings;
};

vtkStandardNewMacro(vtkNPRToonPass);
vtkCxxSetObjectMacro(vtkNPRToonPass, Table, vtkScalarsToColors);

// Our code right after VTK's lighting.
vtkNPRToonPass::vtkNPRToonPass()
  : vtkNPRGeometryPass("Toon", "//VTK::Light::Impl", "toon shading")
  , Internal(new Internals)
{
  this->ShaderStageTime.Modified();
}

vtkNPRToonPass::~vtkNPRToonPass()
{
  this->SetTable(nullptr);
  if (this->Internal->TableTexture)
  {
    this->Internal->TableTexture->Delete();
  }
}

vtkMTimeType vtkNPRToonPass::GetMTime()
{
  vtkMTimeType time = this->Superclass::GetMTime();
  if (this->Table)
  {
    time = std::max(time, this->Table->GetMTime());
  }
  return time;
}

void vtkNPRToonPass::GetShade(double intensity, double rgb[3])
{
  if (!(intensity >= 0.0))
  {
    intensity = 0.0;
  }
  intensity = std::min(intensity, 1.0);
  if (!this->Table)
  {
    const int n = this->NumberOfBands;
    const int band = std::min(static_cast<int>(intensity * n), n - 1);
    rgb[0] = rgb[1] = rgb[2] = (band + 1.0) / n;
    return;
  }
  const double* range = this->Table->GetRange();
  const int sample = std::min(static_cast<int>(intensity * UserTableSamples), UserTableSamples - 1);
  // The sample's own intensity is the centre of its interval.
  const double value = range[0] + (sample + 0.5) / UserTableSamples * (range[1] - range[0]);
  double color[3];
  this->Table->GetColor(value, color);
  for (int i = 0; i < 3; ++i)
  {
    rgb[i] = std::min(std::max(color[i], 0.0), 1.0);
  }
}

void vtkNPRToonPass::UpdateTable(vtkWindow* window)
{
  Internals& internal = *this->Internal;
  const vtkMTimeType time = this->GetMTime();
  if (internal.TableTexture && internal.TableTime == time)
  {
    return;
  }
  const int size = this->Table ? UserTableSamples : this->NumberOfBands;
  internal.TableValues.assign(4 * size, 1.0f);
  for (int i = 0; i < size; ++i)
  {
    double rgb[3];
    this->GetShade((i + 0.5) / size, rgb);
    std::copy(rgb, rgb + 3, internal.TableValues.begin() + 4 * i);
  }
  if (!internal.TableTexture)
  {
    internal.TableTexture = vtkTextureObject::New();
  }
  internal.TableTexture->SetContext(static_cast<vtkOpenGLRenderWindow*>(window));
  internal.TableTexture->SetMinificationFilter(vtkTextureObject::Nearest);
  internal.TableTexture->SetMagnificationFilter(vtkTextureObject::Nearest);
  internal.TableTexture->SetWrapS(vtkTextureObject::ClampToEdge);
  internal.TableTexture->SetWrapT(vtkTextureObject::ClampToEdge);
  internal.TableTexture->Create2DFromRaw(size, 1, 4, VTK_FLOAT, internal.TableValues.data());
  internal.TableTime = time;
}

void vtkNPRToonPass::UpdateLights(const vtkRenderState* state)
{
  Internals& internal = *this->Internal;
  vtkRenderer* renderer = state->GetRenderer();
  vtkTransform* view = renderer->GetActiveCamera()->GetModelViewTransformObject();
  internal.LightCount = 0;
  internal.AnyPositional = false;
  int switchedOn = 0;
  vtkCollectionSimpleIterator it;
  renderer->GetLights()->InitTraversal(it);
  while (vtkLight* light = renderer->GetLights()->GetNextLight(it))
  {
    if (light->GetSwitch() == 0 || light->GetIntensity() <= 0.0)
    {
      continue;
    }
    if (++switchedOn > MaximumNumberOfLights)
    {
      continue;
    }
    const int i = internal.LightCount++;
    const double* color = light->GetDiffuseColor();
    // Rec. 709 luminance: a white light of intensity 1 gives 1.
    internal.Intensity[i] = static_cast<float>(
      light->GetIntensity() * (0.2126 * color[0] + 0.7152 * color[1] + 0.0722 * color[2]));
    double direction[3], position[3], viewDirection[3], viewPosition[3];
    light->GetTransformedFocalPoint(direction);
    light->GetTransformedPosition(position);
    vtkMath::Subtract(direction, position, direction); // the way the light shines
    if (vtkMath::Normalize(direction) == 0.0)
    {
      direction[0] = direction[1] = 0.0;
      direction[2] = -1.0;
    }
    view->TransformNormal(direction, viewDirection);
    vtkMath::Normalize(viewDirection);
    for (int j = 0; j < 4; ++j)
    {
      internal.Spot[i][j] = internal.Attenuation[i][j] = 0.0f;
    }
    if (light->GetPositional())
    {
      internal.AnyPositional = true;
      view->TransformPoint(position, viewPosition);
      for (int j = 0; j < 3; ++j)
      {
        internal.Position[i][j] = static_cast<float>(viewPosition[j]);
        internal.Spot[i][j] = static_cast<float>(viewDirection[j]);
        internal.Attenuation[i][j] = static_cast<float>(light->GetAttenuationValues()[j]);
      }
      internal.Position[i][3] = 1.0f;
      internal.Spot[i][3] = light->GetConeAngle() < 90.0
        ? static_cast<float>(std::cos(vtkMath::RadiansFromDegrees(light->GetConeAngle())))
        : -2.0f;
      internal.Attenuation[i][3] = static_cast<float>(light->GetExponent());
    }
    else
    {
      for (int j = 0; j < 3; ++j)
      {
        internal.Position[i][j] = static_cast<float>(-viewDirection[j]);
      }
      internal.Position[i][3] = 0.0f;
    }
  }
  if (switchedOn > MaximumNumberOfLights && !internal.WarnedAboutLights)
  {
    vtkWarningMacro(<< switchedOn << " lights are on; toon shading uses the first "
                    << MaximumNumberOfLights);
    internal.WarnedAboutLights = true;
  }
}

void vtkNPRToonPass::Render(const vtkRenderState* state)
{
  if (!this->StartRender(state))
  {
    return; // no delegate, or a picking render
  }
  vtkRenderer* renderer = state->GetRenderer();

  this->UpdateTable(renderer->GetRenderWindow());
  this->UpdateLights(state);
  // What is compiled into the shaders: the mappers rebuild them when it changes.
  const std::string settings = std::string(this->PerVertex ? "v" : "p") +
    (this->Specular ? "s" : "") + std::to_string(this->Internal->LightCount) +
    (this->Internal->AnyPositional ? "p" : "d");
  if (settings != this->Internal->ShaderSettings)
  {
    this->Internal->ShaderSettings = settings;
    this->ShaderStageTime.Modified();
  }

  this->PreRender(state); // the mappers now call this pass's shader hooks
  this->Internal->TableTexture->Activate();
  this->DelegatePass->Render(state);
  this->NumberOfRenderedProps = this->DelegatePass->GetNumberOfRenderedProps();
  this->Internal->TableTexture->Deactivate();
  this->PostRender(state);
  vtkOpenGLCheckErrorMacro("failed after vtkNPRToonPass::Render");
}

namespace
{
// The lit fragment shaders of vtkOpenGLPolyDataMapper (Gouraud, Phong, flat), not PBR. VTK's
// declarations, not mere mentions: the G-buffer's code, already in place when this pass is its
// delegate, names normalVCVSOutput too; and VTK 9.1 declares lightColor0 in unlit shaders.
bool IsLitPolyDataShader(const std::string& fragmentShader)
{
  return fragmentShader.find("uniform vec3 lightColor0;") != std::string::npos &&
    fragmentShader.find("vec3 diffuseColor") != std::string::npos &&
    fragmentShader.find("vec3 ambientColor") != std::string::npos &&
    fragmentShader.find("vec3 normalVCVSOutput") != std::string::npos &&
    fragmentShader.find("float specularPower") != std::string::npos &&
    fragmentShader.find("albedo") == std::string::npos;
}

// Whether VTK's vertex shader computes the normal and position the per-vertex lighting needs.
bool IsPerVertexCapable(const std::string& vertexShader, const std::string& geometryShader)
{
  return geometryShader.empty() &&
    vertexShader.find("normalVCVSOutput = normalMatrix * normalMC") != std::string::npos &&
    vertexShader.find("vertexVCVSOutput = MCVCMatrix * vertexMC") != std::string::npos &&
    vertexShader.find("//VTK::Light::Impl") != std::string::npos;
}

// Highlights only for actors that have some: the Phong term is a third of the shader's cost on
// llvmpipe. (A change of the property rebuilds the mapper's shaders.)
bool HasHighlights(const std::string& fragmentShader, vtkProp* prop)
{
  vtkActor* actor = vtkActor::SafeDownCast(prop);
  return actor && actor->GetProperty()->GetSpecular() > 0.0 &&
    fragmentShader.find("vec3 specularColor") != std::string::npos &&
    fragmentShader.find("float specularPower") != std::string::npos;
}
}

void vtkNPRToonPass::FillShaderCode(std::string& vertexShader, std::string& geometryShader,
  std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop)
{
  vtkNPRShaderHook& hook = *this->Hook;
  // Lines and points keep their own colours: no bands on them.
  if (!IsLitPolyDataShader(fragmentShader) || vtkNPRKeepsOwnLook(mapper, prop))
  {
    hook.Fill(fragmentShader, "", "");
    return;
  }
  const vtkNPRShaderHook::Shaders shaders{ vertexShader, geometryShader, fragmentShader };
  const vtkNPRShaderHook::Sources before(shaders);
  const bool perVertex = this->PerVertex && IsPerVertexCapable(vertexShader, geometryShader);
  const Internals& internal = *this->Internal;
  const std::string defines = vtkNPRShaderHook::Defines({
    { "NPR_TOON_PER_VERTEX", perVertex },
    { "NPR_TOON_SPECULAR", this->Specular && HasHighlights(fragmentShader, prop) },
    { "NPR_TOON_HAVE_VERTEX_VC", fragmentShader.find("vec4 vertexVC = ") != std::string::npos },
    { "NPR_TOON_LIGHTS", internal.LightCount },
    { "NPR_TOON_LIGHT_ARRAY", std::max(1, internal.LightCount) },
    { "NPR_TOON_POSITIONAL", internal.AnyPositional },
  });
  hook.Fill(fragmentShader, defines + vtkNPRToonLighting + vtkNPRToonDecl, vtkNPRToonImpl);
  if (perVertex)
  {
    vtkShaderProgram::Substitute(vertexShader, "//VTK::Light::Dec",
      std::string("//VTK::Light::Dec\n") + defines + vtkNPRToonLighting + vtkNPRToonVertexDecl,
      false);
    vtkShaderProgram::Substitute(vertexShader, "//VTK::Light::Impl",
      std::string("//VTK::Light::Impl\n") + vtkNPRToonVertexImpl, false);
  }
  // If not: the prop as VTK draws it, rather than no prop (or a crash).
  hook.KeepOrRevert(this, prop, shaders, before);
}

bool vtkNPRToonPass::SetShaderParameters(
  vtkShaderProgram* program, vtkAbstractMapper*, vtkProp*, vtkOpenGLVertexArrayObject*)
{
  Internals& internal = *this->Internal;
  if (!internal.TableTexture || !program->IsUniformUsed("nprToonTable"))
  {
    return true;
  }
  program->SetUniformi("nprToonTable", internal.TableTexture->GetTextureUnit());
  program->SetUniformi("nprToonTableSize", internal.TableTexture->GetWidth());
  if (internal.LightCount > 0)
  {
    // Array uniforms are set whole; unused ones were dropped by the compiler.
    const int n = internal.LightCount;
    if (program->IsUniformUsed("nprToonLightPosition"))
    {
      program->SetUniform4fv("nprToonLightPosition", n, internal.Position);
    }
    if (program->IsUniformUsed("nprToonLightSpot"))
    {
      program->SetUniform4fv("nprToonLightSpot", n, internal.Spot);
    }
    if (program->IsUniformUsed("nprToonLightAttenuation"))
    {
      program->SetUniform4fv("nprToonLightAttenuation", n, internal.Attenuation);
    }
    if (program->IsUniformUsed("nprToonLightIntensity"))
    {
      program->SetUniform1fv("nprToonLightIntensity", n, internal.Intensity);
    }
  }
  return true;
}

void vtkNPRToonPass::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Superclass::ReleaseGraphicsResources(window);
  if (this->Internal->TableTexture)
  {
    this->Internal->TableTexture->ReleaseGraphicsResources(window);
    this->Internal->TableTexture->Delete();
    this->Internal->TableTexture = nullptr;
  }
}

void vtkNPRToonPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfBands: " << this->NumberOfBands << "\n";
  os << indent << "Table: " << this->Table << "\n";
  os << indent << "PerVertex: " << this->PerVertex << "\n";
  os << indent << "Specular: " << this->Specular << "\n";
}
