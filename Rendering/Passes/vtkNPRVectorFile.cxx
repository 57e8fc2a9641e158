// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNPRVectorFile.h"

#include "vtkErrorCode.h"
#include "vtkNPRDrawingExporter.h"

#include <cairo-pdf.h>
#include <cairo-ps.h>
#include <cairo-svg.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <system_error>

namespace
{
cairo_status_t AppendToString(void* closure, const unsigned char* data, unsigned int length)
{
  static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
  return CAIRO_STATUS_SUCCESS;
}
}

int vtkNPRCheckVectorPath(const char* fileName, unsigned long& code, std::string& error)
{
  if (!fileName || !*fileName)
  {
    code = vtkErrorCode::NoFileNameError;
    error = "no file name";
    return -1;
  }
  const std::string path = fileName;
  const int format = vtkNPRDrawingExporter::GetFormatFromFileName(fileName);
  std::error_code ec;
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  if (format < 0)
  {
    code = vtkErrorCode::FileFormatError;
    error = path +
      ": unsupported extension (supported: " + vtkNPRDrawingExporter::GetSupportedExtensions() +
      ")";
  }
  else if (std::filesystem::is_directory(path, ec))
  {
    code = vtkErrorCode::CannotOpenFileError;
    error = path + ": is a directory";
  }
  else if (!parent.empty() && !std::filesystem::is_directory(parent, ec))
  {
    code = vtkErrorCode::CannotOpenFileError;
    error = path + ": no such directory: " + parent.string();
  }
  else
  {
    return format;
  }
  return -1;
}

cairo_surface_t* vtkNPRCreateVectorSurface(
  int format, std::string& bytes, double width, double height)
{
  cairo_surface_t* surface = nullptr;
  switch (format)
  {
    case vtkNPRDrawingExporter::SVG:
      surface = cairo_svg_surface_create_for_stream(AppendToString, &bytes, width, height);
      cairo_svg_surface_set_document_unit(surface, CAIRO_SVG_UNIT_PT);
      break;
    case vtkNPRDrawingExporter::PDF:
      surface = cairo_pdf_surface_create_for_stream(AppendToString, &bytes, width, height);
      cairo_pdf_surface_set_metadata(surface, CAIRO_PDF_METADATA_CREATOR, "vtkNPR");
      break;
    default:
      surface = cairo_ps_surface_create_for_stream(AppendToString, &bytes, width, height);
      cairo_ps_surface_set_eps(surface, format == vtkNPRDrawingExporter::EPS ? 1 : 0);
      break;
  }
  return surface;
}

bool vtkNPRCairoSucceeded(cairo_t* cr, std::string& error)
{
  if (cairo_status(cr) == CAIRO_STATUS_SUCCESS)
  {
    return true;
  }
  error = std::string("Cairo: ") + cairo_status_to_string(cairo_status(cr));
  return false;
}

bool vtkNPRFinishVectorSurface(cairo_surface_t* surface, std::string& error)
{
  cairo_surface_finish(surface);
  const cairo_status_t status = cairo_surface_status(surface);
  cairo_surface_destroy(surface);
  if (status != CAIRO_STATUS_SUCCESS)
  {
    error = std::string("Cairo: ") + cairo_status_to_string(status);
    return false;
  }
  return true;
}

bool vtkNPRWriteVectorFile(
  const std::string& path, const std::string& bytes, unsigned long& code, std::string& error)
{
  std::ofstream file(path, std::ios::binary | std::ios::trunc);
  if (!file)
  {
    code = vtkErrorCode::CannotOpenFileError;
    error = path + ": cannot open for writing: " + std::strerror(errno);
    return false;
  }
  file.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  file.close();
  if (!file)
  {
    std::remove(path.c_str()); // no partial file
    code = vtkErrorCode::OutOfDiskSpaceError;
    error = path + ": cannot write the file";
    return false;
  }
  return true;
}
