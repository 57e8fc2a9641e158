// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nprBenchmarkReport.h"

#include "nprTiming.h"
#include "nprWindowImage.h"

#include "vtkAxis.h"
#include "vtkChartLegend.h"
#include "vtkChartXY.h"
#include "vtkContextScene.h"
#include "vtkContextView.h"
#include "vtkDoubleArray.h"
#include "vtkImageData.h"
#include "vtkNPRRenderWindowFactory.h"
#include "vtkNew.h"
#include "vtkPen.h"
#include "vtkPlotLine.h"
#include "vtkPlotPoints.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkTable.h"
#include "vtkTextProperty.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <numeric>
#include <sstream>
#include <stdexcept>

namespace
{
std::string Quoted(const std::string& text)
{
  if (text.find_first_of(",\"\n") == std::string::npos)
  {
    return text;
  }
  std::string quoted = "\"";
  for (char c : text)
  {
    quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  }
  return quoted + "\"";
}

std::ofstream OpenForWriting(const std::string& path)
{
  std::ofstream file(path);
  if (!file)
  {
    throw std::runtime_error(path + ": cannot write");
  }
  return file;
}

double Mean(const std::vector<double>& values)
{
  return values.empty() ? 0.0 : std::accumulate(values.begin(), values.end(), 0.0) / values.size();
}

std::string SizeName(const nprBenchmarkRow& row)
{
  return std::to_string(row.Width) + "x" + std::to_string(row.Height);
}

// The distinct values of a field, in the order they first appear.
template <typename Field>
std::vector<std::string> Distinct(const std::vector<nprBenchmarkRow>& rows, Field field)
{
  std::vector<std::string> values;
  for (const nprBenchmarkRow& row : rows)
  {
    const std::string value = field(row);
    if (std::find(values.begin(), values.end(), value) == values.end())
    {
      values.push_back(value);
    }
  }
  return values;
}

bool Sane(double value, double low, double high)
{
  return std::isfinite(value) && value >= low && value <= high;
}

// A chart in a headless window, white, its legend beside the plot (where no point can hide
// under it); the plots' tables live as long as it.
struct Chart
{
  vtkSmartPointer<vtkRenderWindow> Window;
  vtkNew<vtkContextView> View;
  vtkNew<vtkChartXY> XY;
  std::vector<vtkSmartPointer<vtkTable>> Tables;

  vtkTable* AddTable(
    const std::vector<double>& x, const std::vector<double>& y, const std::string& name)
  {
    vtkNew<vtkDoubleArray> xs, ys;
    xs->SetName("x");
    ys->SetName(name.c_str());
    for (size_t i = 0; i < x.size(); ++i)
    {
      xs->InsertNextValue(x[i]);
      ys->InsertNextValue(y[i]);
    }
    this->Tables.push_back(vtkSmartPointer<vtkTable>::New());
    this->Tables.back()->AddColumn(xs);
    this->Tables.back()->AddColumn(ys);
    return this->Tables.back();
  }

  void Write(const std::string& path)
  {
    // Twice: the plots take a log scale only after the axes turned it on in a render.
    this->Window->Render();
    this->Window->Render();
    nprWritePNG(nprReadWindowImage(this->Window, false), path); // the frame just rendered
  }
};

std::unique_ptr<Chart> MakeChart(const std::string& path, const std::string& title,
  const std::string& xTitle, const std::string& yTitle)
{
  auto chart = std::unique_ptr<Chart>(new Chart);
  chart->Window =
    vtkSmartPointer<vtkRenderWindow>::Take(vtkNPRRenderWindowFactory::CreateRenderWindow());
  if (!chart->Window)
  {
    throw std::runtime_error(path + ": no render window for the plot");
  }
  chart->Window->SetSize(1200, 700);
  chart->View->SetRenderWindow(chart->Window);
  chart->View->GetRenderer()->SetBackground(1.0, 1.0, 1.0);
  chart->View->GetScene()->AddItem(chart->XY);
  chart->XY->SetTitle(title);
  chart->XY->GetTitleProperties()->SetFontSize(16);
  chart->XY->GetAxis(vtkAxis::BOTTOM)->SetTitle(xTitle);
  chart->XY->GetAxis(vtkAxis::LEFT)->SetTitle(yTitle);
  chart->XY->SetShowLegend(true);
  chart->XY->GetLegend()->SetInline(false);
  chart->XY->GetLegend()->SetVerticalAlignment(vtkChartLegend::CENTER);
  chart->XY->GetLegend()->SetHorizontalAlignment(vtkChartLegend::RIGHT);
  return chart;
}

// Distinct colours and shapes: a qualitative palette, markers cycling through five shapes.
void StyleSeries(vtkPlotPoints* plot, size_t index)
{
  static const unsigned char palette[][3] = { { 228, 26, 28 }, { 55, 126, 184 }, { 77, 175, 74 },
    { 152, 78, 163 }, { 255, 127, 0 }, { 166, 86, 40 }, { 247, 129, 191 }, { 0, 0, 0 },
    { 23, 190, 207 }, { 0, 128, 128 }, { 31, 60, 120 }, { 120, 20, 60 } };
  static const int shapes[] = { vtkPlotPoints::CIRCLE, vtkPlotPoints::SQUARE,
    vtkPlotPoints::DIAMOND, vtkPlotPoints::CROSS, vtkPlotPoints::PLUS };
  const unsigned char* color = palette[index % (sizeof(palette) / sizeof(palette[0]))];
  plot->SetColor(color[0], color[1], color[2], 255);
  plot->SetMarkerStyle(shapes[index % (sizeof(shapes) / sizeof(shapes[0]))]);
  plot->GetPen()->SetWidth(2.0);
}
}

std::string nprFormat(double value, int digits)
{
  if (std::isnan(value))
  {
    return "nan";
  }
  if (std::isinf(value))
  {
    return value > 0 ? "inf" : "-inf";
  }
  char text[64];
  std::snprintf(text, sizeof(text), "%.*g", digits, value);
  return text;
}

int nprBenchmarkStatus(const std::string& problems, const std::string& what)
{
  if (problems.empty())
  {
    return 0;
  }
  std::cerr << "npr-benchmark: error" << what << ":\n" << problems;
  return 1;
}

std::string nprCheckBenchmarkRows(const std::vector<nprBenchmarkRow>& rows)
{
  std::string problems;
  for (const nprBenchmarkRow& row : rows)
  {
    std::string bad;
    for (int t = 0; t < 2; ++t)
    {
      if (!Sane(row.Precision[t], 0, 1) || !Sane(row.Recall[t], 0, 1) || !Sane(row.F1[t], 0, 1))
      {
        bad += " precision/recall/F1 out of [0,1]";
      }
    }
    if (!Sane(row.MeanDistance, 0, 1e6))
    {
      bad += " distance";
    }
    if (!Sane(row.MedianMs, 0, 1e7) || !(row.MedianMs > 0) || !Sane(row.Ratio, 0, 1e6))
    {
      bad += " time";
    }
    if (!bad.empty())
    {
      problems +=
        row.Scene + " " + row.Camera + " " + SizeName(row) + " " + row.Method + ":" + bad + "\n";
    }
  }
  return problems;
}

void nprWriteBenchmarkCSV(const std::string& path, const std::vector<nprBenchmarkRow>& rows)
{
  std::ofstream file = OpenForWriting(path);
  file << "scene,triangles,camera,width,height,method,settings,frames,median_ms,min_ms,"
          "shaded_median_ms,ratio_to_shaded,method_pixels,reference_pixels,precision_1px,"
          "recall_1px,f1_1px,precision_2px,recall_2px,f1_2px,mean_distance_px\n";
  for (const nprBenchmarkRow& row : rows)
  {
    file << Quoted(row.Scene) << "," << row.Triangles << "," << Quoted(row.Camera) << ","
         << row.Width << "," << row.Height << "," << Quoted(row.Method) << ","
         << Quoted(row.Settings) << "," << row.Frames << "," << nprFormat(row.MedianMs, 5) << ","
         << nprFormat(row.MinMs, 5) << "," << nprFormat(row.ShadedMedianMs, 5) << ","
         << nprFormat(row.Ratio, 4) << "," << row.MethodPixels << "," << row.ReferencePixels;
    for (int t = 0; t < 2; ++t)
    {
      file << "," << nprFormat(row.Precision[t]) << "," << nprFormat(row.Recall[t]) << ","
           << nprFormat(row.F1[t]);
    }
    file << "," << nprFormat(row.MeanDistance) << "\n";
  }
}

namespace
{
// Per method and size, over scenes and cameras: medians of the times, means of the errors.
void WriteMethodTable(std::ostream& file, const std::vector<nprBenchmarkRow>& rows,
  const std::vector<std::string>& methods)
{
  file << "| method | size | views | median ms | shaded ms | ratio to shaded | P@1 | R@1 | F1@1 "
          "| F1@2 | distance px |\n";
  file << "|---|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|\n";
  for (const std::string& size : Distinct(rows, SizeName))
  {
    for (const std::string& method : methods)
    {
      std::vector<double> ms, shaded, ratio, precision, recall, f1, f2, distance;
      for (const nprBenchmarkRow& row : rows)
      {
        if (row.Method == method && SizeName(row) == size)
        {
          ms.push_back(row.MedianMs);
          shaded.push_back(row.ShadedMedianMs);
          ratio.push_back(row.Ratio);
          precision.push_back(row.Precision[0]);
          recall.push_back(row.Recall[0]);
          f1.push_back(row.F1[0]);
          f2.push_back(row.F1[1]);
          distance.push_back(row.MeanDistance);
        }
      }
      if (ms.empty())
      {
        continue;
      }
      file << "| " << method << " | " << size << " | " << ms.size() << " | "
           << nprFormat(nprMedian(ms), 4) << " | " << nprFormat(nprMedian(shaded), 4) << " | "
           << nprFormat(nprMedian(ratio), 3) << " | " << nprFormat(Mean(precision), 3) << " | "
           << nprFormat(Mean(recall), 3) << " | " << nprFormat(Mean(f1), 3) << " | "
           << nprFormat(Mean(f2), 3) << " | " << nprFormat(Mean(distance), 3) << " |\n";
    }
  }
}

// F1@1 per scene (mean over cameras and sizes): where each method loses accuracy.
void WriteSceneTable(std::ostream& file, const std::vector<nprBenchmarkRow>& rows,
  const std::vector<std::string>& methods)
{
  const auto scenes = Distinct(rows, [](const nprBenchmarkRow& r) { return r.Scene; });
  file << "\nF1 at 1 px by scene (mean over cameras and sizes):\n\n| method |";
  for (const std::string& scene : scenes)
  {
    file << " " << scene << " |";
  }
  file << "\n|---|";
  for (size_t i = 0; i < scenes.size(); ++i)
  {
    file << "--:|";
  }
  file << "\n";
  for (const std::string& method : methods)
  {
    file << "| " << method << " |";
    for (const std::string& scene : scenes)
    {
      std::vector<double> f1;
      for (const nprBenchmarkRow& row : rows)
      {
        if (row.Method == method && row.Scene == scene)
        {
          f1.push_back(row.F1[0]);
        }
      }
      file << " " << (f1.empty() ? std::string("–") : nprFormat(Mean(f1), 3)) << " |";
    }
    file << "\n";
  }
}
}

void nprWriteBenchmarkMarkdown(
  const std::string& path, const std::vector<nprBenchmarkRow>& rows, const nprBenchmarkInfo& info)
{
  std::ofstream file = OpenForWriting(path);
  file << "Renderer: " << info.Renderer << " (backend " << info.Backend << "); " << info.Frames
       << " timed frames per method and view, interleaved with the shaded frame; whole run "
       << nprFormat(info.Seconds / 60.0, 3) << " min.\n\n";
  file << "Scenes:\n"
       << info.Scenes << "\nCameras (after ResetCamera, perspective): " << info.Cameras
       << ". Sizes: " << info.Sizes << ".\n\nMethods:\n"
       << info.Methods << "\n";
  const auto methods = Distinct(rows, [](const nprBenchmarkRow& r) { return r.Method; });
  WriteMethodTable(file, rows, methods);
  WriteSceneTable(file, rows, methods);

  // The Pareto front of the plot.
  const auto front = nprParetoFront(nprPlotPoints(rows, "", true));
  file << "\nPareto front (median ratio to shaded against mean F1@1, every size):";
  for (const nprPlotPoint& point : front)
  {
    file << " " << point.Name << " (" << nprFormat(point.Time, 3) << ", " << nprFormat(point.F1, 3)
         << ")" << (&point == &front.back() ? "." : ";");
  }
  file << "\n";
}

std::vector<nprPlotPoint> nprPlotPoints(
  const std::vector<nprBenchmarkRow>& rows, const std::string& size, bool ratio)
{
  std::vector<nprPlotPoint> points;
  for (const std::string& method :
    Distinct(rows, [](const nprBenchmarkRow& r) { return r.Method; }))
  {
    std::vector<double> times, f1;
    for (const nprBenchmarkRow& row : rows)
    {
      if (row.Method == method && (size.empty() || SizeName(row) == size))
      {
        times.push_back(ratio ? row.Ratio : row.MedianMs);
        f1.push_back(row.F1[0]);
      }
    }
    if (!times.empty())
    {
      points.push_back({ method, nprMedian(times), Mean(f1) });
    }
  }
  return points;
}

std::vector<nprPlotPoint> nprParetoFront(const std::vector<nprPlotPoint>& points)
{
  std::vector<nprPlotPoint> sorted = points;
  // Fastest first; at equal times the most accurate first, so it alone is kept.
  std::sort(sorted.begin(), sorted.end(),
    [](const nprPlotPoint& a, const nprPlotPoint& b)
    { return a.Time < b.Time || (a.Time == b.Time && a.F1 > b.F1); });
  std::vector<nprPlotPoint> front;
  for (const nprPlotPoint& point : sorted)
  {
    if (front.empty() || point.F1 > front.back().F1)
    {
      front.push_back(point);
    }
  }
  return front;
}

void nprWritePlot(const std::string& path, const std::vector<nprPlotPoint>& points,
  const std::string& title, const std::string& timeTitle)
{
  std::unique_ptr<Chart> chart = MakeChart(path, title, timeTitle, "mean F1 at 1 px");
  auto table = [&](const std::vector<nprPlotPoint>& series, const std::string& name)
  {
    std::vector<double> x, y;
    for (const nprPlotPoint& point : series)
    {
      x.push_back(point.Time);
      y.push_back(point.F1);
    }
    return chart->AddTable(x, y, name);
  };

  // The front first, so that the methods' markers are drawn over its rings.
  const std::vector<nprPlotPoint> front = nprParetoFront(points);
  if (!front.empty())
  {
    // A one-point front is a ring without a line.
    auto* line = vtkPlotPoints::SafeDownCast(
      chart->XY->AddPlot(front.size() > 1 ? vtkChart::LINE : vtkChart::POINTS));
    line->SetInputData(table(front, "Pareto front"), 0, 1);
    line->SetColor(0.55, 0.55, 0.55);
    line->SetWidth(2.0);
    line->SetMarkerStyle(vtkPlotPoints::CIRCLE);
    line->SetMarkerSize(20.0);
  }
  for (size_t i = 0; i < points.size(); ++i)
  {
    auto* plot = vtkPlotPoints::SafeDownCast(chart->XY->AddPlot(vtkChart::POINTS));
    plot->SetInputData(table({ points[i] }, points[i].Name), 0, 1);
    StyleSeries(plot, i);
    plot->SetMarkerSize(11.0);
  }
  // Fixed ranges from zero time and up to F1 = 1, with room around the markers.
  double maxTime = 0.0, minF1 = 1.0;
  for (const nprPlotPoint& point : points)
  {
    maxTime = std::max(maxTime, point.Time);
    minF1 = std::min(minF1, point.F1);
  }
  chart->XY->GetAxis(vtkAxis::BOTTOM)->SetBehavior(vtkAxis::FIXED);
  chart->XY->GetAxis(vtkAxis::BOTTOM)->SetRange(0.0, maxTime > 0 ? 1.1 * maxTime : 1.0);
  chart->XY->GetAxis(vtkAxis::LEFT)->SetBehavior(vtkAxis::FIXED);
  const double low = std::max(0.0, std::floor((minF1 - 0.05) * 20.0) / 20.0);
  chart->XY->GetAxis(vtkAxis::LEFT)->SetRange(low, 1.0 + 0.02 * (1.0 - low));
  chart->Write(path);
}

void nprWriteSeriesPlot(const std::string& path, const std::vector<nprPlotSeries>& series,
  const std::string& title, const std::string& xTitle, const std::string& yTitle, bool logScale)
{
  std::unique_ptr<Chart> chart = MakeChart(path, title, xTitle, yTitle);
  for (size_t i = 0; i < series.size(); ++i)
  {
    auto* plot = vtkPlotPoints::SafeDownCast(chart->XY->AddPlot(vtkChart::LINE));
    plot->SetInputData(chart->AddTable(series[i].X, series[i].Y, series[i].Name), 0, 1);
    StyleSeries(plot, i);
    plot->SetMarkerSize(9.0);
  }
  chart->XY->GetAxis(vtkAxis::BOTTOM)->SetLogScale(logScale);
  chart->XY->GetAxis(vtkAxis::LEFT)->SetLogScale(logScale);
  chart->Write(path);
}

void nprWriteStressCSV(const std::string& path, const std::vector<nprStressRow>& rows)
{
  std::ofstream file = OpenForWriting(path);
  file << "scene,case,detail,f1_1px_own_reference,f1_1px_unit_reference,drift,"
          "reference_f1_vs_unit,mean_distance_unit_px,method_pixels,reference_pixels,"
          "stray_pixels,covered_pixels,coverage_changed,nonfinite_pixels,bad_depth_pixels,"
          "near,far,note\n";
  for (const nprStressRow& row : rows)
  {
    file << Quoted(row.Scene) << "," << Quoted(row.Case) << "," << Quoted(row.Detail) << ","
         << nprFormat(row.F1Own) << "," << nprFormat(row.F1Unit) << "," << nprFormat(row.Drift)
         << "," << nprFormat(row.ReferenceF1) << "," << nprFormat(row.MeanDistanceUnit) << ","
         << row.MethodPixels << "," << row.ReferencePixels << "," << row.StrayPixels << ","
         << row.CoveredPixels << "," << row.CoverageChanged << "," << row.NonFinitePixels << ","
         << row.BadDepthPixels << "," << nprFormat(row.Near, 6) << "," << nprFormat(row.Far, 6)
         << "," << Quoted(row.Note) << "\n";
  }
}

void nprWriteStressMarkdown(
  const std::string& path, const std::vector<nprStressRow>& rows, const nprBenchmarkInfo& info)
{
  std::ofstream file = OpenForWriting(path);
  file << "Renderer: " << info.Renderer << " (backend " << info.Backend << "); size " << info.Sizes
       << ", camera " << info.Cameras << "; edge pass, float G-buffer, default "
       << "settings; run " << nprFormat(info.Seconds, 3) << " s.\n\n";
  file << "| scene | case | detail | F1@1 own ref | F1@1 unit ref | drift | ref vs unit ref "
          "| stray px | coverage changed | non-finite px | bad depth px | note |\n";
  file << "|---|---|---|--:|--:|--:|--:|--:|--:|--:|--:|---|\n";
  for (const nprStressRow& row : rows)
  {
    file << "| " << row.Scene << " | " << row.Case << " | " << row.Detail << " | "
         << nprFormat(row.F1Own, 3) << " | " << nprFormat(row.F1Unit, 3) << " | "
         << nprFormat(row.Drift, 3) << " | " << nprFormat(row.ReferenceF1, 3) << " | "
         << row.StrayPixels << " | " << row.CoverageChanged << " | " << row.NonFinitePixels << " | "
         << row.BadDepthPixels << " | " << row.Note << " |\n";
  }
}

std::string nprFixed(double value, int decimals)
{
  std::ostringstream text;
  text.setf(std::ios::fixed);
  text.precision(decimals);
  text << value;
  return text.str();
}

std::string nprMarkdownHead(const std::vector<std::string>& columns)
{
  std::string rule = "|";
  for (size_t i = 0; i < columns.size(); ++i)
  {
    rule += "---|";
  }
  return nprMarkdownRow(columns) + rule + "\n";
}

std::string nprMarkdownRow(const std::vector<std::string>& cells)
{
  std::string row = "|";
  for (const std::string& cell : cells)
  {
    row += " " + cell + " |";
  }
  return row + "\n";
}

std::string nprCsvRow(const std::vector<std::string>& cells, const std::vector<double>& numbers)
{
  std::ostringstream row;
  const char* separator = "";
  for (const std::string& cell : cells)
  {
    row << separator << cell;
    separator = ",";
  }
  for (double number : numbers)
  {
    row << separator << number;
    separator = ",";
  }
  row << "\n";
  return row.str();
}
