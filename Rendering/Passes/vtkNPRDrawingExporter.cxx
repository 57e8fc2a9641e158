// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNPRDrawingExporter.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkErrorCode.h"
#include "vtkImageData.h"
#include "vtkNPRDrawingLines.h"
#include "vtkNPRDrawingPass.h"
#include "vtkNPREdgePass.h"
#include "vtkNPRFaceShading.h"
#include "vtkNPRFillPainter.h"
#include "vtkNPROverlays.h"
#include "vtkNPRPass.h"
#include "vtkNPRPassUtilities.h"
#include "vtkNPRStrokePainter.h"
#include "vtkNPRVectorFile.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkRendererCollection.h"
#include "vtkSmartPointer.h"

#include <cairo.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace
{
using Clock = std::chrono::steady_clock;
double Seconds(Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Puts each class of strokes of Cairo's SVG into a <g class="npr-..."> group. Cairo 1.16 writes
// one <path .../> element per cairo_stroke, one a line, in painting order; the strokes were
// painted last, class after class, so they are the last `total` <path> elements of the file.
// Returns false (and leaves `svg` as it was) when the file has not that form: fewer <path>
// elements, or anything but white space between two strokes.
bool LabelClasses(std::string& svg, const vtkNPRStrokeCounts& counts)
{
  vtkIdType total = 0;
  for (vtkIdType count : counts)
  {
    total += count;
  }
  if (total == 0)
  {
    return true;
  }
  std::vector<size_t> starts;
  for (size_t at = svg.find("<path"); at != std::string::npos; at = svg.find("<path", at + 5))
  {
    starts.push_back(at);
  }
  if (static_cast<vtkIdType>(starts.size()) < total)
  {
    return false;
  }
  starts.erase(starts.begin(), starts.end() - total);
  std::vector<size_t> ends; // just past each stroke's "/>" and its line end
  for (size_t k = 0; k < starts.size(); ++k)
  {
    size_t end = svg.find("/>", starts[k]);
    if (end == std::string::npos || (k + 1 < starts.size() && end > starts[k + 1]) ||
      svg.find('>', starts[k]) != end + 1)
    {
      return false; // not an empty element
    }
    end += 2;
    if (end < svg.size() && svg[end] == '\n')
    {
      ++end;
    }
    if (k + 1 < starts.size())
    {
      for (size_t i = end; i < starts[k + 1]; ++i)
      {
        if (!std::isspace(static_cast<unsigned char>(svg[i])))
        {
          return false;
        }
      }
    }
    ends.push_back(end);
  }
  std::string out;
  out.reserve(svg.size() + 256);
  out.append(svg, 0, starts[0]);
  size_t stroke = 0;
  for (int strokeClass = 0; strokeClass < NPR_STROKE_CLASSES; ++strokeClass)
  {
    if (counts[strokeClass] == 0)
    {
      continue;
    }
    const size_t first = stroke, last = stroke + counts[strokeClass] - 1;
    out += "<g class=\"";
    out += vtkNPRStrokeClassName(strokeClass);
    out += "\">\n";
    out.append(svg, starts[first], ends[last] - starts[first]);
    if (out.back() != '\n')
    {
      out += '\n';
    }
    out += "</g>\n";
    stroke = last + 1;
  }
  out.append(svg, ends.back(), std::string::npos);
  svg.swap(out);
  return true;
}

// Paints the raster over the whole width x height of `cr`.
void PaintRaster(cairo_t* cr, vtkImageData* raster, int width, int height)
{
  const int* dimensions = raster->GetDimensions();
  const int rw = dimensions[0], rh = dimensions[1];
  cairo_surface_t* image = cairo_image_surface_create(CAIRO_FORMAT_RGB24, rw, rh);
  unsigned char* data = cairo_image_surface_get_data(image);
  const int stride = cairo_image_surface_get_stride(image);
  const auto* rgb = static_cast<const unsigned char*>(raster->GetScalarPointer());
  const int components = raster->GetNumberOfScalarComponents();
  for (int j = 0; j < rh; ++j) // VTK's row 0 is the bottom, Cairo's the top
  {
    const unsigned char* in = rgb + static_cast<size_t>(rh - 1 - j) * rw * components;
    auto* out = reinterpret_cast<std::uint32_t*>(data + static_cast<size_t>(j) * stride);
    for (int i = 0; i < rw; ++i, in += components)
    {
      out[i] = 0xff000000u | (std::uint32_t(in[0]) << 16) | (std::uint32_t(in[1]) << 8) | in[2];
    }
  }
  cairo_surface_mark_dirty(image);
  cairo_save(cr);
  cairo_scale(cr, static_cast<double>(width) / rw, static_cast<double>(height) / rh);
  cairo_set_source_surface(cr, image, 0, 0);
  cairo_paint(cr);
  cairo_restore(cr);
  cairo_surface_destroy(image);
}
}

struct vtkNPRDrawingExporter::Internals
{
  vtkNew<vtkNPRDrawingLines> OwnLines;       // when there is no drawing pass
  vtkSmartPointer<vtkNPRDrawingLines> Lines; // those of the last Write()
  std::string ErrorMessage;
  vtkNPROverlays Overlays; // the 2D props of the last Write() without a raster
  vtkNPRStrokeCounts Counts{};
  vtkIdType FilledFaces = 0;
  vtkIdType LeftOut = 0; // 3D props not drawn in a figure without the window's image
  bool Labelled = false;
  bool Embedded = false;
  double StrokesTime = 0.0, WriteTime = 0.0;
};

vtkStandardNewMacro(vtkNPRDrawingExporter);
vtkCxxSetObjectMacro(vtkNPRDrawingExporter, Renderer, vtkRenderer);
vtkCxxSetObjectMacro(vtkNPRDrawingExporter, RenderWindow, vtkRenderWindow);
vtkCxxSetObjectMacro(vtkNPRDrawingExporter, DrawingPass, vtkNPRDrawingPass);
vtkCxxSetObjectMacro(vtkNPRDrawingExporter, EdgePass, vtkNPREdgePass);

vtkNPRDrawingExporter::vtkNPRDrawingExporter()
  : Internal(new Internals)
{
  this->Internal->Lines = this->Internal->OwnLines;
}

vtkNPRDrawingExporter::~vtkNPRDrawingExporter()
{
  this->SetRenderer(nullptr);
  this->SetRenderWindow(nullptr);
  this->SetDrawingPass(nullptr);
  this->SetEdgePass(nullptr);
  this->SetFileName(nullptr);
}

const char* vtkNPRDrawingExporter::GetSupportedExtensions()
{
  return ".svg, .pdf, .ps, .eps";
}

int vtkNPRDrawingExporter::GetFormatFromFileName(const char* fileName)
{
  if (!fileName)
  {
    return -1;
  }
  const std::string extension =
    vtkNPRLowerCase(std::filesystem::path(fileName).extension().string());
  if (extension == ".svg")
  {
    return SVG;
  }
  if (extension == ".pdf")
  {
    return PDF;
  }
  if (extension == ".ps")
  {
    return PS;
  }
  if (extension == ".eps")
  {
    return EPS;
  }
  return -1;
}

const char* vtkNPRDrawingExporter::GetErrorMessage() const
{
  return this->Internal->ErrorMessage.c_str();
}

vtkNPRDrawingLines* vtkNPRDrawingExporter::GetDrawingLines()
{
  return this->Internal->Lines;
}

vtkIdType vtkNPRDrawingExporter::GetNumberOfStrokes(int strokeClass) const
{
  return strokeClass >= 0 && strokeClass < NPR_STROKE_CLASSES ? this->Internal->Counts[strokeClass]
                                                              : 0;
}

vtkIdType vtkNPRDrawingExporter::GetNumberOfStrokes() const
{
  vtkIdType total = 0;
  for (vtkIdType count : this->Internal->Counts)
  {
    total += count;
  }
  return total;
}

vtkIdType vtkNPRDrawingExporter::GetNumberOfTexts() const
{
  return this->Internal->Overlays.GetNumberOfTexts();
}

vtkIdType vtkNPRDrawingExporter::GetNumberOfImagedOverlays() const
{
  return this->Internal->Overlays.GetNumberOfImageProps();
}

vtkIdType vtkNPRDrawingExporter::GetNumberOfFilledFaces() const
{
  return this->Internal->FilledFaces;
}

vtkIdType vtkNPRDrawingExporter::GetNumberOfPropsLeftOut() const
{
  return this->Internal->LeftOut;
}

bool vtkNPRDrawingExporter::GetClassesLabelled() const
{
  return this->Internal->Labelled;
}

bool vtkNPRDrawingExporter::GetImageEmbedded() const
{
  return this->Internal->Embedded;
}

double vtkNPRDrawingExporter::GetStrokesTime() const
{
  return this->Internal->StrokesTime;
}

double vtkNPRDrawingExporter::GetWriteTime() const
{
  return this->Internal->WriteTime;
}

bool vtkNPRDrawingExporter::Fail(unsigned long code, const std::string& message)
{
  this->ErrorCode = code;
  this->Internal->ErrorMessage = message;
  vtkErrorMacro(<< message);
  return false;
}

// What one Write() draws and where, resolved before any work.
struct vtkNPRDrawingExporter::Target
{
  std::string Path;
  int Format = -1;
  vtkRenderer* Renderer = nullptr;
  int Width = 0, Height = 0;
  vtkNPREdgePass* Edges = nullptr;
  vtkNPRDrawingLines* Lines = nullptr; // the drawing pass's, else the exporter's own
  vtkNPRStrokeStyle Style;
  double FaceColor[3] = { 1.0, 1.0, 1.0 }; // the drawing pass's
  bool DrawingStyle = false;               // the renderer's vtkNPRPass draws the drawing style
};

bool vtkNPRDrawingExporter::Write()
{
  Internals& internal = *this->Internal;
  this->ErrorCode = vtkErrorCode::NoError;
  internal.ErrorMessage.clear();
  internal.Counts.fill(0);
  internal.FilledFaces = internal.LeftOut = 0;
  internal.Labelled = internal.Embedded = false;
  internal.StrokesTime = internal.WriteTime = 0.0;

  // What to write, and where: checked before any work.
  Target target;
  if (!this->CheckPath(target) || !this->FindRenderer(target))
  {
    return false;
  }
  this->ResolveStyle(target);
  // The raster under the lines: the renderer's part of the window, rendered again.
  vtkSmartPointer<vtkImageData> raster;
  if (target.Renderer->GetRenderWindow() &&
    (this->EmbedImage == 1 || (this->EmbedImage == -1 && !target.DrawingStyle && !this->FillFaces)))
  {
    raster = vtkNPRGrabViewport(target.Renderer);
    if (raster->GetNumberOfPoints() == 0)
    {
      vtkWarningMacro(<< target.Path << ": the window's image could not be read: none is embedded");
      raster = nullptr;
    }
  }
  // Without the image under them the scene's own line and point cells (an outline, axes, a
  // point cloud) are vector too, and so are its 2D props (text, scalar bars) over them.
  internal.Overlays = vtkNPROverlays();
  if (!raster && this->Overlays)
  {
    internal.Overlays.Capture(target.Renderer);
  }
  if (!this->ComputeStrokes(target, !raster))
  {
    return false;
  }
  if (!raster)
  {
    this->ReportPropsLeftOut(target);
  }
  // Painting, into memory: the file is written only once everything succeeded.
  const Clock::time_point start = Clock::now();
  std::string bytes;
  if (!this->Paint(target, raster, bytes) || !this->WriteFile(target.Path, bytes))
  {
    return false;
  }
  internal.WriteTime = Seconds(start);
  return true;
}

bool vtkNPRDrawingExporter::CheckPath(Target& target)
{
  std::string error;
  target.Format = vtkNPRCheckVectorPath(this->FileName, this->ErrorCode, error);
  if (target.Format < 0)
  {
    return this->Fail(this->ErrorCode, error);
  }
  target.Path = this->FileName;
  return true;
}

bool vtkNPRDrawingExporter::FindRenderer(Target& target)
{
  vtkRenderer* renderer = this->Renderer;
  if (!renderer && this->RenderWindow)
  {
    renderer = this->RenderWindow->GetRenderers()->GetFirstRenderer();
  }
  if (!renderer)
  {
    return this->Fail(vtkErrorCode::UnknownError, "no renderer (SetRenderer or SetRenderWindow)");
  }
  int width = this->Size[0], height = this->Size[1];
  if (width <= 0 || height <= 0)
  {
    const int* size = renderer->GetRenderWindow() ? renderer->GetSize() : nullptr;
    width = size ? size[0] : 0;
    height = size ? size[1] : 0;
  }
  if (width <= 0 || height <= 0)
  {
    return this->Fail(
      vtkErrorCode::UnknownError, "no size: set Size or put the renderer in a window with a size");
  }
  target.Renderer = renderer;
  target.Width = width;
  target.Height = height;
  return true;
}

void vtkNPRDrawingExporter::ResolveStyle(Target& target)
{
  // Explicit passes, else the renderer's vtkNPRPass, else the defaults.
  vtkNPRPass* npr = vtkNPRPass::SafeDownCast(target.Renderer->GetPass());
  vtkNPRDrawingPass* drawing = this->DrawingPass;
  target.Edges = this->EdgePass;
  if (npr)
  {
    drawing = drawing ? drawing : npr->GetDrawingPass();
    target.Edges = target.Edges ? target.Edges : npr->GetEdgePass();
  }
  target.DrawingStyle =
    npr && std::strcmp(vtkNPRPass::GetStyleName(npr->GetStyle()), "drawing") == 0;
  target.Style = vtkNPRMakeStrokeStyle(drawing, target.Edges, target.Renderer);
  if (drawing)
  {
    drawing->GetFaceColor(target.FaceColor);
  }
  // The drawing pass's lines keep the edge table and occluders it built for its frames: on a
  // large model, building them again would double the time and the memory of the export.
  target.Lines = drawing ? drawing->GetDrawingLines() : this->Internal->OwnLines.Get();
}

bool vtkNPRDrawingExporter::ComputeStrokes(const Target& target, bool linePrimitives)
{
  const Clock::time_point start = Clock::now();
  const vtkNPRStrokeStyle& style = target.Style;
  vtkNPRDrawingLines* lines = this->Internal->Lines = target.Lines;
  lines->SetRenderer(target.Renderer);
  lines->SetSize(target.Width, target.Height);
  vtkNPRSelectStrokeLines(lines, style, target.Edges);
  const bool passLines = lines->GetLinePrimitives(), passPoints = lines->GetPointPrimitives();
  lines->SetLinePrimitives(linePrimitives);
  lines->SetPointPrimitives(linePrimitives);
  const bool updated = lines->Update() && (!this->FillFaces || lines->UpdateFaces());
  lines->SetLinePrimitives(passLines);
  lines->SetPointPrimitives(passPoints);
  if (lines != this->Internal->OwnLines.Get())
  {
    // A pass held by the renderer must not hold the renderer (a cycle, hence a leak).
    lines->SetRenderer(nullptr);
  }
  if (!updated)
  {
    return this->Fail(vtkErrorCode::UnknownError, "cannot compute the strokes");
  }
  this->Internal->StrokesTime = Seconds(start);
  return true;
}

bool vtkNPRDrawingExporter::Paint(const Target& target, vtkImageData* raster, std::string& bytes)
{
  Internals& internal = *this->Internal;
  cairo_surface_t* surface =
    vtkNPRCreateVectorSurface(target.Format, bytes, target.Width, target.Height);
  cairo_t* cr = cairo_create(surface);
  double background[3];
  target.Renderer->GetBackground(background);
  cairo_set_source_rgb(cr, background[0], background[1], background[2]);
  cairo_paint(cr);
  if (raster)
  {
    PaintRaster(cr, raster, target.Width, target.Height);
    internal.Embedded = true;
  }
  std::string error, unused;
  const bool painted = (!this->FillFaces || this->PaintFaces(cr, target, error)) &&
    vtkNPRPaintStrokes(
      cr, internal.Lines->GetStrokes(), target.Style, target.Height, internal.Counts, error) &&
    vtkNPRPaintPoints(cr, internal.Lines->GetVisiblePoints(), target.Style.Scale, target.Height,
      internal.Counts[NPR_STROKES_POINT], error) &&
    internal.Overlays.Paint(
      cr, target.Width, target.Height, internal.Counts[NPR_STROKES_TEXT], error);
  cairo_destroy(cr);
  const bool finished = vtkNPRFinishVectorSurface(surface, painted ? error : unused);
  if (!painted || !finished)
  {
    return this->Fail(vtkErrorCode::UnknownError, target.Path + ": " + error);
  }
  if (target.Format == SVG)
  {
    internal.Labelled = LabelClasses(bytes, internal.Counts);
    if (!internal.Labelled)
    {
      vtkWarningMacro(<< target.Path << ": Cairo's SVG has not the expected form (Cairo "
                      << cairo_version_string()
                      << "): the strokes are written without their class groups");
    }
  }
  return true;
}

bool vtkNPRDrawingExporter::PaintFaces(cairo_t* cr, const Target& target, std::string& error)
{
  vtkPolyData* faces = this->Internal->Lines->GetFaces();
  return vtkNPRPaintFaces(cr, faces, this->FillColors == FACE_COLOR ? target.FaceColor : nullptr,
    vtkNPRFillColors(faces, this->FillColors, target.Renderer), this->FillSeam, target.Height,
    this->Internal->FilledFaces, error);
}

void vtkNPRDrawingExporter::ReportPropsLeftOut(const Target& target)
{
  // Each kind once, with its count, in drawing order.
  std::vector<std::pair<std::string, int>> kinds;
  vtkNPRDrawingLines* lines = this->Internal->Lines;
  this->Internal->LeftOut = lines->GetNumberOfPropsLeftOut();
  for (vtkIdType i = 0; i < lines->GetNumberOfPropsLeftOut(); ++i)
  {
    const std::string name = lines->GetPropLeftOut(i);
    auto kind = std::find_if(kinds.begin(), kinds.end(),
      [&name](const std::pair<std::string, int>& k) { return k.first == name; });
    if (kind == kinds.end())
    {
      kinds.emplace_back(name, 1);
    }
    else
    {
      ++kind->second;
    }
  }
  if (kinds.empty())
  {
    return;
  }
  std::ostringstream list;
  for (size_t i = 0; i < kinds.size(); ++i)
  {
    list << (i ? ", " : "") << (kinds[i].second > 1 ? std::to_string(kinds[i].second) + " x " : "")
         << kinds[i].first;
  }
  vtkWarningMacro(<< target.Path << ": left out of the vector figure, which has no image of the "
                  << "window under it: " << list.str()
                  << " (EmbedImage 1 embeds the window's image, where they show)");
}

bool vtkNPRDrawingExporter::WriteFile(const std::string& path, const std::string& bytes)
{
  std::string error;
  return vtkNPRWriteVectorFile(path, bytes, this->ErrorCode, error) ||
    this->Fail(this->ErrorCode, error);
}

void vtkNPRDrawingExporter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Renderer: " << this->Renderer << "\n";
  os << indent << "RenderWindow: " << this->RenderWindow << "\n";
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "Size: " << this->Size[0] << " x " << this->Size[1] << "\n";
  os << indent << "DrawingPass: " << this->DrawingPass << "\n";
  os << indent << "EdgePass: " << this->EdgePass << "\n";
  os << indent << "EmbedImage: " << this->EmbedImage << "\n";
  os << indent << "FillFaces: " << this->FillFaces << "\n";
  os << indent << "FillColors: " << this->FillColors << "\n";
  os << indent << "FillSeam: " << this->FillSeam << "\n";
  os << indent << "Overlays: " << this->Overlays << "\n";
  os << indent << "ErrorCode: " << this->ErrorCode << "\n";
  os << indent << "ErrorMessage: " << this->Internal->ErrorMessage << "\n";
}
