// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// What the sources of the TestStrokePainter program share: the hand-made stroke set and the style
// they paint it with (TestStrokePainter.cxx).
#ifndef TestStrokePainter_h
#define TestStrokePainter_h

#include "nprTesting.h"

#include "vtkNPRStrokePainter.h"
#include "vtkPolyData.h" // for MakeStrokes

namespace nprStrokePainter
{
constexpr int Width = 200, Height = 100;

// The strokes in image coordinates (row 0 at the bottom): a silhouette along y = 20 from x = 20
// to 180; a hidden silhouette along y = 60 from x = 10 to 190; a square crease loop with corners
// (130, 30) and (170, 50) whose last point id is its first.
vtkSmartPointer<vtkPolyData> MakeStrokes();

// 2 px lines, blue creases, hidden lines 1 px wide in orange, dashed 6 on and 4 off.
vtkNPRStrokeStyle TestStyle();
}

#endif
