// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNPRLegacyVTKChecks.h"

#include "vtkNPRFormatParsing.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <vector>

namespace
{
using vtkNPRFormatParsing::Invalid;

std::string Malformed(const std::string& what)
{
  return "malformed legacy VTK file: " + what;
}

[[noreturn]] void Fail(const std::string& what)
{
  throw Invalid(Malformed(what));
}

std::string Upper(std::string text)
{
  std::transform(text.begin(), text.end(), text.begin(),
    [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  return text;
}

// Bytes of a legacy data type, 0 when unknown; isFloat for float and double.
int LegacyTypeSize(const std::string& type, bool& isFloat)
{
  const std::string t = Upper(type);
  isFloat = t == "FLOAT" || t == "DOUBLE";
  if (t == "CHAR" || t == "UNSIGNED_CHAR")
  {
    return 1;
  }
  if (t == "SHORT" || t == "UNSIGNED_SHORT")
  {
    return 2;
  }
  if (t == "INT" || t == "UNSIGNED_INT" || t == "FLOAT")
  {
    return 4;
  }
  if (t == "DOUBLE" || t == "LONG" || t == "UNSIGNED_LONG" || t == "VTKTYPEINT64" ||
    t == "VTKTYPEUINT64" || t == "VTKIDTYPE")
  {
    return 8;
  }
  return 0;
}

// Walks a legacy VTK file: keywords as tokens, data as ASCII tokens or big-endian binary values.
class LegacyWalker
{
public:
  explicit LegacyWalker(std::string text)
    : Text(std::move(text))
  {
  }

  std::string Line()
  {
    const size_t end = std::min(this->Text.find('\n', this->Position), this->Text.size());
    std::string line = this->Text.substr(this->Position, end - this->Position);
    this->Position = std::min(end + 1, this->Text.size());
    if (!line.empty() && line.back() == '\r')
    {
      line.pop_back();
    }
    return line;
  }

  bool Token(std::string& token)
  {
    while (this->Position < this->Text.size() &&
      std::isspace(static_cast<unsigned char>(this->Text[this->Position])))
    {
      ++this->Position;
    }
    const size_t start = this->Position;
    while (this->Position < this->Text.size() &&
      !std::isspace(static_cast<unsigned char>(this->Text[this->Position])))
    {
      ++this->Position;
    }
    token = this->Text.substr(start, this->Position - start);
    return !token.empty();
  }

  size_t Size() const { return this->Text.size(); }

  void SetBinary(bool binary) { this->Binary = binary; }
  bool IsBinary() const { return this->Binary; }
  // Where `what` first occurs in the whole file (npos: nowhere).
  size_t Find(const std::string& what) const { return this->Text.find(what); }

  // Binary data starts after the keyword line.
  void StartData()
  {
    if (this->Binary)
    {
      this->Line();
    }
  }

  // The next value: an ASCII number, or a binary one of the given size (integer or float).
  bool Value(int size, bool isFloat, double& value)
  {
    if (!this->Binary)
    {
      std::string token;
      return this->Token(token) && vtkNPRFormatParsing::ParseNumber(token, value);
    }
    if (this->Text.size() - this->Position < static_cast<size_t>(size))
    {
      return false;
    }
    unsigned char bytes[8];
    for (int i = 0; i < size; ++i) // big-endian in the file
    {
      bytes[size - 1 - i] = static_cast<unsigned char>(this->Text[this->Position + i]);
    }
    this->Position += static_cast<size_t>(size);
    if (isFloat)
    {
      float f;
      double d;
      size == 4 ? (std::memcpy(&f, bytes, 4), value = f) : (std::memcpy(&d, bytes, 8), value = d);
    }
    else
    {
      value = static_cast<double>(vtkNPRFormatParsing::DecodeInteger(bytes, size, true, false));
    }
    return true;
  }

private:
  std::string Text;
  size_t Position = 0;
  bool Binary = false;
};

// "M.m" as vtkDataReader reads it: the major version (5 and later: OFFSETS and CONNECTIVITY).
double ReadVersion(const std::string& versionText)
{
  const size_t digits = versionText.find_first_not_of(" ");
  const size_t dot = versionText.find('.', digits);
  if (digits == std::string::npos || dot == std::string::npos || dot == digits ||
    versionText.find_first_not_of("0123456789", digits) != dot ||
    versionText.find_first_not_of("0123456789", dot + 1) != std::string::npos ||
    dot + 1 == versionText.size() || dot - digits > 2 ||
    std::atoi(versionText.c_str() + digits) < 1 || std::atoi(versionText.c_str() + digits) > 5)
  {
    Fail("unknown file version '" + versionText + "'");
  }
  return std::atoi(versionText.c_str() + digits);
}

bool IsCellSection(const std::string& keyword)
{
  return keyword == "VERTICES" || keyword == "LINES" || keyword == "POLYGONS" ||
    keyword == "TRIANGLE_STRIPS" || keyword == "CELLS";
}

// The file, section by section: POINTS, then the cell sections and CELL_TYPES, up to the point
// and cell data.
class LegacyVTKFile
{
public:
  explicit LegacyVTKFile(std::string text)
    : Walker(std::move(text))
  {
  }

  void Check()
  {
    this->CheckHeader();
    if (this->Walker.IsBinary())
    {
      this->CheckSpaceRuns();
    }
    if (!this->HasPointsAndCells())
    {
      return; // image and rectilinear data: no points or cells to check
    }
    std::string keyword;
    while (this->Walker.Token(keyword) && this->CheckSection(Upper(keyword)))
    {
    }
    if (!this->IndexError.empty())
    {
      throw Invalid(this->IndexError); // CELLS without CELL_TYPES
    }
  }

private:
  // VTK 9.1's legacy reader hangs (a loop without end) on 256 or more spaces in a row anywhere
  // in a binary file, between sections or inside the data (issue 36, the fuzzer).
  void CheckSpaceRuns() const
  {
    const std::string run(256, ' ');
    const size_t at = this->Walker.Find(run);
    if (at != std::string::npos)
    {
      Fail("256 or more spaces in a row at byte " + std::to_string(at) +
        " of a binary file (VTK's legacy reader hangs on them)");
    }
  }

  // The version, the title and ASCII or BINARY.
  void CheckHeader()
  {
    const std::string header = this->Walker.Line();
    if (header.compare(0, 22, "# vtk DataFile Version") != 0)
    {
      Fail("it does not start with '# vtk DataFile Version'");
    }
    this->Version = ReadVersion(header.substr(22));
    this->Walker.Line(); // the title
    const std::string format = Upper(this->Walker.Line());
    const bool binary = format.compare(0, 6, "BINARY") == 0;
    if (!binary && format.compare(0, 5, "ASCII") != 0)
    {
      Fail("the third line is neither ASCII nor BINARY");
    }
    this->Walker.SetBinary(binary);
  }

  // The DATASET line: whether the dataset has points and cells.
  bool HasPointsAndCells()
  {
    std::string keyword, type;
    if (!this->Walker.Token(keyword) || Upper(keyword) != "DATASET" || !this->Walker.Token(type))
    {
      Fail("no DATASET line");
    }
    type = Upper(type);
    return type == "POLYDATA" || type == "UNSTRUCTURED_GRID" || type == "STRUCTURED_GRID";
  }

  // One section after its keyword; false at the point and cell data, where the check ends.
  bool CheckSection(const std::string& keyword)
  {
    std::string skipped;
    if (keyword == "METADATA")
    {
      this->SkipMetadata();
    }
    else if (keyword == "DIMENSIONS")
    {
      this->Walker.Token(skipped), this->Walker.Token(skipped), this->Walker.Token(skipped);
    }
    else if (keyword == "POINTS")
    {
      this->CheckPoints();
    }
    else if (keyword == "CELL_TYPES")
    {
      this->CheckCellTypes();
    }
    else if (IsCellSection(keyword))
    {
      this->CheckCells(keyword);
    }
    else if (keyword == "POINT_DATA" || keyword == "CELL_DATA" || keyword == "FIELD")
    {
      return false; // point and cell data, fields: VTK's reader checks what it needs of them
    }
    else
    {
      FailUnknownKeyword(keyword);
    }
    return true;
  }

  // Information keys of the array before: up to a blank line.
  void SkipMetadata()
  {
    this->Walker.Line();
    for (std::string line = this->Walker.Line();
         !line.empty() && line.find_first_not_of(" \t") != std::string::npos;
         line = this->Walker.Line())
    {
    }
  }

  // vtkDataReader takes any word that starts with a keyword for it ("POINTS<garbage>"), and
  // VTK 9.1 then crashed reading on.
  [[noreturn]] static void FailUnknownKeyword(const std::string& keyword)
  {
    std::string shown;
    for (char c : keyword.substr(0, 40))
    {
      shown += std::isprint(static_cast<unsigned char>(c)) ? c : '?';
    }
    Fail("unknown keyword '" + shown + "'");
  }

  void CheckPoints()
  {
    std::string a, b;
    long long count = 0;
    bool isFloat;
    int size = 0;
    if (!this->Walker.Token(a) || !vtkNPRFormatParsing::ParseInteger(a, count) || count < 0 ||
      !this->Walker.Token(b) || !(size = LegacyTypeSize(b, isFloat)))
    {
      Fail("bad POINTS line");
    }
    if (count > static_cast<long long>(this->Walker.Size()))
    {
      Fail("POINTS declares " + std::to_string(count) + " points, more than the file holds");
    }
    this->Walker.StartData();
    for (long long i = 0; i < 3 * count; ++i)
    {
      double value;
      if (!this->Walker.Value(size, isFloat, value))
      {
        Fail("POINTS declares " + std::to_string(count) + " points but holds " +
          std::to_string(i / 3));
      }
    }
    this->Points = count;
  }

  void CheckCellTypes()
  {
    std::string a;
    long long count = 0;
    if (!this->Walker.Token(a) || !vtkNPRFormatParsing::ParseInteger(a, count) ||
      count != this->Cells || this->Cells < 0)
    {
      Fail("CELL_TYPES does not count the " + std::to_string(this->Cells) + " cells");
    }
    this->Walker.StartData();
    bool polyhedron = false;
    for (long long i = 0; i < count; ++i)
    {
      double value;
      if (!this->Walker.Value(4, false, value))
      {
        Fail(
          "CELL_TYPES declares " + std::to_string(count) + " types but holds " + std::to_string(i));
      }
      polyhedron = polyhedron || value == 42;
    }
    if (!this->IndexError.empty() && !polyhedron)
    {
      throw Invalid(this->IndexError);
    }
    this->IndexError.clear(); // a polyhedron's face stream holds counts among its point indices
  }

  // VERTICES, LINES, POLYGONS, TRIANGLE_STRIPS or CELLS: "KEY cells values", then the cells.
  void CheckCells(const std::string& keyword)
  {
    if (this->Points < 0)
    {
      Fail(keyword + " before POINTS");
    }
    std::string a, b;
    long long cells = 0, values = 0;
    if (!this->Walker.Token(a) || !vtkNPRFormatParsing::ParseInteger(a, cells) || cells < 0 ||
      !this->Walker.Token(b) || !vtkNPRFormatParsing::ParseInteger(b, values) || values < 0)
    {
      Fail("bad " + keyword + " line");
    }
    if (cells > static_cast<long long>(this->Walker.Size()) ||
      values > static_cast<long long>(this->Walker.Size()))
    {
      Fail(keyword + " declares more values than the file holds");
    }
    std::vector<long long> offsets, connectivity;
    if (this->Version < 5.0)
    {
      this->ReadCountedCells(keyword, cells, values, offsets, connectivity);
    }
    else
    {
      this->ReadOffsetsAndConnectivity(keyword, cells, values, offsets, connectivity);
    }
    this->CheckPointIndices(keyword, connectivity);
    if (keyword == "CELLS")
    {
      this->Cells = static_cast<long long>(offsets.empty() ? 0 : offsets.size() - 1);
    }
  }

  // Before 5.0: every cell as its point count followed by its point indices.
  void ReadCountedCells(const std::string& keyword, long long cells, long long count,
    std::vector<long long>& offsets, std::vector<long long>& connectivity)
  {
    this->Walker.StartData();
    std::vector<long long> values;
    for (long long i = 0; i < count; ++i)
    {
      double value;
      if (!this->Walker.Value(4, false, value) || value != std::floor(value))
      {
        Fail(keyword + " declares " + std::to_string(count) + " values but holds " +
          std::to_string(i));
      }
      values.push_back(vtkNPRFormatParsing::ToLongLong(value, -1));
    }
    offsets.push_back(0);
    for (size_t i = 0; i < values.size(); i += static_cast<size_t>(values[i]) + 1)
    {
      if (values[i] < 0 || static_cast<long long>(values.size() - i - 1) < values[i])
      {
        Fail(keyword + " cell " + std::to_string(offsets.size() - 1) + " runs past the section");
      }
      connectivity.insert(connectivity.end(), values.begin() + static_cast<long>(i) + 1,
        values.begin() + static_cast<long>(i + 1 + static_cast<size_t>(values[i])));
      offsets.push_back(static_cast<long long>(connectivity.size()));
    }
    if (static_cast<long long>(offsets.size()) - 1 != cells)
    {
      Fail(keyword + " declares " + std::to_string(cells) + " cells but holds " +
        std::to_string(offsets.size() - 1));
    }
  }

  // 5.x: "KEY offsets connectivity", then OFFSETS and CONNECTIVITY arrays.
  void ReadOffsetsAndConnectivity(const std::string& keyword, long long offsetCount,
    long long connectivityCount, std::vector<long long>& offsets,
    std::vector<long long>& connectivity)
  {
    this->ReadIndexArray(keyword, "OFFSETS", offsetCount, offsets);
    this->ReadIndexArray(keyword, "CONNECTIVITY", connectivityCount, connectivity);
    for (size_t i = 0; i < offsets.size(); ++i)
    {
      if ((i == 0 && offsets[i] != 0) || (i > 0 && offsets[i] < offsets[i - 1]) ||
        offsets[i] > connectivityCount ||
        (i + 1 == offsets.size() && offsets[i] != connectivityCount))
      {
        Fail(
          keyword + " OFFSETS are not increasing from 0 to " + std::to_string(connectivityCount));
      }
    }
  }

  // "NAME type" and its count integers.
  void ReadIndexArray(
    const std::string& keyword, const char* name, long long count, std::vector<long long>& array)
  {
    std::string a, b;
    bool isFloat;
    int size = 0;
    if (!this->Walker.Token(a) || Upper(a) != name || !this->Walker.Token(b) ||
      !(size = LegacyTypeSize(b, isFloat)) || isFloat)
    {
      Fail(keyword + " has no " + name + " array");
    }
    this->Walker.StartData();
    for (long long i = 0; i < count; ++i)
    {
      double value;
      if (!this->Walker.Value(size, false, value))
      {
        Fail(keyword + " " + name + " declares " + std::to_string(count) + " values but holds " +
          std::to_string(i));
      }
      array.push_back(vtkNPRFormatParsing::ToLongLong(value, -1));
    }
  }

  // Every point index names a point; CELLS keeps its first error for CELL_TYPES to judge.
  void CheckPointIndices(const std::string& keyword, const std::vector<long long>& connectivity)
  {
    for (long long index : connectivity)
    {
      if (index < 0 || index >= this->Points)
      {
        const std::string message = Malformed(
          keyword + " uses point " + std::to_string(index) + " of " + std::to_string(this->Points));
        if (keyword != "CELLS")
        {
          throw Invalid(message);
        }
        this->IndexError = this->IndexError.empty() ? message : this->IndexError;
      }
    }
  }

  LegacyWalker Walker;
  double Version = 0;
  long long Points = -1;
  long long Cells = -1;   // of CELLS, for CELL_TYPES
  std::string IndexError; // CELLS: reported unless a polyhedron explains it
};
}

std::string vtkNPRLegacyVTKChecks::CheckLegacyVTK(const std::string& fileName)
{
  return vtkNPRFormatParsing::WhatIsWrong(
    [&] { LegacyVTKFile(vtkNPRFormatParsing::ReadWholeFile(fileName)).Check(); });
}
