// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// npr-benchmark --coherence: how the drawn lines of each style follow the surfaces along camera
// paths (a pan, an orbit, a dolly), and what surface noise costs the sketch against screen noise
// (OUT/coherence.csv, OUT/coherence_cost.csv and OUT/coherence.md).
#ifndef nprBenchmarkCoherence_h
#define nprBenchmarkCoherence_h

struct nprBenchmarkOptions;

// Returns the exit status: 1 when a figure is out of range.
int nprRunBenchmarkCoherence(const nprBenchmarkOptions& options);

#endif
