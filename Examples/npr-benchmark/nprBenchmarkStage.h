// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// What npr-benchmark measures on: one window, one renderer, the mesh, the methods' passes and
// the object-space reference; and the line masks it reads back.
#ifndef nprBenchmarkStage_h
#define nprBenchmarkStage_h

#include "nprBenchmarkMethods.h"
#include "nprBenchmarkOptions.h"

#include "vtkActor.h"
#include "vtkNPRFeatureLines.h"
#include "vtkNPRReferenceMask.h"
#include "vtkNew.h"
#include "vtkPolyDataMapper.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"

#include <string>
#include <utility>
#include <vector>

class vtkCamera;
class vtkNPRPass;
class vtkPolyData;

struct nprMask
{
  int Width = 0;
  int Height = 0;
  std::vector<unsigned char> Pixels; // row 0 = bottom, non-zero = line
};

// The window's first colour channel, thresholded: a line pixel where it is >= 128 (coverage at
// least 50 %).
nprMask nprReadMask(vtkRenderWindow* window);
// White lines on black, 8-bit grey.
void nprWriteMaskPNG(const nprMask& mask, const std::string& path);

struct nprBenchmarkStage
{
  vtkSmartPointer<vtkRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkPolyDataMapper> MeshMapper;
  vtkNew<vtkActor> MeshActor;
  double LineWidth = 1.5;
  vtkNew<vtkNPRFeatureLines> FeatureLines;
  vtkNew<vtkPolyDataMapper> LineMapper;
  vtkNew<vtkActor> LineActor;
  // Kept for the whole run: it builds each mesh's adjacency and occlusion structure once.
  vtkNew<vtkNPRReferenceMask> Reference;
  int DefaultResolve;

  // Throws std::runtime_error when there is no headless render window.
  explicit nprBenchmarkStage(double lineWidth);

  // The mesh as npr-render shades the first model; the lines black on a white background.
  void ShadeMesh();

  // The mesh drawn, and the one whose feature lines the object-space method draws (the same
  // surface; the raw one keeps the file's connectivity).
  void SetMesh(vtkPolyData* mesh, vtkPolyData* topology);

  vtkCamera* Camera();

  // The pass a method renders with (nullptr: VTK's own chain).
  vtkSmartPointer<vtkNPRPass> MakePass(const nprBenchmarkMethod& method) const;

  // Makes the renderer draw this method's frame (pass nullptr and no lines: the shaded frame).
  void Activate(vtkNPRPass* pass, bool objectLines);

  // The object-space lines for the current camera (its values are copied: once per frame).
  void UpdateFeatureLines();

  // One timed frame in milliseconds: nothing may be reused, and the GPU has finished when it
  // returns.
  double TimedFrame(bool objectLines);

  // The method's line mask (white lines on black, thresholded at 50 %).
  nprMask MethodMask(const nprBenchmarkMethod& method, vtkNPRPass* pass);

  // The object-space ground truth for the current camera and size (vtkNPRReferenceMask:
  // visible silhouettes, creases above 30 degrees, boundaries and non-manifold edges).
  nprMask ReferenceMask();
};

// One run of a mode over its methods: the stage, one pass a method, and the rows measured.
template <typename Row>
struct nprBenchmarkRun
{
  nprBenchmarkRun(const nprBenchmarkOptions& options, std::vector<nprBenchmarkMethod> methods)
    : Options(options)
    , Stage(options.LineWidth)
    , Methods(std::move(methods))
  {
    for (const nprBenchmarkMethod& method : this->Methods)
    {
      this->Passes.push_back(this->Stage.MakePass(method));
    }
  }

  const nprBenchmarkOptions& Options;
  nprBenchmarkStage Stage;
  std::vector<nprBenchmarkMethod> Methods;
  std::vector<vtkSmartPointer<vtkNPRPass>> Passes;
  std::vector<Row> Rows;
};

#endif
