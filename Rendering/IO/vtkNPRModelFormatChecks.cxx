// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNPRModelFormatChecks.h"

#include "vtkLZ4DataCompressor.h"
#include "vtkLZMADataCompressor.h"
#include "vtkNPRChunkedInput.h"
#include "vtkSmartPointer.h"
#include "vtkVersionMacros.h"
#include "vtkZLibDataCompressor.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <vector>

namespace
{
using PLYProperty = vtkNPRModelFormatChecks::PLYProperty;
using PLYElement = vtkNPRModelFormatChecks::PLYElement;

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

// A number read as a double, as a long long; fallback when it is not finite or out of long long's
// range, where the conversion is undefined behaviour (UBSan: "1e+20 is outside the range of
// representable values of type 'long long int'", a fuzzed PLY face index).
long long ToLongLong(double value, long long fallback)
{
  return std::isfinite(value) && value > -9.2e18 && value < 9.2e18 ? static_cast<long long>(value)
                                                                   : fallback;
}

// One binary value of the given size as an integer.
long long DecodeInteger(unsigned char* bytes, int size, bool isSigned, bool swap)
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
  value = DecodeInteger(copy, size, isSigned, swap);
  return true;
}

bool ParseInteger(const std::string& token, long long& value);

bool IsIndexList(const PLYElement& element, const PLYProperty& property)
{
  return element.Name == "face" && property.CountSize &&
    (property.Name == "vertex_indices" || property.Name == "vertex_index");
}
// What a binary body that ends inside row i of a fixed-size element says, offset bytes into it.
std::string TruncatedPLYRow(const PLYElement& element, uint64_t row, uint64_t offset)
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
  return "truncated or malformed PLY file in " + element.Name + " " + std::to_string(row) +
    " (property " + property->Name + ")";
}

// One property of row i in a binary body: its list count and items, or its value.
std::string CheckPLYBinaryValue(vtkNPRChunkedInput& input, const PLYElement& element,
  const PLYProperty& property, long long i, long long vertexCount, bool swap)
{
  long long items = 1;
  if (property.CountSize &&
    (!ReadInteger(input, property.CountSize, false, swap, items) || items < 0))
  {
    return "truncated or malformed PLY file in " + element.Name + " " + std::to_string(i);
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
      return "truncated or malformed PLY file in " + element.Name + " " + std::to_string(i) +
        " (property " + property.Name + ")";
    }
    if (indices && (index < 0 || index >= vertexCount))
    {
      return "malformed PLY file: face " + std::to_string(i) + " uses vertex " +
        std::to_string(index) + " of " + std::to_string(vertexCount);
    }
  }
  return "";
}

// The binary body: every value there, every face index naming a vertex. An element of scalar
// properties only is skipped whole; a list is read value by value.
std::string CheckPLYBinaryBody(
  std::istream& in, const std::vector<PLYElement>& elements, long long vertexCount, bool swap)
{
  vtkNPRChunkedInput input(in);
  for (const PLYElement& element : elements)
  {
    uint64_t rowSize = 0;
    bool fixed = true;
    for (const PLYProperty& property : element.Properties)
    {
      rowSize += static_cast<uint64_t>(property.Size);
      fixed = fixed && !property.CountSize;
    }
    if (fixed)
    {
      const uint64_t rows = static_cast<uint64_t>(std::max(element.Count, 0LL));
      const uint64_t size = rowSize && rows > UINT64_MAX / rowSize ? UINT64_MAX : rowSize * rows;
      const uint64_t skipped = input.Skip(size);
      if (skipped < size)
      {
        return TruncatedPLYRow(element, skipped / rowSize, skipped % rowSize);
      }
      continue;
    }
    for (long long i = 0; i < element.Count; ++i)
    {
      for (const PLYProperty& property : element.Properties)
      {
        const std::string error =
          CheckPLYBinaryValue(input, element, property, i, vertexCount, swap);
        if (!error.empty())
        {
          return error;
        }
      }
    }
  }
  return "";
}

}

std::string vtkNPRModelFormatChecks::ReadPLYHeader(
  std::istream& in, std::string& format, std::vector<PLYElement>& elements)
{
  std::string line;
  if (!std::getline(in, line) || line.compare(0, 3, "ply") != 0)
  {
    return "malformed PLY file: it does not start with 'ply'";
  }
  bool ended = false;
  while (!ended && std::getline(in, line))
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
      PLYElement element;
      std::string count;
      if (!(words >> element.Name >> count) ||
        count.find_first_not_of("0123456789") != std::string::npos ||
        !ParseInteger(count, element.Count))
      {
        return "malformed PLY header: bad element line '" + line + "'";
      }
      elements.push_back(element);
    }
    else if (keyword == "property")
    {
      if (elements.empty())
      {
        return "malformed PLY header: a property before any element";
      }
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
          return "malformed PLY header: bad list property '" + line + "'";
        }
      }
      else
      {
        property.Size = TypeSize(type, property.Signed, property.Float);
        if (!property.Size)
        {
          return "malformed PLY header: unknown property type '" + type + "'";
        }
      }
      words >> property.Name;
      elements.back().Properties.push_back(property);
    }
    else if (keyword == "end_header")
    {
      ended = true;
    }
    else if (keyword != "comment" && keyword != "obj_info" && !keyword.empty())
    {
      return "malformed PLY header: unknown line '" + line + "'";
    }
  }
  if (!ended)
  {
    return "malformed PLY header: no end_header";
  }
  return "";
}

std::string vtkNPRModelFormatChecks::CheckPLY(const std::string& fileName)
{
  std::ifstream in(fileName, std::ios::binary);
  std::string format;
  std::vector<PLYElement> elements;
  const std::string headerError = ReadPLYHeader(in, format, elements);
  if (!headerError.empty())
  {
    return headerError;
  }
  // Without a vertex element of x, y and z, vtkPLYReader uses the file it has just closed.
  const auto vertex = std::find_if(elements.begin(), elements.end(),
    [](const PLYElement& element) { return element.Name == "vertex"; });
  for (const char* axis : { "x", "y", "z" })
  {
    if (vertex == elements.end() ||
      std::none_of(vertex->Properties.begin(), vertex->Properties.end(),
        [&](const PLYProperty& property) { return property.Name == axis && !property.CountSize; }))
    {
      return std::string("malformed PLY header: no vertex element with a property ") + axis;
    }
  }
  for (const PLYElement& element : elements)
  {
    // vtkPLYReader frees the face's index list whether the file gave one or not.
    if (element.Name == "face" &&
      std::none_of(element.Properties.begin(), element.Properties.end(),
        [&](const PLYProperty& property) { return IsIndexList(element, property); }))
    {
      return "malformed PLY header: the face element has no vertex_indices list";
    }
    for (const PLYProperty& property : element.Properties)
    {
      // Lists other than the face's indices are read into memory the reader never set up.
      if (property.CountSize && !IsIndexList(element, property) &&
        !(element.Name == "face" && property.Name == "texcoord"))
      {
        return "malformed PLY header: unsupported list property '" + property.Name + "' of " +
          element.Name;
      }
    }
  }
  const bool ascii = format == "ascii";
  const bool little = format == "binary_little_endian";
  if (!ascii && !little && format != "binary_big_endian")
  {
    return "malformed PLY header: unknown format '" + format + "'";
  }
  long long vertexCount = 0;
  for (const PLYElement& element : elements)
  {
    if (element.Name == "vertex")
    {
      vertexCount = element.Count;
    }
  }

  // Walk the body: every value must be there, every face index must name a vertex.
  if (!ascii)
  {
    return CheckPLYBinaryBody(in, elements, vertexCount, !little);
  }
  for (const PLYElement& element : elements)
  {
    for (long long i = 0; i < element.Count; ++i)
    {
      std::istringstream row;
      std::string text;
      do
      {
        if (!std::getline(in, text))
        {
          return "truncated PLY file: " + element.Name + " " + std::to_string(i) + " of " +
            std::to_string(element.Count) + " is missing";
        }
      } while (text.find_first_not_of(" \t\r") == std::string::npos);
      row.str(text);
      for (const PLYProperty& property : element.Properties)
      {
        long long items = 1;
        if (property.CountSize)
        {
          const bool ok = static_cast<bool>(row >> items);
          if (!ok || items < 0)
          {
            return "truncated or malformed PLY file in " + element.Name + " " + std::to_string(i);
          }
        }
        for (long long k = 0; k < items; ++k)
        {
          std::string token; // strtod, unlike operator>>, reads "nan" and "inf"
          char* end = nullptr;
          bool ok = static_cast<bool>(row >> token);
          const double value = ok ? std::strtod(token.c_str(), &end) : 0.0;
          ok = ok && end != token.c_str() && *end == '\0';
          const long long index = ok ? ToLongLong(value, -1) : -1;
          if (!ok)
          {
            return "truncated or malformed PLY file in " + element.Name + " " + std::to_string(i) +
              " (property " + property.Name + ")";
          }
          if (IsIndexList(element, property) && (index < 0 || index >= vertexCount))
          {
            return "malformed PLY file: face " + std::to_string(i) + " uses vertex " +
              std::to_string(index) + " of " + std::to_string(vertexCount);
          }
        }
      }
      std::string extra;
      if (row >> extra)
      {
        return "malformed PLY file: " + element.Name + " " + std::to_string(i) +
          " has more values than its properties ('" + extra + "')";
      }
    }
  }
  std::string rest;
  if (in >> rest)
  {
    return "malformed PLY file: content after the last element ('" + rest.substr(0, 20) + "')";
  }
  {
    // vtkPLYReader frees a line twice when the last one has no end of line.
    std::ifstream end(fileName, std::ios::binary | std::ios::ate);
    char last = '\n';
    if (end.tellg() > 0 && end.seekg(-1, std::ios::end) && end.get(last) && last != '\n')
    {
      return "malformed PLY file: its last line has no end of line";
    }
  }
  return "";
}

std::string vtkNPRModelFormatChecks::CheckSTL(const std::string& fileName)
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

namespace
{
// A whole token as a number (strtod reads "nan" and "inf"); false when it is not one.
bool ParseNumber(const std::string& token, double& value)
{
  char* end = nullptr;
  value = std::strtod(token.c_str(), &end);
  return !token.empty() && end != token.c_str() && *end == '\0';
}

bool ParseInteger(const std::string& token, long long& value)
{
  char* end = nullptr;
  errno = 0;
  value = std::strtoll(token.c_str(), &end, 10);
  return !token.empty() && end != token.c_str() && *end == '\0' && errno == 0;
}
}

std::string vtkNPRModelFormatChecks::CheckOBJ(
  const std::string& fileName, std::vector<long long>& nonFinite, long long& vertices)
{
  std::ifstream in(fileName, std::ios::binary);
  // Counts of v, vt and vn so far; the references of each element, checked at the end against
  // the totals (positive) or when read against the counts so far (negative).
  long long counts[3] = { 0, 0, 0 };
  struct Reference
  {
    long long Line, Value;
    int Kind;
  };
  std::vector<Reference> forward;
  static const char* kinds[3] = { "vertex", "texture coordinate", "normal" };
  std::string line;
  for (long long number = 1; std::getline(in, line); ++number)
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
      continue;
    }
    const std::string where = "malformed OBJ file: line " + std::to_string(number) + ": ";
    if (keyword == "v" || keyword == "vt" || keyword == "vn")
    {
      const int kind = keyword == "v" ? 0 : keyword == "vt" ? 1 : 2;
      const int needed = kind == 1 ? 1 : 3;
      std::string token;
      int values = 0;
      bool finite = true;
      for (; words >> token; ++values)
      {
        double value;
        if (!ParseNumber(token, value))
        {
          return where + "'" + token + "' is not a number";
        }
        finite = finite && (values >= 3 || std::isfinite(value));
      }
      if (values < needed)
      {
        return where + keyword + " has " + std::to_string(values) + " values, needs " +
          std::to_string(needed);
      }
      if (kind == 0 && !finite)
      {
        nonFinite.push_back(counts[0]);
      }
      ++counts[kind];
    }
    else if (keyword == "f" || keyword == "l" || keyword == "p")
    {
      std::string token;
      int corners = 0;
      for (; words >> token; ++corners)
      {
        // v, v/vt, v//vn or v/vt/vn
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
          if (!ParseInteger(part, index) || index == 0)
          {
            return where + "'" + token + "' is not a valid " + keyword + " corner";
          }
#if VTK_VERSION_NUMBER >= VTK_VERSION_CHECK(9, 3, 0) &&                                            \
  VTK_VERSION_NUMBER < VTK_VERSION_CHECK(9, 3, 1)
          // VTK 9.3.0 resolves a relative texture coordinate against the normals' count and a
          // relative normal against the texture coordinates' (fixed in 9.3.1): it crashes or
          // reads the wrong one.
          if (index < 0 && kind > 0)
          {
            return where + keyword + " uses a relative " + kinds[kind] + " index (" +
              std::to_string(index) + "), which VTK 9.3.0's OBJ reader misreads";
          }
#endif
          if (index < 0 && -index > counts[kind])
          {
            return where + keyword + " uses " + kinds[kind] + " " + std::to_string(index) +
              ", before the first (" + std::to_string(counts[kind]) + " so far)";
          }
          if (index > 0)
          {
            forward.push_back({ number, index, kind });
          }
        }
      }
      if (corners < (keyword == "f" ? 3 : keyword == "l" ? 2 : 1))
      {
        return where + keyword + " has " + std::to_string(corners) + " corners";
      }
    }
  }
  for (const Reference& reference : forward)
  {
    if (reference.Value > counts[reference.Kind])
    {
      return "malformed OBJ file: line " + std::to_string(reference.Line) + ": uses " +
        kinds[reference.Kind] + " " + std::to_string(reference.Value) + " of " +
        std::to_string(counts[reference.Kind]);
    }
  }
  vertices = counts[0];
  return "";
}

namespace
{
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

  // Binary data starts after the keyword line.
  void StartBinary() { this->Line(); }

  // The next value: an ASCII number, or a binary one of the given size (integer or float).
  bool Value(bool binary, int size, bool isFloat, double& value)
  {
    if (!binary)
    {
      std::string token;
      return this->Token(token) && ParseNumber(token, value);
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
      int64_t raw = 0;
      std::memcpy(&raw, bytes, static_cast<size_t>(size));
      if (size < 8 && (raw >> (8 * size - 1)) & 1)
      {
        raw |= ~int64_t(0) << (8 * size);
      }
      value = static_cast<double>(raw);
    }
    return true;
  }

private:
  std::string Text;
  size_t Position = 0;
};

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
}

std::string vtkNPRModelFormatChecks::CheckLegacyVTK(const std::string& fileName)
{
  std::ifstream in(fileName, std::ios::binary);
  LegacyWalker walker(std::string(std::istreambuf_iterator<char>(in), {}));
  const std::string bad = "malformed legacy VTK file: ";
  const std::string header = walker.Line();
  if (header.compare(0, 22, "# vtk DataFile Version") != 0)
  {
    return bad + "it does not start with '# vtk DataFile Version'";
  }
  // "M.m" as vtkDataReader reads it (major 5 and later: OFFSETS and CONNECTIVITY).
  const std::string versionText = header.substr(22);
  const size_t digits = versionText.find_first_not_of(" ");
  const size_t dot = versionText.find('.', digits);
  if (digits == std::string::npos || dot == std::string::npos || dot == digits ||
    versionText.find_first_not_of("0123456789", digits) != dot ||
    versionText.find_first_not_of("0123456789", dot + 1) != std::string::npos ||
    dot + 1 == versionText.size() || dot - digits > 2 ||
    std::atoi(versionText.c_str() + digits) < 1 || std::atoi(versionText.c_str() + digits) > 5)
  {
    return bad + "unknown file version '" + versionText + "'";
  }
  const double version = std::atoi(versionText.c_str() + digits);
  walker.Line(); // the title
  const std::string format = Upper(walker.Line());
  const bool binary = format.compare(0, 6, "BINARY") == 0;
  if (!binary && format.compare(0, 5, "ASCII") != 0)
  {
    return bad + "the third line is neither ASCII nor BINARY";
  }
  std::string keyword, type;
  if (!walker.Token(keyword) || Upper(keyword) != "DATASET" || !walker.Token(type))
  {
    return bad + "no DATASET line";
  }
  type = Upper(type);
  if (type != "POLYDATA" && type != "UNSTRUCTURED_GRID" && type != "STRUCTURED_GRID")
  {
    return ""; // image and rectilinear data: no points or cells to check
  }

  long long points = -1;
  long long cells = -1;   // of CELLS, for CELL_TYPES
  std::string indexError; // CELLS: reported unless a polyhedron explains it
  while (walker.Token(keyword))
  {
    keyword = Upper(keyword);
    std::string a, b;
    long long first = 0, second = 0;
    if (keyword == "METADATA") // information keys of the array before: up to a blank line
    {
      walker.Line();
      for (std::string line = walker.Line();
           !line.empty() && line.find_first_not_of(" \t") != std::string::npos;
           line = walker.Line())
      {
      }
      continue;
    }
    if (keyword == "DIMENSIONS")
    {
      walker.Token(a), walker.Token(a), walker.Token(a);
      continue;
    }
    if (keyword == "POINTS")
    {
      bool isFloat;
      int size = 0;
      if (!walker.Token(a) || !ParseInteger(a, first) || first < 0 || !walker.Token(b) ||
        !(size = LegacyTypeSize(b, isFloat)))
      {
        return bad + "bad POINTS line";
      }
      if (first > static_cast<long long>(walker.Size()))
      {
        return bad + "POINTS declares " + std::to_string(first) +
          " points, more than the file holds";
      }
      if (binary)
      {
        walker.StartBinary();
      }
      for (long long i = 0; i < 3 * first; ++i)
      {
        double value;
        if (!walker.Value(binary, size, isFloat, value))
        {
          return bad + "POINTS declares " + std::to_string(first) + " points but holds " +
            std::to_string(i / 3);
        }
      }
      points = first;
      continue;
    }
    const bool cellSection = keyword == "VERTICES" || keyword == "LINES" || keyword == "POLYGONS" ||
      keyword == "TRIANGLE_STRIPS" || keyword == "CELLS";
    if (keyword == "CELL_TYPES")
    {
      if (!walker.Token(a) || !ParseInteger(a, first) || first != cells || cells < 0)
      {
        return bad + "CELL_TYPES does not count the " + std::to_string(cells) + " cells";
      }
      if (binary)
      {
        walker.StartBinary();
      }
      bool polyhedron = false;
      for (long long i = 0; i < first; ++i)
      {
        double value;
        if (!walker.Value(binary, 4, false, value))
        {
          return bad + "CELL_TYPES declares " + std::to_string(first) + " types but holds " +
            std::to_string(i);
        }
        polyhedron = polyhedron || value == 42;
      }
      if (!indexError.empty() && !polyhedron)
      {
        return indexError;
      }
      indexError.clear(); // a polyhedron's face stream holds counts among its point indices
      continue;
    }
    if (!cellSection)
    {
      if (keyword == "POINT_DATA" || keyword == "CELL_DATA" || keyword == "FIELD")
      {
        break; // point and cell data, fields: VTK's reader checks what it needs of them
      }
      // vtkDataReader takes any word that starts with a keyword for it ("POINTS<garbage>"),
      // and VTK 9.1 then crashed reading on.
      std::string shown;
      for (char c : keyword.substr(0, 40))
      {
        shown += std::isprint(static_cast<unsigned char>(c)) ? c : '?';
      }
      return bad + "unknown keyword '" + shown + "'";
    }
    if (points < 0)
    {
      return bad + keyword + " before POINTS";
    }
    if (!walker.Token(a) || !ParseInteger(a, first) || first < 0 || !walker.Token(b) ||
      !ParseInteger(b, second) || second < 0)
    {
      return bad + "bad " + keyword + " line";
    }
    if (first > static_cast<long long>(walker.Size()) ||
      second > static_cast<long long>(walker.Size()))
    {
      return bad + keyword + " declares more values than the file holds";
    }
    std::vector<long long> offsets, connectivity;
    if (version < 5.0)
    {
      if (binary)
      {
        walker.StartBinary();
      }
      std::vector<long long> values;
      for (long long i = 0; i < second; ++i)
      {
        double value;
        if (!walker.Value(binary, 4, false, value) || value != std::floor(value))
        {
          return bad + keyword + " declares " + std::to_string(second) + " values but holds " +
            std::to_string(i);
        }
        values.push_back(ToLongLong(value, -1));
      }
      offsets.push_back(0);
      for (size_t i = 0; i < values.size(); i += static_cast<size_t>(values[i]) + 1)
      {
        if (values[i] < 0 || static_cast<long long>(values.size() - i - 1) < values[i])
        {
          return bad + keyword + " cell " + std::to_string(offsets.size() - 1) +
            " runs past the section";
        }
        connectivity.insert(connectivity.end(), values.begin() + static_cast<long>(i) + 1,
          values.begin() + static_cast<long>(i + 1 + static_cast<size_t>(values[i])));
        offsets.push_back(static_cast<long long>(connectivity.size()));
      }
      if (static_cast<long long>(offsets.size()) - 1 != first)
      {
        return bad + keyword + " declares " + std::to_string(first) + " cells but holds " +
          std::to_string(offsets.size() - 1);
      }
    }
    else
    {
      // 5.x: "KEY offsets connectivity", then OFFSETS and CONNECTIVITY arrays.
      for (auto* array : { &offsets, &connectivity })
      {
        const char* name = array == &offsets ? "OFFSETS" : "CONNECTIVITY";
        const long long count = array == &offsets ? first : second;
        bool isFloat;
        int size = 0;
        if (!walker.Token(a) || Upper(a) != name || !walker.Token(b) ||
          !(size = LegacyTypeSize(b, isFloat)) || isFloat)
        {
          return bad + keyword + " has no " + name + " array";
        }
        if (binary)
        {
          walker.StartBinary();
        }
        for (long long i = 0; i < count; ++i)
        {
          double value;
          if (!walker.Value(binary, size, false, value))
          {
            return bad + keyword + " " + name + " declares " + std::to_string(count) +
              " values but holds " + std::to_string(i);
          }
          array->push_back(ToLongLong(value, -1));
        }
      }
      for (size_t i = 0; i < offsets.size(); ++i)
      {
        if ((i == 0 && offsets[i] != 0) || (i > 0 && offsets[i] < offsets[i - 1]) ||
          offsets[i] > second || (i + 1 == offsets.size() && offsets[i] != second))
        {
          return bad + keyword + " OFFSETS are not increasing from 0 to " + std::to_string(second);
        }
      }
    }
    for (size_t i = 0; i < connectivity.size(); ++i)
    {
      if (connectivity[i] < 0 || connectivity[i] >= points)
      {
        const std::string message = bad + keyword + " uses point " +
          std::to_string(connectivity[i]) + " of " + std::to_string(points);
        if (keyword != "CELLS")
        {
          return message;
        }
        indexError = indexError.empty() ? message : indexError;
      }
    }
    if (keyword == "CELLS")
    {
      cells = static_cast<long long>(offsets.empty() ? 0 : offsets.size() - 1);
    }
  }
  if (!indexError.empty())
  {
    return indexError; // CELLS without CELL_TYPES
  }
  return "";
}

namespace
{
// The value of attribute `name` in the XML tag that starts at `tag`; "" when absent.
std::string XMLAttribute(const std::string& text, size_t tag, const std::string& name)
{
  const size_t end = text.find('>', tag);
  for (size_t at = text.find(name + "=\"", tag); at < end; at = text.find(name + "=\"", at + 1))
  {
    if (std::isspace(static_cast<unsigned char>(text[at - 1])))
    {
      const size_t start = at + name.size() + 2;
      const size_t close = text.find('"', start);
      return close < end ? text.substr(start, close - start) : "";
    }
  }
  return "";
}
}

std::string vtkNPRModelFormatChecks::CheckVTP(const std::string& fileName)
{
  std::ifstream in(fileName, std::ios::binary);
  const std::string text(std::istreambuf_iterator<char>(in), {});
  const std::string bad = "malformed VTP file: ";
  const size_t file = text.find("<VTKFile");
  if (file == std::string::npos)
  {
    return bad + "no VTKFile element";
  }
  const bool compressed = !XMLAttribute(text, file, "compressor").empty();
  const bool bigEndian = XMLAttribute(text, file, "byte_order") == "BigEndian";
  const std::string headerType = XMLAttribute(text, file, "header_type");
  const size_t headerSize = headerType == "UInt64" ? 8 : 4;
  if (!headerType.empty() && headerType != "UInt64" && headerType != "UInt32")
  {
    return bad + "unknown header_type '" + headerType + "'";
  }
  // zlib, LZ4 and LZMA expand at most about 1032 times; raw data not at all.
  const long long most = static_cast<long long>(text.size()) * (compressed ? 1100 : 1);
  const size_t appended = text.find("<AppendedData");
  const size_t body = text.find("<AppendedData") == std::string::npos ? text.size() : appended;
  for (size_t piece = text.find("<Piece"); piece < body; piece = text.find("<Piece", piece + 1))
  {
    for (const char* count :
      { "NumberOfPoints", "NumberOfVerts", "NumberOfLines", "NumberOfStrips", "NumberOfPolys" })
    {
      const std::string value = XMLAttribute(text, piece, count);
      long long number = 0;
      if (!value.empty() &&
        (value.find_first_not_of("0123456789") != std::string::npos ||
          !ParseInteger(value, number) || number > most))
      {
        return bad + count + "=\"" + value + "\" is not a count this file can hold";
      }
    }
  }
  for (size_t array = text.find("<DataArray"); array < body;
       array = text.find("<DataArray", array + 1))
  {
    // vtkXMLReader sizes a vector by it before anything else.
    const std::string components = XMLAttribute(text, array, "NumberOfComponents");
    long long number = 1;
    if (!components.empty() &&
      (components.find_first_not_of("0123456789") != std::string::npos ||
        !ParseInteger(components, number) || number < 1 || number > 4096))
    {
      return bad + "a DataArray has NumberOfComponents=\"" + components.substr(0, 20) + "\"";
    }
  }
  if (appended == std::string::npos || XMLAttribute(text, appended, "encoding") != "raw")
  {
    return ""; // inline and base64 data: the reader checks their lengths against the text
  }
  const size_t tagEnd = text.find('>', appended);
  const size_t underscore =
    tagEnd == std::string::npos ? tagEnd : text.find_first_not_of(" \t\r\n", tagEnd + 1);
  if (underscore == std::string::npos || text[underscore] != '_')
  {
    return bad + "AppendedData without its '_' marker";
  }
  const size_t start = underscore + 1;
  vtkSmartPointer<vtkDataCompressor> compressor;
  auto readHeader = [&](size_t at, unsigned long long& value)
  {
    if (at > text.size() || text.size() - at < headerSize)
    {
      return false;
    }
    unsigned char bytes[8] = { 0 };
    for (size_t i = 0; i < headerSize; ++i)
    {
      bytes[bigEndian ? headerSize - 1 - i : i] = static_cast<unsigned char>(text[at + i]);
    }
    uint64_t raw = 0;
    std::memcpy(&raw, bytes, 8);
    value = raw;
    return true;
  };
  const unsigned long long available = text.size() - start;
  for (size_t array = text.find("<DataArray"); array < appended;
       array = text.find("<DataArray", array + 1))
  {
    if (XMLAttribute(text, array, "format") != "appended")
    {
      continue;
    }
    const std::string name = "array '" + XMLAttribute(text, array, "Name") + "'";
    long long offset = 0;
    if (!ParseInteger(XMLAttribute(text, array, "offset"), offset) || offset < 0 ||
      static_cast<unsigned long long>(offset) > available)
    {
      return bad + name + " has an offset outside the appended data";
    }
    size_t at = start + static_cast<size_t>(offset);
    unsigned long long value = 0;
    if (!compressed)
    {
      if (!readHeader(at, value) || value > available - offset - headerSize)
      {
        return bad + name + " declares more bytes than the appended data holds";
      }
      continue;
    }
    unsigned long long blocks = 0, blockSize = 0, lastSize = 0;
    if (!readHeader(at, blocks) || !readHeader(at + headerSize, blockSize) ||
      !readHeader(at + 2 * headerSize, lastSize) || blocks > available / headerSize)
    {
      return bad + name + " has a broken compression header";
    }
    at += 3 * headerSize;
    unsigned long long compressedBytes = 0;
    std::vector<unsigned long long> blockBytes;
    for (unsigned long long b = 0; b < blocks; ++b, at += headerSize)
    {
      if (!readHeader(at, value) || value > available)
      {
        return bad + name + " has a broken compression header";
      }
      compressedBytes += value;
      blockBytes.push_back(value);
    }
    const unsigned long long bytes =
      blocks ? (blocks - 1) * blockSize + (lastSize ? lastSize : blockSize) : 0;
    if (compressedBytes > text.size() - std::min(at, text.size()) || lastSize > blockSize ||
      blockSize > static_cast<unsigned long long>(most) ||
      (blocks && bytes / blocks > 1100 * (compressedBytes / blocks + 64)))
    {
      return bad + name + " declares " + std::to_string(bytes) + " bytes in " +
        std::to_string(compressedBytes) + " compressed bytes (the file has " +
        std::to_string(text.size()) + ")";
    }
    // Every block must decompress to its size: VTK 9.1's vtkXMLDataParser dereferences a null
    // buffer after a block that does not.
    if (!compressor)
    {
      const std::string kind = XMLAttribute(text, file, "compressor");
      if (kind == "vtkZLibDataCompressor")
      {
        compressor = vtkSmartPointer<vtkZLibDataCompressor>::New();
      }
      else if (kind == "vtkLZ4DataCompressor")
      {
        compressor = vtkSmartPointer<vtkLZ4DataCompressor>::New();
      }
      else if (kind == "vtkLZMADataCompressor")
      {
        compressor = vtkSmartPointer<vtkLZMADataCompressor>::New();
      }
      else
      {
        return bad + "unknown compressor '" + kind.substr(0, 40) + "'";
      }
    }
    std::vector<unsigned char> block;
    for (unsigned long long b = 0; b < blocks; ++b)
    {
      const unsigned long long size = b + 1 == blocks && lastSize ? lastSize : blockSize;
      block.resize(static_cast<size_t>(size));
      const size_t got = size == 0
        ? 0
        : compressor->Uncompress(reinterpret_cast<const unsigned char*>(text.data() + at),
            static_cast<size_t>(blockBytes[b]), block.data(), static_cast<size_t>(size));
      if (got != size)
      {
        return bad + name + ": compressed block " + std::to_string(b + 1) + " of " +
          std::to_string(blocks) + " does not decompress to its " + std::to_string(size) + " bytes";
      }
      at += static_cast<size_t>(blockBytes[b]);
    }
  }
  return "";
}
