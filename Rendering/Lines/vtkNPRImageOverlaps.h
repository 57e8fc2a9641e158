// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// Which triangles of an image overlap another's interior there: only those need a depth order
// (vtkNPRFaceOrder); the others can be painted first, in any order. On a closed mesh seen from
// outside, its front faces overlap only where it folds in front of itself, so most of them need
// neither the partition nor its splits. Private to NPR::Lines.
#ifndef vtkNPRImageOverlaps_h
#define vtkNPRImageOverlaps_h

#include <vector> // for the triangles and the marks

// A triangle's corners in image coordinates, or Unprojected when a corner is not in front of the
// near plane (its image is unbounded: then every triangle is marked).
struct vtkNPRImageTriangle
{
  double X[3], Y[3];
  bool Unprojected = false;
};

// 1 for each triangle whose interior overlaps another's (a shared edge or corner is no overlap),
// or that cannot be told cheaply (in a grid cell crowded beyond a bound; all of them when one is
// unprojected or not finite, or the grid would grow too large): a triangle marked 0 overlaps no
// other. A uniform grid over the triangles' box, each pair tested
// once, in the first cell the two share, with the separating axes of their edges.
std::vector<char> vtkNPRMarkImageOverlaps(const std::vector<vtkNPRImageTriangle>& triangles);

#endif
// VTK-HeaderTest-Exclude: vtkNPRImageOverlaps.h
