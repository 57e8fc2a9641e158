// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkNPRToonPass
 * @brief   Toon shading: the delegate's surfaces lit in a few flat bands instead of smoothly.
 *
 * Wraps the pass that draws the geometry (normally a vtkOpaquePass) and, through the
 * vtkOpenGLRenderPass shader hooks, replaces the diffuse lighting of every lit
 * vtkOpenGLPolyDataMapper (and subclasses) with a lookup:
 *
 *   colour = ambient + diffuse colour x Table(I) [+ specular colour where the highlight is on]
 *
 * where I is the light intensity reaching the surface, summed over the renderer's switched-on
 * lights: intensity x luminance(light colour) x attenuation x max(0, n.l), with VTK's
 * attenuation and spot cones for positional lights. The bands therefore quantise how much
 * light arrives, not its colour; several lights add up before quantisation (the sum is clamped
 * to 1), so a key light and a fill light give one set of bands, not two overlapping sets.
 * The diffuse colour is the actor's colour or its scalar colours (the bands modulate them);
 * textures are applied after, as VTK does. A specular highlight, when the actor has one, is
 * one more hard band: on where the Phong term exceeds one half.
 *
 * The table maps I in [0, 1] to an RGB factor: by default NumberOfBands equal bands, band k of
 * N (k = 0..N-1, I in [k/N, (k+1)/N)) giving (k+1)/N, so the darkest band is 1/N of the colour,
 * not black. A user table (any vtkScalarsToColors: vtkLookupTable, vtkColorTransferFunction)
 * replaces it: its range is mapped onto I in [0, 1] and sampled at 256 intensities.
 *
 * Per pixel (default) the lighting is evaluated for each fragment's interpolated normal.
 * PerVertex evaluates it at the vertices for both faces and interpolates the intensity before the
 * lookup, as the classic comic-style renderers did with a 1D texture: band borders are then
 * straight within each triangle. It needs point normals; without them (or with a geometry shader:
 * wide lines, points as spheres) the lighting falls back to per pixel.
 *
 * Unlit actors (LightingOff), PBR actors and mappers that are not vtkOpenGLPolyDataMapper draw as
 * usual. Drawn alone (vtkNPRPass style TOON) the pass adds nothing but the shader changes: no
 * extra buffer, no extra pass. vtkNPRPass also puts it under the G-buffer (TOON_EDGES, and with
 * one band under vtkNPRSketchPass for the flat colours it sketches).
 *
 * @sa vtkNPRPass vtkNPRGBufferPass vtkNPRSketchPass
 */
#ifndef vtkNPRToonPass_h
#define vtkNPRToonPass_h

#include "vtkNPRGeometryPass.h"
#include "vtkNPRPassesModule.h" // for export macro

#include <memory> // for std::unique_ptr

class vtkScalarsToColors;

class VTKNPRPASSES_EXPORT vtkNPRToonPass : public vtkNPRGeometryPass
{
public:
  static vtkNPRToonPass* New();
  vtkTypeMacro(vtkNPRToonPass, vtkNPRGeometryPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  void Render(const vtkRenderState* state) override;
  void ReleaseGraphicsResources(vtkWindow* window) override;

  ///@{
  /**
   * Number of equal bands of the default table (default 3), clamped to [1, 64]. One band draws
   * the flat, unlit colour.
   */
  vtkSetClampMacro(NumberOfBands, int, 1, 64);
  vtkGetMacro(NumberOfBands, int);
  ///@}

  ///@{
  /**
   * A table that replaces the bands (null by default): its range is mapped onto the light
   * intensity 0..1, its colours multiply the diffuse colour.
   */
  virtual void SetTable(vtkScalarsToColors* table);
  vtkGetObjectMacro(Table, vtkScalarsToColors);
  ///@}

  ///@{
  /**
   * Evaluate the lighting at the vertices and interpolate it (off by default: per pixel).
   */
  vtkSetMacro(PerVertex, bool);
  vtkGetMacro(PerVertex, bool);
  vtkBooleanMacro(PerVertex, bool);
  ///@}

  ///@{
  /**
   * Draw the actors' specular highlights as one hard band (on by default; actors without
   * specular show none either way).
   */
  vtkSetMacro(Specular, bool);
  vtkGetMacro(Specular, bool);
  vtkBooleanMacro(Specular, bool);
  ///@}

  /**
   * The RGB factor the table gives for a light intensity in [0, 1] (as the shader looks it up).
   */
  void GetShade(double intensity, double rgb[3]);

  /**
   * Includes the table's modification time.
   */
  vtkMTimeType GetMTime() override;

  /**
   * Maximum number of lights taken into account; further lights are ignored with a warning.
   */
  static constexpr int MaximumNumberOfLights = 8;

  // vtkOpenGLRenderPass hook: the bands' and lights' uniforms.
  bool SetShaderParameters(vtkShaderProgram* program, vtkAbstractMapper* mapper, vtkProp* prop,
    vtkOpenGLVertexArrayObject* vao = nullptr) override;

protected:
  vtkNPRToonPass();
  ~vtkNPRToonPass() override;

  // The mappers' lighting replaced by the bands (vtkNPRGeometryPass).
  void FillShaderCode(std::string& vertexShader, std::string& geometryShader,
    std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop) override;

  void UpdateTable(vtkWindow* window);
  void UpdateLights(const vtkRenderState* state);

  vtkScalarsToColors* Table = nullptr;
  int NumberOfBands = 3;
  bool PerVertex = false;
  bool Specular = true;

private:
  vtkNPRToonPass(const vtkNPRToonPass&) = delete;
  void operator=(const vtkNPRToonPass&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
