// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// The checks of a glTF 2.0 document's JSON (vtkNPRGLTFChecks), one method per part, in the
// order vtkGLTFReader needs them: the buffers, buffer views and accessors first (the data the
// other parts index), then the meshes (vtkNPRGLTFDocument.cxx); the images, textures and
// materials, the nodes and scenes, the skins and the animations (vtkNPRGLTFScene.cxx). A step
// throws vtkNPRFormatParsing::Invalid with what is wrong. Private to the module.
#ifndef vtkNPRGLTFDocument_h
#define vtkNPRGLTFDocument_h

#include "vtk_jsoncpp.h"

#include <string>
#include <vector>

class vtkNPRGLTFDocument
{
public:
  // The parsed JSON, the folder of external buffers, and a GLB's BIN chunk (null: none).
  vtkNPRGLTFDocument(const Json::Value& root, std::string directory, const std::string* binChunk)
    : Root(root)
    , Directory(std::move(directory))
    , BinChunk(binChunk)
  {
  }

  void Check();

private:
  struct Accessor
  {
    long long BufferView = -1;
    long long Offset = 0; // from the buffer's start
    long long Stride = 0;
    long long Count = 0;
    int ComponentType = 0;
    int Components = 0;
  };

  // Lookups in the JSON (vtkNPRGLTFDocument.cxx).
  const Json::Value& Array(const char* name);
  static long long Integer(const Json::Value& value, const std::string& what, long long low,
    long long high, bool required = true, long long absent = -1);
  long long Index(
    const Json::Value& value, const std::string& what, const char* target, bool required = false);
  void CheckNumbers(const Json::Value& value, const std::string& what, unsigned int count);

  // The data (vtkNPRGLTFDocument.cxx).
  void CheckBuffers();
  std::string ReadBuffer(
    const Json::Value& buffer, Json::ArrayIndex i, const std::string& what, long long length);
  void CheckBufferViews();
  Accessor ReadAccessor(const Json::Value& accessor, const std::string& what);
  void CheckAccessors();
  void CheckMeshes();
  void CheckPrimitive(const Json::Value& primitive, const std::string& what);
  void CheckAttributes(const Json::Value& set, const std::string& where, const Accessor& position);
  long long CheckMode(
    const Json::Value& primitive, const std::string& what, const Accessor& position);
  void CheckIndices(const Accessor& index, const std::string& what, const Accessor& position);

  // What refers to the data (vtkNPRGLTFScene.cxx).
  void CheckTextureInfo(const Json::Value& info, const std::string& what);
  void CheckImagesTexturesMaterials();
  void CheckNodes();
  void CheckNodeHierarchy();
  void CheckScenes();
  void CheckSkins();
  void CheckAnimations();

  const Json::Value& Root;
  std::string Directory;
  const std::string* BinChunk;
  std::vector<std::string> Buffers;
  std::vector<long long> ViewBuffer, ViewOffset, ViewLength, ViewStride;
  std::vector<Accessor> Accessors;
};

#endif
