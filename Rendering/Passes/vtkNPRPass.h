// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkNPRPass
 * @brief   Non-photorealistic rendering for a renderer in one line: renderer->SetPass(npr).
 *
 * Builds and owns the whole chain of passes a renderer needs:
 *
 *   vtkRenderStepsPass: camera, lights,
 *     opaque, by style:
 *       SHADED      vtkOpaquePass (VTK's own drawing, the baseline),
 *       EDGES       vtkNPRGBufferPass (drawing a vtkOpaquePass), then vtkNPREdgePass,
 *       TOON        vtkNPRToonPass (drawing a vtkOpaquePass) straight into the window,
 *       TOON_EDGES  vtkNPRGBufferPass (drawing the toon pass), then vtkNPREdgePass,
 *       SKETCH      vtkNPRGBufferPass (drawing flat colours: a one-band vtkNPRToonPass, or the
 *                   toon pass with SketchToonShading), then vtkNPRSketchPass,
 *       INKED       vtkNPRInkPass (drawing a vtkOpaquePass twice: fat back-face wireframe,
 *                   pushed back by polygon offset, then the faces) straight into the window,
 *       DRAWING     vtkNPRGBufferPass (drawing flat colours, of which only the depth is used),
 *                   then vtkNPRDrawingPass: faces in one colour, the exact object-space lines
 *                   over them, hidden lines dashed on request (SetHiddenLines()), then the
 *                   mesh edges actors show (EdgeVisibilityOn) as VTK draws them,
 *     translucent: vtkTranslucentPass, or vtkDualDepthPeelingPass when the renderer's
 *                  UseDepthPeeling is on (its MaximumNumberOfPeels and OcclusionRatio apply),
 *     volumes, overlay.
 *
 * The edge, sketch and drawing passes write a depth sprite, so everything drawn after the opaque
 * step (translucent props, volumes, 2D actors, renderers on higher layers) composites as with VTK's
 * own chain. Translucent props are shaded as usual in every style.
 *
 * The effect passes are exposed for tuning (GetEdgePass(), GetToonPass(), GetSketchPass(),
 * GetInkPass(), GetDrawingPass(), GetGBufferPass()); the G-buffer channels and encoding follow what
 * the enabled lines need (the edge pass's line types and Encoding). The sketch and the drawing use
 * the edge pass's line settings (types, thresholds, width, colours).
 *
 * Renderer flags that VTK ignores once a pass is set (UseFXAA, UseSSAO, UseShadows) stay ignored;
 * UseDepthPeeling is honoured here.
 *
 * @sa vtkNPRGBufferPass vtkNPREdgePass
 */
#ifndef vtkNPRPass_h
#define vtkNPRPass_h

#include "vtkNPRPassesModule.h" // for export macro
#include "vtkRenderPass.h"

class vtkDualDepthPeelingPass;
class vtkNPRDrawingPass;
class vtkNPREdgePass;
class vtkNPRGBufferPass;
class vtkNPRInkPass;
class vtkNPRSketchPass;
class vtkNPRToonPass;
class vtkOpaquePass;
class vtkRenderStepsPass;
class vtkSequencePass;
class vtkTranslucentPass;

class VTKNPRPASSES_EXPORT vtkNPRPass : public vtkRenderPass
{
public:
  static vtkNPRPass* New();
  vtkTypeMacro(vtkNPRPass, vtkRenderPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  void Render(const vtkRenderState* state) override;
  void ReleaseGraphicsResources(vtkWindow* window) override;

  enum Styles
  {
    SHADED = 0,
    EDGES = 1,
    TOON = 2,
    TOON_EDGES = 3,
    SKETCH = 4,
    INKED = 5,
    DRAWING = 6
  };

  ///@{
  /**
   * The style (default EDGES). Names: shaded, edges, toon, toon+edges, sketch, inked, drawing.
   */
  vtkSetClampMacro(Style, int, SHADED, DRAWING);
  vtkGetMacro(Style, int);
  void SetStyleToShaded() { this->SetStyle(SHADED); }
  void SetStyleToEdges() { this->SetStyle(EDGES); }
  void SetStyleToToon() { this->SetStyle(TOON); }
  void SetStyleToToonEdges() { this->SetStyle(TOON_EDGES); }
  void SetStyleToSketch() { this->SetStyle(SKETCH); }
  void SetStyleToInked() { this->SetStyle(INKED); }
  void SetStyleToDrawing() { this->SetStyle(DRAWING); }
  static const char* GetStyleName(int style);
  /**
   * The style of a name (as GetStyleName() gives it), -1 for an unknown name.
   */
  static int GetStyleFromName(const char* name);
  ///@}

  ///@{
  /**
   * SKETCH: sketch the toon pass's bands instead of flat colours (off by default).
   */
  vtkSetMacro(SketchToonShading, bool);
  vtkGetMacro(SketchToonShading, bool);
  vtkBooleanMacro(SketchToonShading, bool);
  ///@}

  ///@{
  /**
   * DRAWING: draw the hidden lines, dashed (off by default; the drawing pass's HiddenLines).
   */
  void SetHiddenLines(bool hidden);
  bool GetHiddenLines();
  vtkBooleanMacro(HiddenLines, bool);
  ///@}

  ///@{
  /**
   * The passes this one owns, for tuning. Do not replace them inside the chain.
   */
  vtkGetObjectMacro(GBufferPass, vtkNPRGBufferPass);
  vtkGetObjectMacro(EdgePass, vtkNPREdgePass);
  vtkGetObjectMacro(ToonPass, vtkNPRToonPass);
  vtkGetObjectMacro(SketchPass, vtkNPRSketchPass);
  vtkGetObjectMacro(InkPass, vtkNPRInkPass);
  vtkGetObjectMacro(DrawingPass, vtkNPRDrawingPass);
  vtkGetObjectMacro(RenderStepsPass, vtkRenderStepsPass);
  ///@}

protected:
  vtkNPRPass();
  ~vtkNPRPass() override;

  int Style = EDGES;
  bool SketchToonShading = false;
  vtkRenderStepsPass* RenderStepsPass;
  vtkOpaquePass* OpaquePass;           // every prop
  class vtkNPROpaquePass* SurfacePass; // the G-buffer's: annotations are drawn after the effect
  vtkNPRGBufferPass* GBufferPass;
  vtkNPREdgePass* EdgePass;
  vtkNPRToonPass* ToonPass;
  vtkNPRToonPass* FlatPass; // one band, no highlight: the flat colours a sketch fills with
  vtkNPRSketchPass* SketchPass;
  vtkNPRInkPass* InkPass;
  vtkNPRDrawingPass* DrawingPass;
  class vtkNPRLinePrimitivesPass* LinePrimitivesPass;
  class vtkNPRMeshEdgesPass* MeshEdgesPass; // the drawing's: mesh edges over its faces
  vtkSequencePass* EdgesSequence;
  vtkSequencePass* SketchSequence;
  vtkSequencePass* DrawingSequence;
  vtkTranslucentPass* TranslucentPass;
  vtkDualDepthPeelingPass* DepthPeelingPass;

private:
  vtkNPRPass(const vtkNPRPass&) = delete;
  void operator=(const vtkNPRPass&) = delete;
};

#endif
