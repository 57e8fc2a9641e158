// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// Timing of frames (wall-clock durations and their medians), and progress lines for long steps.
#ifndef nprTiming_h
#define nprTiming_h

#include <chrono>
#include <functional>
#include <string>
#include <vector>

class vtkCamera;
class vtkRenderWindow;

using nprClock = std::chrono::steady_clock;

// Seconds since start.
double nprSecondsSince(nprClock::time_point start);

// The median (0 for no values).
double nprMedian(std::vector<double> values);

// Renders one frame and returns its time in milliseconds. The camera is marked modified first,
// so that nothing is reused, and the time runs until the GPU has finished (glFinish). prepare,
// when given, runs in the timed span, after the camera is marked (work that is part of every
// frame, such as extracting lines for the camera).
double nprTimeFrame(
  vtkRenderWindow* window, vtkCamera* camera, const std::function<void()>& prepare = nullptr);

// Progress lines of a command-line program on a large model: each step that took longer than a
// second (NPR_PROGRESS_SECONDS=S changes the threshold; 0 reports every step) is reported on
// stderr as "PROGRAM: STEP: 2.3 s". A quiet one (--quiet) reports nothing.
class nprProgress
{
public:
  nprProgress(std::string program, bool quiet);

  // Starts timing a step.
  void Start();

  // Ends the step started last, reporting it if it took longer than the threshold.
  void Done(const std::string& step);

private:
  std::string Program;
  bool Quiet;
  double Threshold = 1.0;
  nprClock::time_point Begin;
};

#endif
