// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// Command-line parsing shared by npr-render and npr-benchmark: the walk over argv and the parsers
// of numbers, integers, sizes, colours and lists. Every problem is an nprUsageError whose text
// names the flag and what it expects; the programs print it as one line and exit with status 2.
#ifndef nprArguments_h
#define nprArguments_h

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

// A mistake on the command line (as opposed to a failure while running): exit status 2.
struct nprUsageError : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

// Walks argv from argv[1]: each argument in turn, and the value that follows a flag.
class nprArgumentReader
{
public:
  // help: the text of -h and --help.
  nprArgumentReader(int argc, char* argv[], const char* help);
  // Moves to the next argument; false when there is none left. At -h or --help, prints the help
  // on stdout and exits with status 0 (the arguments before it are parsed first, as they come).
  bool Next();
  // The argument Next() moved to.
  const std::string& Current() const { return this->Argument; }
  // Takes the argument after the current one as its value ("FLAG needs a value" when none).
  std::string Value();

private:
  int Count;
  char** Arguments;
  const char* Help;
  int Index = 0;
  std::string Argument;
};

// A finite number ("FLAG expects a number, got 'TEXT'").
double nprParseNumber(const std::string& flag, const std::string& text);
// A finite number in [low, high]: text that is no number fails as in nprParseNumber(), a number
// out of range with "FLAG expects a number in LOW..HIGH, got 'TEXT'".
double nprParseRange(const std::string& flag, const std::string& text, double low, double high);
// A number in [low, high], with "FLAG expects a number in LOW..HIGH, got 'TEXT'" for whatever is
// wrong (npr-benchmark's wording).
double nprParseNumberIn(const std::string& flag, const std::string& text, double low, double high);
// A whole number in [low, high].
int nprParseInteger(const std::string& flag, const std::string& text, int low, int high);
// WxH, each in [low, high]: "FLAG expects FORMAT, got 'TEXT'" without the x, else the problem
// of "FLAG width" or "FLAG height".
std::pair<int, int> nprParseSize(
  const std::string& flag, const std::string& text, int low, int high, const std::string& format);
// A colour name as PyVista reads it ("red", "Navy", "light_grey": CSS names of vtkNamedColors),
// r,g,b in 0..1 or #rrggbb.
void nprParseColor(const std::string& flag, const std::string& text, double rgb[3]);
// The comma-separated parts, as std::getline splits them: an empty part between two commas is
// kept (for the caller to refuse), a trailing comma adds none. dropEmpty leaves empty parts out.
std::vector<std::string> nprSplitList(const std::string& text, bool dropEmpty = false);

#endif
