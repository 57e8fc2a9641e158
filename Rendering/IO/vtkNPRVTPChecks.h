// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// The VTP check (vtkNPRModelFormatChecks): vtkXMLPolyDataReader allocates what a file's counts and
// array headers say before it reads: a mutated size asks for terabytes. Private to the module.
#ifndef vtkNPRVTPChecks_h
#define vtkNPRVTPChecks_h

#include <string>

namespace vtkNPRVTPChecks
{
// VTK XML polydata: the piece's counts and every appended raw array's header (byte count, or
// the blocks of a compressed array) within what the file can hold, and every compressed block
// decompressing to its size. "" for a well-formed file, else what is wrong with it.
std::string CheckVTP(const std::string& fileName);
}

#endif
