// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkNPRInkPass
 * @brief   Silhouettes by the classic inking trick: fat back-face wireframe, then filled fronts.
 *
 * The geometry-only technique of the late 1990s (Rossignac & van Emmerik 1992, Raskar & Cohen
 * 1999), for comparison with the image-space lines of vtkNPREdgePass. The delegate (normally a
 * vtkOpaquePass) draws the opaque props twice:
 *
 * 1. back faces only, as a wireframe (glPolygonMode GL_LINE) of 2 x the line width, in InkColor,
 *    unlit, writing depth;
 * 2. every face filled and shaded as usual, pulled towards the viewer with glPolygonOffset
 *    (factor = the line width in pixels, units 1), so that a filled front face hides the fat
 *    lines everywhere except where they reach past the surface's outline.
 *
 * What is left is an ink line of about the line width outside every silhouette (an outline
 * against the background, an internal silhouette over a farther part), and along the boundary of
 * open surfaces. Creases are not drawn: the trick cannot see them. The offset factor is the line
 * width because a line reaching d pixels past a back-face edge is at that edge's depth: a front
 * face over it must be pulled forward by d pixels of its own depth slope to stay in front.
 *
 * LineWidth is in pixels at 72 DPI (default 1.5), scaled by the window's DPI / 72 and tile
 * scale, clamped to what the OpenGL implementation draws (GL_ALIASED_LINE_WIDTH_RANGE; a warning
 * says so once). Only props drawn by a vtkOpenGLPolyDataMapper (and subclasses, and from VTK 9.3
 * the vtkCompositePolyDataMapper, which draws through one) get ink, and an assembly whose parts
 * all are; other props are drawn once, as usual. Lines are not anti-aliased. CoverageOnly writes a
 * mask instead: ink white, everything the props cover black, the background black.
 *
 * Both draws go through the same shader (the ink is a uniform switch), so alternating them costs
 * no shader rebuild, except in a frame where a surface shows its mesh edges: the wireframe is drawn
 * without VTK's edges geometry shader, so the mappers take their shaders again (from VTK's shader
 * cache: no compile) at each draw; their buffer objects stay. OpenGL's polygon mode and offset are
 * not tracked by vtkOpenGLState in VTK 9.1; this pass sets them directly and restores the defaults
 * (fill, offset off) after each draw. Front faces are culled during the wireframe draw, through
 * vtkOpenGLState, from SetShaderParameters(): each actor's property sets its own culling before its
 * mapper draws, and this hook runs after it. The fragment shader also discards front faces. Culling
 * halves the wireframe's cost: the 1.2M-triangle bunny at 1920x1080 took 3.2x the shaded frame with
 * it and 4.9x without (llvmpipe, 2 cores).
 *
 * @sa vtkNPRPass vtkNPREdgePass
 */
#ifndef vtkNPRInkPass_h
#define vtkNPRInkPass_h

#include "vtkNPRGeometryPass.h"
#include "vtkNPRPassesModule.h" // for export macro

#include <memory> // for std::unique_ptr
#include <vector> // for std::vector

class vtkOpenGLState;
class vtkProp;
class vtkRenderer;

class VTKNPRPASSES_EXPORT vtkNPRInkPass : public vtkNPRGeometryPass
{
public:
  static vtkNPRInkPass* New();
  vtkTypeMacro(vtkNPRInkPass, vtkNPRGeometryPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  void Render(const vtkRenderState* state) override;
  void ReleaseGraphicsResources(vtkWindow* window) override;

  ///@{
  /**
   * Width of the visible ink line in pixels at 72 DPI (default 1.5), clamped to [0.5, 16].
   */
  vtkSetClampMacro(LineWidth, double, 0.5, 16.0);
  vtkGetMacro(LineWidth, double);
  ///@}

  /**
   * The visible line width in pixels for this renderer: LineWidth x DPI / 72 x tile scale. The
   * wireframe is drawn twice as wide (half of it is hidden by the front faces).
   */
  double GetEffectiveLineWidth(vtkRenderer* renderer) const;

  ///@{
  /**
   * Colour of the ink (default black).
   */
  vtkSetVector3Macro(InkColor, double);
  vtkGetVector3Macro(InkColor, double);
  ///@}

  ///@{
  /**
   * Write a mask instead of the image: ink white, surfaces and background black (off by
   * default).
   */
  vtkSetMacro(CoverageOnly, bool);
  vtkGetMacro(CoverageOnly, bool);
  vtkBooleanMacro(CoverageOnly, bool);
  ///@}

  // vtkOpenGLRenderPass hook: the mesh edges' geometry shader left out of the ink's wireframe.
  bool PreReplaceShaderValues(std::string& vertexShader, std::string& geometryShader,
    std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop) override;

  // vtkOpenGLRenderPass hook: the ink switch's uniforms, and front faces culled for the ink.
  bool SetShaderParameters(vtkShaderProgram* program, vtkAbstractMapper* mapper, vtkProp* prop,
    vtkOpenGLVertexArrayObject* vao = nullptr) override;

protected:
  vtkNPRInkPass();
  ~vtkNPRInkPass() override;

  // The ink switch in the mappers' fragment shaders (vtkNPRGeometryPass).
  void FillShaderCode(std::string& vertexShader, std::string& geometryShader,
    std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop) override;

  // The steps of Render().
  double DrawableLineWidth(double width); // at most what this OpenGL draws (warns once)
  void ClearMask(vtkRenderer* renderer);  // CoverageOnly: the background black
  // The top-level props drawn as inked surfaces (sets InkWithoutMeshEdges), and whether the
  // frame draws lines or points at the depth of a surface (a selection highlight, a wireframe,
  // vertices, lines), which pulled faces would hide.
  std::vector<vtkProp*> ListInkedProps(const vtkRenderState* state, bool& linesOrPoints);
  // The delegate's draw of `props` alone.
  void DrawProps(const vtkRenderState* state, std::vector<vtkProp*>& props);
  void DrawBackFaceInk(const vtkRenderState* state, std::vector<vtkProp*>& inked, double lineWidth);
  // All props, shaded; the faces pulled towards the viewer by `pullWidth` pixels of their depth
  // slope (0: at their own depth).
  void DrawFilledFaces(const vtkRenderState* state, double pullWidth);
  // For such a frame: the ink as it shows against the pulled faces, found in an image of its own
  // (colour and depth) and put over the faces drawn at their own depth.
  void DrawInkImage(const vtkRenderState* state, std::vector<vtkProp*>& inked, double lineWidth,
    double visibleWidth);
  void CompositeInkImage(const vtkRenderState* state);
  // Before each draw of a frame with mesh edges: the mappers take the draw's shaders.
  void SwitchMeshEdgesShader();

  enum DrawModes
  {
    DrawShaded = 0,   // as VTK draws it
    DrawInk = 1,      // back faces in ink, front faces discarded
    DrawMaskFill = 2, // CoverageOnly: faces black
    DrawNoInk = 3     // the ink image (DrawInkImage): faces mark the ink they cover
  };

  double LineWidth = 1.5;
  double InkColor[3] = { 0.0, 0.0, 0.0 };
  bool CoverageOnly = false;
  int DrawMode = DrawShaded;
  bool WarnedAboutWidth = false;
  // GL_ALIASED_LINE_WIDTH_RANGE's upper end, read once per context (0: not read yet). Not VTK's
  // cached GetMaximumHardwareLineWidth(): some windows (ParaView's X window on VTK 9.2) leave it 1.
  double WidestLine = 0.0;
  // Whether an inked surface of this frame shows its mesh edges (vtkProperty::EdgeVisibilityOn):
  // VTK draws them through a geometry shader (vtkPolyDataEdgesGS) whose triangles, drawn as a
  // wireframe, gave lines out to the image borders (Mesa llvmpipe, VTK 9.1, even with their
  // corners left in place; up to VTK 9.3 the shader also moves the corners half a line width
  // outwards, to infinity for a triangle seen edge-on). The ink's wireframe is drawn without it
  // (PreReplaceShaderValues), the filled faces with it, the actors' properties untouched.
  bool InkWithoutMeshEdges = false;
  // While the back-face wireframe is drawn: the state through which front faces are culled.
  vtkOpenGLState* InkDrawState = nullptr;

private:
  vtkNPRInkPass(const vtkNPRInkPass&) = delete;
  void operator=(const vtkNPRInkPass&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
