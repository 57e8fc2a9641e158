// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nprBenchmarkDrawing.h"

#include "nprBenchmarkOptions.h"
#include "nprBenchmarkReport.h"
#include "nprBenchmarkScenes.h"
#include "nprBenchmarkStage.h"
#include "nprEdgeMetrics.h"
#include "nprPassSettings.h"
#include "nprTiming.h"

#include "vtkCamera.h"
#include "vtkImageData.h"
#include "vtkNPRDrawingExporter.h"
#include "vtkNPRDrawingLines.h"
#include "vtkNPRDrawingPass.h"
#include "vtkNPREdgePass.h"
#include "vtkNPRPass.h"
#include "vtkNPRRenderWindowFactory.h"
#include "vtkNew.h"
#include "vtkPNGReader.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace
{
struct DrawingRow
{
  std::string Scene, Size, Format;
  bool Hidden = false;
  double Seconds = 0.0, StrokesSeconds = 0.0, LinesSeconds = 0.0, LocatorSeconds = 0.0,
         VisibilitySeconds = 0.0, WriteSeconds = 0.0;
  long long Bytes = 0, Strokes = 0, FeatureEdges = 0;
  double F1 = -1.0, Precision = -1.0, Recall = -1.0; // -1: not measured
};

struct StyleRow
{
  std::string Scene, Size;
  double FirstMs = 0.0, MovedMs = 0.0, StillMs = 0.0, ShadedMs = 0.0;
};

std::string Quoted(const std::string& path)
{
  std::string quoted = "'";
  for (char c : path)
  {
    quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  }
  return quoted + "'";
}

// The drawing rasterised at the image size by rsvg-convert or pdftoppm; null when the program
// is missing or fails.
vtkSmartPointer<vtkImageData> Rasterise(
  const std::string& file, bool pdf, int width, int height, const std::string& png)
{
#if defined(NPR_RSVG_CONVERT) && defined(NPR_PDFTOPPM)
  const std::string program = pdf ? NPR_PDFTOPPM : NPR_RSVG_CONVERT;
  if (program.empty() || program.find("NOTFOUND") != std::string::npos)
  {
    return nullptr;
  }
  const std::string stem = png.substr(0, png.size() - 4);
  const std::string command = pdf
    ? Quoted(program) + " -png -singlefile -scale-to-x " + std::to_string(width) + " -scale-to-y " +
      std::to_string(height) + " " + Quoted(file) + " " + Quoted(stem)
    : Quoted(program) + " -w " + std::to_string(width) + " -h " + std::to_string(height) + " -o " +
      Quoted(png) + " " + Quoted(file);
  if (std::system(command.c_str()) != 0)
  {
    std::cerr << "npr-benchmark: failed: " << command << "\n";
    return nullptr;
  }
  vtkNew<vtkPNGReader> reader;
  reader->SetFileName(png.c_str());
  reader->Update();
  vtkSmartPointer<vtkImageData> image = reader->GetOutput();
  const int* dimensions = image->GetDimensions();
  return dimensions[0] == width && dimensions[1] == height ? image : nullptr;
#else
  (void)file;
  (void)pdf;
  (void)width;
  (void)height;
  (void)png;
  return nullptr;
#endif
}

// Line pixels of a drawing rasterised black on white: the first channel below 160.
std::vector<unsigned char> LinePixels(vtkImageData* image, int width, int height)
{
  std::vector<unsigned char> mask(static_cast<size_t>(width) * height, 0);
  const int components = image->GetNumberOfScalarComponents();
  const auto* pixels = static_cast<const unsigned char*>(image->GetScalarPointer());
  for (size_t i = 0; i < mask.size(); ++i)
  {
    mask[i] = pixels[i * components] < 160 ? 255 : 0;
  }
  return mask;
}

// The file's figures from its exporter; false (and a problem) if it could not be written.
bool ExportDrawing(vtkRenderer* renderer, vtkNPRPass* drawing, const std::string& file,
  DrawingRow& row, std::string& problems)
{
  vtkNew<vtkNPRDrawingExporter> exporter; // new for each file: nothing built before
  exporter->SetRenderer(renderer);
  exporter->SetDrawingPass(drawing->GetDrawingPass());
  exporter->SetEdgePass(drawing->GetEdgePass());
  exporter->SetEmbedImage(0);
  exporter->SetFileName(file.c_str());
  const nprClock::time_point start = nprClock::now();
  if (!exporter->Write())
  {
    problems += file + ": " + exporter->GetErrorMessage() + "\n";
    return false;
  }
  row.Seconds = nprSecondsSince(start);
  row.StrokesSeconds = exporter->GetStrokesTime();
  row.WriteSeconds = exporter->GetWriteTime();
  vtkNPRDrawingLines* lines = exporter->GetDrawingLines();
  row.LinesSeconds = lines->GetLinesTime();
  row.LocatorSeconds = lines->GetLocatorTime();
  row.VisibilitySeconds = lines->GetVisibilityTime();
  row.Bytes = static_cast<long long>(std::filesystem::file_size(file));
  row.Strokes = exporter->GetNumberOfStrokes();
  row.FeatureEdges = lines->GetNumberOfFeatureEdges();
  return true;
}

// The file rasterised (where rsvg-convert and pdftoppm are) against the reference mask.
void ScoreDrawing(
  const std::string& file, const std::string& png, const nprMask& reference, DrawingRow& row)
{
  vtkSmartPointer<vtkImageData> image =
    Rasterise(file, row.Format == "pdf", reference.Width, reference.Height, png);
  if (image)
  {
    const std::vector<unsigned char> mask = LinePixels(image, reference.Width, reference.Height);
    nprEdgeMetrics metrics;
    metrics.Compute(mask.data(), reference.Pixels.data(), reference.Width, reference.Height);
    row.F1 = metrics.F1(1.0);
    row.Precision = metrics.Precision(1.0);
    row.Recall = metrics.Recall(1.0);
  }
}

// SVG and PDF, without and with hidden lines, of the scene at the window's size: one row each.
void MeasureVectorFiles(nprBenchmarkStage& stage, vtkNPRPass* drawing,
  const nprBenchmarkOptions& options, const std::string& scene, const std::string& sizeName,
  const nprMask& reference, std::vector<DrawingRow>& rows, std::string& problems)
{
  for (bool hidden : { false, true })
  {
    drawing->SetHiddenLines(hidden);
    for (const char* format : { "svg", "pdf" })
    {
      DrawingRow row{ scene, sizeName, format, hidden };
      const std::string stem =
        options.Out + "/drawing_" + scene + "_" + sizeName + (hidden ? "_hidden" : "");
      const std::string file = stem + "." + format;
      if (!ExportDrawing(stage.Renderer, drawing, file, row, problems))
      {
        continue;
      }
      if (!hidden)
      {
        ScoreDrawing(file, stem + "_" + format + ".png", reference, row);
      }
      std::cerr << "npr-benchmark: " << file << ": " << nprFixed(row.Seconds, 3) << " s, "
                << row.Bytes << " bytes, " << row.Strokes << " strokes of " << row.FeatureEdges
                << " edges" << (row.F1 >= 0 ? ", F1@1 " + nprFixed(row.F1, 4) : std::string())
                << "\n";
      if (row.Strokes <= 0 || row.Bytes <= 0 || (row.F1 >= 0 && !(row.F1 <= 1.0)))
      {
        problems += file + ": no strokes, an empty file or an F1 out of range\n";
      }
      rows.push_back(row);
    }
  }
  drawing->SetHiddenLines(false);
}

double RenderMs(vtkRenderWindow* window)
{
  const nprClock::time_point start = nprClock::now();
  window->Render();
  return 1000.0 * nprSecondsSince(start);
}

// The drawing style on screen: the first frame (strokes from scratch), a frame after the camera
// turned 1 degree (strokes again, meshes known), an unchanged frame; beside the shaded frame.
StyleRow MeasureDrawingStyle(nprBenchmarkStage& stage, const nprPassSettings& settings, int frames,
  const std::string& scene, const std::string& sizeName)
{
  StyleRow style{ scene, sizeName };
  stage.Activate(nullptr, false);
  style.ShadedMs = nprTimeFrame(stage.Window, stage.Camera());
  vtkNew<vtkNPRPass> fresh; // nothing built yet
  nprApplyPassSettings(fresh, settings);
  stage.Activate(fresh, false);
  style.FirstMs = RenderMs(stage.Window);
  std::vector<double> moved, still;
  for (int frame = 0; frame < std::max(1, frames / 2); ++frame)
  {
    stage.Camera()->Azimuth(1.0);
    stage.Renderer->ResetCameraClippingRange();
    moved.push_back(RenderMs(stage.Window));
    still.push_back(RenderMs(stage.Window));
  }
  style.MovedMs = nprMedian(moved);
  style.StillMs = nprMedian(still);
  stage.Activate(nullptr, false);
  std::cerr << "npr-benchmark: drawing style " << scene << " " << sizeName << ": first "
            << nprFixed(style.FirstMs, 1) << " ms, camera turned " << nprFixed(style.MovedMs, 1)
            << " ms, unchanged " << nprFixed(style.StillMs, 1) << " ms\n";
  return style;
}

// drawing.csv and the vector files' table; returns false if the file could not be written.
bool WriteFileRows(
  const std::string& out, const std::vector<DrawingRow>& rows, std::ostringstream& md)
{
  std::ofstream csv(out + "/drawing.csv");
  csv << "scene,size,format,hidden_lines,seconds,strokes_seconds,lines_seconds,locator_seconds,"
         "visibility_seconds,write_seconds,bytes,strokes,feature_edges,f1_at_1,precision_at_1,"
         "recall_at_1\n";
  md << "| scene | size | file | hidden lines | time (s) | of which lines, locator, visibility "
        "(s) | painting and writing (s) | size (KB) | strokes | feature edges | F1@1 |\n"
        "|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const DrawingRow& row : rows)
  {
    csv << row.Scene << "," << row.Size << "," << row.Format << "," << (row.Hidden ? 1 : 0) << ","
        << row.Seconds << "," << row.StrokesSeconds << "," << row.LinesSeconds << ","
        << row.LocatorSeconds << "," << row.VisibilitySeconds << "," << row.WriteSeconds << ","
        << row.Bytes << "," << row.Strokes << "," << row.FeatureEdges << "," << row.F1 << ","
        << row.Precision << "," << row.Recall << "\n";
    md << "| " << row.Scene << " | " << row.Size << " | " << row.Format << " | "
       << (row.Hidden ? "yes" : "no") << " | " << nprFixed(row.Seconds, 3) << " | "
       << nprFixed(row.LinesSeconds, 2) << ", " << nprFixed(row.LocatorSeconds, 2) << ", "
       << nprFixed(row.VisibilitySeconds, 2) << " | " << nprFixed(row.WriteSeconds, 3) << " | "
       << nprFixed(row.Bytes / 1024.0, 0) << " | " << row.Strokes << " | " << row.FeatureEdges
       << " | " << (row.F1 >= 0 ? nprFixed(row.F1, 4) : std::string("")) << " |\n";
  }
  return static_cast<bool>(csv);
}

// drawing_style.csv and the style's table; returns false if the file could not be written.
bool WriteStyleRows(
  const std::string& out, const std::vector<StyleRow>& styleRows, std::ostringstream& md)
{
  md << "\n"
     << nprMarkdownHead({ "scene", "size", "shaded frame (ms)", "drawing, first frame (ms)",
          "drawing, camera turned 1 degree (ms)", "drawing, unchanged (ms)" });
  std::ofstream styleCsv(out + "/drawing_style.csv");
  styleCsv << "scene,size,shaded_ms,first_ms,moved_ms,unchanged_ms\n";
  for (const StyleRow& row : styleRows)
  {
    md << nprMarkdownRow({ row.Scene, row.Size, nprFixed(row.ShadedMs, 1), nprFixed(row.FirstMs, 1),
      nprFixed(row.MovedMs, 1), nprFixed(row.StillMs, 1) });
    styleCsv << nprCsvRow(
      { row.Scene, row.Size }, { row.ShadedMs, row.FirstMs, row.MovedMs, row.StillMs });
  }
  return static_cast<bool>(styleCsv);
}

void WriteDrawingReports(const nprBenchmarkOptions& options, vtkRenderWindow* window,
  const std::vector<DrawingRow>& rows, const std::vector<StyleRow>& styleRows)
{
  std::ostringstream md;
  const bool filesWritten = WriteFileRows(options.Out, rows, md);
  const bool styleWritten = WriteStyleRows(options.Out, styleRows, md);
  std::ofstream markdown(options.Out + "/drawing.md");
  markdown << "Technical drawings (npr-benchmark --drawing) on "
           << vtkNPRRenderWindowFactory::GetGLRenderer(window)
           << ": each file from a new vtkNPRDrawingExporter (the meshes' adjacency and occlusion "
              "structure built from scratch), 1 px lines; F1@1 of the file rasterised by "
              "rsvg-convert or pdftoppm against the reference mask.\n\n"
           << md.str();
  std::cout << md.str();
  if (!filesWritten || !styleWritten || !markdown)
  {
    throw std::runtime_error(
      options.Out + ": cannot write drawing.csv, drawing_style.csv or drawing.md");
  }
}
}

int nprRunBenchmarkDrawing(const nprBenchmarkOptions& options)
{
  const nprClock::time_point runStart = nprClock::now();
  const std::vector<nprBenchmarkScene> scenes = nprStartBenchmarkRun(options);
  nprBenchmarkStage stage(options.LineWidth);
  // The drawing style, lines 1 px wide (what the reference mask is compared with).
  nprPassSettings settings;
  settings.Style = "drawing";
  settings.LineWidth = 1.0;
  vtkSmartPointer<vtkNPRPass> drawing = nprMakePass(settings);
  std::vector<DrawingRow> rows;
  std::vector<StyleRow> styleRows;
  std::string problems;
  for (const nprBenchmarkScene& scene : scenes)
  {
    stage.SetMesh(scene.Mesh, scene.Raw);
    for (const auto& size : options.Sizes)
    {
      stage.Window->SetSize(size.first, size.second);
      const std::string sizeName = std::to_string(size.first) + "x" + std::to_string(size.second);
      stage.Activate(nullptr, false);
      nprApplyBenchmarkCamera(stage.Renderer, nprBenchmarkCameras()[0]);
      stage.Window->Render();
      const nprMask reference = stage.ReferenceMask();
      MeasureVectorFiles(stage, drawing, options, scene.Name, sizeName, reference, rows, problems);
      styleRows.push_back(
        MeasureDrawingStyle(stage, settings, options.Frames, scene.Name, sizeName));
    }
  }
  WriteDrawingReports(options, stage.Window, rows, styleRows);
  std::cerr << "npr-benchmark: wrote " << options.Out << "/drawing.{csv,md}, drawing_style.csv in "
            << nprFormat(nprSecondsSince(runStart), 4) << " s\n";
  return nprBenchmarkStatus(problems);
}
