// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNPRModelReader.h"

#include "vtkCallbackCommand.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCompositeDataGeometryFilter.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataArray.h"
#include "vtkDataSetReader.h"
#include "vtkDataSetSurfaceFilter.h"
#include "vtkGLTFReader.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNPRGLTFChecks.h"
#include "vtkNPRModelFormatChecks.h"
#include "vtkNPROFFReader.h"
#include "vtkNew.h"
#include "vtkOBJReader.h"
#include "vtkObjectFactory.h"
#include "vtkPLYReader.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSTLReader.h"
#include "vtkSmartPointer.h"
#include "vtkXMLPolyDataReader.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sys/stat.h>
#include <vector>

vtkStandardNewMacro(vtkNPRModelReader);

namespace
{
std::string LowerCaseExtension(const std::string& fileName)
{
  const size_t dot = fileName.find_last_of('.');
  const size_t slash = fileName.find_last_of('/');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash))
  {
    return "";
  }
  std::string extension = fileName.substr(dot);
  std::transform(extension.begin(), extension.end(), extension.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension;
}

// Collects the first error (and warning) a reader reports, instead of printing it.
class MessageCatcher
{
public:
  explicit MessageCatcher(vtkObject* reader)
  {
    this->Callback->SetClientData(this);
    this->Callback->SetCallback(&MessageCatcher::Catch);
    reader->AddObserver(vtkCommand::ErrorEvent, this->Callback);
    reader->AddObserver(vtkCommand::WarningEvent, this->Callback);
  }
  std::string Error;
  std::string Warning;

private:
  static void Catch(vtkObject*, unsigned long event, void* clientData, void* callData)
  {
    auto* self = static_cast<MessageCatcher*>(clientData);
    std::string& slot = event == vtkCommand::ErrorEvent ? self->Error : self->Warning;
    if (slot.empty() && callData)
    {
      slot = static_cast<const char*>(callData);
      // VTK's messages carry the class and file position on their first lines; keep the last.
      while (!slot.empty() && std::isspace(static_cast<unsigned char>(slot.back())))
      {
        slot.pop_back();
      }
      const size_t newline = slot.find_last_of('\n');
      if (newline != std::string::npos)
      {
        slot.erase(0, newline + 1);
      }
      const size_t owner = slot.find("): "); // "vtkSTLReader (0x...): "
      if (slot.compare(0, 3, "vtk") == 0 && owner != std::string::npos)
      {
        slot.erase(0, owner + 3);
      }
    }
  }
  vtkNew<vtkCallbackCommand> Callback;
};

template <typename ReaderType>
vtkSmartPointer<ReaderType> NewReader(const std::string& name)
{
  auto reader = vtkSmartPointer<ReaderType>::New();
  reader->SetFileName(name.c_str());
  return reader;
}

vtkSmartPointer<vtkAlgorithm> MakeReader(const std::string& extension, const std::string& name)
{
  if (extension == ".stl")
  {
    auto reader = NewReader<vtkSTLReader>(name);
    reader->MergingOff(); // keep the file's vertices as they are
    return reader;
  }
  if (extension == ".obj")
  {
    return NewReader<vtkOBJReader>(name);
  }
  if (extension == ".ply")
  {
    return NewReader<vtkPLYReader>(name);
  }
  if (extension == ".vtp")
  {
    return NewReader<vtkXMLPolyDataReader>(name);
  }
  if (extension == ".vtk")
  {
    return NewReader<vtkDataSetReader>(name);
  }
  if (extension == ".gltf" || extension == ".glb")
  {
    return NewReader<vtkGLTFReader>(name);
  }
  if (extension == ".off")
  {
    return NewReader<vtkNPROFFReader>(name);
  }
  return nullptr;
}

// Copies the cells of one kind whose points all exist and are finite, renumbering their points;
// counts those dropped for a non-finite point and for a point index out of range.
void CopyDrawableCells(vtkCellArray* cells, const std::vector<vtkIdType>& newPointIds,
  vtkIdType& inputCellId, vtkCellData* inputData, vtkCellData* outputData, vtkCellArray* kept,
  vtkIdType& nonFinite, vtkIdType& outOfRange)
{
  const vtkIdType numberOfPoints = static_cast<vtkIdType>(newPointIds.size());
  vtkIdType size = 0;
  const vtkIdType* ids = nullptr;
  std::vector<vtkIdType> renumbered;
  for (cells->InitTraversal(); cells->GetNextCell(size, ids); ++inputCellId)
  {
    renumbered.resize(static_cast<size_t>(size));
    bool exists = true, finite = true;
    for (vtkIdType k = 0; k < size && exists; ++k)
    {
      exists = ids[k] >= 0 && ids[k] < numberOfPoints;
      renumbered[static_cast<size_t>(k)] = exists ? newPointIds[static_cast<size_t>(ids[k])] : -1;
      finite = finite && renumbered[static_cast<size_t>(k)] >= 0;
    }
    if (!exists || !finite)
    {
      ++(exists ? nonFinite : outOfRange);
      continue;
    }
    kept->InsertNextCell(size, renumbered.data());
    if (outputData)
    {
      outputData->CopyData(inputData, inputCellId, outputData->GetNumberOfTuples());
    }
  }
}
}

vtkNPRModelReader::vtkNPRModelReader()
{
  this->SetNumberOfInputPorts(0);
}

vtkNPRModelReader::~vtkNPRModelReader()
{
  this->SetFileName(nullptr);
}

void vtkNPRModelReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "ErrorMessage: " << this->ErrorMessage << "\n";
  os << indent << "NumberOfDroppedPoints: " << this->NumberOfDroppedPoints << "\n";
  os << indent << "NumberOfDroppedCells: " << this->NumberOfDroppedCells << "\n";
  os << indent << "NumberOfOutOfRangeCells: " << this->NumberOfOutOfRangeCells << "\n";
}

const char* vtkNPRModelReader::GetSupportedExtensions()
{
  return ".stl .obj .ply .vtp .vtk .gltf .glb .off";
}

bool vtkNPRModelReader::IsSupportedFileName(const char* fileName)
{
  const std::string extension = LowerCaseExtension(fileName ? fileName : "");
  const std::string supported = std::string(GetSupportedExtensions()) + " ";
  return !extension.empty() && supported.find(extension + " ") != std::string::npos;
}

bool vtkNPRModelReader::Fail(const std::string& message)
{
  // One line, whatever the file put into it (an attribute value, VTK's message).
  this->ErrorMessage = message;
  for (char& c : this->ErrorMessage)
  {
    c = (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) ? ' ' : c;
  }
  vtkErrorMacro(<< this->ErrorMessage);
  return false;
}

int vtkNPRModelReader::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  this->ErrorMessage.clear();
  this->WarningMessage.clear();
  this->NumberOfDroppedPoints = 0;
  this->NumberOfDroppedCells = 0;
  this->NumberOfOutOfRangeCells = 0;
  if (!this->Read(this->FileName ? this->FileName : "", output))
  {
    output->Initialize();
    return 0;
  }
  return 1;
}

bool vtkNPRModelReader::Read(const std::string& name, vtkPolyData* output)
{
  if (name.empty())
  {
    return this->Fail("no model file name given");
  }
  struct stat status;
  if (stat(name.c_str(), &status) != 0)
  {
    return this->Fail(name + ": no such file");
  }
  if (S_ISDIR(status.st_mode))
  {
    return this->Fail(name + ": is a directory, not a model file");
  }
  if (!std::ifstream(name, std::ios::binary))
  {
    return this->Fail(name + ": cannot be read (permission denied?)");
  }
  if (status.st_size == 0)
  {
    return this->Fail(name + ": is empty (0 bytes)");
  }
  const std::string extension = LowerCaseExtension(name);
  vtkSmartPointer<vtkAlgorithm> reader = MakeReader(extension, name);
  if (!reader)
  {
    return this->Fail(name + ": unknown model format '" + extension +
      "' (supported: " + GetSupportedExtensions() + ")");
  }
  std::vector<long long> nonFiniteOBJVertices;
  long long objVertices = 0;
  std::string structureError;
  if (extension == ".ply")
  {
    structureError = vtkNPRModelFormatChecks::CheckPLY(name);
  }
  else if (extension == ".stl")
  {
    structureError = vtkNPRModelFormatChecks::CheckSTL(name);
  }
  else if (extension == ".obj")
  {
    structureError = vtkNPRModelFormatChecks::CheckOBJ(name, nonFiniteOBJVertices, objVertices);
  }
  else if (extension == ".vtp")
  {
    structureError = vtkNPRModelFormatChecks::CheckVTP(name);
  }
  else if (extension == ".vtk")
  {
    structureError = vtkNPRModelFormatChecks::CheckLegacyVTK(name);
  }
  else if (extension == ".gltf" || extension == ".glb")
  {
    structureError = vtkNPRGLTFChecks::CheckGLTF(name);
  }
  if (!structureError.empty())
  {
    return this->Fail(name + ": " + structureError);
  }

  MessageCatcher messages(reader);
  reader->Update();
  vtkDataObject* data = reader->GetOutputDataObject(0);
  if (auto* off = vtkNPROFFReader::SafeDownCast(reader))
  {
    if (*off->GetErrorMessage())
    {
      return this->Fail(off->GetErrorMessage()); // already "file:line: what"
    }
  }
  if (!messages.Error.empty())
  {
    return this->Fail(
      name + ": malformed or unreadable " + extension.substr(1) + " file: " + messages.Error);
  }

  // Every format ends as one polydata: composite (glTF) and non-polygonal (legacy) data too.
  vtkSmartPointer<vtkPolyData> surface;
  if (auto* polyData = vtkPolyData::SafeDownCast(data))
  {
    surface = polyData;
  }
  else if (vtkCompositeDataSet::SafeDownCast(data))
  {
    vtkNew<vtkCompositeDataGeometryFilter> merge;
    merge->SetInputData(data);
    merge->Update();
    surface = merge->GetOutput();
  }
  else if (auto* dataSet = vtkDataSet::SafeDownCast(data))
  {
    vtkNew<vtkDataSetSurfaceFilter> extract;
    extract->SetInputData(dataSet);
    extract->Update();
    surface = extract->GetOutput();
  }
  if (!surface || surface->GetNumberOfCells() == 0 || surface->GetNumberOfPoints() == 0)
  {
    return this->Fail(name + ": contains no geometry (no points or no cells)");
  }

  for (vtkCellArray* cells :
    { surface->GetVerts(), surface->GetLines(), surface->GetPolys(), surface->GetStrips() })
  {
    if (cells && !cells->IsValid()) // offsets that run past the connectivity (a VTP file's)
    {
      return this->Fail(name + ": malformed " + extension.substr(1) +
        " file: inconsistent cell offsets and connectivity");
    }
  }
  vtkPoints* points = surface->GetPoints();
  const vtkIdType numberOfPoints = points->GetNumberOfPoints();
  if (!nonFiniteOBJVertices.empty())
  {
    // vtkOBJReader reads "nan" and "inf" as numbers of its own: mark those vertices, which it
    // keeps in file order unless faces give texture or normal indices of their own per corner.
    if (numberOfPoints != objVertices || points->GetData()->GetNumberOfComponents() != 3)
    {
      return this->Fail(name +
        ": NaN/Inf vertices in an OBJ file whose faces give per-corner "
        "texture or normal indices are not supported");
    }
    vtkNew<vtkPoints> marked;
    marked->DeepCopy(points);
    for (long long vertex : nonFiniteOBJVertices)
    {
      const double nan = std::nan("");
      marked->SetPoint(static_cast<vtkIdType>(vertex), nan, nan, nan);
    }
    auto copy = vtkSmartPointer<vtkPolyData>::New();
    copy->ShallowCopy(surface);
    copy->SetPoints(marked);
    surface = copy;
    points = marked;
  }

  // Drop points with NaN or infinite coordinates, the cells that use them, and cells that name
  // a point that does not exist (VTP and VTK files, which VTK's readers take as they are).
  std::vector<vtkIdType> newPointIds(static_cast<size_t>(numberOfPoints), -1);
  vtkIdType finitePoints = 0;
  for (vtkIdType i = 0; i < numberOfPoints; ++i)
  {
    double p[3];
    points->GetPoint(i, p);
    if (std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]))
    {
      newPointIds[static_cast<size_t>(i)] = finitePoints++;
    }
  }
  vtkIdType nonFiniteCells = 0, outOfRangeCells = 0;
  {
    vtkIdType cellId = 0;
    vtkNew<vtkCellArray> scratch;
    for (vtkCellArray* cells :
      { surface->GetVerts(), surface->GetLines(), surface->GetPolys(), surface->GetStrips() })
    {
      CopyDrawableCells(
        cells, newPointIds, cellId, nullptr, nullptr, scratch, nonFiniteCells, outOfRangeCells);
      scratch->Reset();
    }
  }
  if (finitePoints == numberOfPoints && outOfRangeCells == 0)
  {
    output->ShallowCopy(surface);
  }
  else
  {
    vtkNew<vtkPoints> keptPoints;
    keptPoints->SetDataType(points->GetDataType());
    keptPoints->SetNumberOfPoints(finitePoints);
    output->GetPointData()->CopyAllocate(surface->GetPointData(), finitePoints);
    for (vtkIdType i = 0; i < numberOfPoints; ++i)
    {
      const vtkIdType target = newPointIds[static_cast<size_t>(i)];
      if (target >= 0)
      {
        keptPoints->SetPoint(target, points->GetPoint(i));
        output->GetPointData()->CopyData(surface->GetPointData(), i, target);
      }
    }
    output->SetPoints(keptPoints);
    output->GetCellData()->CopyAllocate(surface->GetCellData(), surface->GetNumberOfCells());

    // vtkPolyData numbers its cells vertices first, then lines, polygons, strips.
    vtkIdType inputCellId = 0;
    nonFiniteCells = outOfRangeCells = 0;
    vtkNew<vtkCellArray> verts, lines, polys, strips;
    CopyDrawableCells(surface->GetVerts(), newPointIds, inputCellId, surface->GetCellData(),
      output->GetCellData(), verts, nonFiniteCells, outOfRangeCells);
    CopyDrawableCells(surface->GetLines(), newPointIds, inputCellId, surface->GetCellData(),
      output->GetCellData(), lines, nonFiniteCells, outOfRangeCells);
    CopyDrawableCells(surface->GetPolys(), newPointIds, inputCellId, surface->GetCellData(),
      output->GetCellData(), polys, nonFiniteCells, outOfRangeCells);
    CopyDrawableCells(surface->GetStrips(), newPointIds, inputCellId, surface->GetCellData(),
      output->GetCellData(), strips, nonFiniteCells, outOfRangeCells);
    output->SetVerts(verts);
    output->SetLines(lines);
    output->SetPolys(polys);
    output->SetStrips(strips);
    this->NumberOfDroppedPoints = numberOfPoints - finitePoints;
    this->NumberOfDroppedCells = nonFiniteCells + outOfRangeCells;
    this->NumberOfOutOfRangeCells = outOfRangeCells;
  }

  std::string dropped;
  if (this->NumberOfDroppedPoints)
  {
    dropped = "dropped " + std::to_string(this->NumberOfDroppedPoints) +
      " points with NaN/Inf coordinates and the " + std::to_string(nonFiniteCells) +
      " cells that use them";
  }
  if (outOfRangeCells)
  {
    dropped += std::string(dropped.empty() ? "dropped " : ", and ") +
      std::to_string(outOfRangeCells) + " cells that use a point index past the " +
      std::to_string(numberOfPoints) + " points";
  }
  if (output->GetNumberOfCells() == 0)
  {
    return this->Fail(name + ": nothing to draw: no cell is left after it " + dropped);
  }

  // Nothing drawable: every point used by a cell at one spot or on one line.
  double bounds[6] = { VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX,
    VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
  vtkPoints* keptPoints = output->GetPoints();
  for (vtkCellArray* cells :
    { output->GetVerts(), output->GetLines(), output->GetPolys(), output->GetStrips() })
  {
    vtkIdType size = 0;
    const vtkIdType* ids = nullptr;
    for (cells->InitTraversal(); cells->GetNextCell(size, ids);)
    {
      for (vtkIdType k = 0; k < size; ++k)
      {
        double p[3];
        keptPoints->GetPoint(ids[k], p);
        for (int axis = 0; axis < 3; ++axis)
        {
          bounds[2 * axis] = std::min(bounds[2 * axis], p[axis]);
          bounds[2 * axis + 1] = std::max(bounds[2 * axis + 1], p[axis]);
        }
      }
    }
  }
  int flatAxes = 0;
  for (int axis = 0; axis < 3; ++axis)
  {
    flatAxes += !(bounds[2 * axis + 1] > bounds[2 * axis]);
  }
  if (flatAxes >= 2)
  {
    return this->Fail(name + ": nothing to draw: every point of its " +
      std::to_string(output->GetNumberOfCells()) + " cells lies " +
      (flatAxes == 3 ? "at one spot" : "on one line") + " (zero-area bounds)" +
      (dropped.empty() ? std::string() : " after it " + dropped));
  }
  if (!dropped.empty())
  {
    this->WarningMessage = name + ": " + dropped;
    vtkWarningMacro(<< this->WarningMessage);
  }
  return true;
}
