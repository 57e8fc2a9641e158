// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNPRSTLChecks.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <fstream>

std::string vtkNPRSTLChecks::CheckSTL(const std::string& fileName)
{
  std::ifstream in(fileName, std::ios::binary | std::ios::ate);
  const long long size = static_cast<long long>(in.tellg());
  in.seekg(0);
  std::string start(static_cast<size_t>(std::min<long long>(size, 512)), '\0');
  in.read(&start[0], static_cast<std::streamsize>(start.size()));
  const size_t first = start.find_first_not_of(" \t\r\n");
  if (first != std::string::npos && start.compare(first, 5, "solid") == 0 &&
    start.find('\0') == std::string::npos)
  {
    return ""; // ASCII STL: vtkSTLReader parses it strictly
  }
  if (size < 84)
  {
    return "malformed STL file: too short for a binary STL (" + std::to_string(size) + " bytes)";
  }
  uint32_t triangles = 0;
  std::memcpy(&triangles, start.data() + 80, 4);
  const long long expected = 84 + 50LL * triangles;
  if (size != expected)
  {
    return "malformed binary STL file: its header promises " + std::to_string(triangles) +
      " triangles (" + std::to_string(expected) + " bytes) but the file has " +
      std::to_string(size) + " bytes";
  }
  return "";
}
