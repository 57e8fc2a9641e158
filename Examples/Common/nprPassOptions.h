// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// The command-line options of the styles, shared by npr-render and npr-view: --style and the
// flags of the lines, inking, toon shading and sketches, parsed into an nprPassSettings, and
// their help text.
#ifndef nprPassOptions_h
#define nprPassOptions_h

#include <set>
#include <string>
#include <vector>

class nprArgumentReader;
struct nprPassSettings;

// The help of these options, one section each (it ends with a newline).
extern const char* const nprPassOptionsHelp;

// Whether name is one of vtkNPRPass's style names ("shaded", "edges", ...).
bool nprIsStyleName(const std::string& name);

// The style name text stands for, in any case and with ParaView's spellings ("Edges",
// "Toon + Edges"); throws nprUsageError naming the valid styles (for flag) when there is none.
std::string nprStyleFromText(const std::string& flag, const std::string& text);

// vtkNPRPass's style names, comma separated, for messages.
std::string nprStyleNames();

// When the reader's current argument is one of these options, parses it (taking its value) into
// settings and returns true; returns false for any other argument. Throws nprUsageError for a
// bad value.
bool nprParsePassOption(nprArgumentReader& arguments, nprPassSettings& settings);

// Checks the given flags against the styles that will draw (styles: vtkNPRPass style names;
// npr-view passes them all, as its keys switch styles). Throws nprUsageError for a combination
// that cannot work (nothing left to draw, a line type the encoding cannot find); returns one
// warning for each flag that none of the styles uses, or that another flag turns off.
// alsoUsed: flags used outside the styles (npr-render's --reference-mask takes --lines).
std::vector<std::string> nprCheckPassOptions(const nprPassSettings& settings,
  const std::vector<std::string>& styles, const std::set<std::string>& alsoUsed = {});

#endif
