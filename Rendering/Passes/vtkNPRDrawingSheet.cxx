// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNPRDrawingSheet.h"

#include "vtkCamera.h"
#include "vtkDataArray.h"
#include "vtkErrorCode.h"
#include "vtkMath.h"
#include "vtkNPRDrawingLines.h"
#include "vtkNPRDrawingPass.h"
#include "vtkNPRFaceShading.h"
#include "vtkNPRFillPainter.h"
#include "vtkNPRPass.h"
#include "vtkNPRPassUtilities.h"
#include "vtkNPRStrokePainter.h"
#include "vtkNPRVectorFile.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"

#include <cairo.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace
{
constexpr double PointsPerMillimetre = 72.0 / 25.4;
constexpr double LabelPoints = 9.0;             // the size of the views' names
constexpr double LabelLine = 2.0 * LabelPoints; // the line under each view for its name
constexpr int ViewPadding = 4;                  // pixels around each view's image for the lines

// A standard view: the direction the camera looks in, its up, and where it goes in the grid of
// a first-angle sheet (column, row; the front view at 1, 1); third angle mirrors the grid about
// the front view, except for the back and iso views.
struct ViewKind
{
  const char* Name;
  const char* Title;
  std::array<double, 3> Direction, Up;
  int Column, Row;
};
const ViewKind Kinds[] = {
  { "iso", "ISOMETRIC", { -1, -1, -1 }, { 0, 1, 0 }, 3, 0 },
  { "front", "FRONT", { 0, 0, -1 }, { 0, 1, 0 }, 1, 1 },
  { "top", "TOP", { 0, -1, 0 }, { 0, 0, -1 }, 1, 2 },
  { "right", "RIGHT", { -1, 0, 0 }, { 0, 1, 0 }, 0, 1 },
  { "left", "LEFT", { 1, 0, 0 }, { 0, 1, 0 }, 2, 1 },
  { "back", "BACK", { 0, 0, 1 }, { 0, 1, 0 }, 3, 1 },
  { "bottom", "BOTTOM", { 0, 1, 0 }, { 0, 0, 1 }, 1, 0 },
};

std::string Trim(const std::string& text)
{
  const size_t first = text.find_first_not_of(" \t");
  return first == std::string::npos ? ""
                                    : text.substr(first, text.find_last_not_of(" \t") - first + 1);
}

// One view of the sheet: its kind, its place in the grid, the bounding box's extent in its image
// (model units) and its box on the page (points).
struct SheetView
{
  int Kind;
  int Column, Row;
  double Width = 0.0, Height = 0.0;
  double Box[4] = { 0.0, 0.0, 0.0, 0.0 };
  vtkIdType Strokes = 0;
};

// The view's image axes: right and up, unit length.
void ViewAxes(const ViewKind& kind, double right[3], double up[3])
{
  double direction[3] = { kind.Direction[0], kind.Direction[1], kind.Direction[2] };
  double upHint[3] = { kind.Up[0], kind.Up[1], kind.Up[2] };
  vtkMath::Normalize(direction);
  vtkMath::Cross(direction, upHint, right);
  vtkMath::Normalize(right);
  vtkMath::Cross(right, direction, up);
}

// The bounding box's extent in each view's image (its corners on the view's axes), and the
// largest width of each column and height of each row of the grid.
void MeasureViews(std::vector<SheetView>& views, const double bounds[6],
  std::map<int, double>& columns, std::map<int, double>& rows)
{
  for (SheetView& view : views)
  {
    double right[3], up[3];
    ViewAxes(Kinds[view.Kind], right, up);
    double low[2] = { VTK_DOUBLE_MAX, VTK_DOUBLE_MAX };
    double high[2] = { -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
    for (int corner = 0; corner < 8; ++corner)
    {
      const double p[3] = { bounds[corner & 1], bounds[2 + ((corner >> 1) & 1)],
        bounds[4 + ((corner >> 2) & 1)] };
      const double along[2] = { vtkMath::Dot(p, right), vtkMath::Dot(p, up) };
      for (int k = 0; k < 2; ++k)
      {
        low[k] = std::min(low[k], along[k]);
        high[k] = std::max(high[k], along[k]);
      }
    }
    view.Width = high[0] - low[0];
    view.Height = high[1] - low[1];
    columns[view.Column] = std::max(columns[view.Column], view.Width);
    rows[view.Row] = std::max(rows[view.Row], view.Height);
  }
}
}

struct vtkNPRDrawingSheet::Internals
{
  std::vector<SheetView> Views;
  double Bounds[6];
  double Page[2] = { 0.0, 0.0 };
  double Scale = 0.0;
  double Time = 0.0;
  std::string ErrorMessage;
  vtkNew<vtkNPRDrawingLines> Lines;
};

vtkStandardNewMacro(vtkNPRDrawingSheet);
vtkCxxSetObjectMacro(vtkNPRDrawingSheet, Renderer, vtkRenderer);

vtkNPRDrawingSheet::vtkNPRDrawingSheet()
  : Internal(new Internals)
{
  this->SetViews("iso,front,top,right");
}

vtkNPRDrawingSheet::~vtkNPRDrawingSheet()
{
  this->SetRenderer(nullptr);
  this->SetFileName(nullptr);
  this->SetViews(nullptr);
}

int vtkNPRDrawingSheet::GetPaperSizeFromName(const char* name)
{
  const std::string lower = vtkNPRLowerCase(name ? name : "");
  return lower == "a4" ? A4 : lower == "a3" ? A3 : lower == "letter" ? LETTER : -1;
}

bool vtkNPRDrawingSheet::IsViewName(const char* name)
{
  const std::string lower = vtkNPRLowerCase(Trim(name ? name : ""));
  return std::any_of(
    std::begin(Kinds), std::end(Kinds), [&](const ViewKind& kind) { return lower == kind.Name; });
}

const char* vtkNPRDrawingSheet::GetViewNames()
{
  return "iso, front, top, right, left, back, bottom";
}

const char* vtkNPRDrawingSheet::GetErrorMessage() const
{
  return this->Internal->ErrorMessage.c_str();
}

void vtkNPRDrawingSheet::GetPageSize(double size[2]) const
{
  std::copy_n(this->Internal->Page, 2, size);
}

double vtkNPRDrawingSheet::GetScale() const
{
  return this->Internal->Scale;
}

int vtkNPRDrawingSheet::GetNumberOfViews() const
{
  return static_cast<int>(this->Internal->Views.size());
}

const char* vtkNPRDrawingSheet::GetViewName(int view) const
{
  return view >= 0 && view < this->GetNumberOfViews() ? Kinds[this->Internal->Views[view].Kind].Name
                                                      : nullptr;
}

void vtkNPRDrawingSheet::GetViewBox(int view, double box[4]) const
{
  std::fill_n(box, 4, 0.0);
  if (view >= 0 && view < this->GetNumberOfViews())
  {
    std::copy_n(this->Internal->Views[view].Box, 4, box);
  }
}

vtkIdType vtkNPRDrawingSheet::GetNumberOfStrokes(int view) const
{
  return view >= 0 && view < this->GetNumberOfViews() ? this->Internal->Views[view].Strokes : 0;
}

double vtkNPRDrawingSheet::GetTime() const
{
  return this->Internal->Time;
}

bool vtkNPRDrawingSheet::Fail(unsigned long code, const std::string& message)
{
  this->ErrorCode = code;
  this->Internal->ErrorMessage = message;
  this->Internal->Views.clear();
  vtkErrorMacro(<< message);
  return false;
}

bool vtkNPRDrawingSheet::Write()
{
  const auto start = std::chrono::steady_clock::now();
  Internals& internal = *this->Internal;
  this->ErrorCode = vtkErrorCode::NoError;
  internal.ErrorMessage.clear();
  internal.Views.clear();
  std::string error;
  const int format = vtkNPRCheckVectorPath(this->FileName, this->ErrorCode, error);
  if (format < 0)
  {
    return this->Fail(this->ErrorCode, error);
  }
  if (!this->Renderer)
  {
    return this->Fail(vtkErrorCode::UnknownError, "no renderer");
  }
  std::string bytes;
  if (!this->ParseViews() || !this->LayOut() || !this->Paint(format, bytes))
  {
    return false;
  }
  if (!vtkNPRWriteVectorFile(this->FileName, bytes, this->ErrorCode, error))
  {
    return this->Fail(this->ErrorCode, error);
  }
  internal.Time = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return true;
}

bool vtkNPRDrawingSheet::ParseViews()
{
  std::vector<SheetView>& views = this->Internal->Views;
  std::stringstream list(this->Views ? this->Views : "");
  std::string item;
  while (std::getline(list, item, ','))
  {
    const std::string name = vtkNPRLowerCase(Trim(item));
    const auto* kind = std::find_if(
      std::begin(Kinds), std::end(Kinds), [&](const ViewKind& k) { return name == k.Name; });
    if (kind == std::end(Kinds))
    {
      return this->Fail(
        vtkErrorCode::UnknownError, "unknown view '" + name + "' (views: " + GetViewNames() + ")");
    }
    const int index = static_cast<int>(kind - std::begin(Kinds));
    if (std::any_of(
          views.begin(), views.end(), [&](const SheetView& view) { return view.Kind == index; }))
    {
      return this->Fail(vtkErrorCode::UnknownError, "the view '" + name + "' is given twice");
    }
    SheetView view;
    view.Kind = index;
    // Third angle mirrors the side and top/bottom views about the front view.
    const bool mirror = this->Arrangement == THIRD_ANGLE && kind->Column != 3;
    view.Column = mirror ? 2 - kind->Column : kind->Column;
    view.Row = mirror ? 2 - kind->Row : kind->Row;
    views.push_back(view);
  }
  return !views.empty() || this->Fail(vtkErrorCode::UnknownError, "no views");
}

bool vtkNPRDrawingSheet::LayOut()
{
  Internals& internal = *this->Internal;
  double* bounds = internal.Bounds;
  this->Renderer->ComputeVisiblePropBounds(bounds);
  if (!(bounds[0] <= bounds[1] && bounds[2] <= bounds[3] && bounds[4] <= bounds[5]))
  {
    return this->Fail(vtkErrorCode::UnknownError, "nothing visible to draw");
  }
  // Each view's extent, and the widest view of each column and the highest of each row.
  std::map<int, double> columns, rows;
  MeasureViews(internal.Views, bounds, columns, rows);
  // The paper, and the one scale that fits the grid inside the margins.
  const double sizes[3][2] = { { 210.0, 297.0 }, { 297.0, 420.0 }, { 215.9, 279.4 } };
  const double* paper = sizes[this->PaperSize];
  internal.Page[0] = (this->Landscape ? paper[1] : paper[0]) * PointsPerMillimetre;
  internal.Page[1] = (this->Landscape ? paper[0] : paper[1]) * PointsPerMillimetre;
  const double margin = this->Margin * PointsPerMillimetre;
  const double gap = this->Gap * PointsPerMillimetre;
  double widths = 0.0, heights = 0.0;
  for (const auto& column : columns)
  {
    widths += column.second;
  }
  for (const auto& row : rows)
  {
    heights += row.second;
  }
  const double freeWidth = internal.Page[0] - 2.0 * margin - gap * (columns.size() - 1);
  const double freeHeight = internal.Page[1] - 2.0 * margin - gap * (rows.size() - 1) -
    LabelLine * (rows.size() + 1); // a line under each row, and one for the scale
  if (freeWidth <= 0.0 || freeHeight <= 0.0)
  {
    return this->Fail(vtkErrorCode::UnknownError, "the margins and gaps leave no room for views");
  }
  internal.Scale = std::min(widths > 0.0 ? freeWidth / widths : VTK_DOUBLE_MAX,
    heights > 0.0 ? freeHeight / heights : VTK_DOUBLE_MAX);
  if (internal.Scale == VTK_DOUBLE_MAX)
  {
    return this->Fail(vtkErrorCode::UnknownError, "nothing visible to draw (a single point)");
  }
  // Each view centred in its cell; the grid centred on the page.
  const double s = internal.Scale;
  std::map<int, double> x, y; // the cells' centres
  double at = margin + 0.5 * (freeWidth - s * widths);
  for (const auto& column : columns)
  {
    x[column.first] = at + 0.5 * s * column.second;
    at += s * column.second + gap;
  }
  at = margin + 0.5 * (freeHeight - s * heights);
  for (const auto& row : rows)
  {
    y[row.first] = at + 0.5 * s * row.second;
    at += s * row.second + LabelLine + gap;
  }
  for (SheetView& view : internal.Views)
  {
    const double cx = x[view.Column], cy = y[view.Row];
    const double box[4] = { cx - 0.5 * s * view.Width, cy - 0.5 * s * view.Height,
      cx + 0.5 * s * view.Width, cy + 0.5 * s * view.Height };
    std::copy_n(box, 4, view.Box);
  }
  return true;
}

namespace
{
// A parallel camera that sees the bounding box along the view's direction, one image pixel
// 1 / scale model units, the box's centre in the image's centre.
void AimCamera(
  vtkCamera* camera, const ViewKind& kind, const double bounds[6], double scale, int imageHeight)
{
  double direction[3] = { kind.Direction[0], kind.Direction[1], kind.Direction[2] };
  vtkMath::Normalize(direction);
  const double centre[3] = { 0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]),
    0.5 * (bounds[4] + bounds[5]) };
  const double diagonal = std::max(
    std::hypot(bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4]), 1e-12);
  camera->ParallelProjectionOn();
  camera->SetFocalPoint(centre);
  camera->SetPosition(centre[0] - 2.0 * diagonal * direction[0],
    centre[1] - 2.0 * diagonal * direction[1], centre[2] - 2.0 * diagonal * direction[2]);
  camera->SetViewUp(kind.Up.data());
  camera->SetParallelScale(0.5 * imageHeight / scale);
  camera->SetClippingRange(diagonal, 3.0 * diagonal);
}

// The view's name centred under its box, and the scale in the page's bottom right corner.
void PaintLabel(cairo_t* cr, const std::string& text, double x, double y, bool centred)
{
  cairo_text_extents_t extents;
  cairo_text_extents(cr, text.c_str(), &extents);
  cairo_move_to(
    cr, centred ? x - 0.5 * extents.width - extents.x_bearing : x - extents.x_advance, y);
  cairo_show_text(cr, text.c_str());
}
}

bool vtkNPRDrawingSheet::Paint(int format, std::string& bytes)
{
  Internals& internal = *this->Internal;
  vtkNPRPass* npr = vtkNPRPass::SafeDownCast(this->Renderer->GetPass());
  vtkNPREdgePass* edges = npr ? npr->GetEdgePass() : nullptr;
  const vtkNPRStrokeStyle style =
    vtkNPRMakeStrokeStyle(npr ? npr->GetDrawingPass() : nullptr, edges, nullptr);
  vtkNPRDrawingLines* lines = internal.Lines;
  lines->SetRenderer(this->Renderer);
  vtkNPRSelectStrokeLines(lines, style, edges);
  vtkSmartPointer<vtkCamera> own = this->Renderer->GetActiveCamera();
  cairo_surface_t* surface =
    vtkNPRCreateVectorSurface(format, bytes, internal.Page[0], internal.Page[1]);
  cairo_t* cr = cairo_create(surface);
  cairo_set_source_rgb(cr, 1.0, 1.0, 1.0);
  cairo_paint(cr);
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, LabelPoints);
  std::string error;
  bool painted = true;
  for (SheetView& view : internal.Views)
  {
    // The view's image: the box's size in points and a few pixels around it.
    const int width = static_cast<int>(std::ceil(view.Box[2] - view.Box[0])) + 2 * ViewPadding;
    const int height = static_cast<int>(std::ceil(view.Box[3] - view.Box[1])) + 2 * ViewPadding;
    vtkNew<vtkCamera> camera;
    AimCamera(camera, Kinds[view.Kind], internal.Bounds, internal.Scale, height);
    this->Renderer->SetActiveCamera(camera);
    lines->SetSize(width, height);
    painted = painted && lines->Update() && (!this->FillFaces || lines->UpdateFaces());
    vtkNPRStrokeCounts counts;
    counts.fill(0);
    const double cx = 0.5 * (view.Box[0] + view.Box[2]), cy = 0.5 * (view.Box[1] + view.Box[3]);
    cairo_save(cr);
    cairo_translate(cr, cx - 0.5 * width, cy - 0.5 * height);
    painted = painted && (!this->FillFaces || this->PaintFaces(cr, height, error)) &&
      vtkNPRPaintStrokes(cr, lines->GetStrokes(), style, height, counts, error);
    cairo_restore(cr);
    view.Strokes = lines->GetNumberOfStrokes();
    cairo_set_source_rgb(cr, 0.0, 0.0, 0.0);
    PaintLabel(
      cr, Kinds[view.Kind].Title, cx, view.Box[3] + 0.5 * LabelLine + 0.5 * LabelPoints, true);
  }
  this->Renderer->SetActiveCamera(own);
  lines->SetRenderer(nullptr);
  char scale[64];
  std::snprintf(scale, sizeof(scale), "scale 1 : %.3g", PointsPerMillimetre / internal.Scale);
  const double margin = this->Margin * PointsPerMillimetre;
  PaintLabel(cr, scale, internal.Page[0] - margin, internal.Page[1] - margin, false);
  cairo_destroy(cr);
  const bool finished = vtkNPRFinishVectorSurface(surface, error);
  if (!painted || !finished)
  {
    return this->Fail(vtkErrorCode::UnknownError,
      std::string(this->FileName) + ": " + (error.empty() ? "cannot compute the strokes" : error));
  }
  return true;
}

bool vtkNPRDrawingSheet::PaintFaces(cairo_t* cr, double height, std::string& error)
{
  vtkNPRPass* npr = vtkNPRPass::SafeDownCast(this->Renderer->GetPass());
  double faceColor[3] = { 1.0, 1.0, 1.0 };
  if (npr)
  {
    npr->GetDrawingPass()->GetFaceColor(faceColor);
  }
  vtkPolyData* faces = this->Internal->Lines->GetFaces();
  vtkIdType painted = 0;
  return vtkNPRPaintFaces(cr, faces, this->FillColors == 0 ? faceColor : nullptr,
    vtkNPRFillColors(faces, this->FillColors, this->Renderer), 1.0, height, painted, error);
}

void vtkNPRDrawingSheet::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Renderer: " << this->Renderer << "\n";
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "Views: " << (this->Views ? this->Views : "(none)") << "\n";
  os << indent << "Arrangement: " << (this->Arrangement == FIRST_ANGLE ? "first" : "third")
     << " angle\n";
  os << indent << "PaperSize: "
     << (this->PaperSize == A4      ? "A4"
            : this->PaperSize == A3 ? "A3"
                                    : "letter")
     << (this->Landscape ? ", landscape" : ", portrait") << "\n";
  os << indent << "Margin: " << this->Margin << " mm\n";
  os << indent << "Gap: " << this->Gap << " mm\n";
  os << indent << "FillFaces: " << this->FillFaces << " FillColors: " << this->FillColors << "\n";
  os << indent << "ErrorCode: " << this->ErrorCode << "\n";
}
