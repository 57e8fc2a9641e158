// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// The command-line options of the styles, shared by npr-render and npr-view: --style and the
// flags of the lines, inking, toon shading and sketches, parsed into an nprPassSettings, and
// their help text.
#ifndef nprPassOptions_h
#define nprPassOptions_h

#include <string>

class nprArgumentReader;
struct nprPassSettings;

// The help of these options, one section each (it ends with a newline).
extern const char* const nprPassOptionsHelp;

// Whether name is one of vtkNPRPass's style names ("shaded", "edges", ...).
bool nprIsStyleName(const std::string& name);

// vtkNPRPass's style names, comma separated, for messages.
std::string nprStyleNames();

// When the reader's current argument is one of these options, parses it (taking its value) into
// settings and returns true; returns false for any other argument. Throws nprUsageError for a
// bad value.
bool nprParsePassOption(nprArgumentReader& arguments, nprPassSettings& settings);

#endif
