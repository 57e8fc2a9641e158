// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// npr-benchmark --drawing: technical drawings written as vector files (vtkNPRDrawingExporter) and
// drawn in the drawing style: the time to write each scene's SVG and PDF from a new exporter
// (the meshes' adjacency and occlusion structure built from scratch), the file sizes, strokes
// against feature edges, and the lines rasterised by rsvg-convert and pdftoppm against the
// reference mask (F1@1). Writes OUT/drawing.csv and OUT/drawing.md.
#ifndef nprBenchmarkDrawing_h
#define nprBenchmarkDrawing_h

struct nprBenchmarkOptions;

// Returns the exit status: 1 when a figure is out of range or a file was not written.
int nprRunBenchmarkDrawing(const nprBenchmarkOptions& options);

#endif
