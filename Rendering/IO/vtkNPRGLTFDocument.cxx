// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNPRGLTFDocument.h"

#include "vtkNPRFormatParsing.h"

#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sys/stat.h>

namespace
{
using vtkNPRFormatParsing::Invalid;

// The base64 payload of a data: URI, decoded; throws when it is not valid base64.
std::string DecodeDataURI(const std::string& uri, const std::string& what)
{
  const size_t comma = uri.find(',');
  if (comma == std::string::npos || uri.rfind(";base64", comma) == std::string::npos)
  {
    throw Invalid(what + " has a data: URI that is not base64");
  }
  std::string decoded;
  decoded.reserve((uri.size() - comma) * 3 / 4);
  uint32_t bits = 0;
  int count = 0;
  bool padding = false;
  for (size_t i = comma + 1; i < uri.size(); ++i)
  {
    const char c = uri[i];
    int value = -1;
    if (c >= 'A' && c <= 'Z')
    {
      value = c - 'A';
    }
    else if (c >= 'a' && c <= 'z')
    {
      value = c - 'a' + 26;
    }
    else if (c >= '0' && c <= '9')
    {
      value = c - '0' + 52;
    }
    else if (c == '+')
    {
      value = 62;
    }
    else if (c == '/')
    {
      value = 63;
    }
    else if (c == '=')
    {
      padding = true;
      continue;
    }
    if (value < 0 || padding)
    {
      throw Invalid(what + " has a data: URI that is not valid base64");
    }
    bits = (bits << 6) | static_cast<uint32_t>(value);
    if (++count == 4)
    {
      decoded += static_cast<char>((bits >> 16) & 0xFF);
      decoded += static_cast<char>((bits >> 8) & 0xFF);
      decoded += static_cast<char>(bits & 0xFF);
      bits = 0;
      count = 0;
    }
  }
  if (count == 2)
  {
    decoded += static_cast<char>((bits >> 4) & 0xFF);
  }
  else if (count == 3)
  {
    decoded += static_cast<char>((bits >> 10) & 0xFF);
    decoded += static_cast<char>((bits >> 2) & 0xFF);
  }
  else if (count == 1)
  {
    throw Invalid(what + " has a data: URI that is not valid base64");
  }
  return decoded;
}

int ComponentSize(int componentType)
{
  switch (componentType)
  {
    case 5120: // BYTE
    case 5121: // UNSIGNED_BYTE
      return 1;
    case 5122: // SHORT
    case 5123: // UNSIGNED_SHORT
      return 2;
    case 5125: // UNSIGNED_INT
    case 5126: // FLOAT
      return 4;
    default:
      return 0;
  }
}

int ComponentCount(const std::string& type)
{
  static const char* names[] = { "SCALAR", "VEC2", "VEC3", "VEC4", "MAT2", "MAT3", "MAT4" };
  static const int counts[] = { 1, 2, 3, 4, 4, 9, 16 };
  for (int i = 0; i < 7; ++i)
  {
    if (type == names[i])
    {
      return counts[i];
    }
  }
  return 0;
}
}

void vtkNPRGLTFDocument::Check()
{
  if (!this->Root.isObject())
  {
    throw Invalid("the JSON is not an object");
  }
  const Json::Value& asset = this->Root["asset"];
  if (!asset.isObject() || !asset["version"].isString())
  {
    throw Invalid("no asset.version");
  }
  if (asset["version"].asString().compare(0, 2, "2.") != 0)
  {
    throw Invalid("glTF version '" + asset["version"].asString() + "' is not 2.x");
  }
  for (const char* name : { "buffers", "bufferViews", "accessors", "images", "samplers", "textures",
         "materials", "meshes", "nodes", "scenes", "skins", "cameras", "animations" })
  {
    this->Array(name); // Index() counts their items
  }
  this->CheckBuffers();
  this->CheckBufferViews();
  this->CheckAccessors();
  this->CheckImagesTexturesMaterials();
  this->CheckMeshes();
  this->CheckNodes();
  this->CheckNodeHierarchy();
  this->CheckScenes();
  this->CheckSkins();
  this->CheckAnimations();
}

// The array at the root (an empty one when absent); anything else there is an error.
const Json::Value& vtkNPRGLTFDocument::Array(const char* name)
{
  const Json::Value& value = this->Root[name];
  if (!value.isNull() && !value.isArray())
  {
    throw Invalid(std::string(name) + " is not an array");
  }
  for (const Json::Value& item : value)
  {
    if (!item.isObject())
    {
      throw Invalid(std::string(name) + " holds something that is not an object");
    }
  }
  return value;
}

long long vtkNPRGLTFDocument::Integer(const Json::Value& value, const std::string& what,
  long long low, long long high, bool required, long long absent)
{
  if (value.isNull() && !required)
  {
    return absent;
  }
  if (!value.isIntegral() || (value.isUInt64() && !value.isInt64()))
  {
    throw Invalid(what + (value.isNull() ? " is missing" : " is not an integer"));
  }
  const long long number = value.asInt64();
  if (number < low || number > high)
  {
    throw Invalid(what + " is " + std::to_string(number) + ", outside [" + std::to_string(low) +
      ", " + std::to_string(high) + "]");
  }
  return number;
}

// An index into the root array `target`, optional unless required; -1 when absent.
long long vtkNPRGLTFDocument::Index(
  const Json::Value& value, const std::string& what, const char* target, bool required)
{
  const long long size = static_cast<long long>(this->Root[target].size());
  if (!required && value.isNull())
  {
    return -1;
  }
  if (size == 0)
  {
    throw Invalid(what + " refers to " + target + ", which is empty");
  }
  return Integer(value, what + " (an index into " + target + ")", 0, size - 1);
}

void vtkNPRGLTFDocument::CheckNumbers(
  const Json::Value& value, const std::string& what, unsigned int count)
{
  if (value.isNull())
  {
    return;
  }
  if (!value.isArray() || value.size() != count)
  {
    throw Invalid(what + " is not an array of " + std::to_string(count) + " numbers");
  }
  for (const Json::Value& number : value)
  {
    if (!number.isNumeric())
    {
      throw Invalid(what + " is not an array of " + std::to_string(count) + " numbers");
    }
  }
}

void vtkNPRGLTFDocument::CheckBuffers()
{
  const Json::Value& buffers = this->Array("buffers");
  for (Json::ArrayIndex i = 0; i < buffers.size(); ++i)
  {
    const std::string what = "buffer " + std::to_string(i);
    const Json::Value& buffer = buffers[i];
    const long long length = Integer(buffer["byteLength"], what + " byteLength", 1, 1LL << 40);
    std::string bytes = this->ReadBuffer(buffer, i, what, length);
    if (static_cast<long long>(bytes.size()) < length)
    {
      throw Invalid(what + " holds " + std::to_string(bytes.size()) +
        " bytes, fewer than its byteLength " + std::to_string(length));
    }
    bytes.resize(static_cast<size_t>(length));
    this->Buffers.push_back(std::move(bytes));
  }
}

// A buffer's bytes: a GLB's BIN chunk, a data: URI decoded, or an external file.
std::string vtkNPRGLTFDocument::ReadBuffer(
  const Json::Value& buffer, Json::ArrayIndex i, const std::string& what, long long length)
{
  if (buffer["uri"].isNull())
  {
    if (i != 0 || !this->BinChunk)
    {
      throw Invalid(what + " has no uri (only a GLB's first buffer may have none)");
    }
    return *this->BinChunk;
  }
  if (!buffer["uri"].isString())
  {
    throw Invalid(what + " uri is not a string");
  }
  const std::string uri = buffer["uri"].asString();
  if (uri.compare(0, 5, "data:") == 0)
  {
    return DecodeDataURI(uri, what);
  }
  const std::string path = this->Directory + uri;
  struct stat status;
  if (uri.empty() || uri.find("://") != std::string::npos || stat(path.c_str(), &status) != 0 ||
    !S_ISREG(status.st_mode))
  {
    throw Invalid(what + " file '" + uri + "' is missing");
  }
  // VTK 9.1's glTF reader fails to load a longer file too, and then crashed on its accessors.
  if (status.st_size != length)
  {
    throw Invalid(what + " file '" + uri + "' has " + std::to_string(status.st_size) + " bytes, " +
      (status.st_size < length ? "fewer" : "more") + " than its byteLength " +
      std::to_string(length));
  }
  std::ifstream in(path, std::ios::binary);
  std::string bytes(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>{});
  if (static_cast<long long>(bytes.size()) < length)
  {
    throw Invalid(what + " file '" + uri + "' cannot be read");
  }
  return bytes;
}

void vtkNPRGLTFDocument::CheckBufferViews()
{
  const Json::Value& views = this->Array("bufferViews");
  for (Json::ArrayIndex i = 0; i < views.size(); ++i)
  {
    const std::string what = "bufferView " + std::to_string(i);
    const Json::Value& view = views[i];
    const long long buffer = this->Index(view["buffer"], what + " buffer", "buffers", true);
    const long long bufferLength = static_cast<long long>(this->Buffers[buffer].size());
    const long long offset =
      Integer(view["byteOffset"], what + " byteOffset", 0, bufferLength, false, 0);
    const long long length =
      Integer(view["byteLength"], what + " byteLength", 1, bufferLength - offset);
    const long long stride = Integer(view["byteStride"], what + " byteStride", 4, 252, false, 0);
    this->ViewBuffer.push_back(buffer);
    this->ViewOffset.push_back(offset);
    this->ViewLength.push_back(length);
    this->ViewStride.push_back(stride);
  }
}

vtkNPRGLTFDocument::Accessor vtkNPRGLTFDocument::ReadAccessor(
  const Json::Value& accessor, const std::string& what)
{
  Accessor a;
  a.ComponentType =
    static_cast<int>(Integer(accessor["componentType"], what + " componentType", 5120, 5126));
  const int size = ComponentSize(a.ComponentType);
  if (!size)
  {
    throw Invalid(what + " has an unknown componentType " + std::to_string(a.ComponentType));
  }
  if (!accessor["type"].isString() || !ComponentCount(accessor["type"].asString()))
  {
    throw Invalid(what + " has no valid type (SCALAR, VEC2..4, MAT2..4)");
  }
  a.Components = ComponentCount(accessor["type"].asString());
  a.Count = Integer(accessor["count"], what + " count", 1, 1LL << 32);
  // vtkGLTFDocumentLoader copies min and max by the component count.
  this->CheckNumbers(accessor["min"], what + " min", static_cast<unsigned int>(a.Components));
  this->CheckNumbers(accessor["max"], what + " max", static_cast<unsigned int>(a.Components));
  if (!accessor["sparse"].isNull())
  {
    throw Invalid(what + " is sparse (not supported)");
  }
  // An accessor without a buffer view is all zeros: VTK's reader does not support it.
  a.BufferView = this->Index(accessor["bufferView"], what + " bufferView", "bufferViews", true);
  const long long viewLength = this->ViewLength[a.BufferView];
  const long long offset =
    Integer(accessor["byteOffset"], what + " byteOffset", 0, viewLength, false, 0);
  const long long element = static_cast<long long>(size) * a.Components;
  a.Stride = this->ViewStride[a.BufferView] ? this->ViewStride[a.BufferView] : element;
  if (offset + (a.Count - 1) * a.Stride + element > viewLength)
  {
    throw Invalid(what + " (" + std::to_string(a.Count) + " elements of " +
      std::to_string(element) + " bytes, stride " + std::to_string(a.Stride) + ", offset " +
      std::to_string(offset) + ") does not fit in bufferView " + std::to_string(a.BufferView) +
      " (" + std::to_string(viewLength) + " bytes)");
  }
  a.Offset = this->ViewOffset[a.BufferView] + offset;
  return a;
}

void vtkNPRGLTFDocument::CheckAccessors()
{
  const Json::Value& accessors = this->Array("accessors");
  for (Json::ArrayIndex i = 0; i < accessors.size(); ++i)
  {
    this->Accessors.push_back(this->ReadAccessor(accessors[i], "accessor " + std::to_string(i)));
  }
}

void vtkNPRGLTFDocument::CheckMeshes()
{
  const Json::Value& meshes = this->Array("meshes");
  for (Json::ArrayIndex i = 0; i < meshes.size(); ++i)
  {
    const std::string what = "mesh " + std::to_string(i);
    const Json::Value& primitives = meshes[i]["primitives"];
    if (!primitives.isArray() || primitives.empty())
    {
      throw Invalid(what + " has no primitives array");
    }
    for (Json::ArrayIndex p = 0; p < primitives.size(); ++p)
    {
      this->CheckPrimitive(primitives[p], what + " primitive " + std::to_string(p));
    }
    const Json::Value& weights = meshes[i]["weights"];
    if (!weights.isNull())
    {
      this->CheckNumbers(weights, what + " weights", primitives[0]["targets"].size());
    }
  }
}

void vtkNPRGLTFDocument::CheckPrimitive(const Json::Value& primitive, const std::string& what)
{
  if (!primitive.isObject() || !primitive["attributes"].isObject())
  {
    throw Invalid(what + " has no attributes object");
  }
  const Json::Value& attributes = primitive["attributes"];
  if (attributes["POSITION"].isNull())
  {
    throw Invalid(what + " has no POSITION attribute");
  }
  const Accessor& position =
    this->Accessors[this->Index(attributes["POSITION"], what + " POSITION", "accessors", true)];
  if (position.ComponentType != 5126 || position.Components != 3)
  {
    throw Invalid(what + " POSITION is not a float VEC3 accessor");
  }
  this->CheckAttributes(attributes, what, position);
  const Json::Value& targets = primitive["targets"];
  if (!targets.isNull() && !targets.isArray())
  {
    throw Invalid(what + " targets is not an array");
  }
  for (Json::ArrayIndex t = 0; t < targets.size(); ++t)
  {
    this->CheckAttributes(targets[t], what + " target " + std::to_string(t), position);
  }
  const long long indices = this->CheckMode(primitive, what, position);
  if (indices >= 0)
  {
    this->CheckIndices(this->Accessors[indices], what, position);
  }
}

// The reader copies every attribute of a vertex: each must have the vertex count.
void vtkNPRGLTFDocument::CheckAttributes(
  const Json::Value& set, const std::string& where, const Accessor& position)
{
  if (!set.isObject())
  {
    throw Invalid(where + " is not an object");
  }
  for (const std::string& name : set.getMemberNames())
  {
    const Accessor& accessor =
      this->Accessors[this->Index(set[name], where + " " + name, "accessors", true)];
    if (accessor.Count != position.Count)
    {
      throw Invalid(where + " " + name + " has " + std::to_string(accessor.Count) +
        " elements for " + std::to_string(position.Count) + " vertices");
    }
    if ((name == "NORMAL" || name == "POSITION") &&
      (accessor.ComponentType != 5126 || accessor.Components != 3))
    {
      throw Invalid(where + " " + name + " is not a float VEC3 accessor");
    }
  }
}

// The mode and the material; returns the index accessor (-1: none). The vertices (or indices)
// the mode needs, as the glTF specification has it: VTK 9.1's loader read past the end of a
// triangle list of 8 vertices.
long long vtkNPRGLTFDocument::CheckMode(
  const Json::Value& primitive, const std::string& what, const Accessor& position)
{
  const long long mode = Integer(primitive["mode"], what + " mode", 0, 6, false, 4);
  this->Index(primitive["material"], what + " material", "materials");
  const long long indices = this->Index(primitive["indices"], what + " indices", "accessors");
  const long long elements = indices < 0 ? position.Count : this->Accessors[indices].Count;
  const bool fits = mode == 0 || (mode == 1 && elements % 2 == 0) ||
    ((mode == 2 || mode == 3) && elements >= 2) || (mode == 4 && elements % 3 == 0) ||
    ((mode == 5 || mode == 6) && elements >= 3);
  if (!fits)
  {
    throw Invalid(what + " has " + std::to_string(elements) +
      (indices < 0 ? " vertices" : " indices") + ", which mode " + std::to_string(mode) +
      " cannot use");
  }
  return indices;
}

// Unsigned integer indices, every one below the vertex count.
void vtkNPRGLTFDocument::CheckIndices(
  const Accessor& index, const std::string& what, const Accessor& position)
{
  if (index.Components != 1 ||
    (index.ComponentType != 5121 && index.ComponentType != 5123 && index.ComponentType != 5125))
  {
    throw Invalid(what + " indices is not an unsigned integer SCALAR accessor");
  }
  const std::string& buffer = this->Buffers[this->ViewBuffer[index.BufferView]];
  const int size = ComponentSize(index.ComponentType);
  for (long long k = 0; k < index.Count; ++k)
  {
    uint32_t value = 0;
    std::memcpy(&value, buffer.data() + index.Offset + k * index.Stride, size);
    if (value >= position.Count)
    {
      throw Invalid(what + " index " + std::to_string(k) + " is vertex " + std::to_string(value) +
        " of " + std::to_string(position.Count));
    }
  }
}
