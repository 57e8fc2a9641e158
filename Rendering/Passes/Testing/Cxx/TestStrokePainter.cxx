// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// The Cairo stroke painter (vtkNPRStrokePainter, private to NPR::Passes) on a hand-made
// stroke set: a visible horizontal silhouette, a dashed hidden line and a closed square (crease).
//   raster  coverage where the strokes are and nowhere else, rows bottom-up, premultiplied
//           colours, the dash period and gaps, hidden lines left out when the style says so,
//           each kind's width (silhouettes 4 px and creases 1 px)
//   style   vtkNPRMakeStrokeStyle from an edge pass and a drawing pass, scaled by DPI / 72
//           (TestStrokePainterStyle.cxx)
//   svg     the same painting into Cairo's SVG: one <path> a stroke, the loop closed (Z)
//           (TestStrokePainterSvg.cxx)
#include "TestStrokePainter.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkUnsignedCharArray.h"

#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

vtkSmartPointer<vtkPolyData> nprStrokePainter::MakeStrokes()
{
  auto strokes = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  vtkNew<vtkDoubleArray> image;
  image->SetName("ImageCoordinates");
  image->SetNumberOfComponents(3);
  auto add = [&](double x, double y)
  {
    points->InsertNextPoint(x, y, 0.0);
    image->InsertNextTuple3(x, y, 0.5);
    return points->GetNumberOfPoints() - 1;
  };
  vtkNew<vtkCellArray> lines;
  vtkNew<vtkUnsignedCharArray> types;
  types->SetName("FeatureType");
  vtkNew<vtkUnsignedCharArray> hidden;
  hidden->SetName("Hidden");
  const vtkIdType visible[2] = { add(20, 20), add(180, 20) };
  lines->InsertNextCell(2, visible);
  types->InsertNextValue(1);
  hidden->InsertNextValue(0);
  const vtkIdType dashed[3] = { add(10, 60), add(100, 60), add(190, 60) };
  lines->InsertNextCell(3, dashed);
  types->InsertNextValue(1);
  hidden->InsertNextValue(1);
  const vtkIdType a = add(130, 30), b = add(170, 30), c = add(170, 50), d = add(130, 50);
  const vtkIdType square[5] = { a, b, c, d, a };
  lines->InsertNextCell(5, square);
  types->InsertNextValue(2);
  hidden->InsertNextValue(0);
  strokes->SetPoints(points);
  strokes->SetLines(lines);
  strokes->GetPointData()->AddArray(image);
  strokes->GetCellData()->AddArray(types);
  strokes->GetCellData()->AddArray(hidden);
  vtkNew<vtkIntArray> size;
  size->SetName("ImageSize");
  size->SetNumberOfComponents(2);
  size->InsertNextTuple2(Width, Height);
  strokes->GetFieldData()->AddArray(size);
  return strokes;
}

vtkNPRStrokeStyle nprStrokePainter::TestStyle()
{
  vtkNPRStrokeStyle style;
  style.LineWidth = 2.0;
  style.CreaseLineWidth = 2.0;
  style.CreaseColor[0] = style.CreaseColor[1] = 0.0;
  style.CreaseColor[2] = 1.0; // blue
  style.HiddenLines = true;
  style.HiddenLineWidth = 1.0;
  style.HiddenLineColor[0] = 1.0;
  style.HiddenLineColor[1] = 0.5;
  style.HiddenLineColor[2] = 0.0;
  style.DashLength = 6.0;
  style.GapLength = 4.0;
  return style;
}

namespace
{
using namespace nprStrokePainter;

// RGBA of pixel (x, y), row 0 at the bottom.
const unsigned char* At(const std::vector<unsigned char>& rgba, int x, int y)
{
  return rgba.data() + (static_cast<size_t>(y) * Width + x) * 4;
}

// The visible line, 2 px wide about y = 20: rows 19 and 20 opaque black, rows 17 and 22 empty;
// rows 79 and 80 (where it would be if the rows were top-down) empty; round caps.
void CheckVisibleLine(const std::vector<unsigned char>& rgba)
{
  for (int x : { 25, 100, 175 })
  {
    for (int y : { 19, 20 })
    {
      const unsigned char* p = At(rgba, x, y);
      NPR_CHECK(p[3] == 255 && p[0] == 0 && p[1] == 0 && p[2] == 0,
        "visible line at " << x << "," << y << ": " << int(p[0]) << " " << int(p[1]) << " "
                           << int(p[2]) << " " << int(p[3]));
    }
    for (int y : { 17, 22, 79, 80 })
    {
      NPR_CHECK(At(rgba, x, y)[3] == 0, "no line at " << x << "," << y);
    }
  }
  // Round caps: the line reaches 1 px (half its width) past its ends, no further.
  NPR_CHECK(At(rgba, 180, 19)[3] > 100 && At(rgba, 19, 20)[3] > 100, "round caps");
  NPR_CHECK(At(rgba, 182, 19)[3] == 0 && At(rgba, 17, 20)[3] == 0, "caps too long");
}

// The hidden line, 1 px wide on the border of rows 59 and 60: half covered, premultiplied
// orange (r = a, g = a / 2, b = 0). Returns its columns over the threshold.
std::vector<int> HiddenLineColumns(const std::vector<unsigned char>& rgba)
{
  std::vector<int> on(Width, 0);
  for (int x = 0; x < Width; ++x)
  {
    const unsigned char* p = At(rgba, x, 60);
    on[x] = p[3] > 96 ? 1 : 0;
    if (p[3] > 96)
    {
      NPR_CHECK(std::abs(p[3] - 128) <= 12, "hidden line coverage at x " << x << ": " << int(p[3]));
      NPR_CHECK(std::abs(p[0] - p[3]) <= 1 && std::abs(2 * p[1] - p[3]) <= 2 && p[2] == 0,
        "premultiplied orange at x " << x << ": " << int(p[0]) << " " << int(p[1]) << " "
                                     << int(p[2]) << " " << int(p[3]));
    }
    NPR_CHECK(At(rgba, x, 62)[3] == 0 && At(rgba, x, 57)[3] == 0, "hidden line too wide at " << x);
  }
  return on;
}

// The hidden line's dashes: 6 on, 4 off, round caps of 0.5 px.
void CheckDashes(const std::vector<int>& on)
{
  std::vector<int> starts, gaps, dashes;
  for (int x = 1; x < Width; ++x)
  {
    if (on[x] && !on[x - 1])
    {
      starts.push_back(x);
    }
  }
  for (int x = 1, gap = 0, dash = 0; x < Width && !starts.empty(); ++x)
  {
    if (!on[x] && x > starts.front())
    {
      ++gap;
      if (dash > 0)
      {
        dashes.push_back(dash);
        dash = 0;
      }
    }
    else if (on[x])
    {
      ++dash;
      if (gap > 0)
      {
        gaps.push_back(gap);
        gap = 0;
      }
    }
  }
  // 180 px of line: 18 periods of 10 px, the first dash starting at x = 10, across the stroke's
  // middle point (the pattern runs on).
  NPR_CHECK(!starts.empty() && starts.front() == 10,
    "first dash at " << (starts.empty() ? -1 : starts.front()) << " (-1: none), expected 10");
  NPR_CHECK(starts.size() == 18, starts.size() << " dashes, expected 18");
  for (size_t k = 1; k < starts.size(); ++k)
  {
    NPR_CHECK(starts[k] - starts[k - 1] == 10,
      "dash period " << starts[k] - starts[k - 1] << " at dash " << k);
  }
  // At half the line's coverage the round caps' half pixels stay below the threshold: 6 px on,
  // 4 off, as DashLength and GapLength say.
  NPR_CHECK(gaps.size() == 17 && dashes.size() == 18,
    gaps.size() << " gaps, " << dashes.size() << " dashes");
  for (int gap : gaps)
  {
    NPR_CHECK(gap == 4, "gap of " << gap << " px, expected 4");
  }
  for (int dash : dashes)
  {
    NPR_CHECK(dash == 6, "dash of " << dash << " px, expected 6");
  }
  std::cout << "hidden line: " << starts.size() << " dashes, period 10 px, dashes "
            << (dashes.empty() ? 0 : dashes.front()) << " px, gaps "
            << (gaps.empty() ? 0 : gaps.front()) << " px\n";
}

// The square: its sides blue and opaque, its inside and outside empty (a closed path, not
// filled).
void CheckSquare(const std::vector<unsigned char>& rgba)
{
  const int sides[4][2] = { { 150, 30 }, { 170, 40 }, { 150, 50 }, { 130, 40 } };
  for (const int* p : sides)
  {
    // A side along y = 30 covers rows 29 and 30; along x = 170 columns 169 and 170.
    const unsigned char* q = At(
      rgba, p[0] - (p[0] == 170 || p[0] == 130 ? 1 : 0), p[1] - (p[1] == 30 || p[1] == 50 ? 1 : 0));
    NPR_CHECK(q[3] == 255 && q[2] == 255 && q[0] == 0, "square side at " << p[0] << "," << p[1]);
  }
  NPR_CHECK(At(rgba, 150, 40)[3] == 0 && At(rgba, 125, 40)[3] == 0, "square filled");
}

// Without hidden lines the dashed line is not painted; without creases the square is not.
// Returns the style with both off.
vtkNPRStrokeStyle CheckSwitches(std::vector<unsigned char>& rgba)
{
  std::string error;
  vtkNPRStrokeStyle style = TestStyle();
  style.HiddenLines = false;
  NPR_CHECK(vtkNPRRasterizeStrokes(MakeStrokes(), style, Width, Height, rgba, error), error);
  int hiddenPixels = 0;
  for (int x = 0; x < Width; ++x)
  {
    hiddenPixels += At(rgba, x, 60)[3] ? 1 : 0;
  }
  NPR_CHECK(hiddenPixels == 0, hiddenPixels << " hidden line pixels with HiddenLines off");
  // Without creases the square is not painted.
  style.Creases = false;
  NPR_CHECK(vtkNPRRasterizeStrokes(MakeStrokes(), style, Width, Height, rgba, error), error);
  NPR_CHECK(At(rgba, 150, 29)[3] == 0 && At(rgba, 100, 20)[3] == 255, "creases off");
  return style;
}

// Each kind's width: silhouettes 4 px, creases 1 px. Summed down a column across the line, the
// coverage is the line's width (within 0.1 px).
void CheckKindWidths(std::vector<unsigned char>& rgba)
{
  std::string error;
  vtkNPRStrokeStyle style = TestStyle();
  style.LineWidth = 4.0;
  style.CreaseLineWidth = 1.0;
  NPR_CHECK(vtkNPRRasterizeStrokes(MakeStrokes(), style, Width, Height, rgba, error), error);
  auto across = [&](int x, int from, int to)
  {
    double sum = 0.0;
    for (int y = from; y <= to; ++y)
    {
      sum += At(rgba, x, y)[3] / 255.0;
    }
    return sum;
  };
  const double silhouette = across(100, 12, 27); // the visible line about y = 20
  const double crease = across(150, 25, 34);     // the square's side about y = 30
  std::cout << "kind widths: silhouette " << silhouette << " px, crease " << crease << " px\n";
  NPR_CHECK(std::abs(silhouette - 4.0) < 0.1, "silhouette " << silhouette << " px wide, not 4");
  NPR_CHECK(std::abs(crease - 1.0) < 0.1, "crease " << crease << " px wide, not 1");
}

// An empty stroke set gives a transparent image; arrays missing give an error.
void CheckEmptyAndBare(const vtkNPRStrokeStyle& style, std::vector<unsigned char>& rgba)
{
  std::string error;
  vtkNew<vtkPolyData> empty;
  NPR_CHECK(vtkNPRRasterizeStrokes(empty, style, Width, Height, rgba, error), error);
  bool transparent = true;
  for (unsigned char value : rgba)
  {
    transparent = transparent && value == 0;
  }
  NPR_CHECK(transparent, "empty strokes painted something");
  vtkSmartPointer<vtkPolyData> bare = MakeStrokes();
  bare->GetCellData()->RemoveArray("Hidden");
  error.clear();
  NPR_CHECK(!vtkNPRRasterizeStrokes(bare, style, Width, Height, rgba, error) &&
      error.find("Hidden") != std::string::npos,
    "strokes without Hidden: " << error);
}

int Raster()
{
  std::vector<unsigned char> rgba;
  std::string error;
  NPR_CHECK(vtkNPRRasterizeStrokes(MakeStrokes(), TestStyle(), Width, Height, rgba, error),
    "rasterise: " << error);
  NPR_CHECK(rgba.size() == static_cast<size_t>(Width) * Height * 4, "size " << rgba.size());
  if (rgba.size() != static_cast<size_t>(Width) * Height * 4)
  {
    return nprTestResult();
  }
  CheckVisibleLine(rgba);
  CheckDashes(HiddenLineColumns(rgba));
  CheckSquare(rgba);
  CheckKindWidths(rgba);
  CheckEmptyAndBare(CheckSwitches(rgba), rgba);
  return nprTestResult();
}
NPR_TEST_CASE("raster", Raster);
}
