// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// vtkNPRGLTFDocument's checks of what refers to the data: images, textures and materials, the
// node hierarchy and the scenes, skins and animations.
#include "vtkNPRGLTFDocument.h"

#include "vtkNPRFormatParsing.h"

namespace
{
using vtkNPRFormatParsing::Invalid;
}

void vtkNPRGLTFDocument::CheckTextureInfo(const Json::Value& info, const std::string& what)
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

void vtkNPRGLTFDocument::CheckImagesTexturesMaterials()
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

// Every node's references in range, and no node with two parents or itself as its child.
void vtkNPRGLTFDocument::CheckNodes()
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
}

// With one parent at most, a cycle is a set of nodes without a root: walk up from each.
void vtkNPRGLTFDocument::CheckNodeHierarchy()
{
  const Json::Value& nodes = this->Array("nodes");
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

void vtkNPRGLTFDocument::CheckScenes()
{
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

void vtkNPRGLTFDocument::CheckSkins()
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

void vtkNPRGLTFDocument::CheckAnimations()
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
      Integer(
        channels[c]["sampler"], where + " sampler", 0, static_cast<long long>(samplers.size()) - 1);
      this->Index(channels[c]["target"]["node"], where + " target node", "nodes");
    }
  }
}
