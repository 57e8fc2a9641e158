// Toon shading (vtkNPRToonPass) and sketchy drawing (vtkNPRSketchPass), checked with numbers:
// the number and values of the toon shades, the bands over scalar colours, the G-buffer redrawn
// when the table changes; the sketch with no uncertainty equal to the edges on flat colours, the
// lines displaced by no more than the uncertainty, the z-buffer equal to the smaller of the two
// displaced depth lookups, a second layer hidden by the sketch as drawn; windows, resizes and
// releases; and baseline images.
//
// usage: TestToonSketch CASE [DATA_DIR]   (CASE: see the table at the end of this file)
#include "nprTesting.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCubeSource.h"
#include "vtkDataArray.h"
#include "vtkElevationFilter.h"
#include "vtkImageData.h"
#include "vtkActorCollection.h"
#include "vtkLookupTable.h"
#include "vtkNPREdgePass.h"
#include "vtkNPRGBufferPass.h"
#include "vtkNPRPass.h"
#include "vtkNPRSketchPass.h"
#include "vtkNPRToonPass.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
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
struct Scene : nprPassScene
{
  using nprPassScene::nprPassScene;
  void LookAtOrigin(double distance)
  {
    this->Camera()->SetPosition(0, 0, distance);
    this->Camera()->SetFocalPoint(0, 0, 0);
    this->Camera()->SetViewUp(0, 1, 0);
    this->Camera()->SetClippingRange(1, 10);
  }
  std::vector<float> Depth()
  {
    std::vector<float> depth(static_cast<size_t>(this->Width) * this->Height);
    this->Window->GetZbufferData(0, 0, this->Width - 1, this->Height - 1, depth.data());
    return depth;
  }
};

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
      const Color c = { nprPixel(image, x, y, 0), nprPixel(image, x, y, 1), nprPixel(image, x, y, 2) };
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
    const bool known = std::any_of(
      expected.begin(), expected.end(), [&](const Color& e) { return Near(c, e); });
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

vtkSmartPointer<vtkActor> AddSphere(vtkRenderer* renderer, const double center[3], double radius,
  const double color[3], int resolution = 128)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(center[0], center[1], center[2]);
  sphere->SetRadius(radius);
  sphere->SetThetaResolution(resolution);
  sphere->SetPhiResolution(resolution / 2);
  return nprAddActor(renderer, sphere->GetOutputPort(), color);
}

vtkSmartPointer<vtkActor> AddCube(vtkRenderer* renderer, const double center[3], double size,
  const double color[3])
{
  vtkNew<vtkCubeSource> cube;
  cube->SetCenter(center[0], center[1], center[2]);
  cube->SetXLength(size);
  cube->SetYLength(size);
  cube->SetZLength(size);
  return nprAddActor(renderer, cube->GetOutputPort(), color);
}

// ---- A lit sphere in toon shading shows exactly N shades of its colour ----
int ToonBands()
{
  Scene scene(360, 300);
  const double color[3] = { 0.9, 0.6, 0.3 };
  const double origin[3] = { 0, 0, 0 };
  AddSphere(scene.Renderer, origin, 1.0, color);
  scene.LookAtOrigin(4.5);
  // Parallel: the silhouette is where the normal is at right angles to the headlight, so every
  // band down to intensity 0 is on screen (in perspective the rim is at n.l = radius / distance).
  scene.Camera()->ParallelProjectionOn();
  scene.Camera()->SetParallelScale(1.1);
  scene.Pass->SetStyleToToon();
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
      CheckShades(scene.Render(), ExpectedShades(color, factors),
        std::to_string(bands) + " bands" + (perVertex ? " per vertex" : " per pixel"));
    }
  }

  // On a coarse sphere the two differ: per vertex, band borders are straight within a triangle.
  vtkActor* sphere = vtkActor::SafeDownCast(scene.Renderer->GetActors()->GetItemAsObject(0));
  vtkNew<vtkSphereSource> coarse;
  coarse->SetThetaResolution(12);
  coarse->SetPhiResolution(8);
  vtkPolyDataMapper::SafeDownCast(sphere->GetMapper())->SetInputConnection(coarse->GetOutputPort());
  scene.Camera()->SetParallelScale(0.6);
  scene.Toon()->SetNumberOfBands(3);
  auto perVertexImage = scene.Render();
  scene.Toon()->SetPerVertex(false);
  auto perPixelImage = scene.Render();
  const auto shades = ExpectedShades(color, { 1.0 / 3, 2.0 / 3, 1.0 });
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
  std::cout << differing << " pixels differ between per-vertex and per-pixel on the coarse sphere\n";
  NPR_CHECK(differing > 200, "per-vertex toon looks like per-pixel toon (" << differing << " pixels differ)");

  // A user table: its entries are the bands.
  vtkNew<vtkLookupTable> table;
  table->SetNumberOfTableValues(2);
  table->SetTableValue(0, 0.25, 0.25, 0.25);
  table->SetTableValue(1, 1.0, 1.0, 1.0);
  table->SetRange(0.0, 1.0);
  scene.Toon()->SetTable(table);
  CheckShades(scene.Render(), ExpectedShades(color, { 0.25, 1.0 }), "a two-entry table");
  double shade[3];
  scene.Toon()->GetShade(0.2, shade);
  NPR_CHECK(std::abs(shade[0] - 0.25) < 1.0 / 255, "GetShade(0.2) with the table gives " << shade[0]);
  scene.Toon()->SetTable(nullptr);

  // Zero-length normals: no NaN colour, only band colours (the darkest where n is 0).
  vtkNew<vtkPolyData> flattened;
  coarse->Update();
  flattened->DeepCopy(coarse->GetOutput());
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
      NPR_CHECK(known, "zero-length normals give the colour " << c[0] << "," << c[1] << "," << c[2]);
    }
    NPR_CHECK(colors.size() >= 2, "zero-length normals: " << colors.size() << " colours");
  }
  scene.Toon()->SetPerVertex(false);

  // An unlit actor keeps its flat colour.
  sphere->GetProperty()->LightingOff();
  CheckShades(scene.Render(), ExpectedShades(color, { 1.0 }), "an unlit actor");
  return nprTestResult();
}

// ---- Scalar colours: each pixel is its flat scalar colour times one of the band factors ----
int ToonScalars()
{
  Scene scene(360, 300);
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(128);
  sphere->SetPhiResolution(64);
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
        if (f < 60 || (nprPixel(flat, x, y, 0) == 255 && nprPixel(flat, x, y, 1) == 255 &&
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

// ---- Toon with edges: lines over the bands; the G-buffer is redrawn when the bands change ----
int ToonEdges()
{
  Scene scene(360, 300);
  const double color[3] = { 0.9, 0.6, 0.3 };
  const double center[3] = { 0, 0, 0 };
  AddSphere(scene.Renderer, center, 1.0, color);
  scene.LookAtOrigin(4.5);
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
  for (const Color& band : ExpectedShades(color, { 1.0 / 3, 2.0 / 3, 1.0 }))
  {
    const bool found =
      std::any_of(colors.begin(), colors.end(), [&](const Color& c) { return Near(c, band); });
    NPR_CHECK(found, "band " << band[0] << "," << band[1] << "," << band[2] << " is missing under the lines");
  }
  scene.Toon()->SetNumberOfBands(2);
  scene.Render();
  NPR_CHECK(scene.Pass->GetGBufferPass()->GetNumberOfGeometryDraws() == draws + 1,
    "changing the bands did not redraw the G-buffer");
  return nprTestResult();
}

// A scene with creases, silhouettes and contours at several depths.
void AddParts(vtkRenderer* renderer, const double color[3])
{
  const double cubeCenter[3] = { -0.35, -0.1, 0.0 };
  AddCube(renderer, cubeCenter, 0.9, color);
  const double sphereCenter[3] = { 0.45, 0.2, -0.6 };
  AddSphere(renderer, sphereCenter, 0.55, color, 48);
}

void ViewParts(Scene& scene)
{
  scene.LookAtOrigin(4.0);
  scene.Camera()->Azimuth(25);
  scene.Camera()->Elevation(20);
  scene.Camera()->OrthogonalizeViewUp();
  scene.Camera()->SetClippingRange(1, 10);
}

// ---- Uncertainty 0 reproduces the edges on flat colours exactly, colour and depth ----
int SketchIdentity()
{
  Scene scene(400, 300);
  const double color[3] = { 0.8, 0.75, 0.6 };
  AddParts(scene.Renderer, color);
  ViewParts(scene);
  scene.Edges()->SetCreaseColor(0.1, 0.2, 0.7);
  scene.Edges()->SetContourColor(0.7, 0.1, 0.1);
  scene.Pass->SetStyleToToonEdges();
  scene.Toon()->SetNumberOfBands(1);
  scene.Toon()->SetSpecular(false);
  auto edges = scene.Render();
  const std::vector<float> edgesDepth = scene.Depth();
  scene.Pass->SetStyleToSketch();
  scene.Sketch()->SetUncertainty(0.0);
  auto sketch = scene.Render();
  const std::vector<float> sketchDepth = scene.Depth();
  long long differing = 0, depthDiffering = 0, lines = 0;
  for (int y = 0; y < 300; ++y)
  {
    for (int x = 0; x < 400; ++x)
    {
      bool same = true;
      for (int c = 0; c < 3; ++c)
      {
        same = same && nprPixel(edges, x, y, c) == nprPixel(sketch, x, y, c);
      }
      differing += same ? 0 : 1;
      lines += nprPixel(edges, x, y, 0) < 100 ? 1 : 0;
    }
  }
  for (size_t i = 0; i < edgesDepth.size(); ++i)
  {
    depthDiffering += edgesDepth[i] == sketchDepth[i] ? 0 : 1;
  }
  std::cout << differing << " pixels and " << depthDiffering << " depths differ; " << lines
            << " line pixels\n";
  NPR_CHECK(lines > 500, "the scene has too few lines to compare: " << lines);
  NPR_CHECK(differing == 0, differing << " pixels differ from the edges on flat colours");
  NPR_CHECK(depthDiffering == 0, depthDiffering << " depths differ from the edges' depth sprite");

  // With an uncertainty the image changes.
  scene.Sketch()->SetUncertainty(3.0);
  auto wobbly = scene.Render();
  long long moved = 0;
  for (int y = 0; y < 300; ++y)
  {
    for (int x = 0; x < 400; ++x)
    {
      moved += nprPixel(wobbly, x, y, 0) != nprPixel(edges, x, y, 0) ? 1 : 0;
    }
  }
  NPR_CHECK(moved > 500, "an uncertainty of 3 pixels changed only " << moved << " pixels");
  return nprTestResult();
}

// The pixels darker than half: the lines of a white scene on white.
std::vector<char> DarkPixels(vtkImageData* image, int width, int height)
{
  std::vector<char> dark(static_cast<size_t>(width) * height, 0);
  for (int y = 0; y < height; ++y)
  {
    for (int x = 0; x < width; ++x)
    {
      dark[y * width + x] = nprPixel(image, x, y, 0) < 128 ? 1 : 0;
    }
  }
  return dark;
}

// ---- No line pixel is farther from the unperturbed lines than the uncertainty ----
int SketchDisplacement()
{
  const int width = 400, height = 300;
  Scene scene(width, height);
  const double white[3] = { 1, 1, 1 };
  AddParts(scene.Renderer, white);
  ViewParts(scene);
  scene.Pass->SetStyleToSketch();
  scene.Edges()->SetLineWidth(1.5);
  scene.Sketch()->SetUncertainty(0.0);
  const std::vector<char> exact = DarkPixels(scene.Render(), width, height);
  for (double uncertainty : { 2.0, 5.0 })
  {
    for (unsigned int seed : { 1u, 2u })
    {
      scene.Sketch()->SetUncertainty(uncertainty);
      scene.Sketch()->SetNoiseSeed(seed);
      const std::vector<char> moved = DarkPixels(scene.Render(), width, height);
      // Each line pixel's distance to the nearest unperturbed line pixel.
      const int reach = static_cast<int>(uncertainty) + 4;
      double largest = 0.0;
      long long count = 0;
      for (int y = 0; y < height; ++y)
      {
        for (int x = 0; x < width; ++x)
        {
          if (!moved[y * width + x])
          {
            continue;
          }
          ++count;
          double nearest = 1e9;
          for (int dy = -reach; dy <= reach; ++dy)
          {
            for (int dx = -reach; dx <= reach; ++dx)
            {
              const int u = x + dx, v = y + dy;
              if (u >= 0 && v >= 0 && u < width && v < height && exact[v * width + u])
              {
                nearest = std::min(nearest, std::hypot(dx, dy));
              }
            }
          }
          largest = std::max(largest, nearest);
        }
      }
      // The largest displacement the pass computes over the whole image.
      double largestDisplacement = 0.0;
      for (int y = 0; y < height; ++y)
      {
        for (int x = 0; x < width; ++x)
        {
          double d[2];
          scene.Sketch()->GetDisplacement(scene.Renderer, x, y, false, d);
          largestDisplacement = std::max(largestDisplacement, std::hypot(d[0], d[1]));
        }
      }
      std::cout << "uncertainty " << uncertainty << ", seed " << seed << ": " << count
                << " line pixels, farthest " << largest << " px from the exact lines; largest "
                << "displacement " << largestDisplacement << " px\n";
      // One pixel of tolerance: a line pixel is one whose coverage, mixed from the four texels
      // around the displaced position, exceeds one half.
      NPR_CHECK(largest <= uncertainty + 1.0,
        "a line pixel lies " << largest << " px from the exact lines (uncertainty " << uncertainty << ")");
      NPR_CHECK(largestDisplacement <= uncertainty * (1.0 + 1e-9),
        "the displacement reaches " << largestDisplacement << " px");
      NPR_CHECK(largest >= 0.5 * uncertainty,
        "the lines hardly moved (" << largest << " px for an uncertainty of " << uncertainty << ")");
      NPR_CHECK(largestDisplacement >= 0.7 * uncertainty,
        "the noise hardly reaches the uncertainty (" << largestDisplacement << ")");
    }
  }
  return nprTestResult();
}

// ---- The z-buffer after the sketch is the smaller of the two displaced depth lookups ----
int SketchDepth()
{
  const int width = 400, height = 300;
  Scene scene(width, height);
  const double color[3] = { 0.8, 0.75, 0.6 };
  AddParts(scene.Renderer, color);
  ViewParts(scene);
  scene.Pass->SetStyleToSketch();
  scene.Edges()->SetLineWidth(3.0); // lines reaching onto the background have their own depth
  scene.Sketch()->SetUncertainty(0.0);
  scene.Edges()->SetSilhouettes(false);
  scene.Edges()->SetCreases(false);
  scene.Edges()->SetContours(false);
  scene.Render();
  const std::vector<float> surfaceDepth = scene.Depth(); // the G-buffer's depth
  scene.Edges()->SetSilhouettes(true);
  scene.Edges()->SetCreases(true);
  scene.Edges()->SetContours(true);
  scene.Render();
  const std::vector<float> lineDepth = scene.Depth(); // the depth the lines are drawn at
  scene.Sketch()->SetUncertainty(5.0);
  scene.Sketch()->SetNoiseSeed(3);
  scene.Render();
  const std::vector<float> depth = scene.Depth();

  auto lookup = [&](const std::vector<float>& image, double x, double y, bool& ambiguous) {
    // Too close to a texel border for float and double to agree on the texel: not checked.
    ambiguous = ambiguous || std::abs(x - std::round(x)) < 1e-3 || std::abs(y - std::round(y)) < 1e-3;
    const int u = static_cast<int>(std::floor(x)), v = static_cast<int>(std::floor(y));
    return (u < 0 || v < 0 || u >= width || v >= height) ? 1.0f : image[v * width + u];
  };
  long long checked = 0, wrong = 0, changed = 0;
  for (int y = 0; y < height; ++y)
  {
    for (int x = 0; x < width; ++x)
    {
      double surface[2], lines[2];
      scene.Sketch()->GetDisplacement(scene.Renderer, x, y, true, surface);
      scene.Sketch()->GetDisplacement(scene.Renderer, x, y, false, lines);
      bool ambiguous = false;
      const float expected =
        std::min(lookup(surfaceDepth, x + 0.5 + surface[0], y + 0.5 + surface[1], ambiguous),
          lookup(lineDepth, x + 0.5 + lines[0], y + 0.5 + lines[1], ambiguous));
      if (ambiguous)
      {
        continue;
      }
      ++checked;
      wrong += depth[y * width + x] == expected ? 0 : 1;
      changed += depth[y * width + x] != lineDepth[y * width + x] ? 1 : 0;
    }
  }
  std::cout << checked << " pixels checked, " << wrong << " differ from the smaller displaced "
            << "depth; the displacement changed " << changed << " depths\n";
  NPR_CHECK(checked > 0.98 * width * height, "only " << checked << " pixels could be checked");
  NPR_CHECK(wrong == 0, wrong << " depths are not the smaller of the two displaced lookups");
  NPR_CHECK(changed > 1000, "the displacement changed only " << changed << " depths");
  return nprTestResult();
}

// ---- A second layer is hidden where the sketched surface, as drawn, is in front ----
int SketchLayer()
{
  const int width = 400, height = 300;
  Scene scene(width, height);
  const double grey[3] = { 0.8, 0.8, 0.8 };
  const double origin[3] = { 0, 0, 0 };
  AddCube(scene.Renderer, origin, 1.0, grey);
  scene.LookAtOrigin(5.0);
  scene.Pass->SetStyleToSketch();
  scene.Sketch()->SetUncertainty(6.0);

  vtkNew<vtkRenderer> overlay;
  overlay->SetLayer(1);
  overlay->PreserveDepthBufferOn();
  overlay->SetActiveCamera(scene.Camera());
  overlay->InteractiveOff();
  scene.Window->SetNumberOfLayers(2);
  scene.Window->AddRenderer(overlay);
  const double red[3] = { 1, 0, 0 };
  const double behind[3] = { 0.6, 0, -1.5 };
  vtkSmartPointer<vtkActor> ball = AddSphere(overlay, behind, 0.6, red, 32);
  ball->GetProperty()->LightingOff();

  ball->VisibilityOff();
  scene.Sketch()->SetUncertainty(0.0);
  scene.Render();
  const std::vector<float> exact = scene.Depth();
  scene.Sketch()->SetUncertainty(6.0);
  scene.Render();
  const std::vector<float> sketched = scene.Depth();
  ball->VisibilityOn();
  auto image = scene.Render();

  long long redOverSketch = 0, redElsewhere = 0, displacedOnly = 0;
  for (int y = 0; y < height; ++y)
  {
    for (int x = 0; x < width; ++x)
    {
      const size_t i = static_cast<size_t>(y) * width + x;
      const bool isRed = nprPixel(image, x, y, 0) > 200 && nprPixel(image, x, y, 1) < 60;
      if (sketched[i] < 1.0f)
      {
        redOverSketch += isRed ? 1 : 0;
        displacedOnly += exact[i] == 1.0f ? 1 : 0;
      }
      else
      {
        redElsewhere += isRed ? 1 : 0;
      }
    }
  }
  std::cout << "layer-1 sphere: " << redOverSketch << " red pixels over the sketch, " << redElsewhere
            << " beside it; " << displacedOnly << " pixels covered only by the displaced sketch\n";
  NPR_CHECK(redOverSketch == 0, "the sphere behind the sketch shows through it");
  NPR_CHECK(redElsewhere > 100, "the part of the sphere beside the cube should be drawn");
  NPR_CHECK(displacedOnly > 50, "the displacement should reach past the exact outline");
  return nprTestResult();
}

// ---- Several windows, a resize and a release: every style draws each time ----
int Windows()
{
  const double color[3] = { 0.9, 0.6, 0.3 };
  auto check = [&](Scene& scene, const std::string& what) {
    auto image = scene.Render();
    long long object = 0, dark = 0;
    for (int y = 0; y < scene.Height; ++y)
    {
      for (int x = 0; x < scene.Width; ++x)
      {
        const int r = nprPixel(image, x, y, 0), g = nprPixel(image, x, y, 1);
        object += (r != 255 || g != 255) ? 1 : 0;
        dark += std::max(r, g) < 60 ? 1 : 0;
      }
    }
    const bool lines = scene.Pass->GetStyle() != vtkNPRPass::TOON;
    NPR_CHECK(object > 2000, what << ": only " << object << " object pixels");
    NPR_CHECK(!lines || dark > 100, what << ": only " << dark << " line pixels");
  };
  for (int style : { vtkNPRPass::TOON, vtkNPRPass::TOON_EDGES, vtkNPRPass::SKETCH })
  {
    const std::string name = vtkNPRPass::GetStyleName(style);
    for (int round = 0; round < 2; ++round)
    {
      Scene first(200, 150), second(160, 120);
      for (Scene* scene : { &first, &second })
      {
        const double origin[3] = { 0, 0, 0 };
        AddSphere(scene->Renderer, origin, 1.0, color, 32);
        scene->LookAtOrigin(4.5);
        scene->Pass->SetStyle(style);
      }
      check(first, name + " first window");
      check(second, name + " second window");
      first.Window->SetSize(260, 180);
      first.Width = 260;
      first.Height = 180;
      check(first, name + " resized");
      first.Pass->ReleaseGraphicsResources(first.Window);
      check(first, name + " after ReleaseGraphicsResources");
    }
  }
  return nprTestResult();
}

// ---- Baselines ----
int Baseline(const char* model, const char* name, int style, bool paper)
{
  Scene scene(400, 300);
  nprAddBaselineModel(scene.Renderer, model);
  scene.Pass->SetStyle(style);
  scene.Sketch()->SetPaper(paper);
  scene.Pass->SetSketchToonShading(paper);
  NPR_CHECK(nprCompareWithBaseline(scene.Render(), name), name << " differs from its baseline");
  return nprTestResult();
}
}

int main(int argc, char* argv[])
{
  const std::map<std::string, std::function<int()>> cases = {
    { "toon-bands", ToonBands },
    { "toon-scalars", ToonScalars },
    { "toon-edges", ToonEdges },
    { "sketch-identity", SketchIdentity },
    { "sketch-displacement", SketchDisplacement },
    { "sketch-depth", SketchDepth },
    { "sketch-layer", SketchLayer },
    { "windows", Windows },
    { "baseline-toon-bunny",
      [] { return Baseline("bunny.ply", "toon_bunny", vtkNPRPass::TOON, false); } },
    { "baseline-toon-cad",
      [] { return Baseline("cad_part.vtp", "toon_edges_cad_part", vtkNPRPass::TOON_EDGES, false); } },
    { "baseline-sketch-bunny",
      [] { return Baseline("bunny.ply", "sketch_bunny", vtkNPRPass::SKETCH, false); } },
    { "baseline-sketch-cad",
      [] { return Baseline("cad_part.vtp", "sketch_cad_part", vtkNPRPass::SKETCH, true); } },
  };
  return nprRunTestCase(argc, argv, cases);
}
