// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// npr-benchmark --contours: the edge pass's lines on smooth and scanned surfaces and on CAD
// parts, scored against two object-space truths per view: the mesh's own lines (silhouette
// edges, creases, borders) and the smooth surface's (the contour where the interpolated n.v is
// zero, vtkNPRFeatureLines::SmoothContours, with the same creases and borders). Two line sets:
// every line type ("lines", against creases at 30 degrees too) and silhouettes alone
// ("outline", against contours and borders alone), each at default settings and with the smooth
// silhouettes on ("-smooth").
// Writes OUT/contours.csv and OUT/contours.md.
#ifndef nprBenchmarkContours_h
#define nprBenchmarkContours_h

struct nprBenchmarkOptions;

// Returns the exit status: 1 when a figure is out of range.
int nprRunBenchmarkContours(const nprBenchmarkOptions& options);

#endif
