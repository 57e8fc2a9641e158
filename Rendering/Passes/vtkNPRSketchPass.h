// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkNPRSketchPass
 * @brief   Sketchy drawing (Nienhaus & Döllner 2004): lines and fills that wobble like a hand
 *          drawing, written as a depth sprite.
 *
 * Reads the G-buffer of the edge pass's vtkNPRGBufferPass (drawn earlier in the frame, normally
 * with flat unlit colours: vtkNPRPass style SKETCH) and the lines of the vtkNPREdgePass (their
 * coverage, as vtkNPREdgePass::RenderLineCoverage() gives it), and looks both up through
 * perturbed texture coordinates:
 *
 *   n(p)     = a tileable 2D gradient noise vector (|n| <= 1) at pixel p
 *   lines at   p + Uncertainty x EdgeMatrix    x n(p)
 *   surfaces at p + Uncertainty x SurfaceMatrix x n(p)
 *
 * so lines and fills are displaced by at most Uncertainty pixels, and differently (the two 2x2
 * matrices; one with a norm above 1 is scaled down to norm 1). The lines are drawn over the
 * surface colour, or over the paper (PaperColor, when Paper is on) or the window's background.
 * Surfaces are looked up with nearest sampling, lines bilinearly so they bend smoothly.
 *
 * Depth sprite: the depth is looked up with the same two displacements (the surface depth, and
 * the depth the lines are drawn at) and the smaller of the two is written to gl_FragDepth, so
 * translucent props, volumes, overlays and other layers drawn later are depth-tested against the
 * sketch as drawn. Where the paper shows, the depth is the far plane.
 *
 * Where the noise is taken from (NoiseSpace):
 * - SURFACE (the default): n is a 3D noise of the surface point seen at the pixel (its world
 *   position, from the G-buffer's depth), so the wobble stays on the surface while the camera
 *   pans, orbits or zooms, instead of swimming over it (the shower-door effect). A pixel off the
 *   surface takes the point of the farthest surface within reach (Uncertainty plus the line
 *   width), so lines drawn next to a silhouette wobble with it. The noise's scale follows the
 *   pixel size at that depth in powers of two, the two nearest blended, so a cell stays between
 *   one and two times 100 / NoiseFrequency pixels at any zoom. World positions are taken
 *   relative to a point near the props (on a grid of the noise period), so large coordinates
 *   keep their precision. The noise is attached to the world: a prop whose own matrix changes
 *   moves under its wobble.
 * - SCREEN: n is a noise of the pixel (the seed paper's choice): the same at every frame,
 *   whatever moves.
 *
 * The noise is Perlin gradient noise made on the CPU from NoiseSeed, each of its two components
 * an independent noise: in screen space a 256 x 256 texel tile of 8 x 8 lattice cells; in
 * surface space a 64^3 texel tile holding the noise (period 8 cells, 4 texels a cell) and the
 * same at half the frequency, interpolated trilinearly by the texture unit. The surface noise
 * is computed once per block of up to 4 x 4 pixels (a cell spans at least 8 blocks), within
 * reach of the props' projected bounds, and interpolated bilinearly between the blocks'
 * centres. The same seed gives the same image on every run. NoiseFrequency is the number of lattice
 * cells per 100 pixels. Uncertainty and the noise period are scaled like line widths (DPI / 72
 * x tile scale). With Uncertainty 0 the result is exactly the vtkNPREdgePass image of the same
 * G-buffer.
 *
 * @sa vtkNPRPass vtkNPREdgePass vtkNPRGBufferPass vtkNPRToonPass
 */
#ifndef vtkNPRSketchPass_h
#define vtkNPRSketchPass_h

#include "vtkNPREdgeEffectPass.h"
#include "vtkNPRPassesModule.h" // for export macro

#include <memory> // for std::unique_ptr
#include <string> // for std::string

class vtkImageData;
class vtkOpenGLRenderWindow;
class vtkRenderer;
class vtkShaderProgram;
class vtkTextureObject;

class VTKNPRPASSES_EXPORT vtkNPRSketchPass : public vtkNPREdgeEffectPass
{
public:
  static vtkNPRSketchPass* New();
  vtkTypeMacro(vtkNPRSketchPass, vtkNPREdgeEffectPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;
  void ReleaseGraphicsResources(vtkWindow* window) override;

  ///@{
  /**
   * Largest displacement in pixels at 72 DPI (default 3), clamped to [0, 32].
   */
  vtkSetClampMacro(Uncertainty, double, 0.0, 32.0);
  vtkGetMacro(Uncertainty, double);
  ///@}

  ///@{
  /**
   * Seed of the noise (default 1).
   */
  vtkSetMacro(NoiseSeed, unsigned int);
  vtkGetMacro(NoiseSeed, unsigned int);
  ///@}

  ///@{
  /**
   * Noise lattice cells per 100 pixels (default 2: the wobble changes about every 50 pixels),
   * clamped to [0.05, 25].
   */
  vtkSetClampMacro(NoiseFrequency, double, 0.05, 25.0);
  vtkGetMacro(NoiseFrequency, double);
  ///@}

  enum NoiseSpaces
  {
    SCREEN = 0,
    SURFACE = 1
  };

  ///@{
  /**
   * Where the noise is attached (see the class description): SURFACE (default) or SCREEN.
   */
  vtkSetClampMacro(NoiseSpace, int, SCREEN, SURFACE);
  vtkGetMacro(NoiseSpace, int);
  void SetNoiseSpaceToScreen() { this->SetNoiseSpace(SCREEN); }
  void SetNoiseSpaceToSurface() { this->SetNoiseSpace(SURFACE); }
  const char* GetNoiseSpaceAsString() const;
  ///@}

  ///@{
  /**
   * The 2x2 matrices (row major: a b c d is [a b; c d]) turning the noise vector into the
   * lines' and the surfaces' displacements. Defaults: identity for lines, a reflection
   * (-0.6 0.8 0.8 0.6) for surfaces.
   */
  vtkSetVector4Macro(EdgeMatrix, double);
  vtkGetVector4Macro(EdgeMatrix, double);
  vtkSetVector4Macro(SurfaceMatrix, double);
  vtkGetVector4Macro(SurfaceMatrix, double);
  ///@}

  ///@{
  /**
   * Paper: when on (off by default), the background of the renderer's viewport is PaperColor
   * (default 1, 0.98, 0.92) instead of the window's background.
   */
  vtkSetMacro(Paper, bool);
  vtkGetMacro(Paper, bool);
  vtkBooleanMacro(Paper, bool);
  vtkSetVector3Macro(PaperColor, double);
  vtkGetVector3Macro(PaperColor, double);
  ///@}

  /**
   * Uncertainty in pixels for this renderer: Uncertainty x DPI / 72 x tile scale.
   */
  double GetEffectiveUncertainty(vtkRenderer* renderer) const;

  /**
   * Noise texels per pixel for this renderer (NoiseFrequency / 100 x 32 texels per cell, over
   * the same DPI and tile scale).
   */
  double GetEffectiveNoiseScale(vtkRenderer* renderer) const;

  /**
   * The noise tile (256 x 256, two float components, |vector| <= 1) for the current seed: the
   * shader reads it with wrap-around at texel centres and interpolates bilinearly.
   */
  vtkImageData* GetNoiseImage();

  /**
   * The displacement in pixels at pixel (x, y) of the renderer's viewport, as the shader
   * computes it in NoiseSpace SCREEN, for lines (surfaces = false) or surfaces: uncertainty x
   * matrix x n(p), with the matrices after their normalisation.
   */
  void GetDisplacement(vtkRenderer* renderer, int x, int y, bool surfaces, double displacement[2]);

protected:
  vtkNPRSketchPass();
  ~vtkNPRSketchPass() override;

  // The steps of the frame (vtkNPRImageEffectPass) beside the G-buffer (vtkNPREdgeEffectPass).
  bool UpdateImages(const vtkRenderState* state) override;
  std::string GetCompositeKey(vtkRenderer* renderer) override;
  void GetCompositeRectangle(vtkRenderer* renderer, int rect[4]) override;
  bool DrawComposite(const vtkRenderState* state, const int origin[2]) override;

  double Uncertainty = 3.0;
  unsigned int NoiseSeed = 1;
  double NoiseFrequency = 2.0;
  int NoiseSpace = SURFACE;
  double EdgeMatrix[4] = { 1.0, 0.0, 0.0, 1.0 };
  double SurfaceMatrix[4] = { -0.6, 0.8, 0.8, 0.6 };
  bool Paper = false;
  double PaperColor[3] = { 1.0, 0.98, 0.92 };

private:
  vtkNPRSketchPass(const vtkNPRSketchPass&) = delete;
  void operator=(const vtkNPRSketchPass&) = delete;

  // The lines' coverage and depth (vtkNPREdgePass::RenderLineCoverage), drawn when the G-buffer or
  // the edge pass's settings changed.
  void UpdateCoverage(const vtkRenderState* state);
  std::string GetSketchDefines() const;
  void SetSketchUniforms(vtkShaderProgram* program, vtkRenderer* renderer, const int origin[2]);
  vtkTextureObject* PrepareScreenNoise(vtkOpenGLRenderWindow* window);
  vtkTextureObject* PrepareSurfaceNoiseTile(vtkOpenGLRenderWindow* window);
  // The surface noise of each block x block pixels, drawn when the G-buffer or the settings
  // changed; null when its shader did not compile.
  vtkTextureObject* RenderSurfaceNoise(const vtkRenderState* state, double reach, int block);
  vtkShaderProgram* ReadyNoiseFieldProgram(vtkOpenGLRenderWindow* window, vtkRenderer* renderer);
  void DrawNoiseField(
    const vtkRenderState* state, vtkShaderProgram* program, double reach, int block);
  int GetSurfaceNoiseBlock(vtkRenderer* renderer) const;
  void SetSurfaceNoiseUniforms(
    vtkShaderProgram* program, vtkRenderer* renderer, int height, double reach);

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
