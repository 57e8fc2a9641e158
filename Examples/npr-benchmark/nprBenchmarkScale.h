// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// npr-benchmark --scale: the cost of a model against its size. For each size of a bunny made by
// Loop subdivision (kept in a folder and reused), the wall time and peak memory of whole
// programs, each in a child process (npr-render in five styles and to SVG, F3D where installed,
// a plain VTK program), and of each step inside one (read, normals, feature lines, first and
// later frames per style, the drawing's strokes: --scale-steps); nanoseconds per triangle and
// their growth from the smallest size to the largest. Writes OUT/scale.csv, OUT/scale.md and the
// plots OUT/scale_programs.png and OUT/scale_steps.png.
#ifndef nprBenchmarkScale_h
#define nprBenchmarkScale_h

#include <string>
#include <vector>

struct nprBenchmarkOptions;

// The sizes --scale-sizes takes, smallest first: 62k, 250k, 1m, 4m, 16m (the bunny decimated to
// 62,500 triangles, then 0 to 4 levels of Loop subdivision).
const std::vector<std::string>& nprScaleSizeNames();

// Returns the exit status: 1 when a program of ours failed or a time is not positive.
int nprRunBenchmarkScale(const nprBenchmarkOptions& options);

// --scale-steps FILE (a child of --scale): the steps of one model in this process, each with
// its time and its peak resident memory, into OUT/steps.csv.
int nprRunScaleSteps(const nprBenchmarkOptions& options);

// One step of --scale-steps. Seconds < 0: not measured in this build (a timer-log event that is
// missing); PeakMB < 0: measured within the step before it (a part of it), no peak of its own.
struct nprScaleStep
{
  std::string Name;
  double Seconds = -1.0;
  double PeakMB = -1.0;  // the process's resident memory at its peak during the step
  double AddedMB = -1.0; // that peak less the resident memory when the step began
};

// steps.csv read back (throws std::runtime_error when it is missing or malformed).
std::vector<nprScaleStep> nprReadScaleSteps(const std::string& path);

#endif
