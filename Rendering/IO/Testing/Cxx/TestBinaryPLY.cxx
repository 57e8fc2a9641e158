// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// vtkNPRBinaryPLY, the model reader's fast path for binary PLY: every layout it takes gives what
// vtkPLYReader gives, value for value (points, normals, colours, polygons); the layouts it leaves
// to vtkPLYReader are refused; through vtkNPRModelReader the output is the same either way.
//
// usage: TestBinaryPLY DATA_DIR OUTPUT_DIR
#include "nprTesting.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkIdList.h"
#include "vtkNPRBinaryPLY.h"
#include "vtkNPRModelReader.h"
#include "vtkNew.h"
#include "vtkOutputWindow.h"
#include "vtkPLYReader.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

namespace
{
// A binary PLY file written property by property: each vertex property a type and a value of
// vertex i, the faces as (count, indices) with the given count and index types.
struct PLYFile
{
  struct Property
  {
    std::string Type, Name;
  };
  std::string Format = "binary_little_endian";
  std::vector<Property> Vertex;
  std::string CountType = "uchar", IndexType = "int";
  std::vector<std::vector<int>> Faces;
  int VertexCount = 0;
};

double VertexValue(int i, size_t property)
{
  // Off one line (the reader refuses a mesh whose faces all have zero area).
  return 0.25 * i + 0.125 * static_cast<double>(property) + (i % 3 == 0 ? 1.0 / 3.0 : 0.0) +
    0.5 * static_cast<double>((i * (property + 1)) % 5);
}

template <typename T>
void Put(std::ofstream& out, T value, bool swap)
{
  unsigned char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  for (size_t k = 0; swap && k < sizeof(T) / 2; ++k)
  {
    std::swap(bytes[k], bytes[sizeof(T) - 1 - k]);
  }
  out.write(reinterpret_cast<const char*>(bytes), sizeof(T));
}

void PutTyped(std::ofstream& out, const std::string& type, double value, bool swap)
{
  if (type == "float")
  {
    Put(out, static_cast<float>(value), swap);
  }
  else if (type == "double")
  {
    Put(out, value, swap);
  }
  else if (type == "uchar")
  {
    Put(out, static_cast<uint8_t>(value), swap);
  }
  else if (type == "ushort")
  {
    Put(out, static_cast<uint16_t>(value), swap);
  }
  else if (type == "uint")
  {
    Put(out, static_cast<uint32_t>(value), swap);
  }
  else
  {
    Put(out, static_cast<int32_t>(value), swap);
  }
}

std::string Write(const std::string& path, const PLYFile& file)
{
  std::ofstream out(path, std::ios::binary);
  out << "ply\nformat " << file.Format << " 1.0\nelement vertex " << file.VertexCount << "\n";
  for (const PLYFile::Property& property : file.Vertex)
  {
    out << "property " << property.Type << " " << property.Name << "\n";
  }
  out << "element face " << file.Faces.size() << "\nproperty list " << file.CountType << " "
      << file.IndexType << " vertex_indices\nend_header\n";
  const bool swap = file.Format == "binary_big_endian";
  for (int i = 0; i < file.VertexCount; ++i)
  {
    for (size_t k = 0; k < file.Vertex.size(); ++k)
    {
      const bool byte = file.Vertex[k].Type == "uchar";
      PutTyped(out, file.Vertex[k].Type, byte ? (7 * i + 13 * k) % 256 : VertexValue(i, k), swap);
    }
  }
  for (const std::vector<int>& face : file.Faces)
  {
    PutTyped(out, file.CountType, static_cast<double>(face.size()), swap);
    for (int index : face)
    {
      PutTyped(out, file.IndexType, index, swap);
    }
  }
  return path;
}

bool SameValues(vtkDataArray* a, vtkDataArray* b)
{
  if (!a || !b)
  {
    return !a && !b;
  }
  bool same = a->GetDataType() == b->GetDataType() &&
    a->GetNumberOfComponents() == b->GetNumberOfComponents() &&
    a->GetNumberOfTuples() == b->GetNumberOfTuples() &&
    std::string(a->GetName() ? a->GetName() : "") == (b->GetName() ? b->GetName() : "");
  for (vtkIdType i = 0; same && i < a->GetNumberOfValues(); ++i)
  {
    const int components = a->GetNumberOfComponents();
    same = a->GetComponent(i / components, i % components) ==
      b->GetComponent(i / components, i % components);
  }
  return same;
}

// The fast path's output against vtkPLYReader's, and vtkNPRModelReader's against both.
void CheckLikeVTK(const std::string& path, bool fastPath)
{
  vtkNew<vtkPolyData> fast;
  NPR_CHECK(vtkNPRBinaryPLY::Read(path, fast) == fastPath,
    path << ": the fast path " << (fastPath ? "takes" : "leaves") << " this layout");
  vtkNew<vtkPLYReader> vtk;
  vtk->SetFileName(path.c_str());
  vtk->Update();
  vtkNew<vtkNPRModelReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  for (vtkPolyData* output : { fastPath ? fast.Get() : vtk->GetOutput(), reader->GetOutput() })
  {
    vtkPolyData* expected = vtk->GetOutput();
    NPR_CHECK(SameValues(output->GetPoints()->GetData(), expected->GetPoints()->GetData()),
      path << ": the same points");
    NPR_CHECK(
      SameValues(output->GetPointData()->GetNormals(), expected->GetPointData()->GetNormals()),
      path << ": the same normals");
    NPR_CHECK(
      SameValues(output->GetPointData()->GetScalars(), expected->GetPointData()->GetScalars()),
      path << ": the same colours");
    NPR_CHECK(
      output->GetPointData()->GetNumberOfArrays() == expected->GetPointData()->GetNumberOfArrays(),
      path << ": no other point arrays");
    NPR_CHECK(
      nprSameCells(output->GetPolys(), expected->GetPolys()), path << ": the same polygons");
  }
}

PLYFile Grid(const std::vector<PLYFile::Property>& vertex)
{
  PLYFile file;
  file.Vertex = vertex;
  file.VertexCount = 70000; // more than one block of rows
  for (int i = 0; i + 5 < file.VertexCount; i += 3)
  {
    file.Faces.push_back({ i, i + 1, i + 2 });
    file.Faces.push_back({ i + 1, i + 3, i + 4, i + 2 });
    if (i % 9 == 0)
    {
      file.Faces.push_back({ i, i + 5, i + 4, i + 3, i + 1 });
    }
  }
  return file;
}
}

int main(int argc, char* argv[])
{
  if (argc < 3)
  {
    std::cerr << "usage: TestBinaryPLY DATA_DIR OUTPUT_DIR\n";
    return 2;
  }
  const std::string data = argv[1], out = std::string(argv[2]) + "/binary_ply_";
  const PLYFile::Property x{ "float", "x" }, y{ "float", "y" }, z{ "float", "z" };
  CheckLikeVTK(data + "/bunny.ply", true);
  CheckLikeVTK(data + "/rotor.ply", true);
  CheckLikeVTK(Write(out + "plain.ply", Grid({ x, y, z })), true);
  CheckLikeVTK(
    Write(out + "double.ply", Grid({ { "double", "x" }, { "double", "y" }, { "double", "z" } })),
    true);
  CheckLikeVTK(Write(out + "normals_rgb.ply",
                 Grid({ { "float", "nx" }, x, { "uchar", "red" }, y, { "float", "ny" }, z,
                   { "uchar", "green" }, { "float", "nz" }, { "uchar", "blue" } })),
    true);
  CheckLikeVTK(
    Write(out + "rgba_extra.ply",
      Grid({ x, y, z, { "float", "confidence" }, { "uchar", "red" }, { "uchar", "green" },
        { "uchar", "blue" }, { "uchar", "alpha" }, { "int", "label" } })),
    true);
  PLYFile wide = Grid({ x, y, z });
  wide.CountType = "ushort";
  wide.IndexType = "uint";
  CheckLikeVTK(Write(out + "ushort_uint.ply", wide), true);
  // Left to vtkPLYReader: big-endian, texture coordinates, a colour stored as float.
  PLYFile big = Grid({ x, y, z });
  big.Format = "binary_big_endian";
  CheckLikeVTK(Write(out + "big_endian.ply", big), false);
  CheckLikeVTK(Write(out + "uv.ply", Grid({ x, y, z, { "float", "u" }, { "float", "v" } })), false);
  CheckLikeVTK(Write(out + "float_red.ply",
                 Grid({ x, y, z, { "float", "red" }, { "float", "green" }, { "float", "blue" } })),
    false);
  // A file that ends inside the faces: no output from the fast path.
  const std::string plain = out + "plain.ply";
  std::ifstream whole(plain, std::ios::binary | std::ios::ate);
  const std::streamoff size = whole.tellg();
  std::string bytes(static_cast<size_t>(size) - 7, '\0');
  whole.seekg(0);
  whole.read(&bytes[0], static_cast<std::streamsize>(bytes.size()));
  std::ofstream(out + "truncated.ply", std::ios::binary) << bytes;
  vtkNew<vtkPolyData> truncated;
  NPR_CHECK(
    !vtkNPRBinaryPLY::Read(out + "truncated.ply", truncated) && truncated->GetNumberOfPoints() == 0,
    "a truncated file: refused, the output untouched");
  // A count past what the file holds (a mutated header): refused before anything is allocated,
  // and vtkNPRModelReader says the file is truncated.
  std::ofstream(out + "huge_count.ply", std::ios::binary)
    << "ply\nformat binary_little_endian 1.0\nelement vertex 1000000000000\nproperty float x\n"
       "property float y\nproperty float z\nelement face 1\nproperty list uchar int "
       "vertex_indices\nend_header\n0123456789";
  vtkNew<vtkPolyData> huge;
  NPR_CHECK(!vtkNPRBinaryPLY::Read(out + "huge_count.ply", huge), "a count past the file: refused");
  vtkNew<vtkNPRModelReader> reader;
  reader->SetFileName((out + "huge_count.ply").c_str());
  vtkNew<nprCountingOutputWindow> messages;
  vtkOutputWindow::SetInstance(messages);
  reader->Update();
  NPR_CHECK(std::string(reader->GetErrorMessage()).find("truncated") != std::string::npos,
    "the model reader's error: " << reader->GetErrorMessage());
  return nprTestResult();
}
