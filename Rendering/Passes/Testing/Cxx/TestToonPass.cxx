// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// Toon shading (vtkNPRToonPass), checked with numbers: the number and values of the shades of a
// lit sphere (per pixel and per vertex, a user table, zero-length normals, an unlit actor), the
// bands over scalar colours, and lines over the bands with the G-buffer redrawn when the bands
// change.
//
// usage: TestToonPass CASE [DATA_DIR]   (CASE: the NPR_TEST_CASE names below)
#include "nprTesting.h"

#include "vtkActor.h"
#include "vtkActorCollection.h"
#include "vtkCamera.h"
#include "vtkDataArray.h"
#include "vtkElevationFilter.h"
#include "vtkImageData.h"
#include "vtkLookupTable.h"
#include "vtkNPRGBufferPass.h"
#include "vtkNPRToonPass.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkSphereSource.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace
{
using Scene = nprPassScene;

using Color = std::array<int, 3>;

// The distinct colours of the pixels that are not the (white) background.
std::set<Color> ObjectColors(vtkImageData* image)
{
  std::set<Color> colors;
  const int* dims = image->GetDimensions();
  for (int y = 0; y < dims[1]; ++y)
  {
    for (int x = 0; x < dims[0]; ++x)
    {
      const Color c = { nprPixel(image, x, y, 0), nprPixel(image, x, y, 1),
        nprPixel(image, x, y, 2) };
      if (c != Color{ 255, 255, 255 })
      {
        colors.insert(c);
      }
    }
  }
  return colors;
}

bool Near(const Color& a, const Color& b, int tolerance = 1)
{
  return std::abs(a[0] - b[0]) <= tolerance && std::abs(a[1] - b[1]) <= tolerance &&
    std::abs(a[2] - b[2]) <= tolerance;
}

// Every distinct colour is one of the expected shades and every shade is there.
void CheckShades(vtkImageData* image, const std::vector<Color>& expected, const std::string& what)
{
  const std::set<Color> colors = ObjectColors(image);
  std::cout << what << ": " << colors.size() << " distinct shades, " << expected.size()
            << " expected\n";
  NPR_CHECK(colors.size() == expected.size(),
    what << ": " << colors.size() << " shades instead of " << expected.size());
  for (const Color& c : colors)
  {
    const bool known =
      std::any_of(expected.begin(), expected.end(), [&](const Color& e) { return Near(c, e); });
    NPR_CHECK(known, what << ": unexpected shade " << c[0] << "," << c[1] << "," << c[2]);
  }
  for (const Color& e : expected)
  {
    const bool found =
      std::any_of(colors.begin(), colors.end(), [&](const Color& c) { return Near(c, e); });
    NPR_CHECK(found, what << ": missing shade " << e[0] << "," << e[1] << "," << e[2]);
  }
}

std::vector<Color> ExpectedShades(const double color[3], const std::vector<double>& factors)
{
  std::vector<Color> shades;
  for (double f : factors)
  {
    shades.push_back({ static_cast<int>(std::lround(255.0 * color[0] * f)),
      static_cast<int>(std::lround(255.0 * color[1] * f)),
      static_cast<int>(std::lround(255.0 * color[2] * f)) });
  }
  return shades;
}

// A fine sphere of radius 1 at the origin, seen from 4.5 along +z.
void ShowSphere(Scene& scene, const double color[3])
{
  const double origin[3] = { 0, 0, 0 };
  nprAddSphere(scene.Renderer, origin, 1.0, color);
  scene.LookAtOrigin(4.5);
}

// The banded cases' orange sphere (ShowSphere) in a parallel view: the silhouette is where the
// normal is at right angles to the headlight, so every band down to intensity 0 is on screen and
// the darkest is a ring several pixels wide (in perspective the rim is at n.l = radius /
// distance, and that band a pixel or two wide).
const double Orange[3] = { 0.9, 0.6, 0.3 };
void ShowBandedSphere(Scene& scene)
{
  ShowSphere(scene, Orange);
  scene.ViewParallel(1.1);
}

// ---- A lit sphere in toon shading shows exactly N shades of its colour ----
// N bands give N shades, per pixel and per vertex.
void CheckBandCounts(Scene& scene)
{
  for (bool perVertex : { false, true })
  {
    scene.Toon()->SetPerVertex(perVertex);
    for (int bands : { 1, 2, 3, 5, 8 })
    {
      scene.Toon()->SetNumberOfBands(bands);
      std::vector<double> factors;
      for (int k = 0; k < bands; ++k)
      {
        factors.push_back((k + 1.0) / bands);
      }
      CheckShades(scene.Render(), ExpectedShades(Orange, factors),
        std::to_string(bands) + " bands" + (perVertex ? " per vertex" : " per pixel"));
    }
  }
}

// On a coarse sphere the two differ: per vertex, band borders are straight within a triangle.
void CheckCoarseSphere(Scene& scene, const std::vector<Color>& shades)
{
  auto perVertexImage = scene.Render();
  scene.Toon()->SetPerVertex(false);
  auto perPixelImage = scene.Render();
  CheckShades(perVertexImage, shades, "coarse sphere per vertex");
  CheckShades(perPixelImage, shades, "coarse sphere per pixel");
  long long differing = 0;
  for (int y = 0; y < 300; ++y)
  {
    for (int x = 0; x < 360; ++x)
    {
      differing += nprPixel(perVertexImage, x, y, 0) != nprPixel(perPixelImage, x, y, 0) ? 1 : 0;
    }
  }
  std::cout << differing
            << " pixels differ between per-vertex and per-pixel on the coarse sphere\n";
  NPR_CHECK(differing > 200,
    "per-vertex toon looks like per-pixel toon (" << differing << " pixels differ)");
}

// A user table: its entries are the bands.
void CheckUserTable(Scene& scene)
{
  vtkNew<vtkLookupTable> table;
  table->SetNumberOfTableValues(2);
  table->SetTableValue(0, 0.25, 0.25, 0.25);
  table->SetTableValue(1, 1.0, 1.0, 1.0);
  table->SetRange(0.0, 1.0);
  scene.Toon()->SetTable(table);
  CheckShades(scene.Render(), ExpectedShades(Orange, { 0.25, 1.0 }), "a two-entry table");
  double shade[3];
  scene.Toon()->GetShade(0.2, shade);
  NPR_CHECK(
    std::abs(shade[0] - 0.25) < 1.0 / 255, "GetShade(0.2) with the table gives " << shade[0]);
  scene.Toon()->SetTable(nullptr);
}

// Zero-length normals on every other point of the mesh: no NaN colour, only band colours (the
// darkest where n is 0).
void CheckZeroLengthNormals(
  Scene& scene, vtkActor* sphere, vtkPolyData* mesh, const std::vector<Color>& shades)
{
  vtkNew<vtkPolyData> flattened;
  flattened->DeepCopy(mesh);
  vtkDataArray* normals = flattened->GetPointData()->GetNormals();
  for (vtkIdType i = 0; i < normals->GetNumberOfTuples(); i += 2)
  {
    normals->SetTuple3(i, 0.0, 0.0, 0.0);
  }
  vtkPolyDataMapper::SafeDownCast(sphere->GetMapper())->SetInputData(flattened);
  for (bool perVertex : { false, true })
  {
    scene.Toon()->SetPerVertex(perVertex);
    const std::set<Color> colors = ObjectColors(scene.Render());
    for (const Color& c : colors)
    {
      const bool known =
        std::any_of(shades.begin(), shades.end(), [&](const Color& e) { return Near(c, e); });
      NPR_CHECK(
        known, "zero-length normals give the colour " << c[0] << "," << c[1] << "," << c[2]);
    }
    NPR_CHECK(colors.size() >= 2, "zero-length normals: " << colors.size() << " colours");
  }
  scene.Toon()->SetPerVertex(false);
}

int ToonBands()
{
  Scene scene(360, 300);
  ShowBandedSphere(scene);
  scene.Pass->SetStyleToToon();
  CheckBandCounts(scene);
  vtkActor* sphere = vtkActor::SafeDownCast(scene.Renderer->GetActors()->GetItemAsObject(0));
  auto coarse = nprSphereSource(0.5, 12, 8);
  vtkPolyDataMapper::SafeDownCast(sphere->GetMapper())->SetInputConnection(coarse->GetOutputPort());
  scene.Camera()->SetParallelScale(0.6);
  scene.Toon()->SetNumberOfBands(3);
  const auto shades = ExpectedShades(Orange, { 1.0 / 3, 2.0 / 3, 1.0 });
  CheckCoarseSphere(scene, shades);
  CheckUserTable(scene);
  coarse->Update();
  CheckZeroLengthNormals(scene, sphere, coarse->GetOutput(), shades);
  // An unlit actor keeps its flat colour.
  sphere->GetProperty()->LightingOff();
  CheckShades(scene.Render(), ExpectedShades(Orange, { 1.0 }), "an unlit actor");
  return nprTestResult();
}
NPR_TEST_CASE("toon-bands", ToonBands);

// ---- Scalar colours: each pixel is its flat scalar colour times one of the band factors ----
int ToonScalars()
{
  Scene scene(360, 300);
  auto sphere = nprSphereSource(0.5, 128, 64);
  vtkNew<vtkElevationFilter> elevation;
  elevation->SetInputConnection(sphere->GetOutputPort());
  elevation->SetLowPoint(0, -0.5, 0);
  elevation->SetHighPoint(0, 0.5, 0);
  vtkSmartPointer<vtkActor> actor = nprAddActor(scene.Renderer, elevation->GetOutputPort());
  scene.LookAtOrigin(2.2);
  scene.Pass->SetStyleToToon();
  scene.Toon()->SetNumberOfBands(1);
  auto flat = scene.Render();
  const int bands = 4;
  scene.Toon()->SetNumberOfBands(bands);
  auto toon = scene.Render();
  long long checked = 0, wrong = 0;
  std::set<int> seen;
  for (int y = 0; y < 300; ++y)
  {
    for (int x = 0; x < 360; ++x)
    {
      for (int c = 0; c < 3; ++c)
      {
        const int f = nprPixel(flat, x, y, c);
        if (f < 60 ||
          (nprPixel(flat, x, y, 0) == 255 && nprPixel(flat, x, y, 1) == 255 &&
            nprPixel(flat, x, y, 2) == 255))
        {
          continue;
        }
        const double ratio = nprPixel(toon, x, y, c) / static_cast<double>(f);
        const int band = static_cast<int>(std::lround(ratio * bands)) - 1;
        ++checked;
        // 8-bit rounding of both images: within 1.5 levels of the band's value.
        if (band < 0 || band >= bands ||
          std::abs(nprPixel(toon, x, y, c) - f * (band + 1.0) / bands) > 1.5)
        {
          ++wrong;
        }
        else
        {
          seen.insert(band);
        }
      }
    }
  }
  std::cout << checked << " channel values checked, " << wrong << " not a band of the flat colour, "
            << seen.size() << " bands seen\n";
  NPR_CHECK(checked > 50000, "too few coloured pixels: " << checked);
  NPR_CHECK(wrong == 0, wrong << " channel values are not a band factor times the scalar colour");
  NPR_CHECK(static_cast<int>(seen.size()) == bands, "only " << seen.size() << " bands seen");
  return nprTestResult();
}
NPR_TEST_CASE("toon-scalars", ToonScalars);

// ---- Toon with edges: lines over the bands; the G-buffer is redrawn when the bands change ----
int ToonEdges()
{
  Scene scene(360, 300);
  ShowBandedSphere(scene);
  scene.Pass->SetStyleToToonEdges();
  scene.Toon()->SetNumberOfBands(3);
  scene.Render();
  const int draws = scene.Pass->GetGBufferPass()->GetNumberOfGeometryDraws();
  auto image = scene.Render();
  NPR_CHECK(scene.Pass->GetGBufferPass()->GetNumberOfGeometryDraws() == draws,
    "an unchanged frame drew the geometry again");
  long long dark = 0;
  for (int y = 0; y < 300; ++y)
  {
    for (int x = 0; x < 360; ++x)
    {
      dark += std::max(nprPixel(image, x, y, 0), nprPixel(image, x, y, 1)) < 40 ? 1 : 0;
    }
  }
  std::cout << dark << " line pixels\n";
  NPR_CHECK(dark > 500, "the silhouette of the sphere is missing (" << dark << " dark pixels)");
  const std::set<Color> colors = ObjectColors(image);
  for (const Color& band : ExpectedShades(Orange, { 1.0 / 3, 2.0 / 3, 1.0 }))
  {
    const bool found =
      std::any_of(colors.begin(), colors.end(), [&](const Color& c) { return Near(c, band); });
    NPR_CHECK(found,
      "band " << band[0] << "," << band[1] << "," << band[2] << " is missing under the lines");
  }
  scene.Toon()->SetNumberOfBands(2);
  scene.Render();
  NPR_CHECK(scene.Pass->GetGBufferPass()->GetNumberOfGeometryDraws() == draws + 1,
    "changing the bands did not redraw the G-buffer");
  return nprTestResult();
}
NPR_TEST_CASE("toon-edges", ToonEdges);
}
