// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// A width per kind of line (issue 37): vtkNPREdgePass's SilhouetteLineWidth, CreaseLineWidth,
// ContourLineWidth and SuggestiveContourLineWidth, on a cube turned to show three faces
// (silhouettes around it, creases between its faces; contours off). The ink of a mask is the sum
// of its coverage: a line's length times its width.
// - default: every kind's width set to LineWidth draws the frame of the defaults bit for bit, and
//   a kind not drawn widens nothing;
// - kinds: one kind alone at its own width is that kind at LineWidth bit for bit; with silhouettes
//   4 px and creases 1 px, the creases' ink is within 25 % of creases alone at 1 px and the
//   silhouettes' within 10 % of silhouettes alone at 4 px (a narrower kind is a level set of the
//   widest kind's filter, not its own).
//
// usage: TestEdgePassLineWeights default|kinds
#include "nprTestImages.h"
#include "nprTestMeshes.h"
#include "nprTesting.h"

#include "vtkActor.h"
#include "vtkImageData.h"
#include "vtkNPREdgePass.h"
#include "vtkNPRPass.h"
#include "vtkPointData.h"
#include "vtkUnsignedCharArray.h"

#include <cmath>

namespace
{
struct CubeScene : nprPassScene
{
  CubeScene()
    : nprPassScene(300, 240)
  {
    vtkSmartPointer<vtkActor> cube = this->ShowCube(4.0, nprGrey);
    cube->RotateX(25.0);
    cube->RotateY(35.0);
    this->Edges()->ContoursOff();
  }

  // Draws only the kinds given (silhouettes, creases).
  vtkSmartPointer<vtkImageData> MaskOf(bool silhouettes, bool creases)
  {
    this->Edges()->SetSilhouettes(silhouettes);
    this->Edges()->SetCreases(creases);
    return this->Mask();
  }
};

// The sum of the mask's coverage over its pixels, in pixels.
double Ink(vtkImageData* mask)
{
  vtkUnsignedCharArray* values =
    vtkUnsignedCharArray::SafeDownCast(mask->GetPointData()->GetScalars());
  double sum = 0.0;
  const int components = values ? values->GetNumberOfComponents() : 1;
  for (vtkIdType i = 0; values && i < values->GetNumberOfTuples(); ++i)
  {
    sum += values->GetValue(i * components) / 255.0;
  }
  return sum;
}

bool Same(vtkImageData* a, vtkImageData* b)
{
  return nprCompareImages(a, b, { 0, 0.0 }).DifferingPixels == 0;
}

int Default()
{
  CubeScene scene;
  vtkNPREdgePass* edges = scene.Edges();
  const auto frame = scene.Render();
  const auto mask = scene.Mask();
  NPR_CHECK(Ink(mask) > 300.0, "no lines drawn: no test");
  edges->SetSilhouetteLineWidth(1.5);
  edges->SetCreaseLineWidth(1.5);
  edges->SetContourLineWidth(1.5);
  edges->SetSuggestiveContourLineWidth(1.5);
  NPR_CHECK(Same(scene.Render(), frame), "the kinds at LineWidth changed the frame");
  NPR_CHECK(Same(scene.Mask(), mask), "the kinds at LineWidth changed the lines");
  // Contours are off: their width widens nothing.
  edges->SetContourLineWidth(8.0);
  NPR_CHECK(edges->GetEffectiveLineWidth(scene.Renderer) == 1.5,
    "widest line " << edges->GetEffectiveLineWidth(scene.Renderer) << " with contours off");
  NPR_CHECK(Same(scene.Render(), frame), "a kind not drawn changed the frame");
  edges->SetContourLineWidth(-1.0);
  NPR_CHECK(edges->GetContourLineWidth() == 0.0, "a negative width was not clamped to 0");
  edges->SetCreaseLineWidth(40.0);
  NPR_CHECK(edges->GetCreaseLineWidth() == 16.0, "a width of 40 was not clamped to 16");
  return nprTestResult();
}
NPR_TEST_CASE("default", Default);

int Kinds()
{
  CubeScene scene;
  vtkNPREdgePass* edges = scene.Edges();
  edges->SetLineWidth(4.0);
  const auto silhouettesAt4 = scene.MaskOf(true, false);
  edges->SetLineWidth(1.0);
  const auto creasesAt1 = scene.MaskOf(false, true);
  edges->SetLineWidth(1.5);
  edges->SetSilhouetteLineWidth(4.0);
  edges->SetCreaseLineWidth(1.0);
  NPR_CHECK(Same(scene.MaskOf(true, false), silhouettesAt4),
    "silhouettes alone at their own width differ from silhouettes at LineWidth");
  NPR_CHECK(Same(scene.MaskOf(false, true), creasesAt1),
    "creases alone at their own width differ from creases at LineWidth");
  const double both = Ink(scene.MaskOf(true, true));
  const double silhouettes = Ink(silhouettesAt4), creases = Ink(creasesAt1);
  std::cout << "ink: silhouettes alone at 4 px " << silhouettes << ", creases alone at 1 px "
            << creases << ", both " << both << " (creases in it " << both - silhouettes
            << ", silhouettes " << both - creases << ")\n";
  NPR_CHECK(creases > 100.0 && silhouettes > 3.0 * creases, "the cube's lines are missing");
  NPR_CHECK(std::abs((both - silhouettes) / creases - 1.0) <= 0.25,
    "the creases' ink with 4 px silhouettes: " << both - silhouettes << ", alone " << creases);
  NPR_CHECK(std::abs((both - creases) / silhouettes - 1.0) <= 0.10,
    "the silhouettes' ink with 1 px creases: " << both - creases << ", alone " << silhouettes);
  return nprTestResult();
}
NPR_TEST_CASE("kinds", Kinds);
}
