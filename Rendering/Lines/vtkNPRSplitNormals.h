// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// Point normals of a polygonal mesh, split at a feature angle, as VTK 9.1's vtkPolyDataNormals
// computes them (splitting on, consistency off, no flipping), value for value, but on every core.
//
// vtkPolyDataNormals walks the points one at a time and finds each polygon's neighbours through
// vtkPolyData::GetCellEdgeNeighbors (a third of npr-render's time on a 5M-triangle PLY after the
// merge). Here each point's fan is split on its own, in parallel: the faces around a point are
// grouped into regions of faces joined across edges whose normals differ by less than the feature
// angle, walking from each face in the same order as vtkPolyDataNormals, so that the points
// added for the second and later regions get the same numbers; each point normal is the sum of
// its faces' unit normals in face order, normalised, as there.
//
// One difference, on purpose: VTK 9.1 looks up the wrong face's normal when it splits a mesh that
// also holds vertices or lines (its face normals start after them); here a face's own is used.
// Private to the module: vtkNPRShadingNormals' second step.
#ifndef vtkNPRSplitNormals_h
#define vtkNPRSplitNormals_h

class vtkPolyData;

namespace vtkNPRSplitNormals
{
// Writes input with split point normals into output, or returns false (nothing written, the
// input untouched) for a mesh it does not handle, which vtkPolyDataNormals should take: one with
// triangle strips, or a point whose faces fall into more than 255 regions. The output takes over
// the input's points (grown in place) and polygons (rewritten in place), and the input is left
// without them: at 16M triangles copies would be 600 MB more at the peak.
bool Compute(vtkPolyData* input, double featureAngle, vtkPolyData* output);
}

#endif
