// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// Whole programs measured as child processes (wall time and peak resident memory, through
// npr-measure), this process's own resident memory and its peak since a reset (/proc/self), and
// a private X server for programs that need one (npr-benchmark --scale; Linux only).
#ifndef nprBenchmarkProcess_h
#define nprBenchmarkProcess_h

#include <string>
#include <vector>

struct nprChildResult
{
  int ExitCode = -1;    // the program's exit status; -1 when it did not exit normally
  std::string Problem;  // empty when it exited 0: "exit status 1", "signal 9", "timed out"...
  double Seconds = 0.0; // wall time from fork to exit
  double PeakMB = 0.0;  // ru_maxrss of the child (MiB)
};

// Runs argv[0] (searched in PATH when it has no slash) with argv, its stdout and stderr
// appended to log, DISPLAY set to display (or removed when display is empty), and waits for it;
// it is killed after timeoutSeconds.
nprChildResult nprRunChild(const std::vector<std::string>& argv, const std::string& log,
  const std::string& display, double timeoutSeconds);

// The program's full path when it is found in PATH (or is a path to an executable), else "".
std::string nprFindProgram(const std::string& name);

// The path of this process's executable.
std::string nprOwnExecutable();

// This process's resident memory now, and its peak since the last nprResetPeakMemory() (or
// since it started), in MiB: VmRSS and VmHWM of /proc/self/status.
double nprResidentMB();
double nprPeakResidentMB();
// Sets the peak back to the current resident memory (writes 5 to /proc/self/clear_refs). False
// when the kernel refuses it: the peak then stays the process's.
bool nprResetPeakMemory();

// An X server of its own (Xvfb, 1920x1080x24, no TCP) for as long as it lives: for programs
// that cannot draw without one. Display() is ":N", or "" when Xvfb is missing or failed.
class nprPrivateXServer
{
public:
  explicit nprPrivateXServer(const std::string& log);
  ~nprPrivateXServer();
  nprPrivateXServer(const nprPrivateXServer&) = delete;
  nprPrivateXServer& operator=(const nprPrivateXServer&) = delete;
  const std::string& Display() const { return this->DisplayName; }

private:
  int Pid = -1;
  std::string DisplayName;
};

#endif
