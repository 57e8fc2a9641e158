// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// npr-benchmark --speed: the frame time of every style side by side with VTK's own passes
// (vtkSobelGradientMagnitudePass, vtkOutlineGlowPass, vtkSSAOPass, vtkEDLShading) and
// vtkPolyDataSilhouette, interleaved frame by frame in one window while the camera turns 1 degree
// per frame; and vtkNPRFeatureLines per camera change. Writes OUT/speed.csv and OUT/speed.md.
#ifndef nprBenchmarkSpeed_h
#define nprBenchmarkSpeed_h

struct nprBenchmarkOptions;

// Returns the exit status: 1 when a time is not positive.
int nprRunBenchmarkSpeed(const nprBenchmarkOptions& options);

#endif
