// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nprBenchmarkScale.h"

#include "nprBenchmarkOptions.h"
#include "nprBenchmarkProcess.h"
#include "nprBenchmarkReport.h"
#include "nprTiming.h"

#include "vtkCleanPolyData.h"
#include "vtkLoopSubdivisionFilter.h"
#include "vtkNew.h"
#include "vtkPLYReader.h"
#include "vtkPLYWriter.h"
#include "vtkPolyData.h"
#include "vtkQuadricDecimation.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <thread>

namespace
{
// The bunny decimated to this many triangles: each Loop level multiplies them by 4, so the
// sizes are round (62,500, 250,000, 1M, 4M, 16M) and all the same surface.
const long long BaseTriangles = 62500;
const double ChildTimeoutSeconds = 1800.0;

struct ScaleSize
{
  std::string Name;
  int Levels = 0;
  std::string Mesh; // the PLY file
  long long Triangles = 0;
};

// One measured figure of one size: a whole program, or a step of --scale-steps.
struct ScaleRow
{
  std::string Size;
  long long Triangles = 0;
  std::string Kind; // "program" or "step"
  std::string Name;
  double Seconds = -1.0; // < 0: not measured, Status says why
  double PeakMB = -1.0;
  double AddedMB = -1.0; // steps: the peak over the memory at the step's start
  std::string Status;
  bool Ours = true; // a failure of ours is an error; another program's is reported only

  double NanosecondsPerTriangle() const
  {
    return this->Seconds >= 0.0 ? 1e9 * this->Seconds / static_cast<double>(this->Triangles) : -1.0;
  }
};

// Where the programs are, and the X display F3D draws on ("" with Missing set when none).
struct ScaleTools
{
  std::string Self, NPRRender, PlainVTK, F3D, Display, F3DMissing;
};

struct ScaleProgram
{
  std::string Name;
  std::vector<std::string> Arguments; // empty: not run, Status says why
  std::string Output;
  std::string Status;
  bool X = false;   // drawn on the X display
  bool Ours = true; // its failure is an error
};

// The face count in a PLY file's header; -1 when the file is missing or not a PLY.
long long PLYFaces(const std::string& path)
{
  std::ifstream file(path, std::ios::binary);
  std::string line;
  if (!std::getline(file, line) || line.compare(0, 3, "ply") != 0)
  {
    return -1;
  }
  long long faces = -1;
  for (int i = 0; i < 100 && std::getline(file, line); ++i)
  {
    if (line.compare(0, 13, "element face ") == 0)
    {
      faces = std::atoll(line.c_str() + 13);
    }
    else if (line.compare(0, 10, "end_header") == 0)
    {
      return faces;
    }
  }
  return -1;
}

// The bunny decimated to BaseTriangles (quadric decimation), refined by levels of Loop
// subdivision, written as binary PLY (through a .part.ply file, so that an interrupted write is
// not taken for a mesh).
void MakeScaleMesh(const std::string& bunny, int levels, const std::string& path)
{
  vtkNew<vtkPLYReader> reader;
  reader->SetFileName(bunny.c_str());
  vtkNew<vtkCleanPolyData> clean;
  clean->SetInputConnection(reader->GetOutputPort());
  clean->Update();
  const double triangles = static_cast<double>(clean->GetOutput()->GetNumberOfPolys());
  if (triangles < BaseTriangles)
  {
    throw std::runtime_error(bunny + ": not the bunny (fewer than 62,500 triangles)");
  }
  vtkNew<vtkQuadricDecimation> decimate;
  decimate->SetInputConnection(clean->GetOutputPort());
  decimate->SetTargetReduction(1.0 - BaseTriangles / triangles);
  vtkNew<vtkLoopSubdivisionFilter> refine;
  refine->SetInputConnection(decimate->GetOutputPort());
  refine->SetNumberOfSubdivisions(levels);
  vtkNew<vtkPLYWriter> writer;
  writer->SetInputConnection(levels > 0 ? refine->GetOutputPort() : decimate->GetOutputPort());
  writer->SetFileTypeToBinary();
  // vtkPLYWriter adds .ply to a name without it.
  const std::string part = path.substr(0, path.rfind(".ply")) + ".part.ply";
  writer->SetFileName(part.c_str());
  if (!writer->Write() || std::rename(part.c_str(), path.c_str()) != 0)
  {
    throw std::runtime_error(path + ": cannot write the mesh");
  }
}

// Each size's mesh from the folder, made first when it is missing.
std::vector<ScaleSize> ScaleMeshes(const nprBenchmarkOptions& options)
{
  std::vector<ScaleSize> sizes;
  for (const std::string& name : options.ScaleSizes)
  {
    ScaleSize size;
    size.Name = name;
    const auto& names = nprScaleSizeNames();
    size.Levels = static_cast<int>(std::find(names.begin(), names.end(), name) - names.begin());
    size.Mesh = options.ScaleMeshes + "/bunny_" + name + ".ply";
    size.Triangles = PLYFaces(size.Mesh);
    if (size.Triangles <= 0)
    {
      std::cerr << "npr-benchmark: making " << size.Mesh << " (Loop subdivision, " << size.Levels
                << (size.Levels == 1 ? " level)\n" : " levels)\n");
      const nprClock::time_point start = nprClock::now();
      MakeScaleMesh(options.Data + "/bunny.ply", size.Levels, size.Mesh);
      size.Triangles = PLYFaces(size.Mesh);
      std::cerr << "npr-benchmark: made it in " << nprFixed(nprSecondsSince(start), 1) << " s\n";
    }
    if (size.Triangles <= 0)
    {
      throw std::runtime_error(size.Mesh + ": no triangles in its header");
    }
    sizes.push_back(size);
  }
  return sizes;
}

ScaleTools FindTools(const std::string& out, std::unique_ptr<nprPrivateXServer>& xserver)
{
  ScaleTools tools;
  tools.Self = nprOwnExecutable();
  const std::string folder = tools.Self.substr(0, tools.Self.find_last_of('/') + 1);
  tools.NPRRender = nprFindProgram(folder + "npr-render");
  tools.PlainVTK = nprFindProgram(folder + "npr-plain-vtk");
  tools.F3D = nprFindProgram("f3d");
  const char* display = std::getenv("DISPLAY");
  if (tools.F3D.empty())
  {
    tools.F3DMissing = "not installed";
  }
  else if (display && *display)
  {
    tools.Display = display;
  }
  else
  {
    // Debian's f3d draws only on an X display (without one it crashes).
    xserver.reset(new nprPrivateXServer(out + "/logs/Xvfb.log"));
    tools.Display = xserver->Display();
    tools.F3DMissing = tools.Display.empty() ? "no X display (Xvfb missing or failed)" : "";
  }
  return tools;
}

// Every whole program measured on a mesh, writing into stem + its own name.
std::vector<ScaleProgram> ScalePrograms(const ScaleTools& tools, const std::string& mesh,
  const std::string& stem, const std::pair<int, int>& size)
{
  const std::string wxh = std::to_string(size.first) + "x" + std::to_string(size.second);
  std::vector<ScaleProgram> programs;
  // f3d: another program's (its failure is reported, not an error), drawn on the X display.
  auto add = [&](const std::string& name, const std::string& program,
               const std::vector<std::string>& arguments, const std::string& output, bool f3d,
               const std::string& missing)
  {
    ScaleProgram entry{ name, {}, output, missing, f3d, !f3d };
    if (missing.empty())
    {
      entry.Arguments = { program };
      entry.Arguments.insert(entry.Arguments.end(), arguments.begin(), arguments.end());
    }
    programs.push_back(entry);
  };
  const std::string nprRender = tools.NPRRender.empty() ? "not built" : "";
  for (const char* style : { "shaded", "edges", "sketch", "toon+edges", "drawing" })
  {
    const std::string png = stem + "npr-render_" + style + ".png";
    add(std::string("npr-render --style ") + style, tools.NPRRender,
      { mesh, "--style", style, "--size", wxh, "-o", png }, png, false, nprRender);
  }
  const std::string svg = stem + "npr-render_drawing.svg";
  add("npr-render --style drawing -o x.svg", tools.NPRRender,
    { mesh, "--style", "drawing", "--size", wxh, "-o", svg }, svg, false, nprRender);
  const std::string resolution = std::to_string(size.first) + "," + std::to_string(size.second);
  for (bool edges : { false, true })
  {
    const std::string png = stem + (edges ? "f3d_edges.png" : "f3d.png");
    std::vector<std::string> arguments = { "--output", png, "--resolution", resolution, mesh };
    if (edges)
    {
      arguments.insert(arguments.begin(), "--edges");
    }
    add(edges ? "F3D --output --edges" : "F3D --output", tools.F3D, arguments, png, true,
      tools.F3DMissing);
  }
  const std::string plain = stem + "plain_vtk.png";
  add("plain VTK: vtkPLYReader, vtkPolyDataNormals, render, PNG", tools.PlainVTK,
    { mesh, wxh, plain }, plain, false, tools.PlainVTK.empty() ? "not built" : "");
  return programs;
}

// A file name for a program's log: "npr-render --style toon+edges" as
// "npr_render_style_toon+edges".
std::string LogName(const std::string& name)
{
  std::string log;
  for (char c : name)
  {
    const bool kept = std::isalnum(static_cast<unsigned char>(c)) || c == '+';
    if (kept || (!log.empty() && log.back() != '_'))
    {
      log += kept ? c : '_';
    }
  }
  return log;
}

long long FileSize(const std::string& path)
{
  std::ifstream file(path, std::ios::binary | std::ios::ate);
  return file ? static_cast<long long>(file.tellg()) : -1;
}

ScaleRow RunProgram(const ScaleProgram& program, const ScaleSize& size, const ScaleTools& tools,
  const std::string& log)
{
  ScaleRow row{ size.Name, size.Triangles, "program", program.Name };
  row.Ours = program.Ours;
  row.Status = program.Status;
  if (!program.Arguments.empty())
  {
    std::remove(program.Output.c_str());
    const nprChildResult result = nprRunChild(
      program.Arguments, log, program.X ? tools.Display : std::string(), ChildTimeoutSeconds);
    row.Status = !result.Problem.empty() ? result.Problem
      : FileSize(program.Output) <= 0    ? "wrote nothing"
                                         : "";
    if (row.Status.empty())
    {
      row.Seconds = result.Seconds;
      row.PeakMB = result.PeakMB;
    }
  }
  std::cerr << "npr-benchmark: " << size.Name << ": " << program.Name << ": "
            << (row.Status.empty()
                   ? nprFixed(row.Seconds, 2) + " s, " + nprFixed(row.PeakMB, 0) + " MB"
                   : row.Status)
            << "\n";
  return row;
}

// The steps of one size in a child npr-benchmark (--scale-steps).
std::vector<ScaleRow> RunSteps(const ScaleSize& size, const ScaleTools& tools,
  const nprBenchmarkOptions& options, const std::string& log)
{
  const std::string out = options.Out + "/steps/" + size.Name;
  const auto& window = options.Sizes.front();
  const std::vector<std::string> arguments = { tools.Self, "--scale-steps", size.Mesh, "--data",
    options.Data, "--out", out, "--frames", std::to_string(options.Frames), "--sizes",
    std::to_string(window.first) + "x" + std::to_string(window.second), "--line-width",
    nprFormat(options.LineWidth) };
  std::cerr << "npr-benchmark: " << size.Name << ": the steps (log: " << log << ")\n";
  const nprChildResult result = nprRunChild(arguments, log, "", ChildTimeoutSeconds);
  if (!result.Problem.empty())
  {
    ScaleRow row{ size.Name, size.Triangles, "step", "npr-benchmark --scale-steps" };
    row.Status = result.Problem;
    return { row };
  }
  std::vector<ScaleRow> rows;
  for (const nprScaleStep& step : nprReadScaleSteps(out + "/steps.csv"))
  {
    ScaleRow row{ size.Name, size.Triangles, "step", step.Name, step.Seconds, step.PeakMB,
      step.AddedMB };
    row.Status = step.Seconds < 0.0 ? "n/a" : "";
    rows.push_back(row);
  }
  return rows;
}

// The names of one kind of row, in the order they first appear.
std::vector<std::string> RowNames(const std::vector<ScaleRow>& rows, const std::string& kind)
{
  std::vector<std::string> names;
  for (const ScaleRow& row : rows)
  {
    if (row.Kind == kind && std::find(names.begin(), names.end(), row.Name) == names.end())
    {
      names.push_back(row.Name);
    }
  }
  return names;
}

const ScaleRow* FindRow(const std::vector<ScaleRow>& rows, const std::string& kind,
  const std::string& name, const std::string& size)
{
  for (const ScaleRow& row : rows)
  {
    if (row.Kind == kind && row.Name == name && row.Size == size)
    {
      return &row;
    }
  }
  return nullptr;
}

// Every program on one size, then its steps.
std::vector<ScaleRow> MeasureSize(
  const ScaleSize& size, const ScaleTools& tools, const nprBenchmarkOptions& options)
{
  std::vector<ScaleRow> rows;
  const std::string stem = options.Out + "/images/" + size.Name + "_";
  for (const ScaleProgram& program : ScalePrograms(tools, size.Mesh, stem, options.Sizes.front()))
  {
    const std::string log = LogName(program.Name.substr(0, program.Name.find(':')));
    rows.push_back(
      RunProgram(program, size, tools, options.Out + "/logs/" + size.Name + "_" + log + ".log"));
  }
  const std::vector<ScaleRow> steps =
    RunSteps(size, tools, options, options.Out + "/logs/" + size.Name + "_steps.log");
  rows.insert(rows.end(), steps.begin(), steps.end());
  return rows;
}

// Per size, kind and name, the median of each figure over the runs; a failure in any run is
// the row's (status, no figures).
std::vector<ScaleRow> MedianRows(const std::vector<ScaleRow>& runs)
{
  std::vector<ScaleRow> rows;
  for (const ScaleRow& first : runs)
  {
    if (FindRow(rows, first.Kind, first.Name, first.Size))
    {
      continue;
    }
    ScaleRow row = first;
    std::vector<double> seconds, peaks, added;
    for (const ScaleRow& run : runs)
    {
      if (run.Kind == row.Kind && run.Name == row.Name && run.Size == row.Size)
      {
        row.Status = row.Status.empty() ? run.Status : row.Status;
        seconds.push_back(run.Seconds);
        peaks.push_back(run.PeakMB);
        added.push_back(run.AddedMB);
      }
    }
    const bool measured = row.Status.empty();
    row.Seconds = measured ? nprMedian(seconds) : -1.0;
    row.PeakMB = measured && row.PeakMB >= 0.0 ? nprMedian(peaks) : -1.0;
    row.AddedMB = measured && row.AddedMB >= 0.0 ? nprMedian(added) : -1.0;
    rows.push_back(row);
  }
  return rows;
}

// ns per triangle at the largest size over that at the smallest; < 0 when either is missing.
double GrowthRatio(const std::vector<ScaleRow>& rows, const std::string& kind,
  const std::string& name, const std::vector<ScaleSize>& sizes)
{
  const ScaleRow* small = FindRow(rows, kind, name, sizes.front().Name);
  const ScaleRow* large = FindRow(rows, kind, name, sizes.back().Name);
  if (sizes.size() < 2 || !small || !large || small->Seconds <= 0.0 || large->Seconds < 0.0)
  {
    return -1.0;
  }
  return large->NanosecondsPerTriangle() / small->NanosecondsPerTriangle();
}

// About 3 significant digits, never in e-notation: "6590", "18.0", "0.41".
std::string Nanoseconds(double ns)
{
  return nprFixed(ns, ns >= 100.0 ? 0 : ns >= 10.0 ? 1 : 2);
}

// One table: per size the time (s for programs, ms for steps) and the peak memory, then ns per
// triangle at each size and the growth from the smallest to the largest.
void WriteTable(std::ostream& md, const std::vector<ScaleRow>& rows, const std::string& kind,
  const std::vector<ScaleSize>& sizes)
{
  const bool steps = kind == "step";
  md << "| " << (steps ? "step" : "program") << " |";
  for (const ScaleSize& size : sizes)
  {
    md << " " << size.Name << (steps ? " ms" : " s") << " | " << size.Name << " MB |";
  }
  for (const ScaleSize& size : sizes)
  {
    md << " ns/tri " << size.Name << " |";
  }
  md << " " << sizes.back().Name << " / " << sizes.front().Name << " | within 1.3x |\n|---|";
  for (size_t i = 0; i < 3 * sizes.size() + 2; ++i)
  {
    md << "--:|";
  }
  md << "\n";
  for (const std::string& name : RowNames(rows, kind))
  {
    md << "| " << name << " |";
    for (const ScaleSize& size : sizes)
    {
      const ScaleRow* row = FindRow(rows, kind, name, size.Name);
      const bool timed = row && row->Seconds >= 0.0;
      md << " "
         << (timed ? nprFixed(steps ? 1e3 * row->Seconds : row->Seconds, steps ? 1 : 2)
                   : (row ? row->Status : std::string("–")))
         << " | ";
      if (row && row->PeakMB >= 0.0)
      {
        md << nprFixed(row->PeakMB, 0)
           << (steps && row->AddedMB >= 0.0 ? " (+" + nprFixed(row->AddedMB, 0) + ")" : "");
      }
      else
      {
        md << "–";
      }
      md << " |";
    }
    for (const ScaleSize& size : sizes)
    {
      const ScaleRow* row = FindRow(rows, kind, name, size.Name);
      md << " " << (row && row->Seconds >= 0.0 ? Nanoseconds(row->NanosecondsPerTriangle()) : "–")
         << " |";
    }
    const double growth = GrowthRatio(rows, kind, name, sizes);
    md << " " << (growth >= 0.0 ? nprFixed(growth, 2) : "–") << " | "
       << (growth < 0.0       ? "–"
              : growth <= 1.3 ? "yes"
                              : "no")
       << " |\n";
  }
}

void WriteCSV(const std::string& path, const std::vector<ScaleRow>& rows)
{
  std::ofstream csv(path);
  csv << "size,triangles,kind,name,seconds,peak_mb,added_mb,ns_per_triangle,status\n";
  auto value = [](double x, int digits) { return x >= 0.0 ? nprFormat(x, digits) : ""; };
  for (const ScaleRow& row : rows)
  {
    csv << row.Size << "," << row.Triangles << "," << row.Kind << ",\"" << row.Name << "\","
        << value(row.Seconds, 6) << "," << value(row.PeakMB, 6) << "," << value(row.AddedMB, 6)
        << "," << value(row.NanosecondsPerTriangle(), 5) << ",\"" << row.Status << "\"\n";
  }
  if (!csv)
  {
    throw std::runtime_error(path + ": cannot write");
  }
}

// /proc/loadavg's first three figures.
std::string LoadAverage()
{
  std::ifstream file("/proc/loadavg");
  double load[3] = { -1.0, -1.0, -1.0 };
  file >> load[0] >> load[1] >> load[2];
  return nprFixed(load[0], 2) + ", " + nprFixed(load[1], 2) + ", " + nprFixed(load[2], 2);
}

std::string ReadLine(const std::string& path)
{
  std::ifstream file(path);
  std::string line;
  std::getline(file, line);
  return line.empty() ? "an unknown OpenGL" : line;
}

void WriteMarkdown(const std::string& path, const std::vector<ScaleRow>& rows,
  const std::vector<ScaleSize>& sizes, const nprBenchmarkOptions& options, double seconds,
  const std::string& loadAtStart)
{
  std::ostringstream md;
  const auto& window = options.Sizes.front();
  md << "Scale (npr-benchmark --scale) on "
     << ReadLine(options.Out + "/steps/" + sizes.front().Name + "/renderer.txt") << ", "
     << std::thread::hardware_concurrency() << " cores, " << window.first << "x" << window.second
     << "; the bunny decimated to 62,500 triangles and refined by Loop subdivision:";
  for (const ScaleSize& size : sizes)
  {
    md << " " << size.Name << " = " << size.Triangles << " triangles (" << size.Levels
       << (size.Levels == 1 ? " level)" : " levels)") << (&size == &sizes.back() ? "." : ",");
  }
  // The load average says whether others shared the machine.
  md << " Whole run " << nprFixed(seconds / 60.0, 1) << " min; load average (1, 5, 15 min) "
     << loadAtStart << " at the start, " << LoadAverage() << " at the end.\n\n"
     << "Every figure is the median of " << options.Runs << " run" << (options.Runs > 1 ? "s" : "")
     << " (each run measures every size in turn).\n\n"
     << "Whole programs, each a child process: wall time from its start to its exit, and its "
        "peak resident memory (ru_maxrss from wait4). F3D draws on an X display (a private Xvfb "
        "when DISPLAY is not set).\n\n";
  WriteTable(md, rows, "program", sizes);
  md << "\nSteps in one child process (npr-benchmark --scale-steps), in npr-render's order: each "
        "step's wall time (later frames and camera changes: the median of "
     << options.Frames
     << ", the camera turned 1 degree before each) and the peak resident memory during it "
        "(VmHWM after writing 5 to /proc/self/clear_refs at its start; in brackets what it "
        "added to the memory at its start). Timer-log parts (vtkTimerLog events of the step "
        "above, no peak of their own) show n/a where this build logs no such event.\n\n";
  WriteTable(md, rows, "step", sizes);
  std::ofstream file(path);
  file << md.str();
  std::cout << md.str();
  if (!file)
  {
    throw std::runtime_error(path + ": cannot write");
  }
}

// ns per triangle against triangles, one line per program or step that was measured.
void WritePlots(
  const std::vector<ScaleRow>& rows, const std::vector<ScaleSize>& sizes, const std::string& out)
{
  for (const std::string kind : { "program", "step" })
  {
    std::vector<nprPlotSeries> series;
    for (const std::string& name : RowNames(rows, kind))
    {
      nprPlotSeries line{ name };
      for (const ScaleSize& size : sizes)
      {
        const ScaleRow* row = FindRow(rows, kind, name, size.Name);
        if (row && row->Seconds > 0.0)
        {
          line.X.push_back(static_cast<double>(size.Triangles));
          line.Y.push_back(row->NanosecondsPerTriangle());
        }
      }
      if (!line.X.empty())
      {
        series.push_back(line);
      }
    }
    const bool programs = kind == "program";
    nprWriteSeriesPlot(out + (programs ? "/scale_programs.png" : "/scale_steps.png"), series,
      programs ? "Whole programs: time per triangle" : "Steps: time per triangle", "triangles",
      "ns per triangle", true);
  }
}

// What is wrong with the figures: a program or step of ours that failed (one not built, or a
// timer-log event this build does not log, is only reported), a time that is not positive.
std::string Problems(const std::vector<ScaleRow>& rows)
{
  std::string problems;
  for (const ScaleRow& row : rows)
  {
    const bool failed =
      row.Ours && !row.Status.empty() && row.Status != "n/a" && row.Status != "not built";
    const bool bad = row.Seconds >= 0.0 && !(std::isfinite(row.Seconds) && row.Seconds > 0.0);
    if (failed || bad)
    {
      problems +=
        row.Size + " " + row.Name + ": " + (failed ? row.Status : "no positive time") + "\n";
    }
  }
  return problems;
}
}

const std::vector<std::string>& nprScaleSizeNames()
{
  static const std::vector<std::string> names = { "62k", "250k", "1m", "4m", "16m" };
  return names;
}

int nprRunBenchmarkScale(const nprBenchmarkOptions& options)
{
  const nprClock::time_point runStart = nprClock::now();
  const std::string loadAtStart = LoadAverage();
  nprMakeBenchmarkFolders(options);
  for (const char* folder : { "/logs", "/images", "/steps" })
  {
    nprMakeBenchmarkFolder(options.Out + folder);
  }
  nprMakeBenchmarkFolder(options.ScaleMeshes);
  const std::vector<ScaleSize> sizes = ScaleMeshes(options);
  std::unique_ptr<nprPrivateXServer> xserver;
  const ScaleTools tools = FindTools(options.Out, xserver);
  // Run by run, every size in turn: a burst of other work on a shared machine falls on all.
  std::vector<ScaleRow> runs;
  for (int run = 0; run < options.Runs; ++run)
  {
    for (const ScaleSize& size : sizes)
    {
      std::cerr << "npr-benchmark: run " << run + 1 << " of " << options.Runs << ", " << size.Name
                << "\n";
      const std::vector<ScaleRow> measured = MeasureSize(size, tools, options);
      runs.insert(runs.end(), measured.begin(), measured.end());
    }
  }
  const std::vector<ScaleRow> rows = MedianRows(runs);
  xserver.reset();

  WriteCSV(options.Out + "/scale.csv", rows);
  WriteMarkdown(
    options.Out + "/scale.md", rows, sizes, options, nprSecondsSince(runStart), loadAtStart);
  WritePlots(rows, sizes, options.Out);
  std::cerr << "npr-benchmark: wrote " << options.Out
            << "/scale.{csv,md}, scale_programs.png, scale_steps.png in "
            << nprFixed(nprSecondsSince(runStart), 1) << " s\n";
  const std::string problems = Problems(rows);
  return nprBenchmarkStatus(problems);
}
