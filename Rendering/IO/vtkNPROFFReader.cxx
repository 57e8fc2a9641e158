// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNPROFFReader.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <vector>

vtkStandardNewMacro(vtkNPROFFReader);

namespace
{
struct ParseError : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

// Reads the file line by line, skipping blank lines and comments, and splits lines into tokens.
class OFFLineReader
{
public:
  OFFLineReader(std::istream& stream, std::string name)
    : Stream(stream)
    , Name(std::move(name))
  {
  }

  // The next line with content; false at the end of the file.
  bool Next(std::vector<std::string>& tokens)
  {
    std::string line;
    while (std::getline(this->Stream, line))
    {
      ++this->Line;
      const size_t hash = line.find('#');
      if (hash != std::string::npos)
      {
        line.erase(hash);
      }
      std::istringstream words(line);
      tokens.clear();
      std::string word;
      while (words >> word)
      {
        tokens.push_back(word);
      }
      if (!tokens.empty())
      {
        return true;
      }
    }
    return false;
  }

  void Require(std::vector<std::string>& tokens, const char* what)
  {
    if (!this->Next(tokens))
    {
      this->Fail(std::string("unexpected end of file: expected ") + what);
    }
  }

  [[noreturn]] void Fail(const std::string& message) const
  {
    std::ostringstream text;
    text << this->Name << ":" << this->Line << ": " << message;
    throw ParseError(text.str());
  }

  double Number(const std::string& token, const char* what) const
  {
    const char* begin = token.c_str();
    char* end = nullptr;
    errno = 0;
    const double value = std::strtod(begin, &end);
    if (end == begin || *end || (errno == ERANGE && std::isfinite(value) && value != 0.0))
    {
      this->Fail(std::string("'") + token + "' is not a number (" + what + ")");
    }
    return value;
  }

  long long Integer(const std::string& token, const char* what) const
  {
    const char* begin = token.c_str();
    char* end = nullptr;
    errno = 0;
    const long long value = std::strtoll(begin, &end, 10);
    if (end == begin || *end || errno == ERANGE)
    {
      this->Fail(std::string("'") + token + "' is not an integer (" + what + ")");
    }
    return value;
  }

private:
  std::istream& Stream;
  std::string Name;
  long long Line = 0;
};

struct OFFHeader
{
  bool TextureCoordinates = false;
  bool Colors = false;
  bool Normals = false;
};

// Parses "[ST][C][N]OFF"; false when the keyword is no OFF keyword at all.
bool ParseKeyword(std::string keyword, OFFHeader& header, const OFFLineReader& lines)
{
  if (keyword.size() < 3 || keyword.compare(keyword.size() - 3, 3, "OFF") != 0)
  {
    return false;
  }
  keyword.erase(keyword.size() - 3);
  if (keyword.compare(0, 2, "ST") == 0)
  {
    header.TextureCoordinates = true;
    keyword.erase(0, 2);
  }
  if (!keyword.empty() && keyword[0] == 'C')
  {
    header.Colors = true;
    keyword.erase(0, 1);
  }
  if (!keyword.empty() && keyword[0] == 'N')
  {
    header.Normals = true;
    keyword.erase(0, 1);
  }
  if (keyword == "4" || keyword == "n" || keyword == "4n")
  {
    lines.Fail("4D and n-dimensional OFF vertices are not supported");
  }
  if (!keyword.empty())
  {
    return false;
  }
  return true;
}

unsigned char ColorByte(double value, bool scaled)
{
  const double byte = scaled ? value * 255.0 : value;
  return static_cast<unsigned char>(std::min(255.0, std::max(0.0, std::round(byte))));
}

void Describe(vtkDataArray* array, const char* name, int components)
{
  array->SetName(name);
  array->SetNumberOfComponents(components);
}

// 3 or 4 colour values as RGBA bytes: scaled from 0..1 when none is over 1, else as 0..255.
void ToRGBA(const double* values, size_t count, unsigned char rgba[4])
{
  const bool scaled = std::all_of(values, values + count, [](double v) { return v <= 1.0; });
  for (size_t c = 0; c < count; ++c)
  {
    rgba[c] = ColorByte(values[c], scaled);
  }
}

// The mesh as the file's parts are read: the header and its counts, the vertices with their
// attributes, the faces with their colours; then what is left of the file.
class OFFMesh
{
public:
  explicit OFFMesh(OFFLineReader& lines)
    : Lines(lines)
  {
  }

  void ReadHeader()
  {
    this->Lines.Require(this->Tokens, "the OFF keyword");
    if (!ParseKeyword(this->Tokens[0], this->Header, this->Lines))
    {
      this->Lines.Fail(
        "'" + this->Tokens[0] + "' is no OFF keyword (OFF, COFF, NOFF, CNOFF, STOFF, ...)");
    }
    if (this->Tokens.size() > 1 && this->Tokens[1] == "BINARY")
    {
      this->Lines.Fail("binary OFF is not supported");
    }
    this->Tokens.erase(this->Tokens.begin());
    if (this->Tokens.empty())
    {
      this->Lines.Require(this->Tokens, "the counts 'vertices faces edges'");
    }
    if (this->Tokens.size() < 2 || this->Tokens.size() > 3)
    {
      this->Lines.Fail("expected the counts 'vertices faces [edges]'");
    }
    this->NumberOfVertices = this->Lines.Integer(this->Tokens[0], "vertex count");
    this->NumberOfFaces = this->Lines.Integer(this->Tokens[1], "face count");
    if (this->NumberOfVertices < 0 || this->NumberOfFaces < 0)
    {
      this->Lines.Fail("negative vertex or face count");
    }
  }

  void ReadVertices()
  {
    this->Points->SetDataTypeToDouble();
    // The count is only the file's word (a mutated one asked for 2^31 points): reserve a little,
    // grow as the vertex lines come.
    this->Points->Allocate(
      static_cast<vtkIdType>(std::min<long long>(this->NumberOfVertices, 1 << 16)));
    Describe(this->Normals, "Normals", 3);
    Describe(this->TextureCoordinates, "TextureCoordinates", 2);
    Describe(this->PointColors, "Colors", 4);
    for (long long i = 0; i < this->NumberOfVertices; ++i)
    {
      this->Lines.Require(this->Tokens, "a vertex line");
      this->ReadVertex();
    }
  }

  void ReadFaces()
  {
    Describe(this->FaceColors, "Colors", 4);
    for (long long f = 0; f < this->NumberOfFaces; ++f)
    {
      this->Lines.Require(this->Tokens, "a face line");
      this->ReadFace();
    }
  }

  void CheckEnd()
  {
    if (this->Lines.Next(this->Tokens))
    {
      this->Lines.Fail("unexpected content after the last face ('" + this->Tokens[0] + "')");
    }
  }

  void CopyTo(vtkPolyData* output) const
  {
    output->SetPoints(this->Points);
    output->SetPolys(this->Polygons);
    if (this->Header.Normals)
    {
      output->GetPointData()->SetNormals(this->Normals);
    }
    if (this->Header.TextureCoordinates)
    {
      output->GetPointData()->SetTCoords(this->TextureCoordinates);
    }
    if (this->Header.Colors)
    {
      output->GetPointData()->SetScalars(this->PointColors);
    }
    else if (this->AnyFaceColor)
    {
      output->GetCellData()->SetScalars(this->FaceColors);
    }
  }

private:
  // "x y z [nx ny nz] [r g b [a]] [s t]", as the header's prefixes say.
  void ReadVertex()
  {
    const OFFHeader& header = this->Header;
    const size_t valuesPerVertex =
      3 + (header.Normals ? 3 : 0) + (header.TextureCoordinates ? 2 : 0);
    if (this->Tokens.size() < valuesPerVertex)
    {
      this->Lines.Fail("vertex line has " + std::to_string(this->Tokens.size()) +
        " values, expected " + std::to_string(valuesPerVertex) +
        (header.Colors ? " and a colour" : ""));
    }
    std::vector<double> values;
    for (const std::string& token : this->Tokens)
    {
      values.push_back(this->Lines.Number(token, "vertex"));
    }
    this->Points->InsertNextPoint(values[0], values[1], values[2]);
    size_t next = 3;
    if (header.Normals)
    {
      this->Normals->InsertNextTuple3(values[next], values[next + 1], values[next + 2]);
      next += 3;
    }
    if (header.Colors)
    {
      const size_t count = values.size() - next - (header.TextureCoordinates ? 2 : 0);
      if (count != 3 && count != 4)
      {
        this->Lines.Fail("a vertex colour has 3 or 4 values, found " + std::to_string(count));
      }
      unsigned char rgba[4] = { 0, 0, 0, 255 };
      ToRGBA(values.data() + next, count, rgba);
      this->PointColors->InsertNextTypedTuple(rgba);
      next += count;
    }
    if (header.TextureCoordinates)
    {
      this->TextureCoordinates->InsertNextTuple2(values[next], values[next + 1]);
      next += 2;
    }
    if (next != values.size())
    {
      this->Lines.Fail("vertex line has " + std::to_string(values.size() - next) + " extra values");
    }
  }

  // "n i0 ... i(n-1) [r g b [a]]"
  void ReadFace()
  {
    const long long size = this->Lines.Integer(this->Tokens[0], "face size");
    if (size < 3)
    {
      this->Lines.Fail("a face needs at least 3 vertices, this one has " + std::to_string(size));
    }
    if (static_cast<long long>(this->Tokens.size()) < size + 1)
    {
      this->Lines.Fail("face line lists " + std::to_string(this->Tokens.size() - 1) +
        " indices of " + std::to_string(size));
    }
    this->Ids.resize(static_cast<size_t>(size));
    for (long long k = 0; k < size; ++k)
    {
      const long long index =
        this->Lines.Integer(this->Tokens[static_cast<size_t>(k + 1)], "face index");
      if (index < 0 || index >= this->NumberOfVertices)
      {
        this->Lines.Fail("face index " + std::to_string(index) + " is out of range [0, " +
          std::to_string(this->NumberOfVertices) + ")");
      }
      this->Ids[static_cast<size_t>(k)] = static_cast<vtkIdType>(index);
    }
    this->Polygons->InsertNextCell(static_cast<vtkIdType>(size), this->Ids.data());
    this->ReadFaceColor(static_cast<size_t>(size) + 1);
  }

  // The face's colour from tokens[first] on, white when it has none.
  void ReadFaceColor(size_t first)
  {
    const size_t colorCount = this->Tokens.size() - first;
    unsigned char rgba[4] = { 255, 255, 255, 255 };
    if (colorCount != 0)
    {
      if (colorCount != 3 && colorCount != 4)
      {
        this->Lines.Fail("a face colour has 3 or 4 values, found " + std::to_string(colorCount));
      }
      std::vector<double> color;
      for (size_t c = 0; c < colorCount; ++c)
      {
        color.push_back(this->Lines.Number(this->Tokens[first + c], "face colour"));
      }
      ToRGBA(color.data(), colorCount, rgba);
      this->AnyFaceColor = true;
    }
    this->FaceColors->InsertNextTypedTuple(rgba);
  }

  OFFLineReader& Lines;
  std::vector<std::string> Tokens;
  OFFHeader Header;
  long long NumberOfVertices = 0;
  long long NumberOfFaces = 0;
  vtkNew<vtkPoints> Points;
  vtkNew<vtkFloatArray> Normals;
  vtkNew<vtkFloatArray> TextureCoordinates;
  vtkNew<vtkUnsignedCharArray> PointColors;
  vtkNew<vtkCellArray> Polygons;
  vtkNew<vtkUnsignedCharArray> FaceColors;
  bool AnyFaceColor = false;
  std::vector<vtkIdType> Ids;
};
}

vtkNPROFFReader::vtkNPROFFReader()
{
  this->SetNumberOfInputPorts(0);
}

vtkNPROFFReader::~vtkNPROFFReader()
{
  this->SetFileName(nullptr);
}

void vtkNPROFFReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "ErrorMessage: " << this->ErrorMessage << "\n";
}

bool vtkNPROFFReader::CanReadFile(const char* fileName)
{
  std::ifstream stream(fileName ? fileName : "");
  if (!stream)
  {
    return false;
  }
  OFFLineReader lines(stream, fileName);
  std::vector<std::string> tokens;
  OFFHeader header;
  try
  {
    return lines.Next(tokens) && ParseKeyword(tokens[0], header, lines);
  }
  catch (const ParseError&)
  {
    return false;
  }
}

int vtkNPROFFReader::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  this->ErrorMessage.clear();
  const std::string name = this->FileName ? this->FileName : "";
  std::ifstream stream(name, std::ios::in);
  if (name.empty() || !stream)
  {
    this->ErrorMessage = name.empty() ? "no file name given" : name + ": cannot be opened";
    vtkErrorMacro(<< this->ErrorMessage);
    return 0;
  }

  OFFLineReader lines(stream, name);
  try
  {
    OFFMesh mesh(lines);
    mesh.ReadHeader();
    mesh.ReadVertices();
    mesh.ReadFaces();
    mesh.CheckEnd();
    mesh.CopyTo(output);
  }
  catch (const ParseError& error)
  {
    output->Initialize();
    this->ErrorMessage = error.what();
    vtkErrorMacro(<< this->ErrorMessage);
    return 0;
  }
  return 1;
}
