// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// The main of every test program of named cases: "PROGRAM CASE [DATA_DIR]" runs the case its
// sources registered with NPR_TEST_CASE. A program with a main of its own does not link this one
// (the linker takes it from the nprTesting archive only where main is missing).
#include "nprTesting.h"

int main(int argc, char* argv[])
{
  return nprRunTestCase(argc, argv, nprTestCases());
}
