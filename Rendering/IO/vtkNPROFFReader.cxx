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
  std::vector<std::string> tokens;
  try
  {
    lines.Require(tokens, "the OFF keyword");
    OFFHeader header;
    if (!ParseKeyword(tokens[0], header, lines))
    {
      lines.Fail("'" + tokens[0] + "' is no OFF keyword (OFF, COFF, NOFF, CNOFF, STOFF, ...)");
    }
    if (tokens.size() > 1 && tokens[1] == "BINARY")
    {
      lines.Fail("binary OFF is not supported");
    }
    tokens.erase(tokens.begin());
    if (tokens.empty())
    {
      lines.Require(tokens, "the counts 'vertices faces edges'");
    }
    if (tokens.size() < 2 || tokens.size() > 3)
    {
      lines.Fail("expected the counts 'vertices faces [edges]'");
    }
    const long long numberOfVertices = lines.Integer(tokens[0], "vertex count");
    const long long numberOfFaces = lines.Integer(tokens[1], "face count");
    if (numberOfVertices < 0 || numberOfFaces < 0)
    {
      lines.Fail("negative vertex or face count");
    }

    const size_t valuesPerVertex =
      3 + (header.Normals ? 3 : 0) + (header.TextureCoordinates ? 2 : 0);
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    // The count is only the file's word (a mutated one asked for 2^31 points): reserve a little,
    // grow as the vertex lines come.
    points->Allocate(static_cast<vtkIdType>(std::min<long long>(numberOfVertices, 1 << 16)));
    vtkNew<vtkFloatArray> normals;
    normals->SetName("Normals");
    normals->SetNumberOfComponents(3);
    vtkNew<vtkFloatArray> textureCoordinates;
    textureCoordinates->SetName("TextureCoordinates");
    textureCoordinates->SetNumberOfComponents(2);
    vtkNew<vtkUnsignedCharArray> pointColors;
    pointColors->SetName("Colors");
    pointColors->SetNumberOfComponents(4);

    for (long long i = 0; i < numberOfVertices; ++i)
    {
      lines.Require(tokens, "a vertex line");
      if (tokens.size() < valuesPerVertex)
      {
        lines.Fail("vertex line has " + std::to_string(tokens.size()) + " values, expected " +
          std::to_string(valuesPerVertex) + (header.Colors ? " and a colour" : ""));
      }
      std::vector<double> values;
      for (const std::string& token : tokens)
      {
        values.push_back(lines.Number(token, "vertex"));
      }
      size_t next = 0;
      points->InsertNextPoint(values[0], values[1], values[2]);
      next = 3;
      if (header.Normals)
      {
        normals->InsertNextTuple3(values[next], values[next + 1], values[next + 2]);
        next += 3;
      }
      if (header.Colors)
      {
        const size_t count = values.size() - next - (header.TextureCoordinates ? 2 : 0);
        if (count != 3 && count != 4)
        {
          lines.Fail("a vertex colour has 3 or 4 values, found " + std::to_string(count));
        }
        const bool scaled = std::all_of(
          values.begin() + next, values.begin() + next + count, [](double v) { return v <= 1.0; });
        unsigned char rgba[4] = { 0, 0, 0, 255 };
        for (size_t c = 0; c < count; ++c)
        {
          rgba[c] = ColorByte(values[next + c], scaled);
        }
        pointColors->InsertNextTypedTuple(rgba);
        next += count;
      }
      if (header.TextureCoordinates)
      {
        textureCoordinates->InsertNextTuple2(values[next], values[next + 1]);
        next += 2;
      }
      if (next != values.size())
      {
        lines.Fail("vertex line has " + std::to_string(values.size() - next) + " extra values");
      }
    }

    vtkNew<vtkCellArray> polygons;
    vtkNew<vtkUnsignedCharArray> faceColors;
    faceColors->SetName("Colors");
    faceColors->SetNumberOfComponents(4);
    bool anyFaceColor = false;
    std::vector<vtkIdType> ids;
    for (long long f = 0; f < numberOfFaces; ++f)
    {
      lines.Require(tokens, "a face line");
      const long long size = lines.Integer(tokens[0], "face size");
      if (size < 3)
      {
        lines.Fail("a face needs at least 3 vertices, this one has " + std::to_string(size));
      }
      if (static_cast<long long>(tokens.size()) < size + 1)
      {
        lines.Fail("face line lists " + std::to_string(tokens.size() - 1) + " indices of " +
          std::to_string(size));
      }
      ids.resize(static_cast<size_t>(size));
      for (long long k = 0; k < size; ++k)
      {
        const long long index = lines.Integer(tokens[static_cast<size_t>(k + 1)], "face index");
        if (index < 0 || index >= numberOfVertices)
        {
          lines.Fail("face index " + std::to_string(index) + " is out of range [0, " +
            std::to_string(numberOfVertices) + ")");
        }
        ids[static_cast<size_t>(k)] = static_cast<vtkIdType>(index);
      }
      polygons->InsertNextCell(static_cast<vtkIdType>(size), ids.data());

      const size_t colorCount = tokens.size() - static_cast<size_t>(size) - 1;
      unsigned char rgba[4] = { 255, 255, 255, 255 };
      if (colorCount != 0)
      {
        if (colorCount != 3 && colorCount != 4)
        {
          lines.Fail("a face colour has 3 or 4 values, found " + std::to_string(colorCount));
        }
        std::vector<double> color;
        for (size_t c = 0; c < colorCount; ++c)
        {
          color.push_back(lines.Number(tokens[static_cast<size_t>(size) + 1 + c], "face colour"));
        }
        const bool scaled =
          std::all_of(color.begin(), color.end(), [](double v) { return v <= 1.0; });
        for (size_t c = 0; c < colorCount; ++c)
        {
          rgba[c] = ColorByte(color[c], scaled);
        }
        anyFaceColor = true;
      }
      faceColors->InsertNextTypedTuple(rgba);
    }
    if (lines.Next(tokens))
    {
      lines.Fail("unexpected content after the last face ('" + tokens[0] + "')");
    }

    output->SetPoints(points);
    output->SetPolys(polygons);
    if (header.Normals)
    {
      output->GetPointData()->SetNormals(normals);
    }
    if (header.TextureCoordinates)
    {
      output->GetPointData()->SetTCoords(textureCoordinates);
    }
    if (header.Colors)
    {
      output->GetPointData()->SetScalars(pointColors);
    }
    else if (anyFaceColor)
    {
      output->GetCellData()->SetScalars(faceColors);
    }
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
