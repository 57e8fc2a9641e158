// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkNPRGBufferPass
 * @brief   Draws the opaque geometry once into a G-buffer that image-space effects read.
 *
 * The delegate (normally a vtkOpaquePass) draws into a framebuffer of the renderer's size with:
 *
 * - colour (RGBA8): the shaded image as VTK would draw it;
 * - depth (a depth texture of the format of the framebuffer the pass draws for, so that the
 *   depths are the ones VTK draws there, where a texture can take it: 16, 24, 32-bit or float
 *   without stencil, single-sampled; 32-bit float otherwise and for log depth);
 * - geometry (32-bit float): r = view-space depth (distance along the view direction, 0 on the
 *   background), g = the view-space normal (octahedral, 12 bits per coordinate, packed in one
 *   float), b = the object id (1-based index of the prop in the frame).
 *
 * Only what the effects need is allocated and written: the geometry attachment is R32F when
 * neither normals nor ids are wanted, RG32F with normals, RGBA32F with ids or face normals.
 *
 * GeometryEncoding chooses how the geometry attachment stores this (for measuring what
 * precision the lines need; vtkNPREdgePass reads each):
 * - FLOAT (default): as above, 32-bit float; with FaceNormalsRequested, a = the face normal,
 *   packed as the shading normal (RGBA32F).
 * - HALF: 16-bit float; r = view depth, g and b = the octahedral normal's two coordinates,
 *   a = id (exact up to 2048 props): R16F with depth only, RGBA16F otherwise.
 * - PACKED8 / PACKED16: the 1990s packed depth+normal buffer, one unsigned normalised channel
 *   (R8 / R16): 1 + depth + nx + ny + nz, where the depth (view depth mapped from the camera's
 *   clipping range onto 0..1) and each normal coordinate (mapped from -1..1) are quantised to
 *   0..63 (8 bits: the sum is at most 253 of 255) or 0..16383 (16 bits). The normal terms are
 *   packed only when normals are requested; ids never are. 0 is the background. Ids are written
 * only when asked for and more than one prop with opaque geometry is visible (with one, coverage
 * says the same). With no prop to draw, nothing is allocated or drawn.
 *
 * The extra outputs are written by every vtkOpenGLPolyDataMapper (and its subclasses: composite,
 * glyph, point-Gaussian helpers) through the vtkOpenGLRenderPass shader hooks, as vtkSSAOPass does.
 * Lit actors give their shading normal; unlit actors and zero-length or NaN normals give the face
 * normal from the derivatives of the view-space position. Line and point primitives (lines,
 * vertices, the wireframe and points representations) are not geometry: they are left out of the
 * G-buffer, so that no lines are traced along them, and vtkNPRPass draws them as VTK does after
 * the effect, depth-tested against its depth sprite (GetHasLinePrimitives()). Tubes (vtkTubeFilter)
 * are surfaces. Other mappers draw colour and depth only; they appear as background to the effects.
 *
 * Reuse: when neither the props (their MTime and redraw MTime, which includes their mapper and
 * its input), the camera, the lights, the renderer's lighting settings, the size, this pass nor
 * its delegate changed since the last frame, the geometry is not drawn again and the last G-buffer
 * is kept (ReuseUnchangedFrames, on by default). GetNumberOfGeometryDraws() counts the draws.
 *
 * Depth-only mode (DepthOnly, off by default): the delegate is any pass that leaves colour and
 * depth in the framebuffer (a whole vtkRenderStepsPass, a compositing pass of a parallel
 * renderer such as ParaView's IceT pass); no shader is changed. The geometry attachment is
 * derived from the depth buffer alone: view depth, and the normal of the surface rebuilt from the
 * depths of neighbouring pixels (vtkNPRDepthGeometryFS: face normals, within the precision of
 * the depth buffer). It is always in the FLOAT encoding with normals and without ids, so
 * silhouettes work as usual, creases follow the rebuilt normals (the facets of a tessellated
 * surface, and curved surfaces seen at grazing angles, may give creases the mapper's smooth
 * normals would not), and object contours fall back to coverage (the outline against the
 * background). The captured colour and depth are copied back into the framebuffer the pass was
 * called with, so that what the effects leave alone (the background, translucent geometry the
 * delegate drew) is kept. Frames are never reused in this mode and the content rectangle is the
 * whole buffer.
 * Picking: VTK 9.1 does not call the hardware selector once a renderer has a pass, so during a
 * selection render this pass runs the selector itself (vtkPropPicker, vtkHardwareSelector) and
 * makes no G-buffer.
 *
 * @sa vtkNPREdgePass vtkNPRPass
 */
#ifndef vtkNPRGBufferPass_h
#define vtkNPRGBufferPass_h

#include "vtkNPRGeometryPass.h"
#include "vtkNPRPassesModule.h" // for export macro

#include <memory> // for std::unique_ptr
#include <vector> // for CountOpaqueProps

class vtkMatrix4x4;
class vtkOpenGLFramebufferObject;
class vtkOpenGLRenderWindow;
class vtkOpenGLState;
class vtkRenderer;
class vtkTextureObject;

class VTKNPRPASSES_EXPORT vtkNPRGBufferPass : public vtkNPRGeometryPass
{
public:
  static vtkNPRGBufferPass* New();
  vtkTypeMacro(vtkNPRGBufferPass, vtkNPRGeometryPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  void Render(const vtkRenderState* state) override;
  void ReleaseGraphicsResources(vtkWindow* window) override;

  ///@{
  /**
   * Whether the effects need normals and object ids. Off by default: colour and depth only.
   */
  vtkSetMacro(NormalsRequested, bool);
  vtkGetMacro(NormalsRequested, bool);
  vtkBooleanMacro(NormalsRequested, bool);
  vtkSetMacro(ObjectIdsRequested, bool);
  vtkGetMacro(ObjectIdsRequested, bool);
  vtkBooleanMacro(ObjectIdsRequested, bool);
  ///@}

  ///@{
  /**
   * Also write each fragment's face normal, from the derivatives of its view-space position, beside
   * the shading normal (off by default; FLOAT encoding with normals only, in the alpha channel):
   * vtkNPREdgePass finds creases between faces from it, as the mesh has them, where the shading
   * normals may be averaged across a sharp edge.
   */
  vtkSetMacro(FaceNormalsRequested, bool);
  vtkGetMacro(FaceNormalsRequested, bool);
  vtkBooleanMacro(FaceNormalsRequested, bool);
  ///@}

  enum GeometryEncodings
  {
    FLOAT = 0,
    HALF = 1,
    PACKED8 = 2,
    PACKED16 = 3
  };

  ///@{
  /**
   * How the geometry attachment stores depth, normal and id (default FLOAT; see above).
   */
  vtkSetClampMacro(GeometryEncoding, int, FLOAT, PACKED16);
  vtkGetMacro(GeometryEncoding, int);
  ///@}

  /**
   * The name of an encoding (float, half, packed8, packed16), "unknown" for another value, and
   * the encoding of a name, -1 for an unknown name. The one table of the encodings' names.
   */
  static const char* GetEncodingName(int encoding);
  static int GetEncodingFromName(const char* name);

  ///@{
  /**
   * Derive the G-buffer from the delegate's depth only (off by default; see above).
   */
  vtkSetMacro(DepthOnly, bool);
  vtkGetMacro(DepthOnly, bool);
  vtkBooleanMacro(DepthOnly, bool);
  ///@}

  ///@{
  /**
   * Start the colour attachment from the image under the renderer's viewport in the framebuffer
   * this pass is called to draw into, instead of clearing it (off by default; vtkNPRPass turns it
   * on for the styles of vtkNPREdgePass). Where the copy is exact (see GetHoldsWindowImage()),
   * the G-buffer's colour and depth are the frame as the opaque surfaces leave it, background
   * included, and an effect copies them back whole with CopySurfacesBack() instead of shading
   * every pixel that has no line. The geometry attachment is cleared as always.
   */
  vtkSetMacro(WindowImageRequested, bool);
  vtkGetMacro(WindowImageRequested, bool);
  vtkBooleanMacro(WindowImageRequested, bool);
  ///@}

  /**
   * Whether this frame's G-buffer holds the window's image under the surfaces:
   * WindowImageRequested, the geometry drawn this frame (not a reused frame), the framebuffer
   * single-sampled with 8-bit linear RGBA colour and a depth format a texture can take (16, 24,
   * 32-bit or float, no stencil), OpenGL's depth (not GetDepthRemapped()), and the renderer
   * clearing its depth (Erase on, PreserveDepthBuffer off), so that the depth under the surfaces is
   * the far plane's.
   */
  bool GetHoldsWindowImage() const;

  /**
   * Copies the G-buffer's colour and depth over the content rectangle (GetContentRectangle(), the
   * part the window's image was copied into) into the bound draw framebuffer at the viewport's
   * `origin`, bit for bit (glBlitFramebuffer): what a composite without lines writes there, the
   * background's pixels included. Returns false, having copied nothing, unless
   * GetHoldsWindowImage() and the bound draw framebuffer and origin are the ones the image was
   * taken from.
   */
  bool CopySurfacesBack(vtkOpenGLRenderWindow* window, const int origin[2]);

  ///@{
  /**
   * Keep the last G-buffer when nothing that affects it changed (on by default).
   */
  vtkSetMacro(ReuseUnchangedFrames, bool);
  vtkGetMacro(ReuseUnchangedFrames, bool);
  vtkBooleanMacro(ReuseUnchangedFrames, bool);
  ///@}

  ///@{
  /**
   * What the last frame's G-buffer holds. Valid after Render() until ReleaseGraphicsResources().
   * The textures are null when nothing was drawn (no props) or the channel was not written.
   */
  bool GetHasContent() const { return this->HasContent; }
  bool GetWritesNormals() const { return this->WritesNormals; }
  bool GetWritesObjectIds() const { return this->WritesObjectIds; }
  bool GetWritesFaceNormals() const { return this->WritesFaceNormals; }
  int GetWrittenEncoding() const { return this->WrittenEncoding; }
  vtkTextureObject* GetColorTexture() const
  {
    return this->HasContent ? this->ColorTexture : nullptr;
  }
  vtkTextureObject* GetGeometryTexture() const
  {
    return this->HasContent ? this->GeometryTexture : nullptr;
  }
  vtkTextureObject* GetDepthTexture() const
  {
    return this->HasContent ? this->DepthTexture : nullptr;
  }
  ///@}

  /**
   * The part of the G-buffer the opaque props can cover (their projected bounding boxes), as
   * x0, y0, x1, y1 in pixels, inclusive; effects skip the rest, which is background.
   */
  const int* GetContentRectangle() const { return this->ContentRectangle; }

  /**
   * The camera's projection was perspective in the last frame.
   */
  bool GetPerspective() const { return this->Perspective; }

  /**
   * The view-space ray through the centre of pixel (i, j) of the last frame's G-buffer is
   * origin + i perPixelX + j perPixelY: from the eye through the pixel for a perspective view
   * (not of unit length), the direction of projection for a parallel one.
   */
  void GetViewRay(float origin[3], float perPixelX[3], float perPixelY[3]) const;

  /**
   * The view-space step between the points of neighbouring pixels (i + 1, j) and (i, j + 1) on
   * the near plane: for a parallel view, the step between their points at any one view depth.
   */
  void GetViewPixelStep(float stepX[3], float stepY[3]) const;

  /**
   * The view depths that the packed encodings map onto 0..1 in the last frame (the camera's
   * clipping range).
   */
  const float* GetPackedDepthRange() const { return this->PackedDepthRange; }

  /**
   * The depth attachment holds log(z / near) / log(far / near) of the view depth z instead of
   * OpenGL's perspective depth. This happens for perspective cameras whose far/near clipping
   * ratio exceeds 1e4: the perspective depth of a 32-bit float attachment then no longer orders
   * nearby surfaces far from the near plane (at a ratio of 1e6 a bunny's back showed through its
   * front), while the logarithm keeps the same relative precision at every distance. The
   * effects convert it back when they write their depth sprite. GetDepthRemap() gives near and
   * log(far / near).
   */
  bool GetDepthRemapped() const { return this->DepthRemapped; }
  const float* GetDepthRemap() const { return this->DepthRemap; }

  /**
   * The last Render() was a hardware-selection (picking) render: no G-buffer was made.
   */
  bool GetLastRenderWasSelection() const { return this->LastRenderWasSelection; }

  /**
   * Number of times the geometry was drawn into the G-buffer (not counting reused frames).
   */
  vtkGetMacro(NumberOfGeometryDraws, int);

  /**
   * Whether the last G-buffer left out line or point primitives, which are to be drawn afterwards.
   */
  bool GetHasLinePrimitives() const { return this->HasContent && this->HasLinePrimitives; }

  /**
   * Changes whenever the G-buffer's content changes: effects that derive images from it (the
   * line image of vtkNPREdgePass) recompute them only then.
   */
  unsigned long GetContentVersion() const { return this->ContentVersion; }

  // vtkOpenGLRenderPass hook: the G-buffer outputs' uniforms.
  bool SetShaderParameters(vtkShaderProgram* program, vtkAbstractMapper* mapper, vtkProp* prop,
    vtkOpenGLVertexArrayObject* vao = nullptr) override;

protected:
  vtkNPRGBufferPass();
  ~vtkNPRGBufferPass() override;

  // The G-buffer outputs in the mappers' fragment shaders (vtkNPRGeometryPass).
  void FillShaderCode(std::string& vertexShader, std::string& geometryShader,
    std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop) override;

  void AllocateBuffers(vtkOpenGLRenderWindow* window, int width, int height, int components,
    int encoding, unsigned int depthFormat);
  // The depth attachment's format: the bound draw framebuffer's where a texture can take it and
  // the depth is OpenGL's (not remapped), else 32-bit float; and whether this frame can hold the
  // window's image (see GetHoldsWindowImage()).
  unsigned int ChooseDepthFormat(const vtkRenderState* state, bool& windowImage) const;
  // Replaces the cleared colour attachment's content rectangle by the window's image under it.
  bool CopyWindowImageIn(
    vtkOpenGLState* state, unsigned int framebuffer, unsigned int buffer, const int origin[2]);
  bool SceneUnchanged(const vtkRenderState* state, int width, int height);
  vtkMTimeType GetSettingsTime();
  void ComputeContentRectangle(const vtkRenderState* state, int width, int height);
  void RenderDepthOnly(const vtkRenderState* state, int width, int height);
  // The steps of Render() and RenderDepthOnly().
  static int CountOpaqueProps(const std::vector<vtkProp*>& parts);
  void UpdateOutputs(int opaqueProps);
  void SetOutputs(bool normals, bool ids, bool faceNormals, int encoding);
  // The camera's matrices, projection type and depth range; with mayRemapDepth, the log depth
  // for far/near ratios above 1e4 (not in depth-only mode, where the delegate writes the depth).
  void UpdateProjection(vtkRenderer* renderer, int width, int height, bool mayRemapDepth);
  void DrawGeometry(const vtkRenderState* state, int width, int height, bool windowImage);
  void DeriveGeometryFromDepth(vtkOpenGLRenderWindow* window, int width, int height);
  void CopyBack(const vtkRenderState* state, int width, int height);
  // The view-space points of pixels (0, 0), (1, 0) and (0, 1)'s centres on the near and far planes.
  void GetPixelCentrePoints(double nearPoints[3][3], double farPoints[3][3]) const;

  bool NormalsRequested = false;
  bool ObjectIdsRequested = false;
  bool FaceNormalsRequested = false;
  bool ReuseUnchangedFrames = true;
  bool DepthOnly = false;
  bool WindowImageRequested = false;
  int GeometryEncoding = FLOAT;

  vtkTextureObject* ColorTexture = nullptr;
  vtkTextureObject* GeometryTexture = nullptr;
  vtkTextureObject* DepthTexture = nullptr;
  vtkMatrix4x4* InverseProjection = nullptr;

  bool HasContent = false;
  bool WritesNormals = false;
  bool WritesObjectIds = false;
  bool WritesFaceNormals = false;
  int WrittenEncoding = FLOAT;
  float PackedDepthRange[2] = { 0, 1 };
  bool DepthRemapped = false;
  float DepthRemap[2] = { 0, 1 };
  bool Perspective = true;
  int NumberOfGeometryDraws = 0;
  bool HasLinePrimitives = false;
  unsigned long ContentVersion = 0;
  float Viewport[4] = { 0, 0, 1, 1 };
  int ContentRectangle[4] = { 0, 0, 0, 0 };

private:
  vtkNPRGBufferPass(const vtkNPRGBufferPass&) = delete;
  void operator=(const vtkNPRGBufferPass&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
