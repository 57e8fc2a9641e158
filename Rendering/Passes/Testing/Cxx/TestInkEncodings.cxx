// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// The inking pass (vtkNPRInkPass) and the G-buffer encodings of the edge pass (half, packed 8-
// and 16-bit depth+normal), checked with numbers: ink only along a cube's outline, as wide as
// asked, no crease, OpenGL state restored; the mask; windows, resizes and releases; and baseline
// images. The program's other cases: TestInkEncodingsBuffers.cxx.
//
// usage: TestInkEncodings CASE [DATA_DIR]   (CASE: the NPR_TEST_CASE names below)
#include "TestInkEncodings.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCubeSource.h"
#include "vtkImageData.h"
#include "vtkNPREdgePass.h"
#include "vtkNPRGBufferPass.h"
#include "vtkNPRInkPass.h"
#include "vtkNPROpenGL.h"
#include "vtkNPRPass.h"
#include "vtkNew.h"
#include "vtkPropPicker.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"
#include "vtkTextureObject.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace
{
using namespace nprInkEncodingsTesting;

// ---- Inking ----
// A cube seen from a corner: ink lies along the outline, outside it, about the line width wide;
// nothing inside (the creases are not the trick's), and OpenGL's polygon state is restored.
int InkedCube()
{
  const int size = 200;
  for (bool parallel : { true, false })
  {
    Scene scene(size, size);
    vtkSmartPointer<vtkActor> cube = AddCubeSeenFromCorner(scene, parallel);
    scene.Pass->SetStyleToShaded();
    const Mask object = Threshold(scene.Render(), IsObject);
    const Mask outline = Boundary(object, size, size);
    const std::vector<double> toOutline = DistanceTo(outline, size, size);
    scene.Pass->SetStyleToInked();
    scene.Ink()->SetLineWidth(2.0);
    const Mask ink = Threshold(scene.Render(), IsInk);

    long long inside = 0, far = 0;
    for (size_t i = 0; i < ink.size(); ++i)
    {
      if (!ink[i])
      {
        continue;
      }
      inside += object[i] && toOutline[i] > 1.5; // on a face, away from the outline
      far += toOutline[i] > 3.5;                 // more than the width past the outline
    }
    const std::vector<double> toInk = DistanceTo(ink, size, size);
    long long missed = 0;
    for (size_t i = 0; i < outline.size(); ++i)
    {
      missed += outline[i] && toInk[i] > 1.5;
    }
    std::cout << (parallel ? "parallel" : "perspective") << ": " << Count(ink) << " ink pixels, "
              << Count(outline) << " outline pixels, " << inside << " inside, " << far << " far, "
              << missed << " outline pixels without ink\n";
    NPR_CHECK(Count(outline) > 300, "the cube is drawn");
    NPR_CHECK(inside == 0, inside << " ink pixels on the faces (creases or leaks)");
    NPR_CHECK(far == 0, far << " ink pixels farther than the line width from the outline");
    NPR_CHECK(missed <= Count(outline) / 100, missed << " outline pixels without ink");
    // About 2 pixels of ink per outline pixel.
    NPR_CHECK(Count(ink) > 1.3 * Count(outline) && Count(ink) < 3.2 * Count(outline),
      Count(ink) << " ink pixels for " << Count(outline) << " outline pixels at width 2");

    // The same ink when the property culls faces itself (the pass culls front faces under it).
    cube->GetProperty()->BackfaceCullingOn();
    NPR_CHECK(Threshold(scene.Render(), IsInk) == ink, "the same ink with backface culling");
    cube->GetProperty()->BackfaceCullingOff();

    scene.Window->MakeCurrent();
    GLint mode[2] = { 0, 0 };
    glGetIntegerv(GL_POLYGON_MODE, mode);
    NPR_CHECK(!glIsEnabled(GL_POLYGON_OFFSET_FILL) && mode[0] == GL_FILL,
      "polygon offset and mode are restored");
  }
  return nprTestResult();
}
NPR_TEST_CASE("inked-cube", InkedCube);

// The ink's width follows LineWidth; the mask is the ink, white on black.
int InkedWidthAndMask()
{
  const int size = 200;
  Scene scene(size, size);
  AddCubeSeenFromCorner(scene, false);
  scene.Pass->SetStyleToInked();
  std::map<double, long long> counts;
  for (double width : { 1.0, 4.0 })
  {
    scene.Ink()->SetLineWidth(width);
    counts[width] = Count(Threshold(scene.Render(), IsInk));
  }
  NPR_CHECK(counts[4.0] > 2.5 * counts[1.0] && counts[4.0] < 5.5 * counts[1.0],
    "width 4 gives " << counts[4.0] << " ink pixels, width 1 " << counts[1.0]);

  scene.Ink()->SetLineWidth(2.0);
  const Mask ink = Threshold(scene.Render(), IsInk);
  scene.Ink()->CoverageOnlyOn();
  vtkSmartPointer<vtkImageData> maskImage = scene.Render();
  scene.Ink()->CoverageOnlyOff();
  const Mask white =
    Threshold(maskImage, [](int r, int g, int b) { return r > 200 && g > 200 && b > 200; });
  const Mask black =
    Threshold(maskImage, [](int r, int g, int b) { return r < 30 && g < 30 && b < 30; });
  NPR_CHECK(Count(white) + Count(black) == static_cast<long long>(size) * size,
    "the mask is white or black only");
  NPR_CHECK(white == ink,
    "the mask's white pixels are the ink's pixels (" << Count(white) << " vs " << Count(ink)
                                                     << ")");

  // Picking still works under the inked style.
  vtkNew<vtkPropPicker> picker;
  NPR_CHECK(picker->Pick(size / 2, size / 2, 0, scene.Renderer) && picker->GetActor(),
    "the cube is picked");
  return nprTestResult();
}
NPR_TEST_CASE("inked-width-mask", InkedWidthAndMask);

// ---- Windows: inked and packed in two windows at once, resized, released ----
int Windows()
{
  for (int round = 0; round < 2; ++round)
  {
    Scene a(160, 120), b(120, 160);
    AddCubeSeenFromCorner(a, false);
    AddCubeSeenFromCorner(b, true);
    a.Pass->SetStyleToInked();
    b.Pass->SetStyleToEdges();
    b.Edges()->SetEncoding(vtkNPREdgePass::PACKED16);
    for (int frame = 0; frame < 3; ++frame)
    {
      NPR_CHECK(Count(Threshold(a.Render(), IsInk)) > 100, "ink in window a");
      NPR_CHECK(Count(Threshold(b.Render(), IsInk)) > 100, "lines in window b");
      a.Window->SetSize(160 + 40 * frame, 120);
      b.Edges()->SetEncoding(frame % 2 ? vtkNPREdgePass::PACKED8 : vtkNPREdgePass::HALF);
    }
    a.Pass->ReleaseGraphicsResources(a.Window);
    b.Pass->ReleaseGraphicsResources(b.Window);
    NPR_CHECK(Count(Threshold(a.Render(), IsInk)) > 100, "ink after a release");
  }
  return nprTestResult();
}
NPR_TEST_CASE("windows", Windows);

// ---- Baselines ----
int Baseline(const char* model, const char* name, int style, int encoding)
{
  Scene scene(400, 300);
  nprAddBaselineModel(scene.Renderer, model);
  scene.Pass->SetStyle(style);
  scene.Edges()->SetEncoding(encoding);
  scene.Ink()->SetLineWidth(2.0);
  NPR_CHECK(nprCompareWithBaseline(scene.Render(), name), name << " differs from its baseline");
  return nprTestResult();
}
NPR_TEST_CASE("baseline-inked-bunny",
  [] { return Baseline("bunny.ply", "inked_bunny", vtkNPRPass::INKED, vtkNPREdgePass::FLOAT); });
NPR_TEST_CASE("baseline-inked-cad",
  []
  { return Baseline("cad_part.vtp", "inked_cad_part", vtkNPRPass::INKED, vtkNPREdgePass::FLOAT); });
NPR_TEST_CASE("baseline-packed8-cad",
  []
  {
    return Baseline("cad_part.vtp", "packed8_cad_part", vtkNPRPass::EDGES, vtkNPREdgePass::PACKED8);
  });
NPR_TEST_CASE("baseline-packed16-bunny",
  []
  { return Baseline("bunny.ply", "packed16_bunny", vtkNPRPass::EDGES, vtkNPREdgePass::PACKED16); });
NPR_TEST_CASE("baseline-half-cad",
  []
  { return Baseline("cad_part.vtp", "half_cad_part", vtkNPRPass::EDGES, vtkNPREdgePass::HALF); });
}
