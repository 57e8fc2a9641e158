// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// npr-benchmark --stress: the edge pass on scaled, translated, near/far-stretched and degenerate
// versions of each scene, against the unit case (OUT/stress.csv and OUT/stress.md).
#ifndef nprBenchmarkStress_h
#define nprBenchmarkStress_h

struct nprBenchmarkOptions;

// Returns the exit status: 1 when --max-drift is given and a case exceeds it.
int nprRunBenchmarkStress(const nprBenchmarkOptions& options);

#endif
