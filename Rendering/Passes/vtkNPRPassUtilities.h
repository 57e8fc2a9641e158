// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// Helpers shared by the module's passes. Private to the module.
#ifndef vtkNPRPassUtilities_h
#define vtkNPRPassUtilities_h

#include "vtkOpenGLState.h" // for the scoped state savers

#include <string> // for std::string

class vtkAbstractMapper;
class vtkActor;
class vtkObject;
class vtkOpenGLFramebufferObject;
class vtkOpenGLRenderWindow;
class vtkOpenGLState;
class vtkProp;
class vtkProperty;
class vtkRenderState;
class vtkRenderbuffer;
class vtkRenderer;
class vtkTextureObject;
class vtkWindow;

// A new texture object of the window with these filters (vtkTextureObject::Nearest or Linear)
// and wrap modes on every axis (ClampToEdge, Repeat, ...); the caller allocates and deletes it.
vtkTextureObject* vtkNPRNewTexture(vtkOpenGLRenderWindow* window, int filter, int wrap);

// The text in lower case (ASCII): file extensions, the names of views and papers.
std::string vtkNPRLowerCase(std::string text);

// How many pixels one pixel at 72 DPI is in this renderer's window: DPI / 72 x tile scale.
double vtkNPRWindowScale(vtkRenderer* renderer);

// A line width given in pixels at 72 DPI, in this renderer's pixels, kept within [0.5, 32].
double vtkNPREffectiveLineWidth(vtkRenderer* renderer, double width);

// VTK 9.1 does not call the hardware selector once a renderer has a pass: a pass that draws the
// props runs it itself during a selection render. Returns false (and does nothing) otherwise;
// true with the number of props the selector rendered.
bool vtkNPRRenderSelection(const vtkRenderState* state, int& renderedProps);

// Where the renderer's viewport starts in the framebuffer being drawn (0, 0 in a pass's own
// framebuffer object).
void vtkNPRViewportOrigin(const vtkRenderState* state, int origin[2]);

// The size of the image a pass draws for the renderer: the framebuffer object it was called with,
// or the renderer's part of the window (of this tile, in a tiled render).
void vtkNPRTargetSize(const vtkRenderState* state, int& width, int& height);

// Where the part of the renderer's viewport being drawn lies in a tiled render (a
// vtkWindowToImageFilter's Scale, ParaView's screenshots larger than the view): its pixel offset
// within the whole viewport, and which of its sides (left, bottom, right, top) meet another
// tile instead of the viewport's edge (1) or not (0). Untiled: 0, 0 and no such side.
void vtkNPRTilePlacement(vtkRenderer* renderer, int offset[2], int tileSides[4]);

// Puts `tag` (one of ours) on the line after VTK's shader template tag `vtkTag` in `source`.
// The passes hook into VTK's poly-data shaders this way, and those templates change between VTK
// releases: a VTK poly-data shader (one with //VTK::Color::Impl) that lacks `vtkTag` is reported
// as an error by `pass` (once per pass class and tag) instead of drawing silently without the
// effect. Returns whether the tag was inserted.
bool vtkNPRInsertAfterShaderTag(
  std::string& source, const char* vtkTag, const char* tag, vtkObject* pass, const char* stage);

// The prop a user added that `prop` is drawn for: the top-level prop a vtkNPROpaquePass is
// drawing (a follower, an LOD actor, an axes actor), or `prop` itself outside one.
vtkProp* vtkNPRUserProp(vtkProp* prop);

// Whether the top-level prop `prop` is an annotation rather than a surface: followers (3D text
// labels), VTK's axes actors, image slices and any other prop that is neither a vtkActor, an
// assembly nor a vtkLODProp3D. Annotations keep their own look; actors, LOD actors, LOD props,
// glyphs and assemblies get styled.
bool vtkNPRIsAnnotation(vtkProp* prop);

// Whether the actor draws point splats (a vtkPointGaussianMapper, ParaView's Point Gaussian): a
// point cloud, often translucent through an opacity array, whose splats VTK 9.1 draws as
// triangles with alpha; they are not a surface.
bool vtkNPRDrawsSplats(vtkActor* actor);

// Whether VTK draws the mesh edges of a surface with this property (EdgeVisibilityOn on the
// Surface representation, ParaView's "Surface With Edges").
bool vtkNPRDrawsMeshEdges(vtkProperty* property);

// Whether the vtkOpenGLPolyDataMapper `mapper`, drawing for `prop`, keeps its own look, as VTK
// draws it: a line or point primitive (lines, vertices, or polygons in the wireframe or points
// representation), splats (vtkNPRDrawsSplats), or anything drawn for an annotation
// (vtkNPRIsAnnotation of vtkNPRUserProp).
// Valid from the mapper's shader hooks (its bound primitive).
bool vtkNPRKeepsOwnLook(vtkAbstractMapper* mapper, vtkProp* prop);

// The state a full-screen depth-sprite composite changes, restored when this goes out of scope.
// Apply() sets what the composites need: the viewport (callers such as ParaView's image-processing
// slot call a pass with whatever viewport was last set), depth test LEQUAL with depth writes
// (gl_FragDepth), alpha blending of colour over what is there, scissor test on, to the viewport
// (a caller limits it further where it draws less).
class vtkNPRCompositeState
{
public:
  explicit vtkNPRCompositeState(vtkOpenGLState* state);
  void Apply(const int origin[2], int width, int height);

private:
  vtkOpenGLState* State;
  vtkOpenGLState::ScopedglViewport Viewport;
  vtkOpenGLState::ScopedglEnableDisable DepthTest;
  vtkOpenGLState::ScopedglEnableDisable Blend;
  vtkOpenGLState::ScopedglEnableDisable ScissorTest;
  vtkOpenGLState::ScopedglScissor Scissor;
  vtkOpenGLState::ScopedglDepthFunc DepthFunc;
  vtkOpenGLState::ScopedglDepthMask DepthMask;
  vtkOpenGLState::ScopedglBlendFuncSeparate BlendFunc;
};

// The internal formats of the bound draw framebuffer's colour and depth that glBlitFramebuffer
// copies bit for bit to and from buffers of the same formats: GL_RGBA8 or GL_RGB8 (linear, not
// sRGB) and a depth (and stencil) format it names; false for a multisampled framebuffer or any
// other format.
bool vtkNPRDrawFramebufferFormats(
  vtkOpenGLState* state, unsigned int& colorFormat, unsigned int& depthFormat);

// Copies `rect` (x0, y0, x1, y1, inclusive) of the bound read framebuffer's colour and, with
// `depth`, its depth to the bound draw framebuffer at `to` (its lower left corner), with
// glBlitFramebuffer and the scissor test off. Returns false on an OpenGL error (formats that do
// not match), having copied nothing.
bool vtkNPRBlitRectangle(vtkOpenGLState* state, const int rect[4], const int to[2], bool depth);

// A rectangle of the framebuffer being drawn into (colour and depth), kept after a composite so
// that a frame in which nothing changed gets it back by one copy instead of compositing again.
// Both copies are glBlitFramebuffer calls between buffers of identical formats, so the pixels and
// depths come back bit for bit; Capture() keeps nothing (returns false) where that cannot hold: a
// multisampled framebuffer, colour other than 8-bit normalised, or a depth format it does not know.
class vtkNPRKeptImage
{
public:
  vtkNPRKeptImage() = default;
  ~vtkNPRKeptImage();
  vtkNPRKeptImage(const vtkNPRKeptImage&) = delete;
  vtkNPRKeptImage& operator=(const vtkNPRKeptImage&) = delete;

  // Copies `rect` (x0, y0, x1, y1, inclusive) of the current draw framebuffer.
  bool Capture(vtkOpenGLRenderWindow* window, const int rect[4]);
  // Copies the kept rectangle back to where it was taken from, in the current draw framebuffer
  // (which must be the one it was taken from: the caller keys its reuse on that).
  bool Restore(vtkOpenGLRenderWindow* window);
  bool IsValid() const { return this->Valid; }
  void Invalidate() { this->Valid = false; }
  void ReleaseGraphicsResources(vtkWindow* window);

private:
  vtkOpenGLFramebufferObject* Framebuffer = nullptr;
  vtkRenderbuffer* Color = nullptr;
  vtkRenderbuffer* Depth = nullptr;
  unsigned int ColorFormat = 0;
  unsigned int DepthFormat = 0;
  int Size[2] = { 0, 0 };
  int Rect[4] = { 0, 0, -1, -1 };
  bool Valid = false;
};

#endif
