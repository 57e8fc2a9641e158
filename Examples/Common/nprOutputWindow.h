// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// VTK's output window for the command-line programs: VTK's messages are several lines each
// ("ERROR: In file, line N\nvtkClass (0x...): message"), where the programs report one line per
// problem. It keeps the last message, summarised, for the program's own error line, and prints
// messages only when asked: each on one line after a prefix (npr-benchmark), or in full with
// Verbose (NPR_VERBOSE=1).
#ifndef nprOutputWindow_h
#define nprOutputWindow_h

#include "vtkOutputWindow.h"

#include <string>

class nprOutputWindow : public vtkOutputWindow
{
public:
  static nprOutputWindow* New();
  vtkTypeMacro(nprOutputWindow, vtkOutputWindow);

  // Every kind of message goes the same way.
  void DisplayErrorText(const char* text) override { this->DisplayText(text); }
  void DisplayWarningText(const char* text) override { this->DisplayText(text); }
  void DisplayGenericWarningText(const char* text) override { this->DisplayText(text); }
  void DisplayText(const char* text) override;

  // The last line of a message, without trailing white space.
  static std::string LastLine(std::string text);
  // The last line without VTK's "vtkClass (0x...): " in front: what the message says.
  static std::string Summarise(std::string text);

  std::string Last;       // the last message, summarised
  bool Verbose = false;   // print every message in full (to stderr)
  std::string EchoPrefix; // when set: print every message to stderr after it (its last line,
                          // or in full with Verbose)

protected:
  nprOutputWindow() = default;
  ~nprOutputWindow() override = default;

private:
  nprOutputWindow(const nprOutputWindow&) = delete;
  void operator=(const nprOutputWindow&) = delete;
};

#endif
