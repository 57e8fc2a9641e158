#include "vtkNPRModelFormatChecks.h"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <vector>

namespace
{
struct PLYProperty
{
  std::string Name;
  int Size = 0;      // bytes of the value, or of each list item
  int CountSize = 0; // bytes of a list's count; 0 for a scalar property
  bool Signed = false;
  bool Float = false;
};

struct PLYElement
{
  std::string Name;
  long long Count = 0;
  std::vector<PLYProperty> Properties;
};

// Size in bytes of a PLY scalar type, 0 for an unknown type.
int TypeSize(const std::string& type, bool& isSigned, bool& isFloat)
{
  static const std::map<std::string, int> sizes = { { "char", 1 }, { "int8", 1 }, { "uchar", 1 },
    { "uint8", 1 }, { "short", 2 }, { "int16", 2 }, { "ushort", 2 }, { "uint16", 2 },
    { "int", 4 }, { "int32", 4 }, { "uint", 4 }, { "uint32", 4 }, { "float", 4 },
    { "float32", 4 }, { "double", 8 }, { "float64", 8 } };
  const auto it = sizes.find(type);
  isFloat = type.compare(0, 5, "float") == 0 || type == "double";
  isSigned = !isFloat && type[0] != 'u';
  return it == sizes.end() ? 0 : it->second;
}

// Reads one binary value of the property's type as an integer.
bool ReadInteger(std::istream& in, int size, bool isSigned, bool swap, long long& value)
{
  unsigned char bytes[8];
  if (!in.read(reinterpret_cast<char*>(bytes), size))
  {
    return false;
  }
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
  value = static_cast<long long>(raw);
  return true;
}

bool IsIndexList(const PLYElement& element, const PLYProperty& property)
{
  return element.Name == "face" && property.CountSize &&
    (property.Name == "vertex_indices" || property.Name == "vertex_index");
}
}

std::string vtkNPRModelFormatChecks::CheckPLY(const std::string& fileName)
{
  std::ifstream in(fileName, std::ios::binary);
  std::string line;
  if (!std::getline(in, line) || line.compare(0, 3, "ply") != 0)
  {
    return "malformed PLY file: it does not start with 'ply'";
  }
  std::string format;
  std::vector<PLYElement> elements;
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
      if (!(words >> element.Name >> element.Count) || element.Count < 0)
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
  for (const PLYElement& element : elements)
  {
    for (long long i = 0; i < element.Count; ++i)
    {
      std::istringstream row;
      if (ascii)
      {
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
      }
      for (const PLYProperty& property : element.Properties)
      {
        long long items = 1;
        if (property.CountSize)
        {
          const bool ok = ascii ? static_cast<bool>(row >> items)
                                : ReadInteger(in, property.CountSize, false, !little, items);
          if (!ok || items < 0)
          {
            return "truncated or malformed PLY file in " + element.Name + " " + std::to_string(i);
          }
        }
        for (long long k = 0; k < items; ++k)
        {
          long long index = 0;
          bool ok = true;
          if (ascii)
          {
            std::string token; // strtod, unlike operator>>, reads "nan" and "inf"
            char* end = nullptr;
            ok = static_cast<bool>(row >> token);
            const double value = ok ? std::strtod(token.c_str(), &end) : 0.0;
            ok = ok && end != token.c_str() && *end == '\0';
            index = ok && std::isfinite(value) ? static_cast<long long>(value) : -1;
          }
          else if (property.Float)
          {
            ok = static_cast<bool>(in.ignore(property.Size)) && in.gcount() == property.Size;
          }
          else
          {
            ok = ReadInteger(in, property.Size, property.Signed, !little, index);
          }
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
