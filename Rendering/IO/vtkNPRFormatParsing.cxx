// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNPRFormatParsing.h"

#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <utility>

std::string vtkNPRFormatParsing::ReadWholeFile(const std::string& fileName)
{
  std::ifstream in(fileName, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

bool vtkNPRFormatParsing::ParseNumber(const std::string& token, double& value)
{
  char* end = nullptr;
  value = std::strtod(token.c_str(), &end);
  return !token.empty() && end != token.c_str() && *end == '\0';
}

bool vtkNPRFormatParsing::ParseInteger(const std::string& token, long long& value)
{
  char* end = nullptr;
  errno = 0;
  value = std::strtoll(token.c_str(), &end, 10);
  return !token.empty() && end != token.c_str() && *end == '\0' && errno == 0;
}

long long vtkNPRFormatParsing::ToLongLong(double value, long long fallback)
{
  return std::isfinite(value) && value > -9.2e18 && value < 9.2e18 ? static_cast<long long>(value)
                                                                   : fallback;
}

long long vtkNPRFormatParsing::DecodeInteger(
  unsigned char* bytes, int size, bool isSigned, bool swap)
{
  if (swap)
  {
    for (int i = 0; i < size / 2; ++i)
    {
      std::swap(bytes[i], bytes[size - 1 - i]);
    }
  }
  uint64_t raw = 0;
  std::memcpy(&raw, bytes, static_cast<size_t>(size)); // little-endian host
  if (isSigned && size < 8 && (raw >> (8 * size - 1)) & 1)
  {
    raw |= ~uint64_t(0) << (8 * size);
  }
  return static_cast<long long>(raw);
}
