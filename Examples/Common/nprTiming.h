// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// Timing of frames: wall-clock durations and their medians.
#ifndef nprTiming_h
#define nprTiming_h

#include <chrono>
#include <functional>
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

#endif
