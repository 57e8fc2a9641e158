// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// What the format checks (vtkNPRModelFormatChecks and the checker of each format) share: the
// error a check's steps throw, and the parsing of numbers and binary integers. Private to the
// module.
#ifndef vtkNPRFormatParsing_h
#define vtkNPRFormatParsing_h

#include <stdexcept>
#include <string>

namespace vtkNPRFormatParsing
{
// What is wrong with a file: thrown by a check's steps, caught where the check returns it.
struct Invalid : std::runtime_error
{
  explicit Invalid(const std::string& message)
    : std::runtime_error(message)
    , Message(message)
  {
  }

  // The whole message, with any NUL byte the file put into it (what() stops at the first).
  std::string Message;
};

// "" when none of a check's steps throws Invalid, else what the first found wrong.
template <typename Steps>
std::string WhatIsWrong(Steps&& steps)
{
  try
  {
    steps();
  }
  catch (const Invalid& error)
  {
    return error.Message;
  }
  return "";
}

// The bytes of a file, as a string ("" when it cannot be read).
std::string ReadWholeFile(const std::string& fileName);

// A whole token as a number (strtod reads "nan" and "inf"); false when it is not one.
bool ParseNumber(const std::string& token, double& value);

// A whole token as a base-10 integer; false when it is not one or out of long long's range.
bool ParseInteger(const std::string& token, long long& value);

// A number read as a double, as a long long; fallback when it is not finite or out of long long's
// range, where the conversion is undefined behaviour (UBSan: "1e+20 is outside the range of
// representable values of type 'long long int'", a fuzzed PLY face index).
long long ToLongLong(double value, long long fallback);

// One binary value of the given size (1 to 8 bytes) as an integer, its bytes swapped first when
// swap is set (the host is little-endian).
long long DecodeInteger(unsigned char* bytes, int size, bool isSigned, bool swap);
}

#endif
