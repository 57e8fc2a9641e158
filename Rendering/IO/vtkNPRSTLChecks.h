// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// The STL check (vtkNPRModelFormatChecks): vtkSTLReader takes any bytes as binary STL. Private to
// the module.
#ifndef vtkNPRSTLChecks_h
#define vtkNPRSTLChecks_h

#include <string>

namespace vtkNPRSTLChecks
{
// "" for ASCII STL (vtkSTLReader parses it strictly) or a binary STL whose size is what its
// triangle count says, else what is wrong with it.
std::string CheckSTL(const std::string& fileName);
}

#endif
