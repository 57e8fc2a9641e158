// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkNPROFFReader
 * @brief   Strict reader of Geomview OFF meshes (VTK 9.1 has none).
 *
 * Reads ASCII OFF, with the optional vertex-attribute prefixes of Geomview's format:
 * `[ST][C][N]OFF` (texture coordinates, RGBA colour, normal per vertex). The header keyword may
 * be followed on the same line by the counts `nv nf ne`; `#` starts a comment. Each face is
 * `n i0 ... i(n-1)` with n >= 3, optionally followed by a colour (3 or 4 values, 0..1 or 0..255),
 * which becomes cell scalars "Colors".
 *
 * Strict means every departure from the format is an error naming the line: an unknown or missing
 * keyword, the binary variant, 4D or n-dimensional vertices, a missing, negative or non-integer
 * count, a short vertex or face line, a face index out of range, a token that is not a number,
 * fewer lines than the counts promise, or anything but comments after the last face.
 * On error the output is empty, GetErrorMessage() holds the message, and ErrorEvent is invoked.
 * Coordinates that parse as NaN or Inf are read as such (see vtkNPRModelReader, which drops them).
 */
#ifndef vtkNPROFFReader_h
#define vtkNPROFFReader_h

#include "vtkNPRIOModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

#include <string> // for std::string

class VTKNPRIO_EXPORT vtkNPROFFReader : public vtkPolyDataAlgorithm
{
public:
  static vtkNPROFFReader* New();
  vtkTypeMacro(vtkNPROFFReader, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The file to read.
   */
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

  /**
   * The error of the last read, "file:line: what" ("" when it succeeded).
   */
  const char* GetErrorMessage() const { return this->ErrorMessage.c_str(); }

  /**
   * True when the file starts with an OFF keyword (a cheap test; the full read may still fail).
   */
  static bool CanReadFile(const char* fileName);

protected:
  vtkNPROFFReader();
  ~vtkNPROFFReader() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  char* FileName = nullptr;
  std::string ErrorMessage;

private:
  vtkNPROFFReader(const vtkNPROFFReader&) = delete;
  void operator=(const vtkNPROFFReader&) = delete;
};

#endif
