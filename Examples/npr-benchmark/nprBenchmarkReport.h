// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// What npr-benchmark writes: the rows of figures as CSV, the aggregated Markdown table and the
// plots (VTK charts, rendered headless).
#ifndef nprBenchmarkReport_h
#define nprBenchmarkReport_h

#include <string>
#include <vector>

// One scene x camera x size x method.
struct nprBenchmarkRow
{
  std::string Scene;
  long long Triangles = 0;
  std::string Camera;
  int Width = 0;
  int Height = 0;
  std::string Method;
  std::string Settings; // the method's parameters, for the reader
  int Frames = 0;
  double MedianMs = 0.0;
  double MinMs = 0.0;
  double ShadedMedianMs = 0.0;
  double Ratio = 0.0; // MedianMs / ShadedMedianMs
  long long MethodPixels = 0;
  long long ReferencePixels = 0;
  double Precision[2] = { 0, 0 }; // at 1 and 2 pixels
  double Recall[2] = { 0, 0 };
  double F1[2] = { 0, 0 };
  double MeanDistance = 0.0;
};

// Run-wide facts printed at the head of the Markdown report.
struct nprBenchmarkInfo
{
  std::string Renderer; // GL_RENDERER
  std::string Backend;
  int Frames = 0;
  std::string Sizes;
  std::string Scenes; // one line per scene: name, triangles, description
  std::string Cameras;
  std::string Methods; // one line per method: name, settings
  double Seconds = 0.0;
};

// The figures that can go wrong (NaN, out of range): empty when every row is sane.
std::string nprCheckBenchmarkRows(const std::vector<nprBenchmarkRow>& rows);

// A mode's exit status: 0 without problems; else 1, after printing them on stderr under
// "npr-benchmark: error:" and what (": figures out of range").
int nprBenchmarkStatus(const std::string& problems, const std::string& what = "");

void nprWriteBenchmarkCSV(const std::string& path, const std::vector<nprBenchmarkRow>& rows);
void nprWriteBenchmarkMarkdown(
  const std::string& path, const std::vector<nprBenchmarkRow>& rows, const nprBenchmarkInfo& info);

// One point of the plot: a method's time and accuracy.
struct nprPlotPoint
{
  std::string Name;
  double Time = 0.0;
  double F1 = 0.0;
};
// The methods not beaten on both axes (faster and at least as accurate), fastest first.
std::vector<nprPlotPoint> nprParetoFront(const std::vector<nprPlotPoint>& points);
// Per method over all rows of the given size ("" for every size): the median of the times
// (ratios to shaded when ratio is true, else milliseconds) and the mean F1 at 1 pixel.
std::vector<nprPlotPoint> nprPlotPoints(
  const std::vector<nprBenchmarkRow>& rows, const std::string& size, bool ratio);
// Draws the points (one series per method, the Pareto front ringed and joined) with vtkChartXY
// in a headless window and writes a PNG.
void nprWritePlot(const std::string& path, const std::vector<nprPlotPoint>& points,
  const std::string& title, const std::string& timeTitle);

// One line of a plot: its points, joined in order.
struct nprPlotSeries
{
  std::string Name;
  std::vector<double> X, Y;
};
// Draws each series as a line with markers (both axes logarithmic with logScale), as
// nprWritePlot draws, and writes a PNG.
void nprWriteSeriesPlot(const std::string& path, const std::vector<nprPlotSeries>& series,
  const std::string& title, const std::string& xTitle, const std::string& yTitle, bool logScale);

// ---- Stress mode ----
struct nprStressRow
{
  std::string Scene;
  std::string Case;
  std::string Detail;       // what was done, in numbers
  double F1Own = 0.0;       // F1@1 of the edge pass against this case's reference mask
  double F1Unit = 0.0;      // F1@1 of the edge pass against the unit case's reference mask
  double Drift = 0.0;       // F1Unit - the unit case's F1@1
  double ReferenceF1 = 0.0; // F1@1 of this case's reference against the unit case's
  double MeanDistanceUnit = 0.0;
  long long MethodPixels = 0;
  long long ReferencePixels = 0;
  long long StrayPixels = 0;     // line pixels > 3 px from every unit-reference line pixel
  long long CoveredPixels = 0;   // G-buffer pixels with geometry
  long long CoverageChanged = 0; // covered here xor covered in the unit case
  long long NonFinitePixels = 0; // covered, with a NaN or infinite depth or normal code
  long long BadDepthPixels = 0;  // covered, depth outside [near, far] (0.1 % margin) or <= 0
  double Near = 0.0;
  double Far = 0.0;
  std::string Note;
};
void nprWriteStressCSV(const std::string& path, const std::vector<nprStressRow>& rows);
void nprWriteStressMarkdown(
  const std::string& path, const std::vector<nprStressRow>& rows, const nprBenchmarkInfo& info);

// A number for CSV and Markdown: %.*g, "nan" and "inf" spelt out.
std::string nprFormat(double value, int digits = 4);
// A number with a fixed count of decimals (the tables' milliseconds and ratios).
std::string nprFixed(double value, int decimals);

// A Markdown table's head: "| a | b |\n|---|---|\n".
std::string nprMarkdownHead(const std::vector<std::string>& columns);
// A Markdown table's row: "| a | b |\n".
std::string nprMarkdownRow(const std::vector<std::string>& cells);
// A CSV row: the text cells, then the numbers as a stream writes them (6 significant digits).
std::string nprCsvRow(const std::vector<std::string>& cells, const std::vector<double>& numbers);

#endif
