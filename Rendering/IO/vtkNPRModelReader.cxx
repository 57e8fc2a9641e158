// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNPRModelReader.h"

#include "vtkCallbackCommand.h"
#include "vtkCellArray.h"
#include "vtkCompositeDataGeometryFilter.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataArray.h"
#include "vtkDataSetReader.h"
#include "vtkDataSetSurfaceFilter.h"
#include "vtkGLTFReader.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNPRBinaryPLY.h"
#include "vtkNPRDrawableSurface.h"
#include "vtkNPRModelFormatChecks.h"
#include "vtkNPROFFReader.h"
#include "vtkNew.h"
#include "vtkOBJReader.h"
#include "vtkObjectFactory.h"
#include "vtkPLYReader.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSTLReader.h"
#include "vtkSmartPointer.h"
#include "vtkTimerLog.h"
#include "vtkXMLPolyDataReader.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>
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

// Why the file cannot be read at all, or "".
std::string CheckFile(const std::string& name)
{
  if (name.empty())
  {
    return "no model file name given";
  }
  struct stat status;
  if (stat(name.c_str(), &status) != 0)
  {
    return name + ": no such file";
  }
  if (S_ISDIR(status.st_mode))
  {
    return name + ": is a directory, not a model file";
  }
  if (!std::ifstream(name, std::ios::binary))
  {
    return name + ": cannot be read (permission denied?)";
  }
  if (status.st_size == 0)
  {
    return name + ": is empty (0 bytes)";
  }
  return "";
}

// Runs VTK's reader and makes one polydata of what it read: composite (glTF) and
// non-polygonal (legacy) data too. Returns why it failed, or "".
std::string ReadSurface(vtkAlgorithm* reader, const std::string& name, const std::string& extension,
  vtkSmartPointer<vtkPolyData>& surface)
{
  MessageCatcher messages(reader);
  reader->Update();
  vtkDataObject* data = reader->GetOutputDataObject(0);
  auto* off = vtkNPROFFReader::SafeDownCast(reader);
  if (off && *off->GetErrorMessage())
  {
    return off->GetErrorMessage(); // already "file:line: what"
  }
  if (!messages.Error.empty())
  {
    return name + ": malformed or unreadable " + extension.substr(1) + " file: " + messages.Error;
  }
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
  return "";
}

// Why what was read cannot be drawn at all, or "".
std::string CheckSurface(
  const std::string& name, const std::string& extension, vtkPolyData* surface)
{
  if (!surface || surface->GetNumberOfCells() == 0 || surface->GetNumberOfPoints() == 0)
  {
    return name + ": contains no geometry (no points or no cells)";
  }
  for (vtkCellArray* cells :
    { surface->GetVerts(), surface->GetLines(), surface->GetPolys(), surface->GetStrips() })
  {
    if (cells && !cells->IsValid()) // offsets that run past the connectivity (a VTP file's)
    {
      return name + ": malformed " + extension.substr(1) +
        " file: inconsistent cell offsets and connectivity";
    }
  }
  return "";
}

// vtkOBJReader reads "nan" and "inf" as numbers of its own: the vertices CheckOBJ found with
// them made NaN again, so that the point check drops them. It keeps the vertices in file order
// unless faces give texture or normal indices of their own per corner.
std::string MarkNonFiniteOBJVertices(const std::string& name,
  const vtkNPRModelFormatChecks::OBJVertices& objVertices, vtkSmartPointer<vtkPolyData>& surface)
{
  if (objVertices.NonFinite.empty())
  {
    return "";
  }
  vtkPoints* points = surface->GetPoints();
  if (points->GetNumberOfPoints() != objVertices.Count ||
    points->GetData()->GetNumberOfComponents() != 3)
  {
    return name +
      ": NaN/Inf vertices in an OBJ file whose faces give per-corner texture or normal "
      "indices are not supported";
  }
  vtkNew<vtkPoints> marked;
  marked->DeepCopy(points);
  for (long long vertex : objVertices.NonFinite)
  {
    const double nan = std::nan("");
    marked->SetPoint(static_cast<vtkIdType>(vertex), nan, nan, nan);
  }
  auto copy = vtkSmartPointer<vtkPolyData>::New();
  copy->ShallowCopy(surface);
  copy->SetPoints(marked);
  surface = copy;
  return "";
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
  std::string error = CheckFile(name);
  if (!error.empty())
  {
    return this->Fail(error);
  }
  const std::string extension = LowerCaseExtension(name);
  vtkSmartPointer<vtkAlgorithm> reader = MakeReader(extension, name);
  if (!reader)
  {
    return this->Fail(name + ": unknown model format '" + extension +
      "' (supported: " + GetSupportedExtensions() + ")");
  }
  bool handled = false;
  const bool read = extension == ".ply" && this->ReadBinaryPLY(name, output, handled);
  if (handled)
  {
    return read;
  }
  vtkNPRModelFormatChecks::OBJVertices objVertices;
  vtkTimerLog::MarkStartEvent("vtkNPRModelReader: validate");
  error = vtkNPRModelFormatChecks::Check(extension, name, objVertices);
  vtkTimerLog::MarkEndEvent("vtkNPRModelReader: validate");
  if (!error.empty())
  {
    return this->Fail(name + ": " + error);
  }
  vtkTimerLog::MarkStartEvent("vtkNPRModelReader: read");
  vtkSmartPointer<vtkPolyData> surface;
  error = ReadSurface(reader, name, extension, surface);
  if (error.empty())
  {
    error = CheckSurface(name, extension, surface);
  }
  if (error.empty())
  {
    error = MarkNonFiniteOBJVertices(name, objVertices, surface);
  }
  vtkTimerLog::MarkEndEvent("vtkNPRModelReader: read");
  if (!error.empty())
  {
    return this->Fail(error);
  }
  return this->KeepDrawable(name, surface, output);
}

bool vtkNPRModelReader::ReadBinaryPLY(const std::string& name, vtkPolyData* output, bool& handled)
{
  // The common binary layout, checked as it is read (so no separate check step); anything else,
  // and a file it refuses, goes the checked way with vtkPLYReader (handled stays false).
  vtkTimerLog::MarkStartEvent("vtkNPRModelReader: read");
  vtkNew<vtkPolyData> surface;
  handled = vtkNPRBinaryPLY::Read(name, surface) && CheckSurface(name, ".ply", surface).empty();
  vtkTimerLog::MarkEndEvent("vtkNPRModelReader: read");
  if (!handled)
  {
    return false;
  }
  return this->KeepDrawable(name, surface, output);
}

bool vtkNPRModelReader::KeepDrawable(
  const std::string& name, vtkPolyData* surface, vtkPolyData* output)
{
  vtkTimerLog::MarkStartEvent("vtkNPRModelReader: check points");
  const bool drawable = this->DropUndrawable(name, surface, output);
  vtkTimerLog::MarkEndEvent("vtkNPRModelReader: check points");
  return drawable;
}

bool vtkNPRModelReader::DropUndrawable(
  const std::string& name, vtkPolyData* surface, vtkPolyData* output)
{
  // Drop points with NaN or infinite coordinates or beyond float's range, the cells that use
  // them, and cells that name a point that does not exist (VTP and VTK files, which VTK's
  // readers take as they are).
  const vtkIdType numberOfPoints = surface->GetNumberOfPoints();
  vtkIdType finitePoints = 0, beyondFloat = 0;
  const std::vector<vtkIdType> newPointIds =
    vtkNPRDrawableSurface::NumberFinitePoints(surface->GetPoints(), finitePoints, beyondFloat);
  const vtkNPRDrawableSurface::CellCounts dropped =
    vtkNPRDrawableSurface::CountUndrawableCells(surface, newPointIds);
  if (finitePoints == numberOfPoints && dropped.OutOfRange == 0)
  {
    output->ShallowCopy(surface);
  }
  else
  {
    vtkNPRDrawableSurface::CopyDrawable(surface, newPointIds, finitePoints, output);
    this->NumberOfDroppedPoints = numberOfPoints - finitePoints;
    this->NumberOfDroppedCells = dropped.NonFinite + dropped.OutOfRange;
    this->NumberOfOutOfRangeCells = dropped.OutOfRange;
  }
  std::string droppedText;
  if (this->NumberOfDroppedPoints)
  {
    const vtkIdType nonFinite = this->NumberOfDroppedPoints - beyondFloat;
    droppedText = "dropped " +
      (nonFinite ? std::to_string(nonFinite) + " points with NaN/Inf coordinates" : "") +
      (nonFinite && beyondFloat ? " and " : "") +
      (beyondFloat ? std::to_string(beyondFloat) + " points beyond float's range (3.4e38)" : "") +
      " and the " + std::to_string(dropped.NonFinite) + " cells that use them";
  }
  if (dropped.OutOfRange)
  {
    droppedText += std::string(droppedText.empty() ? "dropped " : ", and ") +
      std::to_string(dropped.OutOfRange) + " cells that use a point index past the " +
      std::to_string(numberOfPoints) + " points";
  }
  const std::string nothing = NothingToDraw(output);
  if (!nothing.empty())
  {
    return this->Fail(name + ": nothing to draw: " + nothing +
      (droppedText.empty() ? std::string() : " after it " + droppedText));
  }
  if (!droppedText.empty())
  {
    this->WarningMessage = name + ": " + droppedText;
    vtkWarningMacro(<< this->WarningMessage);
  }
  return true;
}

std::string vtkNPRModelReader::NothingToDraw(vtkPolyData* output)
{
  const std::string cells = std::to_string(output->GetNumberOfCells()) + " cells";
  if (output->GetNumberOfCells() == 0)
  {
    return "no cell is left";
  }
  double diagonal = 0.0;
  const int flatAxes = vtkNPRDrawableSurface::CountFlatAxes(output, diagonal);
  if (flatAxes >= 2)
  {
    return "every point of its " + cells + " lies " +
      (flatAxes == 3 ? "at one spot" : "on one line") + " (zero-area bounds)";
  }
  if (diagonal < vtkNPRDrawableSurface::SmallestDrawableDiagonal ||
    diagonal > vtkNPRDrawableSurface::LargestDrawableDiagonal)
  {
    std::ostringstream size;
    size << "its " << cells << " span " << diagonal << " (the diagonal of their bounds), "
         << (diagonal < vtkNPRDrawableSurface::SmallestDrawableDiagonal ? "less" : "more")
         << " than float rendering frames (" << vtkNPRDrawableSurface::SmallestDrawableDiagonal
         << " to " << vtkNPRDrawableSurface::LargestDrawableDiagonal << ")";
    return size.str();
  }
  if (vtkNPRDrawableSurface::HasOnlyZeroAreaPolygons(output))
  {
    return "every one of its " + std::to_string(output->GetNumberOfCells()) +
      " faces has zero area (its corners on one line)";
  }
  return std::string();
}
