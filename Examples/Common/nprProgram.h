// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// The frame of a command-line program: VTK's messages through nprOutputWindow, and every error
// as one line "PROGRAM: error: ..." on stderr with exit status 2 (nprUsageError) or 1.
#ifndef nprProgram_h
#define nprProgram_h

#include <functional>

class nprOutputWindow;

// Installs an nprOutputWindow (Verbose from NPR_VERBOSE: set and not 0; VTK's logger silenced
// otherwise, as it prints warnings too), runs body and returns its exit status, or the status of
// the error it threw.
int nprRunProgram(const char* program, const std::function<int(nprOutputWindow*)>& body);

#endif
