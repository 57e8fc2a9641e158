// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNPRGLTFChecks.h"

#include "vtkNPRFormatParsing.h"
#include "vtkNPRGLTFDocument.h"
#include "vtk_jsoncpp.h"

#include <cstdint>
#include <cstring>
#include <memory>
#include <sstream>
#include <stdexcept>

namespace
{
uint32_t ReadUInt32(const std::string& bytes, size_t offset)
{
  uint32_t value = 0;
  std::memcpy(&value, bytes.data() + offset, 4); // glTF is little-endian, as is the host
  return value;
}

// A GLB's container (header, then chunks: JSON first, BIN second): "" or what is wrong with it.
std::string SplitGLB(
  const std::string& file, std::string& json, std::string& binChunk, bool& hasBinChunk)
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
  return "";
}

// The JSON into root: "" or jsoncpp's first error, on one line.
std::string ParseJSON(const std::string& json, Json::Value& root)
{
  Json::CharReaderBuilder builder;
  Json::CharReaderBuilder::strictMode(&builder.settings_);
  builder.settings_["stackLimit"] = 200;
  builder.settings_["failIfExtra"] = false; // trailing NULs or spaces pad a GLB's JSON chunk
  std::unique_ptr<Json::CharReader> reader(builder.newCharReader());
  std::string errors;
  try
  {
    if (reader->parse(json.data(), json.data() + json.size(), &root, &errors))
    {
      return "";
    }
  }
  // jsoncpp throws, not returns, past its stackLimit: values nested more than 200 deep.
  catch (const std::exception& error)
  {
    return std::string(error.what()) + " (nested more than 200 deep)";
  }
  // jsoncpp: "* Line 2, Column 1\n  Syntax error: ...\n": its first error, on one line.
  std::istringstream lines(errors);
  std::string position, what;
  std::getline(lines, position);
  std::getline(lines, what);
  position.erase(0, position.find_first_not_of("* "));
  what.erase(0, what.find_first_not_of(' '));
  return position + ": " + what;
}
}

std::string vtkNPRGLTFChecks::CheckGLTF(const std::string& fileName)
{
  const std::string file = vtkNPRFormatParsing::ReadWholeFile(fileName);
  const size_t slash = fileName.find_last_of('/');
  const std::string directory = slash == std::string::npos ? "" : fileName.substr(0, slash + 1);

  std::string json = file;
  std::string binChunk;
  bool hasBinChunk = false;
  const bool binary = file.compare(0, 4, "glTF") == 0;
  const std::string malformed = std::string("malformed ") + (binary ? "GLB" : "glTF") + " file: ";
  const std::string containerError = binary ? SplitGLB(file, json, binChunk, hasBinChunk) : "";
  if (!containerError.empty())
  {
    return containerError;
  }
  Json::Value root;
  const std::string jsonError = ParseJSON(json, root);
  if (!jsonError.empty())
  {
    return malformed + "invalid JSON: " + jsonError;
  }
  try
  {
    vtkNPRGLTFDocument(root, directory, hasBinChunk ? &binChunk : nullptr).Check();
  }
  // What is wrong (vtkNPRFormatParsing::Invalid), or jsoncpp's own exception on a value of an
  // unexpected kind; what() ends the message at a NUL byte, as the glTF check always has.
  catch (const std::exception& error)
  {
    return malformed + error.what();
  }
  return "";
}
