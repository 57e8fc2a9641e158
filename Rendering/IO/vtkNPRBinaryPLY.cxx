// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNPRBinaryPLY.h"

#include "vtkCellArray.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkNPRChunkedInput.h"
#include "vtkNPRIdBuffer.h"
#include "vtkNPRPLYChecks.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <vector>

namespace
{
using vtkNPRPLYChecks::PLYElement;
using vtkNPRPLYChecks::PLYProperty;

// Where a vertex row's values are: byte offsets of x, y, z, the normal and the colour (-1:
// absent), and whether the coordinates are doubles.
struct VertexLayout
{
  size_t RowSize = 0;
  int Offset[10] = { -1, -1, -1, -1, -1, -1, -1, -1, -1, -1 }; // x y z nx ny nz r g b a
  bool Double[6] = {};
  bool HasNormals = false;
  bool HasColors = false;
  bool HasAlpha = false;
};

// The vertex element's layout, or false for one this reader leaves to vtkPLYReader.
bool MakeVertexLayout(const PLYElement& vertex, VertexLayout& layout)
{
  static const char* const names[10] = { "x", "y", "z", "nx", "ny", "nz", "red", "green", "blue",
    "alpha" };
  for (const PLYProperty& property : vertex.Properties)
  {
    if (property.CountSize || property.Name == "u" || property.Name == "texture_u" ||
      property.Name.compare(0, 8, "diffuse_") == 0)
    {
      return false; // lists, texture coordinates, diffuse colours: vtkPLYReader's own paths
    }
    for (int k = 0; k < 10; ++k)
    {
      if (property.Name == names[k])
      {
        const bool color = k >= 6;
        if (color ? (property.Size != 1 || property.Float || property.Signed)
                  : !(property.Float && (property.Size == 4 || property.Size == 8)))
        {
          return false; // a conversion vtkPLYReader makes its own way
        }
        layout.Offset[k] = static_cast<int>(layout.RowSize);
        if (!color)
        {
          layout.Double[k] = property.Size == 8;
        }
      }
    }
    layout.RowSize += static_cast<size_t>(property.Size);
  }
  auto has = [&](int first, int count)
  {
    bool all = true;
    for (int k = first; k < first + count; ++k)
    {
      all = all && layout.Offset[k] >= 0;
    }
    return all;
  };
  layout.HasNormals = has(3, 3);
  layout.HasColors = has(6, 3);
  layout.HasAlpha = layout.HasColors && layout.Offset[9] >= 0;
  return has(0, 3);
}

// The face element holds its vertex indices only, with an integer count and integer indices.
bool IsPlainFaceElement(const PLYElement& face)
{
  return face.Name == "face" && face.Properties.size() == 1 &&
    face.Properties[0].Name == "vertex_indices" && face.Properties[0].CountSize &&
    !face.Properties[0].Float;
}

// The bytes from the stream's position to the end of the file (-1 when it cannot tell).
std::streamoff BytesLeft(std::istream& in)
{
  const std::streampos here = in.tellg();
  in.seekg(0, std::ios::end);
  const std::streamoff left = here < 0 ? -1 : static_cast<std::streamoff>(in.tellg() - here);
  in.seekg(here);
  return left;
}

// Whether the body can hold what the header counts (the vertex rows and one list count per
// face), before anything is allocated for them: a mutated count must not ask for gigabytes.
bool FitsTheFile(
  std::istream& in, const std::vector<PLYElement>& elements, const VertexLayout& layout)
{
  const long double left = static_cast<long double>(BytesLeft(in));
  const long double needed =
    static_cast<long double>(elements[0].Count) * static_cast<long double>(layout.RowSize) +
    static_cast<long double>(elements[1].Count) * elements[1].Properties[0].CountSize;
  return left >= 0 && elements[0].Count >= 0 && elements[1].Count >= 0 && needed <= left;
}

float ReadCoordinate(const unsigned char* row, int offset, bool isDouble)
{
  if (isDouble)
  {
    double value;
    std::memcpy(&value, row + offset, sizeof value);
    return static_cast<float>(value);
  }
  float value;
  std::memcpy(&value, row + offset, sizeof value);
  return value;
}

// The vertices, converted a block of rows at a time.
bool ReadVertices(
  std::istream& in, long long count, const VertexLayout& layout, vtkPolyData* output)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToFloat();
  points->SetNumberOfPoints(count);
  float* xyz = static_cast<vtkFloatArray*>(points->GetData())->GetPointer(0);
  vtkNew<vtkFloatArray> normals;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  normals->SetNumberOfTuples(layout.HasNormals ? count : 0);
  vtkNew<vtkUnsignedCharArray> colors;
  const int channels = layout.HasAlpha ? 4 : 3;
  colors->SetName(layout.HasAlpha ? "RGBA" : "RGB");
  colors->SetNumberOfComponents(channels);
  colors->SetNumberOfTuples(layout.HasColors ? count : 0);

  std::vector<unsigned char> block(layout.RowSize * 65536);
  for (long long first = 0; first < count; first += 65536)
  {
    const long long rows = std::min<long long>(65536, count - first);
    if (!in.read(reinterpret_cast<char*>(block.data()),
          static_cast<std::streamsize>(layout.RowSize * static_cast<size_t>(rows))))
    {
      return false;
    }
    for (long long r = 0; r < rows; ++r)
    {
      const unsigned char* row = block.data() + layout.RowSize * static_cast<size_t>(r);
      const size_t i = static_cast<size_t>(first + r);
      for (int k = 0; k < 3; ++k)
      {
        xyz[3 * i + k] = ReadCoordinate(row, layout.Offset[k], layout.Double[k]);
      }
      for (int k = 0; layout.HasNormals && k < 3; ++k)
      {
        normals->GetPointer(0)[3 * i + k] =
          ReadCoordinate(row, layout.Offset[3 + k], layout.Double[3 + k]);
      }
      for (int k = 0; layout.HasColors && k < channels; ++k)
      {
        colors->GetPointer(0)[channels * i + k] = row[layout.Offset[6 + k]];
      }
    }
  }
  output->SetPoints(points);
  if (layout.HasColors)
  {
    output->GetPointData()->SetScalars(colors);
  }
  if (layout.HasNormals)
  {
    output->GetPointData()->SetNormals(normals);
  }
  return true;
}

// One little-endian integer of 1, 2 or 4 bytes.
long long Integer(const unsigned char* bytes, int size, bool isSigned)
{
  uint32_t raw = 0;
  std::memcpy(&raw, bytes, static_cast<size_t>(size));
  if (isSigned && size < 4 && (raw >> (8 * size - 1)) & 1)
  {
    raw |= ~uint32_t(0) << (8 * size);
  }
  return isSigned ? static_cast<long long>(static_cast<int32_t>(raw)) : static_cast<long long>(raw);
}

// The faces into the cell array's storage; false for a count over 255 (vtkPLYReader wraps it) or
// a file that ends early.
bool ReadFaces(std::istream& in, long long count, const PLYProperty& list, long long vertexCount,
  vtkPolyData* output)
{
  vtkNPRIdBuffer offsets, connectivity;
  offsets.Reserve(count + 1);
  offsets.Append(0);
  // Room for triangles, the most common faces, but never more ids than the file has bytes for.
  const vtkIdType idsLeft = static_cast<vtkIdType>(BytesLeft(in) / list.Size);
  connectivity.Reserve(std::min<vtkIdType>(3 * count, idsLeft));
  vtkNPRChunkedInput input(in);
  vtkIdType corners[255];
  for (long long f = 0; f < count; ++f)
  {
    const unsigned char* countBytes = input.Take(static_cast<size_t>(list.CountSize));
    const long long size = countBytes ? Integer(countBytes, list.CountSize, false) : -1;
    const unsigned char* items =
      size >= 0 && size <= 255 ? input.Take(static_cast<size_t>(size * list.Size)) : nullptr;
    if (!items)
    {
      return false;
    }
    for (long long k = 0; k < size; ++k)
    {
      corners[k] = static_cast<vtkIdType>(Integer(items + k * list.Size, list.Size, list.Signed));
      if (corners[k] < 0 || corners[k] >= vertexCount)
      {
        return false; // CheckPLY names the face
      }
    }
    connectivity.Append(corners, static_cast<vtkIdType>(size));
    offsets.Append(connectivity.Size());
  }
  vtkNew<vtkCellArray> polys;
  polys->SetData(offsets.Finish(), connectivity.Finish());
  output->SetPolys(polys);
  return true;
}
}

bool vtkNPRBinaryPLY::Read(const std::string& fileName, vtkPolyData* output)
{
  std::ifstream in(fileName, std::ios::binary);
  std::string format;
  std::vector<PLYElement> elements;
  VertexLayout layout;
  if (!vtkNPRPLYChecks::ReadPLYHeader(in, format, elements).empty() ||
    format != "binary_little_endian" || elements.size() != 2 || elements[0].Name != "vertex" ||
    !MakeVertexLayout(elements[0], layout) || !IsPlainFaceElement(elements[1]) ||
    elements[1].Properties[0].Size > 4 || elements[1].Properties[0].CountSize > 4 ||
    !FitsTheFile(in, elements, layout))
  {
    return false;
  }
  vtkNew<vtkPolyData> read;
  if (!ReadVertices(in, elements[0].Count, layout, read) ||
    !ReadFaces(in, elements[1].Count, elements[1].Properties[0], elements[0].Count, read))
  {
    return false;
  }
  output->ShallowCopy(read);
  return true;
}
