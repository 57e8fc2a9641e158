// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNPRInkPass.h"

#include "vtkActor.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataSetMapper.h"
#include "vtkGlyph3DMapper.h"
#include "vtkNPROpenGL.h"
#include "vtkNPRPassUtilities.h"
#include "vtkNPRPropParts.h"
#include "vtkNPRQuadProgram.h"
#include "vtkNPRRenderTarget.h"
#include "vtkNPRShaderHook.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLPolyDataMapper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkSmartPointer.h"
#include "vtkTextureObject.h"
#include "vtkVersionMacros.h"
#if VTK_VERSION_NUMBER >= VTK_VERSION_CHECK(9, 3, 0)
#include "vtkCompositePolyDataMapper.h"
#endif

#include "vtkNPRInkCompositeFS.h"
#include "vtkNPRInkDecl.h"
#include "vtkNPRInkImpl.h"

#include <algorithm>
#include <vector>

vtkStandardNewMacro(vtkNPRInkPass);

namespace
{
// Whether the mapper draws through a vtkOpenGLPolyDataMapper, which calls this pass's hooks.
bool vtkNPRCallsInkHooks(vtkMapper* mapper)
{
  // A vtkDataSetMapper (PyVista's mapper for every data set) and a glyph mapper draw through
  // inner ones.
  if (vtkOpenGLPolyDataMapper::SafeDownCast(mapper) || vtkDataSetMapper::SafeDownCast(mapper) ||
    vtkGlyph3DMapper::SafeDownCast(mapper))
  {
    return true;
  }
#if VTK_VERSION_NUMBER >= VTK_VERSION_CHECK(9, 3, 0)
  // VTK 9.3's composite mapper (ParaView's since 5.12) draws each batch through a
  // vtkOpenGLBatchedPolyDataMapper.
  return vtkCompositePolyDataMapper::SafeDownCast(mapper) != nullptr;
#else
  return false;
#endif
}

// Whether VTK draws the top-level prop as surfaces whose mappers call this pass's hooks: an
// actor, or an assembly whose parts all are such actors (any other part would be drawn as a
// wireframe in its own colours).
bool vtkNPRIsInkable(vtkProp* prop, const std::vector<vtkNPRPropPart>& parts)
{
  return !vtkNPRIsAnnotation(prop) && !parts.empty() &&
    std::all_of(parts.begin(), parts.end(),
      [](const vtkNPRPropPart& part)
      {
        auto* actor = vtkActor::SafeDownCast(part.Prop);
        return actor && vtkNPRCallsInkHooks(actor->GetMapper()) && !vtkNPRIsAnnotation(actor);
      });
}

// Whether the data set (each block of a composite one) has lines or vertices, which VTK draws as
// line and point primitives.
bool vtkNPRHasLinesOrVerts(vtkDataObject* data)
{
  if (auto* polyData = vtkPolyData::SafeDownCast(data))
  {
    return polyData->GetNumberOfLines() > 0 || polyData->GetNumberOfVerts() > 0;
  }
  auto* composite = vtkCompositeDataSet::SafeDownCast(data);
  if (!composite)
  {
    return false;
  }
  vtkSmartPointer<vtkCompositeDataIterator> block;
  block.TakeReference(composite->NewIterator());
  for (block->InitTraversal(); !block->IsDoneWithTraversal(); block->GoToNextItem())
  {
    if (vtkNPRHasLinesOrVerts(block->GetCurrentDataObject()))
    {
      return true;
    }
  }
  return false;
}

// Whether the opaque actor draws lines or points where a surface can be: a representation other
// than Surface, splats, lines or vertices in its data, or a mapper the ink's hooks do not reach.
bool vtkNPRDrawsLinesOrPoints(vtkActor* actor)
{
  vtkProperty* property = actor->GetProperty();
  vtkMapper* mapper = actor->GetMapper();
  if (!mapper || property->GetOpacity() < 1.0)
  {
    return false; // nothing drawn, or drawn after the opaque props
  }
  // A glyph mapper's input holds the glyphs' centres, not what it draws.
  const bool glyphs = vtkGlyph3DMapper::SafeDownCast(mapper) != nullptr;
  return property->GetRepresentation() != VTK_SURFACE || vtkNPRDrawsSplats(actor) ||
    !vtkNPRCallsInkHooks(mapper) ||
    (!glyphs && vtkNPRHasLinesOrVerts(mapper->GetInputDataObject(0, 0)));
}

// Whether a part of the top-level prop shows its mesh edges (vtkProperty::EdgeVisibilityOn on a
// surface): VTK draws them through a geometry shader.
bool vtkNPRShowsMeshEdges(const std::vector<vtkNPRPropPart>& parts)
{
  return std::any_of(parts.begin(), parts.end(),
    [](const vtkNPRPropPart& part)
    { return vtkNPRDrawsMeshEdges(static_cast<vtkActor*>(part.Prop)->GetProperty()); });
}

// While it lives, filled faces are drawn pulled towards the viewer by `width` pixels of their
// depth slope (and one unit): nothing with a width of 0.
class nprPulledFaces
{
public:
  explicit nprPulledFaces(double width)
    : Pulled(width > 0.0)
  {
    if (this->Pulled)
    {
      glEnable(GL_POLYGON_OFFSET_FILL);
      glPolygonOffset(-static_cast<float>(width), -1.0f);
    }
  }
  ~nprPulledFaces()
  {
    if (this->Pulled)
    {
      glPolygonOffset(0.0f, 0.0f);
      glDisable(GL_POLYGON_OFFSET_FILL);
    }
  }
  nprPulledFaces(const nprPulledFaces&) = delete;
  nprPulledFaces& operator=(const nprPulledFaces&) = delete;

private:
  bool Pulled;
};
}

// The ink image of a frame that draws lines or points (DrawInkImage): its colour (alpha 1 where
// the ink shows) and depth, and the program that puts it over the frame.
struct vtkNPRInkPass::Internals
{
  vtkNPRRenderTarget Target;
  vtkSmartPointer<vtkTextureObject> Ink;
  vtkSmartPointer<vtkTextureObject> Depth;
  vtkNPRQuadProgram Composite;
};

// The ink's code after texturing: the colour is final there.
vtkNPRInkPass::vtkNPRInkPass()
  : vtkNPRGeometryPass("Ink", "//VTK::TCoord::Impl", "the ink")
  , Internal(new Internals)
{
}

vtkNPRInkPass::~vtkNPRInkPass() = default;

double vtkNPRInkPass::GetEffectiveLineWidth(vtkRenderer* renderer) const
{
  return vtkNPREffectiveLineWidth(renderer, this->LineWidth);
}

void vtkNPRInkPass::Render(const vtkRenderState* state)
{
  if (!this->StartRender(state))
  {
    return; // no delegate, or a picking render
  }
  vtkRenderer* renderer = state->GetRenderer();
  // Half of the wireframe lies under the front faces: draw it twice the visible width.
  const double visibleWidth = this->GetEffectiveLineWidth(renderer);
  const double drawnWidth = this->DrawableLineWidth(2.0 * visibleWidth);
  if (this->CoverageOnly)
  {
    this->ClearMask(renderer);
  }
  this->PreRender(state); // the mappers now call this pass's shader hooks
  bool linesOrPoints = false;
  std::vector<vtkProp*> inked = this->ListInkedProps(state, linesOrPoints);
  if (inked.empty())
  {
    this->DrawFilledFaces(state, 0.0);
  }
  else if (linesOrPoints)
  {
    this->DrawInkImage(state, inked, drawnWidth, visibleWidth);
    this->DrawFilledFaces(state, 0.0);
    this->CompositeInkImage(state);
  }
  else
  {
    this->DrawBackFaceInk(state, inked, drawnWidth);
    this->DrawFilledFaces(state, visibleWidth);
  }
  this->PostRender(state);
  vtkOpenGLCheckErrorMacro("failed after vtkNPRInkPass::Render");
}

double vtkNPRInkPass::DrawableLineWidth(double width)
{
  if (this->WidestLine <= 0.0)
  {
    float range[2] = { 1.0f, 1.0f };
    glGetFloatv(GL_ALIASED_LINE_WIDTH_RANGE, range);
    this->WidestLine = std::max(1.0f, range[1]);
  }
  const double widest = this->WidestLine;
  if (width > widest)
  {
    if (!this->WarnedAboutWidth)
    {
      vtkWarningMacro("ink lines of " << width << " pixels are drawn " << widest
                                      << " wide, the most this OpenGL draws");
      this->WarnedAboutWidth = true;
    }
    return widest;
  }
  return width;
}

void vtkNPRInkPass::ClearMask(vtkRenderer* renderer)
{
  // A mask: the background black too.
  vtkOpenGLState* glState =
    static_cast<vtkOpenGLRenderWindow*>(renderer->GetRenderWindow())->GetState();
  int width, height, x, y;
  renderer->GetTiledSizeAndOrigin(&width, &height, &x, &y);
  vtkOpenGLState::ScopedglClearColor clearColorSaver(glState);
  vtkOpenGLState::ScopedglScissor scissorSaver(glState);
  vtkOpenGLState::ScopedglEnableDisable scissorTestSaver(glState, GL_SCISSOR_TEST);
  glState->vtkglEnable(GL_SCISSOR_TEST);
  glState->vtkglScissor(x, y, width, height);
  glState->vtkglClearColor(0.0, 0.0, 0.0, 1.0);
  glState->vtkglClear(GL_COLOR_BUFFER_BIT);
}

std::vector<vtkProp*> vtkNPRInkPass::ListInkedProps(
  const vtkRenderState* state, bool& linesOrPoints)
{
  // Ink only for the surfaces whose mapper calls this pass's shader hooks: any other prop would be
  // drawn as a wireframe in its own colours. Annotations are drawn as they are in every case.
  std::vector<vtkProp*> inked;
  this->InkWithoutMeshEdges = false;
  linesOrPoints = false;
  for (int i = 0; i < state->GetPropArrayCount(); ++i)
  {
    vtkProp* prop = state->GetPropArray()[i];
    if (vtkNPRIsAnnotation(prop))
    {
      continue;
    }
    const std::vector<vtkNPRPropPart> parts = vtkNPRPropParts(prop);
    if (vtkNPRIsInkable(prop, parts))
    {
      inked.push_back(prop);
      this->InkWithoutMeshEdges = this->InkWithoutMeshEdges || vtkNPRShowsMeshEdges(parts);
    }
    linesOrPoints = linesOrPoints ||
      std::any_of(parts.begin(), parts.end(),
        [](const vtkNPRPropPart& part)
        {
          auto* actor = vtkActor::SafeDownCast(part.Prop);
          return actor && vtkNPRDrawsLinesOrPoints(actor);
        });
  }
  return inked;
}

void vtkNPRInkPass::DrawProps(const vtkRenderState* state, std::vector<vtkProp*>& props)
{
  vtkRenderState propsState(state->GetRenderer());
  propsState.SetPropArrayAndCount(props.data(), static_cast<int>(props.size()));
  propsState.SetFrameBuffer(state->GetFrameBuffer());
  propsState.SetRequiredKeys(state->GetRequiredKeys());
  this->DelegatePass->Render(&propsState);
}

void vtkNPRInkPass::DrawBackFaceInk(
  const vtkRenderState* state, std::vector<vtkProp*>& inked, double lineWidth)
{
  vtkOpenGLState* glState =
    static_cast<vtkOpenGLRenderWindow*>(state->GetRenderer()->GetRenderWindow())->GetState();
  this->DrawMode = DrawInk;
  glState->vtkglLineWidth(static_cast<float>(lineWidth));
  glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
  // Front faces are culled by SetShaderParameters(), after each actor's property has set its
  // own culling; the shader's discard gives the same image without culling, slower.
  this->InkDrawState = glState;
  this->SwitchMeshEdgesShader();
  this->DrawProps(state, inked);
  this->InkDrawState = nullptr;
  glState->vtkglDisable(GL_CULL_FACE); // as a property without culling leaves it
  glState->vtkglCullFace(GL_BACK);
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  glState->vtkglLineWidth(1.0f);
}

void vtkNPRInkPass::DrawFilledFaces(const vtkRenderState* state, double pullWidth)
{
  this->DrawMode = this->CoverageOnly ? DrawMaskFill : DrawShaded;
  this->SwitchMeshEdgesShader();
  // Pulled towards the viewer by the line width's worth of depth slope: the faces hide the half of
  // each line that lies over them. (Lines pushed back instead keep a selection highlight on the
  // faces visible, but the slivers of faces clipped at the tile borders of a tiled render then
  // show as ink lines across the image: npr.tiled_render.inked measured 958 pixels.)
  {
    nprPulledFaces pulled(pullWidth);
    this->DelegatePass->Render(state);
  }
  this->NumberOfRenderedProps = this->DelegatePass->GetNumberOfRenderedProps();
  this->DrawMode = DrawShaded;
}

void vtkNPRInkPass::DrawInkImage(
  const vtkRenderState* state, std::vector<vtkProp*>& inked, double lineWidth, double visibleWidth)
{
  auto* window = static_cast<vtkOpenGLRenderWindow*>(state->GetRenderer()->GetRenderWindow());
  Internals& internal = *this->Internal;
  int width, height;
  vtkNPRTargetSize(state, width, height);
  if (!internal.Ink)
  {
    internal.Ink.TakeReference(
      vtkNPRNewTexture(window, vtkTextureObject::Nearest, vtkTextureObject::ClampToEdge));
    internal.Ink->Allocate2D(width, height, 4, VTK_UNSIGNED_CHAR);
    internal.Depth.TakeReference(
      vtkNPRNewTexture(window, vtkTextureObject::Nearest, vtkTextureObject::ClampToEdge));
    internal.Depth->AllocateDepth(width, height, vtkTextureObject::Float32);
  }
  internal.Ink->Resize(width, height);
  internal.Depth->Resize(width, height);
  vtkNPRRenderTarget::Scope target(
    internal.Target, window, { internal.Ink }, internal.Depth, width, height);
  target.Clear(0.0, 0.0, 0.0, 0.0);
  // As the usual draw has it (ink, then the faces pulled over it, ties to the ink), with the faces
  // marking the ink they cover as none.
  this->DrawBackFaceInk(state, inked, lineWidth);
  this->DrawMode = DrawNoInk;
  this->SwitchMeshEdgesShader();
  {
    nprPulledFaces pulled(visibleWidth);
    this->DrawProps(state, inked);
  }
  this->DrawMode = DrawShaded;
}

void vtkNPRInkPass::CompositeInkImage(const vtkRenderState* state)
{
  auto* window = static_cast<vtkOpenGLRenderWindow*>(state->GetRenderer()->GetRenderWindow());
  Internals& internal = *this->Internal;
  vtkShaderProgram* composite = internal.Composite.Ready(window, vtkNPRInkCompositeFS, "");
  if (!composite)
  {
    vtkErrorMacro("the ink's composite shader did not compile: the frame has no ink");
    return;
  }
  int origin[2];
  vtkNPRViewportOrigin(state, origin);
  vtkNPRCompositeState compositeState(window->GetState());
  compositeState.Apply(origin, internal.Ink->GetWidth(), internal.Ink->GetHeight());
  // The ink where it showed against the pulled faces (depth test LEQUAL), unless a line or point
  // is in front of it; opaque.
  window->GetState()->vtkglDisable(GL_BLEND);
  internal.Ink->Activate();
  internal.Depth->Activate();
  composite->SetUniformi("inkTexture", internal.Ink->GetTextureUnit());
  composite->SetUniformi("depthTexture", internal.Depth->GetTextureUnit());
  internal.Composite.Render();
  internal.Ink->Deactivate();
  internal.Depth->Deactivate();
}

void vtkNPRInkPass::SwitchMeshEdgesShader()
{
  if (this->InkWithoutMeshEdges)
  {
    // The mappers rebuild their shaders for this draw: the two draws' programs differ.
    this->ShaderStageTime.Modified();
  }
}

bool vtkNPRInkPass::PreReplaceShaderValues(std::string& vertexShader, std::string& geometryShader,
  std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop)
{
  // VTK's mesh edges: the geometry shader vtkPolyDataEdgesGS (it declares edgeEqn) and the
  // fragment code at the Edges tags, which is left out here. What VTK's fragment code for edges
  // drawn as tubes reads is declared, unused.
  if (this->DrawMode == DrawInk && geometryShader.find("edgeEqn") != std::string::npos)
  {
    geometryShader.clear();
    vtkShaderProgram::Substitute(fragmentShader, "//VTK::Edges::Dec",
      "vec4 edgeEqn[3];\nfloat edist[3];\nuniform float lineWidth;\n", false);
    vtkShaderProgram::Substitute(fragmentShader, "//VTK::Edges::Impl", "", false);
  }
  return this->Superclass::PreReplaceShaderValues(
    vertexShader, geometryShader, fragmentShader, mapper, prop);
}

void vtkNPRInkPass::FillShaderCode(std::string& vertexShader, std::string& geometryShader,
  std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop)
{
  // Lines and points are not inked: absent from the ink draw, as VTK draws them in the other.
  this->Hook->Apply(this, prop, { vertexShader, geometryShader, fragmentShader }, vtkNPRInkDecl,
    vtkNPRKeepsOwnLook(mapper, prop) ? "  if (nprInkMode == 1) { discard; }\n" : vtkNPRInkImpl);
}

bool vtkNPRInkPass::SetShaderParameters(
  vtkShaderProgram* program, vtkAbstractMapper* mapper, vtkProp*, vtkOpenGLVertexArrayObject*)
{
  if (this->InkDrawState && vtkOpenGLPolyDataMapper::SafeDownCast(mapper))
  {
    // The mapper draws right after this call, after its actor's property set its own culling.
    this->InkDrawState->vtkglCullFace(GL_FRONT);
    this->InkDrawState->vtkglEnable(GL_CULL_FACE);
  }
  if (program->IsUniformUsed("nprInkMode"))
  {
    program->SetUniformi("nprInkMode", this->DrawMode);
  }
  if (program->IsUniformUsed("nprInkColor"))
  {
    const float white[3] = { 1.0f, 1.0f, 1.0f };
    const float ink[3] = { static_cast<float>(this->InkColor[0]),
      static_cast<float>(this->InkColor[1]), static_cast<float>(this->InkColor[2]) };
    program->SetUniform3f("nprInkColor", this->CoverageOnly ? white : ink);
  }
  return true;
}

void vtkNPRInkPass::ReleaseGraphicsResources(vtkWindow* window)
{
  this->WidestLine = 0.0; // the next context is asked again
  Internals& internal = *this->Internal;
  internal.Target.ReleaseGraphicsResources(window);
  internal.Composite.Release(window);
  for (vtkTextureObject* texture : { internal.Ink.Get(), internal.Depth.Get() })
  {
    if (texture)
    {
      texture->ReleaseGraphicsResources(window);
    }
  }
  internal.Ink = nullptr;
  internal.Depth = nullptr;
  this->Superclass::ReleaseGraphicsResources(window);
}

void vtkNPRInkPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "LineWidth: " << this->LineWidth << "\n";
  os << indent << "InkColor: " << this->InkColor[0] << " " << this->InkColor[1] << " "
     << this->InkColor[2] << "\n";
  os << indent << "CoverageOnly: " << this->CoverageOnly << "\n";
}
