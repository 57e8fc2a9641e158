// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// npr-benchmark's command line: its options, --help and their parsing.
#ifndef nprBenchmarkOptions_h
#define nprBenchmarkOptions_h

#include <string>
#include <utility>
#include <vector>

struct nprBenchmarkOptions
{
  std::string Data;
  std::string Out;
  std::string DenseMesh; // bunny_1m.ply; default DATA/bunny_1m.ply
  int Frames = 10;
  std::vector<std::pair<int, int>> Sizes = { { 1024, 768 }, { 1920, 1080 } };
  std::vector<std::string> Scenes;
  bool ScenesGiven = false;
  std::vector<std::string> Methods;
  int Cameras = 3;
  int OrbitStep = 0; // --contours: > 0, the orbit's azimuth step instead of the cameras
  double LineWidth = 1.5;
  bool Quick = false;
  bool Stress = false;
  bool Coherence = false;
  bool Drawing = false;
  bool Speed = false;
  bool Contours = false;
  bool Scale = false;
  std::vector<std::string> ScaleSizes; // --scale: of nprScaleSizeNames()
  std::string ScaleMeshes;             // --scale: the meshes' folder (default OUT/meshes)
  std::string ScaleSteps; // --scale-steps FILE: that model's steps (a child of --scale)
  int Runs = 3;           // --speed: the whole interleaved measurement repeated
  std::vector<std::string> StressCases; // name parts; empty: every case
  double MaxDrift = -1.0;               // < 0: report only
  bool SaveMasks = false;
};

// Prints --help and exits for -h; throws nprUsageError for anything else that is wrong. The
// defaults of --quick and --stress are filled in.
nprBenchmarkOptions nprParseBenchmarkOptions(int argc, char* argv[]);

// Creates OUT (and OUT/masks with --save-masks); throws std::runtime_error when it cannot.
void nprMakeBenchmarkFolders(const nprBenchmarkOptions& options);
// Creates one folder (and its parents); throws std::runtime_error when it cannot.
void nprMakeBenchmarkFolder(const std::string& path);

// The sizes for the report: "1024x768, 1920x1080".
std::string nprBenchmarkSizesLine(const nprBenchmarkOptions& options);

#endif
