// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// A vtkGlyph3DMapper's glyphs in the styles. The mapper draws its glyphs through a
// vtkOpenGLGlyph3DHelper, which gives each instance its matrix in an attribute (GCMCMatrix); a
// pass's shader code that leaves that attribute unused lets the compiler drop it, and VTK prints
// "Error setting 'GCMCMatrix' in shader VAO". (vtkNPRLinePrimitivesPass, which draws the line
// primitives of a scene after the effect, once put every polygon at a constant position: glyphs
// beside any line actor printed it in edges, toon+edges and sketch.) Each case renders spheres
// (coloured by height) and cones glyphed at the points of grids, alone and with a box outline
// beside them, counts VTK's errors and warnings (none) and checks that the glyphs are drawn with
// the style's lines or bands.
//
// The drawing style is left out: its lines come from the actors' meshes (NPR::Lines), which does
// not expand glyphs yet.
//
// usage: TestGlyphStyles edges|toon|toon-edges|sketch|inked
// NPR_TEST_DUMP=prefix saves the frames as prefix<style number>[o].png (o: with the outline).
#include "nprTesting.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkConeSource.h"
#include "vtkElevationFilter.h"
#include "vtkGlyph3DMapper.h"
#include "vtkImageData.h"
#include "vtkNPRPass.h"
#include "vtkNPRToonPass.h"
#include "vtkOutlineSource.h"
#include "vtkPlaneSource.h"
#include "vtkRenderWindow.h"
#include "vtkSphereSource.h"

#include <algorithm>
#include <cstdlib>
#include <map>
#include <string>
#include <vector>

namespace
{
// A grid's points, at z = 0 (y from -1 to 1, glyphed with the source) and coloured by height.
vtkSmartPointer<vtkActor> AddGlyphs(
  vtkRenderer* renderer, vtkAlgorithmOutput* source, double x, bool scalars)
{
  vtkNew<vtkPlaneSource> grid;
  grid->SetOrigin(x - 0.5, -1.0, 0.0);
  grid->SetPoint1(x + 0.5, -1.0, 0.0);
  grid->SetPoint2(x - 0.5, 1.0, 0.0);
  grid->SetResolution(2, 4);
  vtkNew<vtkElevationFilter> height;
  height->SetInputConnection(grid->GetOutputPort());
  height->SetLowPoint(0.0, -1.0, 0.0);
  height->SetHighPoint(0.0, 1.0, 0.0);
  vtkNew<vtkGlyph3DMapper> mapper;
  mapper->SetInputConnection(height->GetOutputPort());
  mapper->SetSourceConnection(source);
  mapper->SetScalarVisibility(scalars);
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  renderer->AddActor(actor);
  return actor;
}

// Spheres (with normals, coloured by height) and cones (without normals, one colour), with or
// without a black box outline around them.
struct GlyphScene : nprPassScene
{
  GlyphScene(int style, bool withOutline)
    : nprPassScene(240, 240)
  {
    this->Pass->SetStyle(style);
    this->Toon()->SetNumberOfBands(3);
    vtkNew<vtkSphereSource> sphere;
    sphere->SetRadius(0.2);
    sphere->SetThetaResolution(24);
    sphere->SetPhiResolution(12);
    AddGlyphs(this->Renderer, sphere->GetOutputPort(), -0.8, true);
    vtkNew<vtkConeSource> cone;
    cone->SetHeight(0.4);
    cone->SetRadius(0.2);
    cone->SetResolution(16);
    AddGlyphs(this->Renderer, cone->GetOutputPort(), 0.8, false);
    if (withOutline)
    {
      // A line primitive: the styles with a G-buffer draw lines after their effect, in a draw
      // of every actor that puts the polygons beyond the far plane.
      vtkNew<vtkOutlineSource> outline;
      outline->SetBounds(-1.6, 1.6, -1.2, 1.2, -0.3, 0.3);
      const double black[3] = { 0.0, 0.0, 0.0 };
      nprAddActor(this->Renderer, outline->GetOutputPort(), black);
    }
    this->Renderer->ResetCamera();
    this->Camera()->Azimuth(20);
    this->Camera()->Elevation(20);
    this->Renderer->ResetCameraClippingRange();
  }
};

// The glyphs' base colours: five heights of spheres and the cones.
constexpr size_t BaseColours = 6;

// Pixels neither the white background nor dark ink; ink pixels; the share of the surface in its
// commonest colours, three bands of each base colour (banded lighting covers nearly all of it).
struct GlyphCounts
{
  long long Surface = 0, Ink = 0;
  double Banded = 0.0;
};

GlyphCounts Count(vtkImageData* image, int width, int height)
{
  GlyphCounts counts;
  std::map<int, long long> colours;
  for (int y = 0; y < height; ++y)
  {
    for (int x = 0; x < width; ++x)
    {
      const int r = nprPixel(image, x, y, 0), g = nprPixel(image, x, y, 1),
                b = nprPixel(image, x, y, 2);
      if (std::max({ r, g, b }) < 60)
      {
        ++counts.Ink;
      }
      else if (std::min({ r, g, b }) < 250)
      {
        ++counts.Surface;
        ++colours[(r << 16) | (g << 8) | b];
      }
    }
  }
  std::vector<long long> sizes;
  for (const auto& colour : colours)
  {
    sizes.push_back(colour.second);
  }
  std::sort(sizes.rbegin(), sizes.rend());
  long long common = 0;
  for (size_t i = 0; i < std::min(3 * BaseColours, sizes.size()); ++i)
  {
    common += sizes[i];
  }
  counts.Banded = counts.Surface ? static_cast<double>(common) / counts.Surface : 0.0;
  return counts;
}

// Two frames of the scene (the helper sets its instance attributes when its program changes),
// VTK's messages counted into messages; the second frame.
vtkSmartPointer<vtkImageData> RenderCounting(
  int style, bool withOutline, nprCountingOutputWindow* messages)
{
  vtkOutputWindow* previous = vtkOutputWindow::GetInstance();
  previous->Register(nullptr);
  vtkOutputWindow::SetInstance(messages);
  GlyphScene scene(style, withOutline);
  scene.Render();
  vtkSmartPointer<vtkImageData> image = scene.Render();
  if (const char* dump = std::getenv("NPR_TEST_DUMP")) // a look at the frame
  {
    nprSavePNG(
      image, std::string(dump) + std::to_string(style) + (withOutline ? "o" : "") + ".png");
  }
  vtkOutputWindow::SetInstance(previous);
  previous->UnRegister(nullptr);
  return image;
}

// lines: the style draws ink lines; banded: it draws toon bands.
int TestGlyphs(int style, const char* name, bool lines, bool banded)
{
  vtkNew<nprCountingOutputWindow> messages;
  const GlyphCounts alone = Count(RenderCounting(style, false, messages), 240, 240);
  const GlyphCounts outlined = Count(RenderCounting(style, true, messages), 240, 240);
  std::cout << name << ": " << messages->Errors << " errors, " << messages->Warnings
            << " warnings; glyphs alone: " << alone.Surface << " surface pixels, " << alone.Ink
            << " ink pixels, " << 100 * alone.Banded << " % of the surface in " << 3 * BaseColours
            << " colours; with an outline: " << outlined.Surface << " surface pixels\n";
  NPR_CHECK(messages->Errors == 0, name << ": VTK reported " << messages->Errors << " errors");
  NPR_CHECK(messages->Warnings == 0, name << ": VTK warned " << messages->Warnings << " times");
  NPR_CHECK(alone.Surface > 3000, name << ": the glyphs were not drawn");
  NPR_CHECK(outlined.Surface > 0.8 * alone.Surface,
    name << ": with a line actor beside them, the glyphs lose their pixels");
  NPR_CHECK(!lines || alone.Ink > 400, name << ": only " << alone.Ink << " ink pixels");
  NPR_CHECK(!banded || alone.Banded > 0.75,
    name << ": the lighting is not banded (" << 100 * alone.Banded << " %)");
  return nprTestResult();
}
NPR_TEST_CASE("edges", [] { return TestGlyphs(vtkNPRPass::EDGES, "edges", true, false); });
NPR_TEST_CASE("toon", [] { return TestGlyphs(vtkNPRPass::TOON, "toon", false, true); });
NPR_TEST_CASE(
  "toon-edges", [] { return TestGlyphs(vtkNPRPass::TOON_EDGES, "toon+edges", true, false); });
NPR_TEST_CASE("sketch", [] { return TestGlyphs(vtkNPRPass::SKETCH, "sketch", true, false); });
NPR_TEST_CASE("inked", [] { return TestGlyphs(vtkNPRPass::INKED, "inked", true, false); });
}
