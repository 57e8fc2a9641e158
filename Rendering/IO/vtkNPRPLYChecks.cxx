// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNPRPLYChecks.h"

#include "vtkNPRChunkedInput.h"
#include "vtkNPRFormatParsing.h"

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>

namespace
{
using vtkNPRFormatParsing::Invalid;
using vtkNPRPLYChecks::PLYElement;
using vtkNPRPLYChecks::PLYProperty;

// Size in bytes of a PLY scalar type, 0 for an unknown type.
int TypeSize(const std::string& type, bool& isSigned, bool& isFloat)
{
  static const std::map<std::string, int> sizes = { { "char", 1 }, { "int8", 1 }, { "uchar", 1 },
    { "uint8", 1 }, { "short", 2 }, { "int16", 2 }, { "ushort", 2 }, { "uint16", 2 }, { "int", 4 },
    { "int32", 4 }, { "uint", 4 }, { "uint32", 4 }, { "float", 4 }, { "float32", 4 },
    { "double", 8 }, { "float64", 8 } };
  const auto it = sizes.find(type);
  isFloat = type.compare(0, 5, "float") == 0 || type == "double";
  isSigned = !isFloat && type[0] != 'u';
  return it == sizes.end() ? 0 : it->second;
}

// "element NAME COUNT", the keyword read.
PLYElement ReadElementLine(std::istringstream& words, const std::string& line)
{
  PLYElement element;
  std::string count;
  if (!(words >> element.Name >> count) ||
    count.find_first_not_of("0123456789") != std::string::npos ||
    !vtkNPRFormatParsing::ParseInteger(count, element.Count))
  {
    throw Invalid("malformed PLY header: bad element line '" + line + "'");
  }
  return element;
}

// "property TYPE NAME" or "property list COUNTTYPE ITEMTYPE NAME", the keyword read.
PLYProperty ReadPropertyLine(std::istringstream& words, const std::string& line)
{
  PLYProperty property;
  std::string type;
  words >> type;
  if (type == "list")
  {
    std::string countType, itemType;
    bool countSigned, countFloat;
    words >> countType >> itemType;
    property.CountSize = TypeSize(countType, countSigned, countFloat);
    property.Size = TypeSize(itemType, property.Signed, property.Float);
    if (!property.CountSize || countFloat || !property.Size)
    {
      throw Invalid("malformed PLY header: bad list property '" + line + "'");
    }
  }
  else
  {
    property.Size = TypeSize(type, property.Signed, property.Float);
    if (!property.Size)
    {
      throw Invalid("malformed PLY header: unknown property type '" + type + "'");
    }
  }
  words >> property.Name;
  return property;
}

// One header line into format or elements; true at end_header.
bool ReadHeaderLine(std::string line, std::string& format, std::vector<PLYElement>& elements)
{
  if (!line.empty() && line.back() == '\r')
  {
    line.pop_back();
  }
  std::istringstream words(line);
  std::string keyword;
  words >> keyword;
  if (keyword == "format")
  {
    words >> format;
  }
  else if (keyword == "element")
  {
    elements.push_back(ReadElementLine(words, line));
  }
  else if (keyword == "property")
  {
    if (elements.empty())
    {
      throw Invalid("malformed PLY header: a property before any element");
    }
    elements.back().Properties.push_back(ReadPropertyLine(words, line));
  }
  else if (keyword != "end_header" && keyword != "comment" && keyword != "obj_info" &&
    !keyword.empty())
  {
    throw Invalid("malformed PLY header: unknown line '" + line + "'");
  }
  return keyword == "end_header";
}

bool IsIndexList(const PLYElement& element, const PLYProperty& property)
{
  return element.Name == "face" && property.CountSize &&
    (property.Name == "vertex_indices" || property.Name == "vertex_index");
}

// vtkPLY frees memory it never set for an element without properties (heap corruption), and
// finds an element by its name: a second one of a name would be checked but not read.
void CheckElementList(const std::vector<PLYElement>& elements)
{
  for (auto element = elements.begin(); element != elements.end(); ++element)
  {
    if (element->Properties.empty())
    {
      throw Invalid("malformed PLY header: element '" + element->Name + "' has no properties");
    }
    if (std::any_of(elements.begin(), element,
          [&](const PLYElement& earlier) { return earlier.Name == element->Name; }))
    {
      throw Invalid("malformed PLY header: element '" + element->Name + "' given twice");
    }
  }
}

// Without a vertex element of x, y and z, vtkPLYReader uses the file it has just closed.
void CheckVertexElement(const std::vector<PLYElement>& elements)
{
  const auto vertex = std::find_if(elements.begin(), elements.end(),
    [](const PLYElement& element) { return element.Name == "vertex"; });
  for (const char* axis : { "x", "y", "z" })
  {
    if (vertex == elements.end() ||
      std::none_of(vertex->Properties.begin(), vertex->Properties.end(),
        [&](const PLYProperty& property) { return property.Name == axis && !property.CountSize; }))
    {
      throw Invalid(std::string("malformed PLY header: no vertex element with a property ") + axis);
    }
  }
}

void CheckListProperties(const std::vector<PLYElement>& elements)
{
  for (const PLYElement& element : elements)
  {
    // vtkPLYReader frees the face's index list whether the file gave one or not.
    if (element.Name == "face" &&
      std::none_of(element.Properties.begin(), element.Properties.end(),
        [&](const PLYProperty& property) { return IsIndexList(element, property); }))
    {
      throw Invalid("malformed PLY header: the face element has no vertex_indices list");
    }
    for (const PLYProperty& property : element.Properties)
    {
      // Lists other than the face's indices are read into memory the reader never set up.
      if (property.CountSize && !IsIndexList(element, property) &&
        !(element.Name == "face" && property.Name == "texcoord"))
      {
        throw Invalid("malformed PLY header: unsupported list property '" + property.Name +
          "' of " + element.Name);
      }
    }
  }
}

// The count of the (last) vertex element.
long long CountVertices(const std::vector<PLYElement>& elements)
{
  long long vertexCount = 0;
  for (const PLYElement& element : elements)
  {
    if (element.Name == "vertex")
    {
      vertexCount = element.Count;
    }
  }
  return vertexCount;
}

void CheckFaceIndex(long long face, long long index, long long vertexCount)
{
  if (index < 0 || index >= vertexCount)
  {
    throw Invalid("malformed PLY file: face " + std::to_string(face) + " uses vertex " +
      std::to_string(index) + " of " + std::to_string(vertexCount));
  }
}

[[noreturn]] void ThrowTruncated(const PLYElement& element, long long row)
{
  throw Invalid("truncated or malformed PLY file in " + element.Name + " " + std::to_string(row));
}

[[noreturn]] void ThrowTruncated(
  const PLYElement& element, unsigned long long row, const PLYProperty& property)
{
  throw Invalid("truncated or malformed PLY file in " + element.Name + " " + std::to_string(row) +
    " (property " + property.Name + ")");
}

// ---- The binary body -------------------------------------------------------------------------

// One binary integer from a chunked input; false when the input ends first.
bool ReadInteger(vtkNPRChunkedInput& input, int size, bool isSigned, bool swap, long long& value)
{
  const unsigned char* bytes = input.Take(static_cast<size_t>(size));
  if (!bytes)
  {
    return false;
  }
  unsigned char copy[8];
  std::memcpy(copy, bytes, static_cast<size_t>(size));
  value = vtkNPRFormatParsing::DecodeInteger(copy, size, isSigned, swap);
  return true;
}

// A binary body that ends inside row i of a fixed-size element, offset bytes into it.
[[noreturn]] void ThrowTruncatedRow(const PLYElement& element, uint64_t row, uint64_t offset)
{
  const PLYProperty* property = &element.Properties.front();
  for (const PLYProperty& candidate : element.Properties)
  {
    property = &candidate;
    if (offset < static_cast<uint64_t>(candidate.Size))
    {
      break;
    }
    offset -= static_cast<uint64_t>(candidate.Size);
  }
  ThrowTruncated(element, row, *property);
}

// One property of row i in a binary body: its list count and items, or its value.
void CheckBinaryValue(vtkNPRChunkedInput& input, const PLYElement& element,
  const PLYProperty& property, long long i, long long vertexCount, bool swap)
{
  long long items = 1;
  if (property.CountSize &&
    (!ReadInteger(input, property.CountSize, false, swap, items) || items < 0))
  {
    ThrowTruncated(element, i);
  }
  const bool indices = IsIndexList(element, property);
  for (long long k = 0; k < items; ++k)
  {
    long long index = 0;
    const bool ok = property.Float
      ? input.Take(static_cast<size_t>(property.Size)) != nullptr
      : ReadInteger(input, property.Size, property.Signed, swap, index);
    if (!ok)
    {
      ThrowTruncated(element, static_cast<unsigned long long>(i), property);
    }
    if (indices)
    {
      CheckFaceIndex(i, index, vertexCount);
    }
  }
}

// An element of scalar properties only: skipped whole; false when it has a list.
bool SkipFixedSizeElement(vtkNPRChunkedInput& input, const PLYElement& element)
{
  uint64_t rowSize = 0;
  bool fixed = true;
  for (const PLYProperty& property : element.Properties)
  {
    rowSize += static_cast<uint64_t>(property.Size);
    fixed = fixed && !property.CountSize;
  }
  if (!fixed)
  {
    return false;
  }
  const uint64_t rows = static_cast<uint64_t>(std::max(element.Count, 0LL));
  const uint64_t size = rowSize && rows > UINT64_MAX / rowSize ? UINT64_MAX : rowSize * rows;
  const uint64_t skipped = input.Skip(size);
  if (skipped < size)
  {
    ThrowTruncatedRow(element, skipped / rowSize, skipped % rowSize);
  }
  return true;
}

// The binary body: every value there, every face index naming a vertex. An element of scalar
// properties only is skipped whole; a list is read value by value.
void CheckBinaryBody(
  std::istream& in, const std::vector<PLYElement>& elements, long long vertexCount, bool swap)
{
  vtkNPRChunkedInput input(in);
  for (const PLYElement& element : elements)
  {
    if (SkipFixedSizeElement(input, element))
    {
      continue;
    }
    for (long long i = 0; i < element.Count; ++i)
    {
      for (const PLYProperty& property : element.Properties)
      {
        CheckBinaryValue(input, element, property, i, vertexCount, swap);
      }
    }
  }
}

// ---- The ASCII body --------------------------------------------------------------------------

// VTK's PLY reader reads a line into 4096 bytes (its end of line and NUL included): a longer
// one is cut, and the rest read as the next line, which freed memory twice (issue 36).
void CheckLineLength(const std::string& line, const std::string& where)
{
  const size_t longest = 4094;
  if (line.size() > longest)
  {
    throw Invalid("malformed PLY file: " + where + " has " + std::to_string(line.size()) +
      " bytes, more than the " + std::to_string(longest) + " VTK's PLY reader reads");
  }
}

// Row i of an element: the next line that is not blank.
std::string ReadASCIIRow(std::istream& in, const PLYElement& element, long long i)
{
  std::string text;
  do
  {
    if (!std::getline(in, text))
    {
      throw Invalid("truncated PLY file: " + element.Name + " " + std::to_string(i) + " of " +
        std::to_string(element.Count) + " is missing");
    }
    CheckLineLength(text, "the line of " + element.Name + " " + std::to_string(i));
  } while (text.find_first_not_of(" \t\r") == std::string::npos);
  return text;
}

// One value of an ASCII row, as an index (-1 when it is none).
long long ReadASCIIValue(
  std::istringstream& row, const PLYElement& element, const PLYProperty& property, long long i)
{
  std::string token; // strtod, unlike operator>>, reads "nan" and "inf"
  char* end = nullptr;
  bool ok = static_cast<bool>(row >> token);
  const double value = ok ? std::strtod(token.c_str(), &end) : 0.0;
  ok = ok && end != token.c_str() && *end == '\0';
  if (!ok)
  {
    ThrowTruncated(element, static_cast<unsigned long long>(i), property);
  }
  return vtkNPRFormatParsing::ToLongLong(value, -1);
}

// Row i: every property's values there, face indices naming vertices, nothing more.
void CheckASCIIRow(
  std::istringstream& row, const PLYElement& element, long long i, long long vertexCount)
{
  for (const PLYProperty& property : element.Properties)
  {
    long long items = 1;
    if (property.CountSize)
    {
      const bool ok = static_cast<bool>(row >> items);
      if (!ok || items < 0)
      {
        ThrowTruncated(element, i);
      }
    }
    for (long long k = 0; k < items; ++k)
    {
      const long long index = ReadASCIIValue(row, element, property, i);
      if (IsIndexList(element, property))
      {
        CheckFaceIndex(i, index, vertexCount);
      }
    }
  }
  std::string extra;
  if (row >> extra)
  {
    throw Invalid("malformed PLY file: " + element.Name + " " + std::to_string(i) +
      " has more values than its properties ('" + extra + "')");
  }
}

void CheckASCIIBody(
  std::istream& in, const std::vector<PLYElement>& elements, long long vertexCount)
{
  for (const PLYElement& element : elements)
  {
    for (long long i = 0; i < element.Count; ++i)
    {
      std::istringstream row(ReadASCIIRow(in, element, i));
      CheckASCIIRow(row, element, i, vertexCount);
    }
  }
}

// Nothing after the last element, and an end of line after the last line.
void CheckASCIIEnd(std::istream& in, const std::string& fileName)
{
  std::string rest;
  if (in >> rest)
  {
    throw Invalid(
      "malformed PLY file: content after the last element ('" + rest.substr(0, 20) + "')");
  }
  // vtkPLYReader frees a line twice when the last one has no end of line.
  std::ifstream end(fileName, std::ios::binary | std::ios::ate);
  char last = '\n';
  if (end.tellg() > 0 && end.seekg(-1, std::ios::end) && end.get(last) && last != '\n')
  {
    throw Invalid("malformed PLY file: its last line has no end of line");
  }
}

void CheckFormat(const std::string& format)
{
  if (format != "ascii" && format != "binary_little_endian" && format != "binary_big_endian")
  {
    throw Invalid("malformed PLY header: unknown format '" + format + "'");
  }
}
}

std::string vtkNPRPLYChecks::ReadPLYHeader(
  std::istream& in, std::string& format, std::vector<PLYElement>& elements)
{
  std::string line;
  if (!std::getline(in, line) || line.compare(0, 3, "ply") != 0)
  {
    return "malformed PLY file: it does not start with 'ply'";
  }
  return vtkNPRFormatParsing::WhatIsWrong(
    [&]
    {
      CheckLineLength(line, "header line 1");
      bool ended = false;
      for (int number = 2; !ended && std::getline(in, line); ++number)
      {
        CheckLineLength(line, "header line " + std::to_string(number));
        ended = ReadHeaderLine(line, format, elements);
      }
      if (!ended)
      {
        throw Invalid("malformed PLY header: no end_header");
      }
    });
}

std::string vtkNPRPLYChecks::CheckPLY(const std::string& fileName)
{
  std::ifstream in(fileName, std::ios::binary);
  std::string format;
  std::vector<PLYElement> elements;
  const std::string headerError = ReadPLYHeader(in, format, elements);
  if (!headerError.empty())
  {
    return headerError;
  }
  return vtkNPRFormatParsing::WhatIsWrong(
    [&]
    {
      CheckElementList(elements);
      CheckVertexElement(elements);
      CheckListProperties(elements);
      CheckFormat(format);
      // Walk the body: every value must be there, every face index must name a vertex.
      const long long vertexCount = CountVertices(elements);
      if (format != "ascii")
      {
        CheckBinaryBody(in, elements, vertexCount, format != "binary_little_endian");
        return;
      }
      CheckASCIIBody(in, elements, vertexCount);
      CheckASCIIEnd(in, fileName);
    });
}
