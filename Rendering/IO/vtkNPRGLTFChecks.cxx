// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNPRGLTFChecks.h"

#include "vtk_jsoncpp.h"

#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <sys/stat.h>
#include <vector>

namespace
{
struct Invalid : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

uint32_t ReadUInt32(const std::string& bytes, size_t offset)
{
  uint32_t value = 0;
  std::memcpy(&value, bytes.data() + offset, 4); // glTF is little-endian, as is the host
  return value;
}

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

struct Accessor
{
  long long BufferView = -1;
  long long Offset = 0; // from the buffer's start
  long long Stride = 0;
  long long Count = 0;
  int ComponentType = 0;
  int Components = 0;
};

class Document
{
public:
  Document(const Json::Value& root, std::string directory, const std::string* binChunk)
    : Root(root)
    , Directory(std::move(directory))
    , BinChunk(binChunk)
  {
  }

  void Check()
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
    for (const char* name : { "buffers", "bufferViews", "accessors", "images", "samplers",
           "textures", "materials", "meshes", "nodes", "scenes", "skins", "cameras", "animations" })
    {
      this->Array(name); // Index() counts their items
    }
    this->CheckBuffers();
    this->CheckBufferViews();
    this->CheckAccessors();
    this->CheckImagesTexturesMaterials();
    this->CheckMeshes();
    this->CheckNodesAndScenes();
    this->CheckSkins();
    this->CheckAnimations();
  }

private:
  // The array at the root (an empty one when absent); anything else there is an error.
  const Json::Value& Array(const char* name)
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

  static long long Integer(const Json::Value& value, const std::string& what, long long low,
    long long high, bool required = true, long long absent = -1)
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
  long long Index(
    const Json::Value& value, const std::string& what, const char* target, bool required = false)
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

  void CheckNumbers(const Json::Value& value, const std::string& what, unsigned int count)
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

  void CheckBuffers()
  {
    const Json::Value& buffers = this->Array("buffers");
    for (Json::ArrayIndex i = 0; i < buffers.size(); ++i)
    {
      const std::string what = "buffer " + std::to_string(i);
      const Json::Value& buffer = buffers[i];
      const long long length = Integer(buffer["byteLength"], what + " byteLength", 1, 1LL << 40);
      std::string bytes;
      if (buffer["uri"].isNull())
      {
        if (i != 0 || !this->BinChunk)
        {
          throw Invalid(what + " has no uri (only a GLB's first buffer may have none)");
        }
        bytes = *this->BinChunk;
      }
      else if (!buffer["uri"].isString())
      {
        throw Invalid(what + " uri is not a string");
      }
      else
      {
        const std::string uri = buffer["uri"].asString();
        if (uri.compare(0, 5, "data:") == 0)
        {
          bytes = DecodeDataURI(uri, what);
        }
        else
        {
          const std::string path = this->Directory + uri;
          struct stat status;
          if (uri.empty() || uri.find("://") != std::string::npos ||
            stat(path.c_str(), &status) != 0 || !S_ISREG(status.st_mode))
          {
            throw Invalid(what + " file '" + uri + "' is missing");
          }
          if (status.st_size < length)
          {
            throw Invalid(what + " file '" + uri + "' has " + std::to_string(status.st_size) +
              " bytes, fewer than its byteLength " + std::to_string(length));
          }
          std::ifstream in(path, std::ios::binary);
          bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
          if (static_cast<long long>(bytes.size()) < length)
          {
            throw Invalid(what + " file '" + uri + "' cannot be read");
          }
        }
      }
      if (static_cast<long long>(bytes.size()) < length)
      {
        throw Invalid(what + " holds " + std::to_string(bytes.size()) +
          " bytes, fewer than its byteLength " + std::to_string(length));
      }
      bytes.resize(static_cast<size_t>(length));
      this->Buffers.push_back(std::move(bytes));
    }
  }

  void CheckBufferViews()
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

  Accessor ReadAccessor(const Json::Value& accessor, const std::string& what)
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

  void CheckAccessors()
  {
    const Json::Value& accessors = this->Array("accessors");
    for (Json::ArrayIndex i = 0; i < accessors.size(); ++i)
    {
      this->Accessors.push_back(this->ReadAccessor(accessors[i], "accessor " + std::to_string(i)));
    }
  }

  void CheckTextureInfo(const Json::Value& info, const std::string& what)
  {
    if (info.isNull())
    {
      return;
    }
    if (!info.isObject())
    {
      throw Invalid(what + " is not an object");
    }
    this->Index(info["index"], what + " index", "textures", true);
    Integer(info["texCoord"], what + " texCoord", 0, 7, false, 0);
  }

  void CheckImagesTexturesMaterials()
  {
    const Json::Value& images = this->Array("images");
    for (Json::ArrayIndex i = 0; i < images.size(); ++i)
    {
      const std::string what = "image " + std::to_string(i);
      this->Index(images[i]["bufferView"], what + " bufferView", "bufferViews");
      if (!images[i]["uri"].isNull() && !images[i]["uri"].isString())
      {
        throw Invalid(what + " uri is not a string");
      }
    }
    this->Array("samplers");
    const Json::Value& textures = this->Array("textures");
    for (Json::ArrayIndex i = 0; i < textures.size(); ++i)
    {
      const std::string what = "texture " + std::to_string(i);
      this->Index(textures[i]["source"], what + " source", "images");
      this->Index(textures[i]["sampler"], what + " sampler", "samplers");
    }
    const Json::Value& materials = this->Array("materials");
    for (Json::ArrayIndex i = 0; i < materials.size(); ++i)
    {
      const std::string what = "material " + std::to_string(i);
      const Json::Value& material = materials[i];
      const Json::Value& pbr = material["pbrMetallicRoughness"];
      if (!pbr.isNull())
      {
        if (!pbr.isObject())
        {
          throw Invalid(what + " pbrMetallicRoughness is not an object");
        }
        this->CheckNumbers(pbr["baseColorFactor"], what + " baseColorFactor", 4);
        this->CheckTextureInfo(pbr["baseColorTexture"], what + " baseColorTexture");
        this->CheckTextureInfo(pbr["metallicRoughnessTexture"], what + " metallicRoughnessTexture");
      }
      this->CheckNumbers(material["emissiveFactor"], what + " emissiveFactor", 3);
      for (const char* texture : { "normalTexture", "occlusionTexture", "emissiveTexture" })
      {
        this->CheckTextureInfo(material[texture], what + " " + texture);
      }
    }
  }

  void CheckPrimitive(const Json::Value& primitive, const std::string& what)
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
    // The reader copies every attribute of a vertex: each must have the vertex count.
    auto checkAttributes = [&](const Json::Value& set, const std::string& where)
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
    };
    checkAttributes(attributes, what);
    const Json::Value& targets = primitive["targets"];
    if (!targets.isNull() && !targets.isArray())
    {
      throw Invalid(what + " targets is not an array");
    }
    for (Json::ArrayIndex t = 0; t < targets.size(); ++t)
    {
      checkAttributes(targets[t], what + " target " + std::to_string(t));
    }
    const long long mode = Integer(primitive["mode"], what + " mode", 0, 6, false, 4);
    this->Index(primitive["material"], what + " material", "materials");
    const long long indices = this->Index(primitive["indices"], what + " indices", "accessors");
    // The vertices (or indices) the mode needs, as the glTF specification has it: VTK 9.1's
    // loader read past the end of a triangle list of 8 vertices.
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
    if (indices < 0)
    {
      return;
    }
    const Accessor& index = this->Accessors[indices];
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

  void CheckMeshes()
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

  void CheckNodesAndScenes()
  {
    const Json::Value& nodes = this->Array("nodes");
    std::vector<int> parents(nodes.size(), 0);
    for (Json::ArrayIndex i = 0; i < nodes.size(); ++i)
    {
      const std::string what = "node " + std::to_string(i);
      const Json::Value& node = nodes[i];
      this->Index(node["mesh"], what + " mesh", "meshes");
      this->Index(node["skin"], what + " skin", "skins");
      this->Index(node["camera"], what + " camera", "cameras");
      this->CheckNumbers(node["matrix"], what + " matrix", 16);
      this->CheckNumbers(node["translation"], what + " translation", 3);
      this->CheckNumbers(node["rotation"], what + " rotation", 4);
      this->CheckNumbers(node["scale"], what + " scale", 3);
      if (!node["weights"].isNull() && !node["weights"].isArray())
      {
        throw Invalid(what + " weights is not an array");
      }
      const Json::Value& children = node["children"];
      if (!children.isNull() && !children.isArray())
      {
        throw Invalid(what + " children is not an array");
      }
      for (Json::ArrayIndex c = 0; c < children.size(); ++c)
      {
        const long long child = this->Index(children[c], what + " child", "nodes", true);
        // A node with two parents, or its own ancestor, would make the reader loop forever.
        if (child == static_cast<long long>(i) || ++parents[child] > 1)
        {
          throw Invalid(what + " child " + std::to_string(child) +
            " makes the node hierarchy no tree (a cycle or two parents)");
        }
      }
    }
    // With one parent at most, a cycle is a set of nodes without a root: walk up from each.
    if (!nodes.empty())
    {
      std::vector<long long> parentOf(nodes.size(), -1);
      for (Json::ArrayIndex n = 0; n < nodes.size(); ++n)
      {
        for (const Json::Value& child : nodes[n]["children"])
        {
          parentOf[child.asInt64()] = n;
        }
      }
      // 0: not seen, 1: on the current walk, 2: leads to a root.
      std::vector<char> state(nodes.size(), 0);
      std::vector<long long> walk;
      for (Json::ArrayIndex i = 0; i < nodes.size(); ++i)
      {
        walk.clear();
        long long node = i;
        for (; node >= 0 && state[node] == 0; node = parentOf[node])
        {
          state[node] = 1;
          walk.push_back(node);
        }
        if (node >= 0 && state[node] == 1)
        {
          throw Invalid("node " + std::to_string(node) + " is its own ancestor");
        }
        for (long long visited : walk)
        {
          state[visited] = 2;
        }
      }
    }
    const Json::Value& scenes = this->Array("scenes");
    for (Json::ArrayIndex i = 0; i < scenes.size(); ++i)
    {
      const Json::Value& roots = scenes[i]["nodes"];
      if (!roots.isNull() && !roots.isArray())
      {
        throw Invalid("scene " + std::to_string(i) + " nodes is not an array");
      }
      for (const Json::Value& root : roots)
      {
        this->Index(root, "scene " + std::to_string(i) + " node", "nodes", true);
      }
    }
    this->Index(this->Root["scene"], "scene", "scenes");
  }

  void CheckSkins()
  {
    const Json::Value& skins = this->Array("skins");
    for (Json::ArrayIndex i = 0; i < skins.size(); ++i)
    {
      const std::string what = "skin " + std::to_string(i);
      const Json::Value& joints = skins[i]["joints"];
      if (!joints.isArray() || joints.empty())
      {
        throw Invalid(what + " has no joints array");
      }
      for (const Json::Value& joint : joints)
      {
        this->Index(joint, what + " joint", "nodes", true);
      }
      this->Index(skins[i]["skeleton"], what + " skeleton", "nodes");
      const long long matrices =
        this->Index(skins[i]["inverseBindMatrices"], what + " inverseBindMatrices", "accessors");
      if (matrices >= 0 &&
        (this->Accessors[matrices].Components != 16 ||
          this->Accessors[matrices].ComponentType != 5126 ||
          this->Accessors[matrices].Count < static_cast<long long>(joints.size())))
      {
        throw Invalid(what +
          " inverseBindMatrices is not a float MAT4 accessor with one matrix "
          "per joint");
      }
    }
  }

  void CheckAnimations()
  {
    const Json::Value& animations = this->Array("animations");
    for (Json::ArrayIndex i = 0; i < animations.size(); ++i)
    {
      const std::string what = "animation " + std::to_string(i);
      const Json::Value& samplers = animations[i]["samplers"];
      const Json::Value& channels = animations[i]["channels"];
      if (!samplers.isArray() || !channels.isArray())
      {
        throw Invalid(what + " has no samplers and channels arrays");
      }
      for (Json::ArrayIndex s = 0; s < samplers.size(); ++s)
      {
        const std::string where = what + " sampler " + std::to_string(s);
        if (!samplers[s].isObject())
        {
          throw Invalid(where + " is not an object");
        }
        this->Index(samplers[s]["input"], where + " input", "accessors", true);
        this->Index(samplers[s]["output"], where + " output", "accessors", true);
      }
      for (Json::ArrayIndex c = 0; c < channels.size(); ++c)
      {
        const std::string where = what + " channel " + std::to_string(c);
        if (!channels[c].isObject() || !channels[c]["target"].isObject())
        {
          throw Invalid(where + " has no target object");
        }
        Integer(channels[c]["sampler"], where + " sampler", 0,
          static_cast<long long>(samplers.size()) - 1);
        this->Index(channels[c]["target"]["node"], where + " target node", "nodes");
      }
    }
  }

  const Json::Value& Root;
  std::string Directory;
  const std::string* BinChunk;
  std::vector<std::string> Buffers;
  std::vector<long long> ViewBuffer, ViewOffset, ViewLength, ViewStride;
  std::vector<Accessor> Accessors;
};
}

std::string vtkNPRGLTFChecks::CheckGLTF(const std::string& fileName)
{
  std::ifstream in(fileName, std::ios::binary);
  const std::string file(std::istreambuf_iterator<char>(in), {});
  const size_t slash = fileName.find_last_of('/');
  const std::string directory = slash == std::string::npos ? "" : fileName.substr(0, slash + 1);

  std::string json = file;
  std::string binChunk;
  bool hasBinChunk = false;
  const bool binary = file.compare(0, 4, "glTF") == 0;
  if (binary)
  {
    if (file.size() < 20)
    {
      return "malformed GLB file: " + std::to_string(file.size()) + " bytes, too short";
    }
    const uint32_t version = ReadUInt32(file, 4);
    const uint32_t length = ReadUInt32(file, 8);
    if (version != 2)
    {
      return "malformed GLB file: container version " + std::to_string(version) + ", not 2";
    }
    if (length != file.size())
    {
      return "malformed GLB file: its header says " + std::to_string(length) +
        " bytes but the file has " + std::to_string(file.size());
    }
    size_t offset = 12;
    for (int chunk = 0; offset < file.size(); ++chunk)
    {
      if (file.size() - offset < 8)
      {
        return "malformed GLB file: chunk " + std::to_string(chunk) + " has no full header";
      }
      const uint32_t chunkLength = ReadUInt32(file, offset);
      const uint32_t chunkType = ReadUInt32(file, offset + 4);
      if (chunkLength > file.size() - offset - 8)
      {
        return "malformed GLB file: chunk " + std::to_string(chunk) + " (" +
          std::to_string(chunkLength) + " bytes) runs past the end of the file";
      }
      const std::string data = file.substr(offset + 8, chunkLength);
      if (chunk == 0 && chunkType != 0x4E4F534A)
      {
        return "malformed GLB file: the first chunk is not JSON";
      }
      if (chunk == 0)
      {
        json = data;
      }
      else if (chunk == 1 && chunkType == 0x004E4942)
      {
        binChunk = data;
        hasBinChunk = true;
      }
      offset += 8 + chunkLength;
    }
  }

  Json::CharReaderBuilder builder;
  Json::CharReaderBuilder::strictMode(&builder.settings_);
  builder.settings_["stackLimit"] = 200;
  builder.settings_["failIfExtra"] = false; // trailing NULs or spaces pad a GLB's JSON chunk
  std::unique_ptr<Json::CharReader> reader(builder.newCharReader());
  Json::Value root;
  std::string errors;
  if (!reader->parse(json.data(), json.data() + json.size(), &root, &errors))
  {
    // jsoncpp: "* Line 2, Column 1\n  Syntax error: ...\n": its first error, on one line.
    std::istringstream lines(errors);
    std::string position, what;
    std::getline(lines, position);
    std::getline(lines, what);
    position.erase(0, position.find_first_not_of("* "));
    what.erase(0, what.find_first_not_of(' '));
    const std::string first = position + ": " + what;
    return std::string("malformed ") + (binary ? "GLB" : "glTF") + " file: invalid JSON: " + first;
  }
  try
  {
    Document(root, directory, hasBinChunk ? &binChunk : nullptr).Check();
  }
  catch (const Invalid& error)
  {
    return std::string("malformed ") + (binary ? "GLB" : "glTF") + " file: " + error.what();
  }
  catch (const std::exception& error) // jsoncpp's own, on a value of an unexpected kind
  {
    return std::string("malformed ") + (binary ? "GLB" : "glTF") + " file: " + error.what();
  }
  return "";
}
