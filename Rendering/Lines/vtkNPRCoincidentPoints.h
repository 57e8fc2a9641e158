// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// Points of exactly equal coordinates merged, as vtkCleanPolyData merges them at tolerance 0, but
// found by a sort on every core.
//
// The output is the one vtkCleanPolyData gives (point merging on, absolute tolerance 0, no cell
// conversions), point for point and cell for cell: points numbered in the order the cells first
// use them, each with the coordinates and point data of its first use (as VTK 9.1 keeps them);
// consecutive repeated points removed from lines, polygons and strips; cells left with too few
// points dropped, except one that had no more to begin with; cell data following its cells.
// What differs is the cost: vtkCleanPolyData inserts the points one by one into a vtkMergePoints
// hash (46 % of npr-render's time on a 13M-triangle PLY); here the points, keyed by a hash of
// their coordinates, are sorted on every core, and one pass over the cells renumbers them.
#ifndef vtkNPRCoincidentPoints_h
#define vtkNPRCoincidentPoints_h

#include <string>

class vtkPolyData;

namespace vtkNPRCoincidentPoints
{
// Writes input with its coincident points merged into output. Returns "", or why the input
// cannot be merged (a cell naming a point that does not exist).
std::string Merge(vtkPolyData* input, vtkPolyData* output);
}

#endif
