// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// npr-measure: runs a program and writes its wall time and peak resident memory (ru_maxrss from
// wait4) to a file; npr-benchmark --scale runs every measured program through it. A process
// starts with the peak of the one it was forked from (Linux keeps the old memory's high-water
// mark across exec), so the program is forked from this small process, not from npr-benchmark
// (hundreds of MB by then).
// usage: npr-measure RESULT TIMEOUT_S PROGRAM [ARGUMENTS...]
// RESULT gets "STATUS SECONDS PEAK_KB": STATUS is the exit status, -N after signal N, -1000 when
// the program ran past TIMEOUT_S and was killed.
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

namespace
{
volatile sig_atomic_t TimedOut = 0;
pid_t Child = 0;

void OnAlarm(int)
{
  TimedOut = 1;
  kill(Child, SIGKILL);
}
}

int main(int argc, char* argv[])
{
  if (argc < 4 || std::atoi(argv[2]) <= 0)
  {
    std::fprintf(stderr, "usage: npr-measure RESULT TIMEOUT_S PROGRAM [ARGUMENTS...]\n");
    return 2;
  }
  const auto start = std::chrono::steady_clock::now();
  Child = fork();
  if (Child == 0)
  {
    prctl(PR_SET_PDEATHSIG, SIGKILL); // no orphan when this process is killed
    execvp(argv[3], argv + 3);
    _exit(127);
  }
  if (Child < 0)
  {
    return 1;
  }
  std::signal(SIGALRM, OnAlarm);
  alarm(static_cast<unsigned>(std::atoi(argv[2])));
  int status = 0;
  struct rusage usage = {};
  while (wait4(Child, &status, 0, &usage) < 0 && errno == EINTR)
  {
  }
  alarm(0);
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const int code = TimedOut ? -1000 : WIFEXITED(status) ? WEXITSTATUS(status) : -WTERMSIG(status);
  std::FILE* result = std::fopen(argv[1], "w");
  if (!result)
  {
    return 1;
  }
  std::fprintf(result, "%d %.6f %ld\n", code, seconds, usage.ru_maxrss);
  return std::fclose(result) == 0 ? 0 : 1;
}
