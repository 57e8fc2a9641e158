// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkNPRModelReader
 * @brief   Reads a surface model of any format the product supports, strictly, into vtkPolyData.
 *
 * The format comes from the file name's extension (case does not matter): STL (.stl), Wavefront
 * OBJ (.obj), PLY (.ply), VTK XML polydata (.vtp), legacy VTK (.vtk, any dataset: its surface is
 * taken), glTF 2.0 (.gltf, .glb: all meshes merged) and Geomview OFF (.off, vtkNPROFFReader).
 *
 * A missing, unreadable or empty file, an unknown extension, a file the format's reader rejects
 * and a file without any surface, line or vertex cell are errors: the output is empty,
 * GetErrorMessage() holds one line naming the file and the problem, and ErrorEvent is invoked.
 *
 * Before VTK's reader runs, the file's structure is checked where that reader trusts it (PLY,
 * STL, OBJ, legacy VTK, glTF/GLB: vtkNPRModelFormatChecks, vtkNPRGLTFChecks). After it, points
 * with a NaN or infinite coordinate or one beyond float's range are removed with every cell that
 * uses them, and cells that name a point past the end are removed, with one warning that counts
 * them (GetNumberOfDroppedPoints(), GetNumberOfDroppedCells(), GetNumberOfOutOfRangeCells()). A
 * file with nothing drawable left (no cell, every point of the cells at one spot or on one line,
 * bounds too small or too large for float rendering to frame, or only faces without an area)
 * is an error that says which. Point and cell data follow their points and cells.
 */
#ifndef vtkNPRModelReader_h
#define vtkNPRModelReader_h

#include "vtkNPRIOModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

#include <string> // for std::string

class VTKNPRIO_EXPORT vtkNPRModelReader : public vtkPolyDataAlgorithm
{
public:
  static vtkNPRModelReader* New();
  vtkTypeMacro(vtkNPRModelReader, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The file to read.
   */
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

  /**
   * One line naming the file and what is wrong with it ("" after a successful read).
   */
  const char* GetErrorMessage() const { return this->ErrorMessage.c_str(); }

  /**
   * The warning of the last read ("" when there was none), e.g. about dropped points.
   */
  const char* GetWarningMessage() const { return this->WarningMessage.c_str(); }

  ///@{
  /**
   * What the last read removed: points with NaN or infinite coordinates, and cells (those that
   * use such points, and those with a point index out of range, also counted alone).
   */
  vtkGetMacro(NumberOfDroppedPoints, vtkIdType);
  vtkGetMacro(NumberOfDroppedCells, vtkIdType);
  vtkGetMacro(NumberOfOutOfRangeCells, vtkIdType);
  ///@}

  /**
   * True when the file name ends with a supported extension.
   */
  static bool IsSupportedFileName(const char* fileName);

  /**
   * The supported extensions, for messages: ".stl .obj .ply .vtp .vtk .gltf .glb .off".
   */
  static const char* GetSupportedExtensions();

protected:
  vtkNPRModelReader();
  ~vtkNPRModelReader() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  char* FileName = nullptr;
  std::string ErrorMessage;
  std::string WarningMessage;
  vtkIdType NumberOfDroppedPoints = 0;
  vtkIdType NumberOfDroppedCells = 0;
  vtkIdType NumberOfOutOfRangeCells = 0;

private:
  vtkNPRModelReader(const vtkNPRModelReader&) = delete;
  void operator=(const vtkNPRModelReader&) = delete;

  bool Read(const std::string& fileName, vtkPolyData* output);
  bool ReadBinaryPLY(const std::string& fileName, vtkPolyData* output, bool& handled);
  bool KeepDrawable(const std::string& fileName, vtkPolyData* surface, vtkPolyData* output);
  bool DropUndrawable(const std::string& fileName, vtkPolyData* surface, vtkPolyData* output);
  // Why nothing of the output can be drawn (no cell, bounds without an area or outside what
  // float rendering frames, faces without an area), or "" when something can.
  static std::string NothingToDraw(vtkPolyData* output);
  bool Fail(const std::string& message);
};

#endif
