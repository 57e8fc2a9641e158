// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkNPRShadingNormals
 * @brief   Point normals for shading a model, as npr-render prepares every model it draws.
 *
 * Passes a mesh whose point normals are all usable through unchanged. Otherwise, when the mesh
 * has no point normals or some are zero-length or not finite (a warning gives the count), it
 * computes them all:
 *
 * 1. points with exactly equal coordinates are merged (point for point as vtkCleanPolyData at
 *    tolerance 0 merges them, but found by a sort on every core), so that a triangle soup (every
 * triangle with its own points, as OBJ or PLY exporters write) is shaded smoothly, not facet by
 * facet; cells left with fewer than three distinct points are dropped;
 * 2. point normals split at FeatureAngle (default 30 degrees, as the edge pass's crease angle),
 *    so that sharp edges stay sharp, with no reordering of the polygons: value for value what
 *    VTK 9.1's vtkPolyDataNormals computes, but on every core (vtkPolyDataNormals itself for a
 *    mesh with triangle strips).
 *
 * Lines and vertices pass through. Measured effect on the benchmark's stress cases (edge pass,
 * bunny, 640x480): a triangle soup went from an F1 drift of -0.018 against the indexed mesh to
 * 0; every seventh normal zeroed, from -0.012 to 0. The two steps are marked in vtkTimerLog
 * ("vtkNPRShadingNormals: merge", "vtkNPRShadingNormals: normals") when its logging is on.
 *
 * @sa vtkNPRModelReader
 */
#ifndef vtkNPRShadingNormals_h
#define vtkNPRShadingNormals_h

#include "vtkNPRLinesModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

class VTKNPRLINES_EXPORT vtkNPRShadingNormals : public vtkPolyDataAlgorithm
{
public:
  static vtkNPRShadingNormals* New();
  vtkTypeMacro(vtkNPRShadingNormals, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Normals of faces meeting at more than this angle (degrees) are not averaged (default 30),
   * clamped to [0, 180].
   */
  vtkSetClampMacro(FeatureAngle, double, 0.0, 180.0);
  vtkGetMacro(FeatureAngle, double);
  ///@}

  /**
   * After an update: whether normals were computed (false: the input's were kept), and how many
   * of the input's point normals were unusable.
   */
  bool GetComputedNormals() const { return this->ComputedNormals; }
  vtkIdType GetNumberOfInvalidNormals() const { return this->NumberOfInvalidNormals; }

protected:
  vtkNPRShadingNormals() = default;
  ~vtkNPRShadingNormals() override = default;

  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  double FeatureAngle = 30.0;
  bool ComputedNormals = false;
  vtkIdType NumberOfInvalidNormals = 0;

private:
  vtkNPRShadingNormals(const vtkNPRShadingNormals&) = delete;
  void operator=(const vtkNPRShadingNormals&) = delete;
};

#endif
