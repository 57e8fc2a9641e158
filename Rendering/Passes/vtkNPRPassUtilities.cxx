#include "vtkNPRPassUtilities.h"

#include "vtkHardwareSelector.h"
#include "vtkNPROpenGL.h"
#include "vtkObject.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkRenderState.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"

#include <algorithm>
#include <mutex>
#include <set>

double vtkNPRWindowScale(vtkRenderer* renderer)
{
  if (!renderer || !renderer->GetRenderWindow())
  {
    return 1.0;
  }
  vtkWindow* window = renderer->GetRenderWindow();
  return std::max(1, window->GetDPI()) / 72.0 *
    std::max(1, std::max(window->GetTileScale()[0], window->GetTileScale()[1]));
}

bool vtkNPRInsertAfterShaderTag(
  std::string& source, const char* vtkTag, const char* tag, vtkObject* pass, const char* stage)
{
  if (vtkShaderProgram::Substitute(
        source, vtkTag, std::string(vtkTag) + "\n  " + tag + "\n", false))
  {
    return true;
  }
  if (source.find("//VTK::Color::Impl") != std::string::npos)
  {
    static std::mutex mutex;
    static std::set<std::string> reported;
    const std::lock_guard<std::mutex> lock(mutex);
    if (reported.insert(std::string(pass->GetClassName()) + vtkTag).second)
    {
      vtkErrorWithObjectMacro(pass, << "the " << stage << " shader has no " << vtkTag
                                    << " tag: this VTK release changed its poly-data shader "
                                       "templates, so "
                                    << pass->GetClassName() << " cannot add its effect");
    }
  }
  return false;
}

bool vtkNPRRenderSelection(const vtkRenderState* state, int& renderedProps)
{
  vtkRenderer* renderer = state->GetRenderer();
  vtkHardwareSelector* selector = renderer->GetSelector();
  if (!selector)
  {
    return false;
  }
  renderedProps = selector->Render(renderer, state->GetPropArray(), state->GetPropArrayCount());
  return true;
}

void vtkNPRViewportOrigin(const vtkRenderState* state, int origin[2])
{
  int width, height;
  state->GetRenderer()->GetTiledSizeAndOrigin(&width, &height, origin, origin + 1);
  if (state->GetFrameBuffer())
  {
    origin[0] = origin[1] = 0;
  }
}

vtkNPRCompositeState::vtkNPRCompositeState(vtkOpenGLState* state)
  : State(state)
  , Viewport(state)
  , DepthTest(state, GL_DEPTH_TEST)
  , Blend(state, GL_BLEND)
  , ScissorTest(state, GL_SCISSOR_TEST)
  , Scissor(state)
  , DepthFunc(state)
  , DepthMask(state)
  , BlendFunc(state)
{
}

void vtkNPRCompositeState::Apply(const int origin[2], int width, int height)
{
  this->State->vtkglViewport(origin[0], origin[1], width, height);
  this->State->vtkglEnable(GL_SCISSOR_TEST);
  this->State->vtkglEnable(GL_DEPTH_TEST);
  this->State->vtkglDepthFunc(GL_LEQUAL);
  this->State->vtkglDepthMask(GL_TRUE);
  this->State->vtkglEnable(GL_BLEND);
  this->State->vtkglBlendFuncSeparate(
    GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
}

double vtkNPREffectiveLineWidth(vtkRenderer* renderer, double width)
{
  return std::min(std::max(width * vtkNPRWindowScale(renderer), 0.5), 32.0);
}
