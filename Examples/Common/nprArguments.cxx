// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nprArguments.h"

#include "vtkNamedColors.h"
#include "vtkNew.h"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <sstream>

nprArgumentReader::nprArgumentReader(int argc, char* argv[], const char* help)
  : Count(argc)
  , Arguments(argv)
  , Help(help)
{
}

bool nprArgumentReader::Next()
{
  if (this->Index + 1 >= this->Count)
  {
    return false;
  }
  this->Argument = this->Arguments[++this->Index];
  if (this->Argument == "-h" || this->Argument == "--help")
  {
    std::cout << this->Help;
    std::exit(0);
  }
  if (this->Argument == "--version")
  {
    // The program's name as called (without its folder) and vtkNPR's version (NPR_VERSION).
    const std::string program = this->Arguments[0];
    std::cout << program.substr(program.find_last_of('/') + 1) << " " << NPR_VERSION << "\n";
    std::exit(0);
  }
  return true;
}

std::string nprArgumentReader::Value()
{
  if (this->Index + 1 >= this->Count)
  {
    throw nprUsageError(this->Argument + " needs a value");
  }
  return this->Arguments[++this->Index];
}

namespace
{
// A colour name read as PyVista reads it (enable_npr's colours): any case, spaces, '_' and '-'
// ignored, grey spelt either way, looked up among vtkNamedColors' CSS names ("Indian_Red" is
// CSS's indianred, not VTK's indian_red; "grey" is CSS's 128, not VTK's 192).
bool LookUpColorName(const std::string& text, double rgb[3])
{
  std::string name;
  for (char c : text)
  {
    if (c != ' ' && c != '_' && c != '-')
    {
      name += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    }
  }
  if (name.empty() || name.find_first_not_of("abcdefghijklmnopqrstuvwxyz") != std::string::npos)
  {
    return false;
  }
  // VTK spells some CSS greys one way only (lightgrey, darkgray): the other spelling is tried too.
  std::string otherSpelling = name;
  const size_t grey = name.find("grey"), gray = name.find("gray");
  if (grey != std::string::npos || gray != std::string::npos)
  {
    otherSpelling[(grey != std::string::npos ? grey : gray) + 2] =
      grey != std::string::npos ? 'a' : 'e';
  }
  vtkNew<vtkNamedColors> names;
  for (const std::string& candidate : { name == "grey" ? otherSpelling : name, otherSpelling })
  {
    if (names->ColorExists(candidate))
    {
      names->GetColorRGB(candidate, rgb);
      return true;
    }
  }
  return false;
}
}

double nprParseNumber(const std::string& flag, const std::string& text)
{
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || *end || !std::isfinite(value))
  {
    throw nprUsageError(flag + " expects a number, got '" + text + "'");
  }
  return value;
}

double nprParseRange(const std::string& flag, const std::string& text, double low, double high)
{
  nprParseNumber(flag, text);
  return nprParseNumberIn(flag, text, low, high);
}

double nprParseNumberIn(const std::string& flag, const std::string& text, double low, double high)
{
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || *end || !(value >= low && value <= high)) // NaN is never in range
  {
    std::ostringstream range;
    range << low << ".." << high;
    throw nprUsageError(flag + " expects a number in " + range.str() + ", got '" + text + "'");
  }
  return value;
}

int nprParseInteger(const std::string& flag, const std::string& text, int low, int high)
{
  char* end = nullptr;
  const long value = std::strtol(text.c_str(), &end, 10);
  if (text.empty() || *end || value < low || value > high)
  {
    throw nprUsageError(flag + " expects an integer in " + std::to_string(low) + ".." +
      std::to_string(high) + ", got '" + text + "'");
  }
  return static_cast<int>(value);
}

std::pair<int, int> nprParseSize(
  const std::string& flag, const std::string& text, int low, int high, const std::string& format)
{
  const size_t x = text.find('x');
  if (x == std::string::npos)
  {
    throw nprUsageError(flag + " expects " + format + ", got '" + text + "'");
  }
  // Both in turn, so that the width's problem is told first.
  const int width = nprParseInteger(flag + " width", text.substr(0, x), low, high);
  return { width, nprParseInteger(flag + " height", text.substr(x + 1), low, high) };
}

void nprParseColor(const std::string& flag, const std::string& text, double rgb[3])
{
  if (text.size() == 7 && text[0] == '#' &&
    text.find_first_not_of("0123456789abcdefABCDEF", 1) == std::string::npos)
  {
    for (int i = 0; i < 3; ++i)
    {
      rgb[i] = std::strtol(text.substr(1 + 2 * i, 2).c_str(), nullptr, 16) / 255.0;
    }
    return;
  }
  if (LookUpColorName(text, rgb))
  {
    return;
  }
  const std::string expected = flag + " expects a colour name (such as red, navy, wheat), r,g,b " +
    "in 0..1 or #rrggbb, got '" + text + "'";
  const std::vector<std::string> parts = nprSplitList(text);
  if (parts.size() != 3)
  {
    throw nprUsageError(expected);
  }
  for (size_t i = 0; i < 3; ++i)
  {
    char* end = nullptr;
    rgb[i] = std::strtod(parts[i].c_str(), &end);
    if (parts[i].empty() || *end || !(rgb[i] >= 0.0 && rgb[i] <= 1.0)) // NaN fails too
    {
      throw nprUsageError(expected);
    }
  }
}

std::vector<std::string> nprSplitList(const std::string& text, bool dropEmpty)
{
  std::vector<std::string> parts;
  std::stringstream stream(text);
  std::string part;
  while (std::getline(stream, part, ','))
  {
    if (!part.empty() || !dropEmpty)
    {
      parts.push_back(part);
    }
  }
  return parts;
}
