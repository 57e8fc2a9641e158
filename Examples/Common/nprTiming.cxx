// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nprTiming.h"

#include "vtkCamera.h"
#include "vtkRenderWindow.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <utility>

double nprSecondsSince(nprClock::time_point start)
{
  return std::chrono::duration<double>(nprClock::now() - start).count();
}

double nprMedian(std::vector<double> values)
{
  if (values.empty())
  {
    return 0.0;
  }
  std::sort(values.begin(), values.end());
  const size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

double nprTimeFrame(
  vtkRenderWindow* window, vtkCamera* camera, const std::function<void()>& prepare)
{
  const nprClock::time_point start = nprClock::now();
  camera->Modified();
  if (prepare)
  {
    prepare();
  }
  window->Render();
  window->WaitForCompletion();
  return std::chrono::duration<double, std::milli>(nprClock::now() - start).count();
}

nprProgress::nprProgress(std::string program, bool quiet)
  : Program(std::move(program))
  , Quiet(quiet)
  , Begin(nprClock::now())
{
  const char* threshold = std::getenv("NPR_PROGRESS_SECONDS");
  char* end = nullptr;
  const double seconds = threshold ? std::strtod(threshold, &end) : 0.0;
  if (threshold && end != threshold && *end == '\0' && seconds >= 0.0)
  {
    this->Threshold = seconds;
  }
}

void nprProgress::Start()
{
  this->Begin = nprClock::now();
}

void nprProgress::Done(const std::string& step)
{
  const double seconds = nprSecondsSince(this->Begin);
  if (!this->Quiet && seconds >= this->Threshold)
  {
    char time[32];
    std::snprintf(time, sizeof time, "%.1f s", seconds);
    std::cerr << this->Program << ": " << step << ": " << time << std::endl;
  }
}
