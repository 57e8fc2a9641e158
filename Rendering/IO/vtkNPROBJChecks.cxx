// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNPROBJChecks.h"

#include "vtkNPRFormatParsing.h"
#include "vtkVersionMacros.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

namespace
{
using vtkNPRFormatParsing::Invalid;

// The file line by line: the counts of v, vt and vn so far, and the references of each element,
// checked at the end against the totals (positive) or when read against the counts so far
// (negative).
class OBJFile
{
public:
  explicit OBJFile(std::vector<long long>& nonFinite)
    : NonFinite(nonFinite)
  {
  }

  void CheckLine(std::string line, long long number)
  {
    const size_t hash = line.find('#');
    if (hash != std::string::npos)
    {
      line.erase(hash);
    }
    std::istringstream words(line);
    std::string keyword;
    if (!(words >> keyword))
    {
      return;
    }
    const std::string where = "malformed OBJ file: line " + std::to_string(number) + ": ";
    if (keyword == "v" || keyword == "vt" || keyword == "vn")
    {
      this->CheckVertex(words, keyword, where);
    }
    else if (keyword == "f" || keyword == "l" || keyword == "p")
    {
      this->CheckElement(words, keyword, where, number);
    }
  }

  void CheckForwardReferences() const
  {
    for (const Reference& reference : this->Forward)
    {
      if (reference.Value > this->Counts[reference.Kind])
      {
        throw Invalid("malformed OBJ file: line " + std::to_string(reference.Line) + ": uses " +
          Kinds[reference.Kind] + " " + std::to_string(reference.Value) + " of " +
          std::to_string(this->Counts[reference.Kind]));
      }
    }
  }

  long long Vertices() const { return this->Counts[0]; }

private:
  // v, vt or vn: enough numbers; a vertex with a NaN or infinite coordinate noted.
  void CheckVertex(std::istringstream& words, const std::string& keyword, const std::string& where)
  {
    const int kind = keyword == "v" ? 0 : keyword == "vt" ? 1 : 2;
    const int needed = kind == 1 ? 1 : 3;
    std::string token;
    int values = 0;
    bool finite = true;
    for (; words >> token; ++values)
    {
      double value;
      if (!vtkNPRFormatParsing::ParseNumber(token, value))
      {
        throw Invalid(where + "'" + token + "' is not a number");
      }
      finite = finite && (values >= 3 || std::isfinite(value));
    }
    if (values < needed)
    {
      throw Invalid(where + keyword + " has " + std::to_string(values) + " values, needs " +
        std::to_string(needed));
    }
    if (kind == 0 && !finite)
    {
      this->NonFinite.push_back(this->Counts[0]);
    }
    ++this->Counts[kind];
  }

  // f, l or p: every corner valid, and enough of them.
  void CheckElement(std::istringstream& words, const std::string& keyword, const std::string& where,
    long long number)
  {
    std::string token;
    int corners = 0;
    for (; words >> token; ++corners)
    {
      this->CheckCorner(token, keyword, where, number);
    }
    if (corners < (keyword == "f" ? 3 : keyword == "l" ? 2 : 1))
    {
      throw Invalid(where + keyword + " has " + std::to_string(corners) + " corners");
    }
  }

  // v, v/vt, v//vn or v/vt/vn
  void CheckCorner(const std::string& token, const std::string& keyword, const std::string& where,
    long long number)
  {
    size_t start = 0;
    for (int kind = 0; kind < 3 && start <= token.size(); ++kind)
    {
      const size_t slash = std::min(token.find('/', start), token.size());
      const std::string part = token.substr(start, slash - start);
      start = slash + 1;
      if (part.empty() && kind > 0)
      {
        continue;
      }
      long long index = 0;
      if (!vtkNPRFormatParsing::ParseInteger(part, index) || index == 0)
      {
        throw Invalid(where + "'" + token + "' is not a valid " + keyword + " corner");
      }
      this->CheckIndex(index, kind, keyword, where, number);
    }
  }

  void CheckIndex(long long index, int kind, const std::string& keyword, const std::string& where,
    long long number)
  {
#if VTK_VERSION_NUMBER >= VTK_VERSION_CHECK(9, 3, 0) &&                                            \
  VTK_VERSION_NUMBER < VTK_VERSION_CHECK(9, 3, 1)
    // VTK 9.3.0 resolves a relative texture coordinate against the normals' count and a
    // relative normal against the texture coordinates' (fixed in 9.3.1): it crashes or
    // reads the wrong one.
    if (index < 0 && kind > 0)
    {
      throw Invalid(where + keyword + " uses a relative " + Kinds[kind] + " index (" +
        std::to_string(index) + "), which VTK 9.3.0's OBJ reader misreads");
    }
#endif
    if (index < 0 && -index > this->Counts[kind])
    {
      throw Invalid(where + keyword + " uses " + Kinds[kind] + " " + std::to_string(index) +
        ", before the first (" + std::to_string(this->Counts[kind]) + " so far)");
    }
    if (index > 0)
    {
      this->Forward.push_back({ number, index, kind });
    }
  }

  struct Reference
  {
    long long Line, Value;
    int Kind;
  };
  static constexpr const char* Kinds[3] = { "vertex", "texture coordinate", "normal" };

  std::vector<long long>& NonFinite;
  long long Counts[3] = { 0, 0, 0 };
  std::vector<Reference> Forward;
};
}

std::string vtkNPROBJChecks::CheckOBJ(
  const std::string& fileName, std::vector<long long>& nonFinite, long long& vertices)
{
  std::ifstream in(fileName, std::ios::binary);
  OBJFile file(nonFinite);
  const std::string error = vtkNPRFormatParsing::WhatIsWrong(
    [&]
    {
      std::string line;
      for (long long number = 1; std::getline(in, line); ++number)
      {
        file.CheckLine(line, number);
      }
      file.CheckForwardReferences();
    });
  if (error.empty())
  {
    vertices = file.Vertices();
  }
  return error;
}
