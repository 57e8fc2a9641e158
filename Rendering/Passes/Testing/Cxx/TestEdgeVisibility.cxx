// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// Actors with their mesh edges shown (vtkProperty::EdgeVisibilityOn, ParaView's "Surface With
// Edges"), in every style. VTK draws such edges with a geometry shader that moves each triangle's
// corners half a line width outwards; the ink pass's back-face wireframe once drew those moved
// corners, and where a triangle is seen edge-on they lie at infinity: long lines out to the
// image borders. Each case renders a box and a sphere with red edges and checks that nothing is
// drawn away from them, that the red mesh edges are there as VTK draws them without the pass (the
// drawing, whose faces are one colour, draws them again over them: it showed none before), and
// that the style's own lines stay.
//
// inked-property-time checks that an inked frame leaves the actors' properties unmodified.
//
// usage: TestEdgeVisibility inked|inked-property-time|edges|toon|toon-edges|sketch|drawing
// NPR_TEST_DUMP=prefix saves the frame as prefixSTYLE.png.
#include "nprTesting.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCubeSource.h"
#include "vtkImageData.h"
#include "vtkNPRPass.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkSphereSource.h"

#include <algorithm>
#include <cstdlib>
#include <string>
#include <vector>

namespace
{
const double EdgeRed[3] = { 1.0, 0.0, 0.0 };

// A box and a coarse sphere, with their mesh edges shown in red or not, seen at an angle.
struct EdgeScene : nprPassScene
{
  std::vector<vtkSmartPointer<vtkActor>> Actors;

  EdgeScene(int style, bool edgeVisibility)
    : nprPassScene(240, 180)
  {
    this->Pass->SetStyle(style);
    const double sphereCenter[3] = { -0.7, 0.0, 0.0 };
    auto sphere = nprSphereSource(0.5, 12, 8, sphereCenter);
    this->Actors.push_back(nprAddActor(this->Renderer, sphere->GetOutputPort(), nprGrey));
    vtkNew<vtkCubeSource> box;
    box->SetCenter(0.7, 0.0, 0.0);
    this->Actors.push_back(nprAddActor(this->Renderer, box->GetOutputPort(), nprGrey));
    for (const auto& actor : this->Actors)
    {
      actor->GetProperty()->SetEdgeVisibility(edgeVisibility);
      actor->GetProperty()->SetEdgeColor(EdgeRed[0], EdgeRed[1], EdgeRed[2]);
    }
    this->Renderer->ResetCamera();
    this->Camera()->Azimuth(30);
    this->Camera()->Elevation(25);
    this->Renderer->ResetCameraClippingRange();
  }

  // Whether the pixel is within margin pixels of an actor's projected bounding box.
  bool NearActors(int x, int y, double margin)
  {
    for (const auto& actor : this->Actors)
    {
      const double* b = actor->GetBounds();
      double low[2] = { 1e30, 1e30 }, high[2] = { -1e30, -1e30 };
      for (int corner = 0; corner < 8; ++corner)
      {
        const double point[3] = { b[corner & 1], b[2 + ((corner >> 1) & 1)],
          b[4 + ((corner >> 2) & 1)] };
        double display[2];
        this->Project(point, display);
        for (int i = 0; i < 2; ++i)
        {
          low[i] = std::min(low[i], display[i]);
          high[i] = std::max(high[i], display[i]);
        }
      }
      if (x + 0.5 >= low[0] - margin && x + 0.5 <= high[0] + margin && y + 0.5 >= low[1] - margin &&
        y + 0.5 <= high[1] + margin)
      {
        return true;
      }
    }
    return false;
  }
};

bool IsEdgeRed(vtkImageData* image, int x, int y)
{
  return nprPixel(image, x, y, 0) > 150 && nprPixel(image, x, y, 1) < 90 &&
    nprPixel(image, x, y, 2) < 90;
}

bool IsInk(vtkImageData* image, int x, int y)
{
  return nprPixel(image, x, y, 0) < 60 && nprPixel(image, x, y, 1) < 60 &&
    nprPixel(image, x, y, 2) < 60;
}

// What a frame shows: red edge pixels, ink pixels, and pixels drawn away from the actors.
struct EdgeCounts
{
  long long Red = 0, Ink = 0, Stray = 0;
};

EdgeCounts Count(EdgeScene& scene, vtkImageData* image)
{
  EdgeCounts counts;
  for (int y = 0; y < scene.Height; ++y)
  {
    for (int x = 0; x < scene.Width; ++x)
    {
      const bool red = IsEdgeRed(image, x, y), ink = IsInk(image, x, y);
      counts.Red += red ? 1 : 0;
      counts.Ink += ink ? 1 : 0;
      const bool background = std::min({ nprPixel(image, x, y, 0), nprPixel(image, x, y, 1),
                                nprPixel(image, x, y, 2) }) > 240;
      counts.Stray += !background && !scene.NearActors(x, y, 6.0) ? 1 : 0;
    }
  }
  return counts;
}

// The red edge pixels VTK draws without the pass.
long long PlainRedPixels()
{
  EdgeScene plain(vtkNPRPass::SHADED, true);
  plain.Renderer->SetPass(nullptr);
  vtkSmartPointer<vtkImageData> image = plain.Render();
  return Count(plain, image).Red;
}

// The ink pixels of the style's own lines, without mesh edges.
long long InkWithoutEdges(int style)
{
  EdgeScene scene(style, false);
  vtkSmartPointer<vtkImageData> image = scene.Render();
  return Count(scene, image).Ink;
}

// lines: the style draws lines of its own; meshEdges: it shows the mesh edges.
int TestEdges(int style, const char* name, bool lines, bool meshEdges)
{
  const long long plainRed = PlainRedPixels();
  const long long styleInk = lines ? InkWithoutEdges(style) : 0;
  EdgeScene scene(style, true);
  vtkSmartPointer<vtkImageData> image = scene.Render();
  if (const char* dump = std::getenv("NPR_TEST_DUMP")) // a look at the frame
  {
    nprSavePNG(image, std::string(dump) + name + ".png");
  }
  const EdgeCounts counts = Count(scene, image);
  std::cout << name << ": " << counts.Red << " red edge pixels (" << plainRed
            << " without the pass), " << counts.Ink << " ink pixels (" << styleInk
            << " without mesh edges), " << counts.Stray << " pixels drawn away from the actors\n";
  NPR_CHECK(
    counts.Stray == 0, name << ": " << counts.Stray << " pixels drawn away from the actors");
  NPR_CHECK(plainRed > 500, "VTK drew only " << plainRed << " red edge pixels");
  NPR_CHECK(!meshEdges || counts.Red > plainRed / 2,
    name << ": " << counts.Red << " red edge pixels, VTK draws " << plainRed);
  // The style's lines stay; the edges cover part of them (VTK 9.1-9.3 draws them half a line
  // width outside the triangles).
  NPR_CHECK(!lines || styleInk > 300, name << ": only " << styleInk << " ink pixels without edges");
  NPR_CHECK(counts.Ink >= styleInk / 2,
    name << ": " << counts.Ink << " ink pixels, " << styleInk << " without mesh edges");
  return nprTestResult();
}

// The ink draws its wireframe without the edges' geometry shader by a shader replacement, not by
// turning the properties' EdgeVisibility off and on around it: that modified each property twice
// a frame, and VTK prepared the actor's shaders and buffer objects again at both draws.
int TestInkedPropertyTime()
{
  EdgeScene scene(vtkNPRPass::INKED, true);
  scene.Render();
  std::vector<vtkMTimeType> before;
  for (const auto& actor : scene.Actors)
  {
    before.push_back(actor->GetProperty()->GetMTime());
  }
  scene.Render();
  for (size_t i = 0; i < scene.Actors.size(); ++i)
  {
    const vtkMTimeType after = scene.Actors[i]->GetProperty()->GetMTime();
    std::cout << "actor " << i << ": property modified at " << before[i]
              << " before an inked frame, " << after << " after it\n";
    NPR_CHECK(after == before[i], "an inked frame modified actor " << i << "'s property");
  }
  return nprTestResult();
}

NPR_TEST_CASE("inked", [] { return TestEdges(vtkNPRPass::INKED, "inked", true, true); });
NPR_TEST_CASE("inked-property-time", TestInkedPropertyTime);
NPR_TEST_CASE("edges", [] { return TestEdges(vtkNPRPass::EDGES, "edges", true, true); });
NPR_TEST_CASE("toon", [] { return TestEdges(vtkNPRPass::TOON, "toon", false, true); });
NPR_TEST_CASE(
  "toon-edges", [] { return TestEdges(vtkNPRPass::TOON_EDGES, "toon+edges", true, true); });
NPR_TEST_CASE("sketch", [] { return TestEdges(vtkNPRPass::SKETCH, "sketch", true, true); });
NPR_TEST_CASE("drawing", [] { return TestEdges(vtkNPRPass::DRAWING, "drawing", true, true); });
}
