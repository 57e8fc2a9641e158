// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nprProgram.h"

#include "nprArguments.h"
#include "nprOutputWindow.h"

#include "vtkLogger.h"
#include "vtkNew.h"

#include <cstdlib>
#include <cstring>
#include <exception>
#include <iostream>

int nprRunProgram(const char* program, const std::function<int(nprOutputWindow*)>& body)
{
  vtkNew<nprOutputWindow> messages;
  const char* verbose = std::getenv("NPR_VERBOSE");
  messages->Verbose = verbose && *verbose && std::strcmp(verbose, "0") != 0;
  vtkOutputWindow::SetInstance(messages);
  if (!messages->Verbose)
  {
    vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  }
  int status = 0;
  try
  {
    status = body(messages);
  }
  catch (const nprUsageError& error)
  {
    std::cerr << program << ": error: " << error.what() << "\n";
    status = 2;
  }
  catch (const std::exception& error)
  {
    std::cerr << program << ": error: " << error.what() << "\n";
    status = 1;
  }
  vtkOutputWindow::SetInstance(nullptr);
  return status;
}
