// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nprBenchmarkProcess.h"

#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <iostream>
#include <poll.h>
#include <sstream>
#include <stdexcept>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace
{
// The environment without DISPLAY, plus DISPLAY=display when it is given.
std::vector<std::string> ChildEnvironment(const std::string& display)
{
  std::vector<std::string> variables;
  for (char** variable = environ; *variable; ++variable)
  {
    if (std::strncmp(*variable, "DISPLAY=", 8) != 0)
    {
      variables.emplace_back(*variable);
    }
  }
  if (!display.empty())
  {
    variables.push_back("DISPLAY=" + display);
  }
  return variables;
}

// argv-style pointers into strings (which must outlive them), null-terminated.
std::vector<char*> Pointers(const std::vector<std::string>& strings)
{
  std::vector<char*> pointers;
  for (const std::string& text : strings)
  {
    pointers.push_back(const_cast<char*>(text.c_str()));
  }
  pointers.push_back(nullptr);
  return pointers;
}

double StatusMB(const char* field)
{
  std::ifstream status("/proc/self/status");
  std::string line;
  const size_t length = std::strlen(field);
  while (std::getline(status, line))
  {
    if (line.compare(0, length, field) == 0)
    {
      return std::atof(line.c_str() + length) / 1024.0; // "VmRSS:   123 kB"
    }
  }
  return -1.0;
}

// Starts argv with stdout and stderr appended to log and the environment given; the child dies
// with this process.
pid_t Start(const std::vector<std::string>& argv, const std::string& log,
  const std::vector<std::string>& environment)
{
  // Everything the child needs is made before fork: after it, only exec.
  std::vector<char*> arguments = Pointers(argv), variables = Pointers(environment);
  const int output = open(log.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
  if (output < 0)
  {
    throw std::runtime_error(log + ": cannot write");
  }
  std::cout.flush();
  std::cerr.flush();
  const pid_t pid = fork();
  if (pid == 0)
  {
    prctl(PR_SET_PDEATHSIG, SIGKILL);
    dup2(output, 1);
    dup2(output, 2);
    execve(arguments[0], arguments.data(), variables.data());
    _exit(127);
  }
  close(output);
  if (pid < 0)
  {
    throw std::runtime_error("cannot start " + argv[0]);
  }
  return pid;
}

// npr-measure's result: "STATUS SECONDS PEAK_KB".
nprChildResult ReadMeasure(const std::string& path)
{
  std::ifstream file(path);
  int code = 0;
  double seconds = 0.0, peakKB = 0.0;
  nprChildResult result;
  if (!(file >> code >> seconds >> peakKB))
  {
    result.Problem = "npr-measure failed";
    return result;
  }
  result.ExitCode = code;
  result.Seconds = seconds;
  result.PeakMB = peakKB / 1024.0;
  result.Problem = code == 0 ? ""
    : code == 127            ? "could not start"
    : code == -1000          ? "timed out"
    : code < 0               ? "signal " + std::to_string(-code)
                             : "exit status " + std::to_string(code);
  return result;
}
}

nprChildResult nprRunChild(const std::vector<std::string>& argv, const std::string& log,
  const std::string& display, double timeoutSeconds)
{
  const std::string self = nprOwnExecutable();
  const std::string result = log + ".measure";
  std::vector<std::string> command = { self.substr(0, self.find_last_of('/') + 1) + "npr-measure",
    result, std::to_string(static_cast<long>(std::ceil(timeoutSeconds))) };
  command.insert(command.end(), argv.begin(), argv.end());
  std::remove(result.c_str());
  const pid_t pid = Start(command, log, ChildEnvironment(display));
  while (waitpid(pid, nullptr, 0) < 0 && errno == EINTR)
  {
  }
  const nprChildResult measured = ReadMeasure(result);
  std::remove(result.c_str());
  return measured;
}

std::string nprFindProgram(const std::string& name)
{
  if (name.find('/') != std::string::npos)
  {
    return access(name.c_str(), X_OK) == 0 ? name : std::string();
  }
  const char* path = std::getenv("PATH");
  std::istringstream folders(path ? path : "/usr/bin:/bin");
  std::string folder;
  while (std::getline(folders, folder, ':'))
  {
    const std::string candidate = (folder.empty() ? "." : folder) + "/" + name;
    if (access(candidate.c_str(), X_OK) == 0)
    {
      return candidate;
    }
  }
  return std::string();
}

std::string nprOwnExecutable()
{
  char path[4096];
  const ssize_t length = readlink("/proc/self/exe", path, sizeof(path) - 1);
  return length > 0 ? std::string(path, static_cast<size_t>(length)) : std::string();
}

double nprResidentMB()
{
  return StatusMB("VmRSS:");
}

double nprPeakResidentMB()
{
  return StatusMB("VmHWM:");
}

bool nprResetPeakMemory()
{
  std::ofstream refs("/proc/self/clear_refs");
  refs << "5";
  refs.flush();
  return static_cast<bool>(refs);
}

nprPrivateXServer::nprPrivateXServer(const std::string& log)
{
  const std::string xvfb = nprFindProgram("Xvfb");
  int ready[2];
  if (xvfb.empty() || pipe(ready) != 0)
  {
    return;
  }
  // Xvfb writes its display number to the pipe once it accepts clients (-displayfd).
  const std::vector<std::string> argv = { xvfb, "-displayfd", std::to_string(ready[1]), "-screen",
    "0", "1920x1080x24", "-nolisten", "tcp" };
  std::vector<char*> arguments = Pointers(argv);
  const int output = open(log.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
  this->Pid = fork();
  if (this->Pid == 0)
  {
    prctl(PR_SET_PDEATHSIG, SIGTERM);
    close(ready[0]);
    if (output >= 0)
    {
      dup2(output, 1);
      dup2(output, 2);
    }
    execv(arguments[0], arguments.data());
    _exit(127);
  }
  close(ready[1]);
  if (output >= 0)
  {
    close(output);
  }
  std::string number;
  struct pollfd wait = { ready[0], POLLIN, 0 };
  char c = 0;
  while (this->Pid > 0 && poll(&wait, 1, 10000) > 0 && read(ready[0], &c, 1) == 1 && c != '\n')
  {
    number += c;
  }
  close(ready[0]);
  if (!number.empty())
  {
    this->DisplayName = ":" + number;
  }
}

nprPrivateXServer::~nprPrivateXServer()
{
  if (this->Pid > 0)
  {
    kill(this->Pid, SIGTERM);
    waitpid(this->Pid, nullptr, 0);
  }
}
