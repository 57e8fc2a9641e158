// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNPRVTPChecks.h"

#include "vtkLZ4DataCompressor.h"
#include "vtkLZMADataCompressor.h"
#include "vtkNPRFormatParsing.h"
#include "vtkSmartPointer.h"
#include "vtkZLibDataCompressor.h"

#include <algorithm>
#include <cctype>
#include <cstring>
#include <vector>

namespace
{
using vtkNPRFormatParsing::Invalid;

[[noreturn]] void Fail(const std::string& what)
{
  throw Invalid("malformed VTP file: " + what);
}

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

// Whether value is empty or a count of decimal digits within [low, high].
bool IsCountOrEmpty(const std::string& value, long long low, long long high)
{
  long long number = 0;
  return value.empty() ||
    (value.find_first_not_of("0123456789") == std::string::npos &&
      vtkNPRFormatParsing::ParseInteger(value, number) && number >= low && number <= high);
}

// The blocks of a compressed array: how many, their size, the last one's, and each one's
// compressed bytes.
struct CompressionHeader
{
  unsigned long long Blocks = 0;
  unsigned long long BlockSize = 0;
  unsigned long long LastSize = 0;
  std::vector<unsigned long long> BlockBytes;
  unsigned long long CompressedBytes = 0;

  unsigned long long Bytes() const
  {
    return this->Blocks
      ? (this->Blocks - 1) * this->BlockSize + (this->LastSize ? this->LastSize : this->BlockSize)
      : 0;
  }
};

// The file: its counts, then every appended raw array's header.
class VTPFile
{
public:
  explicit VTPFile(std::string text)
    : Text(std::move(text))
  {
  }

  void Check()
  {
    this->ReadFileAttributes();
    // zlib, LZ4 and LZMA expand at most about 1032 times; raw data not at all.
    this->Most = static_cast<long long>(this->Text.size()) * (this->Compressed ? 1100 : 1);
    this->Appended = this->Text.find("<AppendedData");
    const size_t body = this->Appended == std::string::npos ? this->Text.size() : this->Appended;
    this->CheckNesting(body);
    this->CheckPieceCounts(body);
    this->CheckComponentCounts(body);
    if (this->Appended == std::string::npos ||
      XMLAttribute(this->Text, this->Appended, "encoding") != "raw")
    {
      return; // inline and base64 data: the reader checks their lengths against the text
    }
    this->FindAppendedStart();
    for (size_t array = this->Text.find("<DataArray"); array < this->Appended;
         array = this->Text.find("<DataArray", array + 1))
    {
      if (XMLAttribute(this->Text, array, "format") == "appended")
      {
        this->CheckAppendedArray(array);
      }
    }
  }

private:
  // VTK's XML parser builds and frees the element tree recursively: elements nested many
  // thousands deep overflow the stack. A VTP file nests five or six.
  void CheckNesting(size_t body) const
  {
    constexpr int deepest = 64;
    int depth = 0;
    for (size_t tag = this->Text.find('<'); tag < body; tag = this->Text.find('<', tag + 1))
    {
      const char next = tag + 1 < body ? this->Text[tag + 1] : '\0';
      const size_t end = this->Text.find('>', tag);
      if (next == '/')
      {
        --depth;
      }
      else if (next != '?' && next != '!' &&
        (end == std::string::npos || this->Text[end - 1] != '/'))
      {
        if (++depth > deepest)
        {
          Fail("elements nested more than " + std::to_string(deepest) + " deep");
        }
      }
    }
  }

  // The VTKFile element: the compressor, the byte order and the header type.
  void ReadFileAttributes()
  {
    this->File = this->Text.find("<VTKFile");
    if (this->File == std::string::npos)
    {
      Fail("no VTKFile element");
    }
    this->Compressed = !XMLAttribute(this->Text, this->File, "compressor").empty();
    this->BigEndian = XMLAttribute(this->Text, this->File, "byte_order") == "BigEndian";
    const std::string headerType = XMLAttribute(this->Text, this->File, "header_type");
    this->HeaderSize = headerType == "UInt64" ? 8 : 4;
    if (!headerType.empty() && headerType != "UInt64" && headerType != "UInt32")
    {
      Fail("unknown header_type '" + headerType + "'");
    }
  }

  void CheckPieceCounts(size_t body) const
  {
    for (size_t piece = this->Text.find("<Piece"); piece < body;
         piece = this->Text.find("<Piece", piece + 1))
    {
      for (const char* count :
        { "NumberOfPoints", "NumberOfVerts", "NumberOfLines", "NumberOfStrips", "NumberOfPolys" })
      {
        const std::string value = XMLAttribute(this->Text, piece, count);
        if (!IsCountOrEmpty(value, 0, this->Most))
        {
          Fail(std::string(count) + "=\"" + value + "\" is not a count this file can hold");
        }
      }
    }
  }

  // vtkXMLReader sizes a vector by NumberOfComponents before anything else.
  void CheckComponentCounts(size_t body) const
  {
    for (size_t array = this->Text.find("<DataArray"); array < body;
         array = this->Text.find("<DataArray", array + 1))
    {
      const std::string components = XMLAttribute(this->Text, array, "NumberOfComponents");
      if (!IsCountOrEmpty(components, 1, 4096))
      {
        Fail("a DataArray has NumberOfComponents=\"" + components.substr(0, 20) + "\"");
      }
    }
  }

  // The appended data start after the '_' that follows the AppendedData tag.
  void FindAppendedStart()
  {
    const size_t tagEnd = this->Text.find('>', this->Appended);
    const size_t underscore =
      tagEnd == std::string::npos ? tagEnd : this->Text.find_first_not_of(" \t\r\n", tagEnd + 1);
    if (underscore == std::string::npos || this->Text[underscore] != '_')
    {
      Fail("AppendedData without its '_' marker");
    }
    this->Start = underscore + 1;
    this->Available = this->Text.size() - this->Start;
  }

  // One header integer (UInt32 or UInt64, in the file's byte order); false past the end.
  bool ReadHeader(size_t at, unsigned long long& value) const
  {
    if (at > this->Text.size() || this->Text.size() - at < this->HeaderSize)
    {
      return false;
    }
    unsigned char bytes[8] = { 0 };
    std::memcpy(bytes, this->Text.data() + at, this->HeaderSize);
    value = static_cast<unsigned long long>(vtkNPRFormatParsing::DecodeInteger(
      bytes, static_cast<int>(this->HeaderSize), false, this->BigEndian));
    return true;
  }

  void CheckAppendedArray(size_t array)
  {
    const std::string name = "array '" + XMLAttribute(this->Text, array, "Name") + "'";
    long long offset = 0;
    if (!vtkNPRFormatParsing::ParseInteger(XMLAttribute(this->Text, array, "offset"), offset) ||
      offset < 0 || static_cast<unsigned long long>(offset) > this->Available)
    {
      Fail(name + " has an offset outside the appended data");
    }
    const size_t at = this->Start + static_cast<size_t>(offset);
    unsigned long long value = 0;
    if (!this->Compressed)
    {
      if (!this->ReadHeader(at, value) || value > this->Available - offset - this->HeaderSize)
      {
        Fail(name + " declares more bytes than the appended data holds");
      }
      return;
    }
    size_t blocksAt = at;
    const CompressionHeader header = this->ReadCompressionHeader(name, blocksAt);
    this->CheckCompressedSizes(name, header, blocksAt);
    this->CheckBlocksDecompress(name, header, blocksAt);
  }

  // The header at `at`; `at` moved to the first block.
  CompressionHeader ReadCompressionHeader(const std::string& name, size_t& at) const
  {
    CompressionHeader header;
    if (!this->ReadHeader(at, header.Blocks) ||
      !this->ReadHeader(at + this->HeaderSize, header.BlockSize) ||
      !this->ReadHeader(at + 2 * this->HeaderSize, header.LastSize) ||
      header.Blocks > this->Available / this->HeaderSize)
    {
      Fail(name + " has a broken compression header");
    }
    at += 3 * this->HeaderSize;
    for (unsigned long long b = 0; b < header.Blocks; ++b, at += this->HeaderSize)
    {
      unsigned long long value = 0;
      if (!this->ReadHeader(at, value) || value > this->Available)
      {
        Fail(name + " has a broken compression header");
      }
      header.CompressedBytes += value;
      header.BlockBytes.push_back(value);
    }
    return header;
  }

  void CheckCompressedSizes(
    const std::string& name, const CompressionHeader& header, size_t at) const
  {
    const unsigned long long bytes = header.Bytes();
    const unsigned long long blocks = header.Blocks;
    if (header.CompressedBytes > this->Text.size() - std::min(at, this->Text.size()) ||
      header.LastSize > header.BlockSize ||
      header.BlockSize > static_cast<unsigned long long>(this->Most) ||
      (blocks && bytes / blocks > 1100 * (header.CompressedBytes / blocks + 64)))
    {
      Fail(name + " declares " + std::to_string(bytes) + " bytes in " +
        std::to_string(header.CompressedBytes) + " compressed bytes (the file has " +
        std::to_string(this->Text.size()) + ")");
    }
  }

  // The file's compressor, made once.
  vtkDataCompressor* Compressor()
  {
    if (!this->Decompressor)
    {
      const std::string kind = XMLAttribute(this->Text, this->File, "compressor");
      if (kind == "vtkZLibDataCompressor")
      {
        this->Decompressor = vtkSmartPointer<vtkZLibDataCompressor>::New();
      }
      else if (kind == "vtkLZ4DataCompressor")
      {
        this->Decompressor = vtkSmartPointer<vtkLZ4DataCompressor>::New();
      }
      else if (kind == "vtkLZMADataCompressor")
      {
        this->Decompressor = vtkSmartPointer<vtkLZMADataCompressor>::New();
      }
      else
      {
        Fail("unknown compressor '" + kind.substr(0, 40) + "'");
      }
    }
    return this->Decompressor;
  }

  // Every block must decompress to its size: VTK 9.1's vtkXMLDataParser dereferences a null
  // buffer after a block that does not.
  void CheckBlocksDecompress(const std::string& name, const CompressionHeader& header, size_t at)
  {
    vtkDataCompressor* compressor = this->Compressor();
    std::vector<unsigned char> block;
    for (unsigned long long b = 0; b < header.Blocks; ++b)
    {
      const unsigned long long size =
        b + 1 == header.Blocks && header.LastSize ? header.LastSize : header.BlockSize;
      block.resize(static_cast<size_t>(size));
      const size_t got = size == 0
        ? 0
        : compressor->Uncompress(reinterpret_cast<const unsigned char*>(this->Text.data() + at),
            static_cast<size_t>(header.BlockBytes[b]), block.data(), static_cast<size_t>(size));
      if (got != size)
      {
        Fail(name + ": compressed block " + std::to_string(b + 1) + " of " +
          std::to_string(header.Blocks) + " does not decompress to its " + std::to_string(size) +
          " bytes");
      }
      at += static_cast<size_t>(header.BlockBytes[b]);
    }
  }

  const std::string Text;
  size_t File = 0;     // the VTKFile element
  size_t Appended = 0; // the AppendedData element, or npos
  size_t Start = 0;    // the first byte of the appended data
  unsigned long long Available = 0;
  bool Compressed = false;
  bool BigEndian = false;
  size_t HeaderSize = 4;
  long long Most = 0; // the most bytes the file's data can hold
  vtkSmartPointer<vtkDataCompressor> Decompressor;
};
}

std::string vtkNPRVTPChecks::CheckVTP(const std::string& fileName)
{
  return vtkNPRFormatParsing::WhatIsWrong(
    [&] { VTPFile(vtkNPRFormatParsing::ReadWholeFile(fileName)).Check(); });
}
