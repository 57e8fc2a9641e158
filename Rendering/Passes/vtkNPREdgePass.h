// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkNPREdgePass
 * @brief   Silhouette, crease and object-contour lines from a G-buffer, over the shaded image.
 *
 * Reads the G-buffer of a vtkNPRGBufferPass drawn earlier in the same frame and writes, into the
 * current framebuffer, the shaded colour with lines on top plus the depth of every pixel it
 * writes (gl_FragDepth): a depth sprite, so that translucent geometry, volumes, overlays and
 * other layers drawn afterwards composite and depth-test as if the geometry had been drawn there.
 *
 * Line types, each switched and coloured on its own:
 * - Silhouettes: depth discontinuities. A second-order operator (Saito & Takahashi) on 1/z for
 *   perspective and z for parallel cameras, relative to the pixel's depth: it vanishes on planes
 *   at any slant, so grazing faces draw no line. SilhouetteThreshold is the relative depth step
 *   that starts a line (0.005: a step of 0.5 % of the distance). Lines lie on the nearer side.
 *   A fold seen nearly edge-on bends the depth as much as a step; one more depth fetch, on line
 *   pixels only, tells them apart: a step bends the depth the other way, by the threshold, one
 *   pixel beyond on its far side; a fold does not. (A step smaller than the far surface's own
 *   depth change over a pixel fits a fold between the pixels too, and is taken for one.)
 *   With SmoothSilhouettes (off by default, FLOAT and HALF encodings), silhouettes also follow
 *   the contour of the smooth surface that the normals describe: where n.v, the interpolated
 *   normal against the direction to the eye (each pixel's own for perspective cameras), changes
 *   sign between two pixels of an object, the line lies on the pixel nearer the zero. This needs
 *   no threshold: it draws contours whose depth step is too small for SilhouetteThreshold (an
 *   interior contour towards its end, a fold seen nearly edge-on), and nothing on front-facing
 *   smooth regions, where n.v stays positive.
 * - Creases: the angle between the normals of neighbouring pixels of one object exceeds
 *   CreaseAngle (degrees). Lines lie on the side facing the viewer more, or (perspective views)
 *   on the nearer side where the other is the far side of a depth jump across which the two
 *   faces' planes meet: a crease beside a face seen nearly edge-on. The normals compared
 *   are the shading normals, or with FaceCreases (off by default, FLOAT encoding) the faces' own
 *   (the G-buffer's face normals), so that creases are those of the mesh also where the shading
 *   normals are averaged across an edge sharper than the angle (where vtkPolyDataNormals leaves
 *   a point unsplit because the chain of sharp edges through it is broken, as along a crease
 *   whose angle wavers about the threshold).
 * - Suggestive contours (DeCarlo et al. 2003; off by default, FLOAT and HALF encodings): where
 *   n.v, positive, has a minimum along the direction in which the surface recedes (the image
 *   gradient of depth, the view direction projected onto the surface): its first derivative
 *   there vanishes within half a pixel and its second derivative, per pixel squared, exceeds
 *   SuggestiveContourThreshold. They are found in image space from the same five taps as the
 *   other lines (no extra texel fetch): in object space they need the curvature tensor and its
 *   derivative at every vertex, recomputed per mesh, and the lines' visibility. They suggest the
 *   folds that a slightly different view would show as contours: valleys seen from the side.
 * - Contours: the object id changes (props are objects; with one prop, coverage changes).
 *   ContourSide finds the one-pixel line on the nearer object's pixels (INSIDE), on the farther
 *   object's or the background's (OUTSIDE) or on both (BOTH, twice as wide).
 *
 * Lines are widened symmetrically about their one-pixel line.
 *
 * Encoding chooses how the G-buffer stores the geometry the lines are found from (the G-buffer's
 * GeometryEncoding must match; vtkNPRPass keeps them in step): FLOAT (default), HALF, and the
 * packed depth+normal buffers of the 1990s, PACKED8 and PACKED16, where one value per pixel mixes
 * the quantised depth and normal and a Laplacian kernel (optionally after a blur, PackedBlur)
 * above PackedThreshold finds the lines. Packed lines have no type: they take the silhouette
 * colour and are drawn when any line type is on; they straddle each step (about two pixels).
 *
 * They are LineWidth pixels wide (scaled by the window's DPI / 72 and tile scale) and
 * anti-aliased: the one-pixel line image is filtered with a Gaussian and its level set at half
 * the width gives each pixel's coverage. The cost is one pass of 5 texel fetches per pixel to find
 * line pixels (skipped while the G-buffer and settings are unchanged) and one composite pass of
 * (taps + 2) fetches, taps = 4 for widths up to 2.5 pixels, 9 up to 4.5, 25 up to 8.5.
 * MaximumLineFraction adds a pass over the line image between the two.
 *
 * @sa vtkNPRGBufferPass vtkNPRPass
 */
#ifndef vtkNPREdgePass_h
#define vtkNPREdgePass_h

#include "vtkNPRGBufferPass.h" // for the encodings
#include "vtkNPRImageEffectPass.h"
#include "vtkNPRPassesModule.h" // for export macro

#include <memory> // for std::unique_ptr
#include <string> // for std::string

class vtkOpenGLRenderWindow;
class vtkRenderer;
class vtkShaderProgram;
class vtkTextureObject;
struct vtkNPRQuadProgram;

class VTKNPRPASSES_EXPORT vtkNPREdgePass : public vtkNPRImageEffectPass
{
public:
  static vtkNPREdgePass* New();
  vtkTypeMacro(vtkNPREdgePass, vtkNPRImageEffectPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;
  void ReleaseGraphicsResources(vtkWindow* window) override;

  ///@{
  /**
   * The G-buffer this pass reads (drawn before it in the same frame).
   */
  virtual void SetGBufferPass(vtkNPRGBufferPass* pass);
  vtkGetObjectMacro(GBufferPass, vtkNPRGBufferPass);
  ///@}

  ///@{
  /**
   * Silhouettes (depth discontinuities): on by default, black, threshold 0.005.
   * The threshold is a relative depth step, clamped to [1e-5, 1].
   */
  vtkSetMacro(Silhouettes, bool);
  vtkGetMacro(Silhouettes, bool);
  vtkBooleanMacro(Silhouettes, bool);
  vtkSetClampMacro(SilhouetteThreshold, double, 1e-5, 1.0);
  vtkGetMacro(SilhouetteThreshold, double);
  vtkSetVector3Macro(SilhouetteColor, double);
  vtkGetVector3Macro(SilhouetteColor, double);
  ///@}

  ///@{
  /**
   * Silhouettes of the smooth surface, where n.v changes sign between pixels (off by default;
   * see the class description). The G-buffer then holds normals. No effect with the packed
   * encodings. Measured on the benchmark's smooth and scanned scenes (Documentation/edges.md),
   * the depth test already finds every pixel it adds, so it is off by default: it is for
   * contours whose depth step stays below SilhouetteThreshold.
   */
  vtkSetMacro(SmoothSilhouettes, bool);
  vtkGetMacro(SmoothSilhouettes, bool);
  vtkBooleanMacro(SmoothSilhouettes, bool);
  ///@}

  ///@{
  /**
   * Suggestive contours: off by default, black. The threshold is the second derivative of n.v
   * along the receding direction, per pixel squared (default 0.01, clamped to [1e-4, 1]): a
   * valley of n.v whose value rises by half of it one pixel to each side. No effect with the
   * packed encodings.
   */
  vtkSetMacro(SuggestiveContours, bool);
  vtkGetMacro(SuggestiveContours, bool);
  vtkBooleanMacro(SuggestiveContours, bool);
  vtkSetClampMacro(SuggestiveContourThreshold, double, 1e-4, 1.0);
  vtkGetMacro(SuggestiveContourThreshold, double);
  vtkSetVector3Macro(SuggestiveContourColor, double);
  vtkGetVector3Macro(SuggestiveContourColor, double);
  ///@}

  /**
   * True when the G-buffer must hold normals for the line types that are on (creases, smooth
   * silhouettes, suggestive contours).
   */
  bool GetNeedsNormals() const
  {
    return this->Creases || (this->Silhouettes && this->SmoothSilhouettes) ||
      this->SuggestiveContours;
  }

  ///@{
  /**
   * Creases (normal discontinuities): on by default, black, 30 degrees, clamped to [1, 179].
   */
  vtkSetMacro(Creases, bool);
  vtkGetMacro(Creases, bool);
  vtkBooleanMacro(Creases, bool);
  vtkSetClampMacro(CreaseAngle, double, 1.0, 179.0);
  vtkGetMacro(CreaseAngle, double);
  vtkSetVector3Macro(CreaseColor, double);
  vtkGetVector3Macro(CreaseColor, double);
  ///@}

  ///@{
  /**
   * Creases between the faces' own normals (off by default; FLOAT encoding only, where the
   * G-buffer then stores a face normal per pixel beside the shading normal, RGBA32F) instead of
   * between the shading normals. On: the mesh's creases, as vtkNPRFeatureLines and
   * vtkNPRReferenceMask find them, also where the shading normals are averaged across a sharp
   * edge (a CAD part whose crease angle wavers about the threshold). Off: an edge whose shading
   * normals are averaged draws no crease, which is what a surface shaded smooth across its
   * facets on purpose needs (an isosurface with gradient normals, a coarse mesh).
   */
  vtkSetMacro(FaceCreases, bool);
  vtkGetMacro(FaceCreases, bool);
  vtkBooleanMacro(FaceCreases, bool);
  ///@}

  enum ContourSides
  {
    INSIDE = 0,  // on the nearer object
    OUTSIDE = 1, // on the farther object or the background
    BOTH = 2
  };

  ///@{
  /**
   * Object contours (id changes): on by default, black, inside.
   */
  vtkSetMacro(Contours, bool);
  vtkGetMacro(Contours, bool);
  vtkBooleanMacro(Contours, bool);
  vtkSetClampMacro(ContourSide, int, INSIDE, BOTH);
  vtkGetMacro(ContourSide, int);
  void SetContourSideToInside() { this->SetContourSide(INSIDE); }
  void SetContourSideToOutside() { this->SetContourSide(OUTSIDE); }
  void SetContourSideToBoth() { this->SetContourSide(BOTH); }
  vtkSetVector3Macro(ContourColor, double);
  vtkGetVector3Macro(ContourColor, double);
  ///@}

  // The G-buffer's encodings (vtkNPRGBufferPass::GeometryEncodings), by the same names here.
  enum Encodings
  {
    FLOAT = vtkNPRGBufferPass::FLOAT,
    HALF = vtkNPRGBufferPass::HALF,
    PACKED8 = vtkNPRGBufferPass::PACKED8,
    PACKED16 = vtkNPRGBufferPass::PACKED16
  };

  ///@{
  /**
   * How the G-buffer stores depth and normals (default FLOAT). Names: float, half, packed8,
   * packed16.
   */
  vtkSetClampMacro(Encoding, int, FLOAT, PACKED16);
  vtkGetMacro(Encoding, int);
  static const char* GetEncodingName(int encoding);
  /**
   * The encoding of a name (as GetEncodingName() gives it), -1 for an unknown name.
   */
  static int GetEncodingFromName(const char* name);
  ///@}

  ///@{
  /**
   * Packed encodings: the Laplacian magnitude that starts a line, in units of one quantised
   * component's full range (default 0.1, i.e. 6.3 levels of the 8-bit buffer's 63), clamped to
   * [0.001, 4]; and a 3x3 blur before the Laplacian (off by default).
   */
  vtkSetClampMacro(PackedThreshold, double, 0.001, 4.0);
  vtkGetMacro(PackedThreshold, double);
  vtkSetMacro(PackedBlur, bool);
  vtkGetMacro(PackedBlur, bool);
  vtkBooleanMacro(PackedBlur, bool);
  ///@}

  ///@{
  /**
   * Line width in pixels at 72 DPI (default 1.5), clamped to [0.5, 16].
   */
  vtkSetClampMacro(LineWidth, double, 0.5, 16.0);
  vtkGetMacro(LineWidth, double);
  ///@}

  ///@{
  /**
   * The width of one kind of line in pixels at 72 DPI, clamped to [0, 16] (default 0: LineWidth):
   * silhouettes (in the drawing style also boundaries), creases (in the drawing also non-manifold
   * edges), object contours and suggestive contours. Line roles of their own weight: heavy
   * outlines over light creases, as technical illustrations draw them. The drawing's strokes take
   * the widths exactly. The image-space styles filter every kind with the widest kind's Gaussian
   * and draw a narrower kind as a level set of it nearer the line, so a kind much narrower than
   * the widest (under about half its width) has a softer edge and lighter core than the same
   * width drawn alone.
   */
  vtkSetClampMacro(SilhouetteLineWidth, double, 0.0, 16.0);
  vtkGetMacro(SilhouetteLineWidth, double);
  vtkSetClampMacro(CreaseLineWidth, double, 0.0, 16.0);
  vtkGetMacro(CreaseLineWidth, double);
  vtkSetClampMacro(ContourLineWidth, double, 0.0, 16.0);
  vtkGetMacro(ContourLineWidth, double);
  vtkSetClampMacro(SuggestiveContourLineWidth, double, 0.0, 16.0);
  vtkGetMacro(SuggestiveContourLineWidth, double);
  ///@}

  ///@{
  /**
   * Width falling off with depth (off by default): with DepthFalloff on, a line's width is its
   * kind's times NearLineScale (default 1.5) at the camera's near clipping plane, times
   * FarLineScale (default 0.5) at its far one, linear in the distance between (each clamped to
   * [0.1, 4]): near lines heavier. VTK places the clipping planes on the scene's bounds
   * (ResetCameraClippingRange), so the scale runs over the scene's depth. The drawing style's
   * visible strokes take it point by point.
   */
  vtkSetMacro(DepthFalloff, bool);
  vtkGetMacro(DepthFalloff, bool);
  vtkBooleanMacro(DepthFalloff, bool);
  vtkSetClampMacro(NearLineScale, double, 0.1, 4.0);
  vtkGetMacro(NearLineScale, double);
  vtkSetClampMacro(FarLineScale, double, 0.1, 4.0);
  vtkGetMacro(FarLineScale, double);
  ///@}

  /**
   * The width in pixels of the widest line drawn for this renderer: the largest of the widths of
   * the kinds drawn (each LineWidth where it is 0; LineWidth when none is drawn) x DPI / 72 x tile
   * scale.
   */
  double GetEffectiveLineWidth(vtkRenderer* renderer) const;

  /**
   * Each kind's width in pixels for this renderer, in the line image's order: silhouettes,
   * creases, contours, suggestive contours.
   */
  void GetEffectiveLineWidths(vtkRenderer* renderer, double widths[4]) const;

  ///@{
  /**
   * Draw the lines over a surface in a darker shade of the surface's own colour: its colour times
   * this factor, clamped to [0, 1] (default 0: the lines take their own colours, SilhouetteColor
   * and the others). With colour-mapped data (stream tubes, isosurfaces coloured by a scalar) the
   * lines then keep the data's hue where they cover it; 0.5 is a good start. Line parts reaching
   * past a surface take the nearest surface's colour; in the sketch style, the lines on the paper
   * keep their own colours.
   */
  vtkSetClampMacro(SurfaceLineShade, double, 0.0, 1.0);
  vtkGetMacro(SurfaceLineShade, double);
  ///@}

  ///@{
  /**
   * The largest share of an object's width that each of its lines may take, clamped to [0, 1]
   * (default 0: no limit; 0.1 suits flow visualisations). On an object narrower than the line
   * width divided by this fraction (15 pixels at 0.1 and the default width: a stream tube, a
   * distant wire) the lines are drawn thinner and lighter, down to nothing on an object one pixel
   * wide, and only its outline is drawn (silhouettes, or else contours; one line per pixel), so
   * that the colours mapped onto it stay visible. The object's width at a line pixel is the second
   * shortest of its chords along the axes and diagonals, each up to the next outline, another
   * object or the background; creases do not end a chord. It costs a pass over the line image.
   * Off by default: near the tip of an acute corner every chord is short, so corners of CAD parts
   * get lighter. Not with the packed encodings. See SurfaceLineShade.
   */
  vtkSetClampMacro(MaximumLineFraction, double, 0.0, 1.0);
  vtkGetMacro(MaximumLineFraction, double);
  ///@}

  ///@{
  /**
   * Anti-aliased lines (on by default). Off: every pixel is fully line or not.
   */
  vtkSetMacro(AntiAliasing, bool);
  vtkGetMacro(AntiAliasing, bool);
  vtkBooleanMacro(AntiAliasing, bool);
  ///@}

  ///@{
  /**
   * Write the line coverage alone (white lines on black, every pixel opaque) instead of lines
   * over the shaded image: an edge mask for measuring accuracy. Off by default.
   */
  vtkSetMacro(CoverageOnly, bool);
  vtkGetMacro(CoverageOnly, bool);
  vtkBooleanMacro(CoverageOnly, bool);
  ///@}

  ///@{
  /**
   * For passes built on this one (vtkNPRSketchPass), whose shaders include vtkNPRLineColor.glsl:
   * its defines, and the line colours' uniforms.
   */
  std::string GetLineColorDefines() const;
  void SetLineColorUniforms(vtkShaderProgram* program) const;
  ///@}

  /**
   * For passes built on this one (vtkNPRSketchPass): computes the lines as Render() does but
   * writes, into the current framebuffer (of the G-buffer's size, from its origin), each type's
   * coverage in [0, 1] (r silhouettes, g creases, b contours) and in alpha the depth the lines
   * are drawn at: the surface's, or for a line reaching past a surface onto the background, the
   * nearest surface's; 1 elsewhere. Every pixel of the G-buffer's content rectangle is written,
   * nothing outside it (coverage 0 and depth 1 there). False, having drawn nothing, after a
   * picking render, when the G-buffer is empty or on an error (reported).
   */
  bool RenderLineCoverage(const vtkRenderState* state);

  /**
   * True when some line type is on.
   */
  bool GetDrawsLines() const
  {
    return this->Silhouettes || this->Creases || this->Contours || this->SuggestiveContours;
  }

  /**
   * Number of times the line image was computed from the G-buffer (it is reused while the
   * G-buffer and the detection settings are unchanged: line types, thresholds, contour side).
   */
  vtkGetMacro(NumberOfLineImageUpdates, int);

  // KeepUnchangedComposite (vtkNPRImageEffectPass): lines only; CoverageOnly and
  // RenderLineCoverage() always draw.

  ///@{
  /**
   * Composite the lines only over the 16 x 16 pixel blocks a line can reach, and copy the
   * surfaces elsewhere (on by default). The picture is the same bit for bit; what changes is
   * the cost: the line composite's code runs only where lines are. Off: one full-screen
   * composite. The same for RenderLineCoverage(). Not for CoverageOnly's mask (black over the
   * whole view), nor where a line width's mapping covers pixels without a line value: everything
   * is drawn then. The surfaces elsewhere are copied back whole first where CopySurfacesBack
   * allows, else the output without lines (the surfaces' copy, no coverage) is drawn over the
   * line-free blocks.
   */
  vtkSetMacro(SkipLineFreeBlocks, bool);
  vtkGetMacro(SkipLineFreeBlocks, bool);
  vtkBooleanMacro(SkipLineFreeBlocks, bool);
  ///@}

  ///@{
  /**
   * Copy the surfaces' colour and depth back from the G-buffer whole, by one glBlitFramebuffer,
   * where the G-buffer holds the window's image under them
   * (vtkNPRGBufferPass::GetHoldsWindowImage(); vtkNPRPass asks for it while this is on): before
   * the lines' blocks are drawn (SkipLineFreeBlocks), and as the whole composite when no line
   * type is on. On by default. The colours are the same bit for bit; the depths are the G-buffer's
   * own, where the copy shader's go through a float (a few steps of 2^-24 apart at most).
   */
  vtkSetMacro(CopySurfacesBack, bool);
  vtkGetMacro(CopySurfacesBack, bool);
  vtkBooleanMacro(CopySurfacesBack, bool);
  ///@}

  /**
   * Number of composites drawn over the blocks near lines (SkipLineFreeBlocks),
   * RenderLineCoverage()'s images included.
   */
  vtkGetMacro(NumberOfBlockComposites, int);

  /**
   * Number of composites whose surfaces were copied back whole from the G-buffer
   * (vtkNPRGBufferPass::CopySurfacesBack()): those over the blocks near lines, and those with no
   * line type on, which are that copy alone.
   */
  vtkGetMacro(NumberOfSurfaceCopies, int);

protected:
  vtkNPREdgePass();
  ~vtkNPREdgePass() override;

  enum Outputs
  {
    OutputComposite = 0,   // lines over the shaded colour, with the depth sprite
    OutputMask = 1,        // CoverageOnly
    OutputLineCoverage = 2 // RenderLineCoverage()
  };
  // The steps of the frame (vtkNPRImageEffectPass).
  vtkNPRGBufferPass* GetGBuffer() override;
  bool UpdateImages(const vtkRenderState* state) override;
  std::string GetCompositeKey(vtkRenderer* renderer) override;
  void GetCompositeRectangle(vtkRenderer* renderer, int rect[4]) override;
  bool DrawComposite(const vtkRenderState* state, const int origin[2]) override;

  vtkNPRGBufferPass* GBufferPass = nullptr;
  bool Silhouettes = true;
  double SilhouetteThreshold = 0.005;
  double SilhouetteColor[3] = { 0.0, 0.0, 0.0 };
  bool SmoothSilhouettes = false;
  bool SuggestiveContours = false;
  double SuggestiveContourThreshold = 0.01;
  double SuggestiveContourColor[3] = { 0.0, 0.0, 0.0 };
  bool Creases = true;
  double CreaseAngle = 30.0;
  double CreaseColor[3] = { 0.0, 0.0, 0.0 };
  bool FaceCreases = false;
  bool Contours = true;
  int ContourSide = INSIDE;
  double ContourColor[3] = { 0.0, 0.0, 0.0 };
  double LineWidth = 1.5;
  double SilhouetteLineWidth = 0.0;
  bool DepthFalloff = false;
  double NearLineScale = 1.5;
  double FarLineScale = 0.5;
  double CreaseLineWidth = 0.0;
  double ContourLineWidth = 0.0;
  double SuggestiveContourLineWidth = 0.0;
  double MaximumLineFraction = 0.0;
  double SurfaceLineShade = 0.0;
  int Encoding = FLOAT;
  double PackedThreshold = 0.1;
  bool PackedBlur = false;
  bool AntiAliasing = true;
  bool CoverageOnly = false;
  bool SkipLineFreeBlocks = true;
  int NumberOfLineImageUpdates = 0;
  int NumberOfBlockComposites = 0;
  int NumberOfSurfaceCopies = 0;
  bool CopySurfacesBack = true;

private:
  vtkNPREdgePass(const vtkNPREdgePass&) = delete;
  void operator=(const vtkNPREdgePass&) = delete;

  // The one-pixel line image, recomputed only when the G-buffer or the detection settings changed.
  std::string GetDetectDefines(int encoding) const;
  bool UpdateLineImage(const vtkRenderState* state);
  // GetEffectiveLineWidths, with a kind not drawn no wider than the widest drawn.
  void GetDrawnLineWidths(vtkRenderer* renderer, double widths[4]) const;
  // The widest of the kinds' widths that are drawn; the effective LineWidth when none is.
  double GetWidestDrawn(vtkRenderer* renderer, const double widths[4]) const;
  bool DetectLines(vtkOpenGLRenderWindow* window, int encoding, const std::string& defines);
  void SetDetectUniforms(vtkShaderProgram* program, int encoding);
  // MaximumLineFraction: the detected lines thinned on narrow objects, into a second line image.
  bool LimitLineWidths(vtkOpenGLRenderWindow* window, int encoding, vtkRenderer* renderer);
  void DrawLineImage(
    vtkOpenGLRenderWindow* window, vtkTextureObject* image, vtkNPRQuadProgram& program);
  // The composite of the lines (and colour and depth, or the mask, or the coverage).
  std::string GetCompositeDefines(vtkRenderer* renderer, int output, bool lines);
  bool DrawLines(const vtkRenderState* state, const int origin[2], int output);
  // SkipLineFreeBlocks: whether this composite can, and the composite drawn so.
  bool SkipsLineFreeBlocks() const;
  bool UpdateLineBlocks(vtkOpenGLRenderWindow* window);
  bool DrawOverBlocks(vtkOpenGLRenderWindow* window, vtkRenderer* renderer, const int origin[2],
    int output, const std::string& lineDefines);
  void SetCompositeUniforms(vtkShaderProgram* program, const int origin[2], vtkRenderer* renderer);

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
