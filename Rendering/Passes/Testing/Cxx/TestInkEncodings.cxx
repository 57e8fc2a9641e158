// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// The inking pass (vtkNPRInkPass) and the G-buffer encodings of the edge pass (half, packed 8-
// and 16-bit depth+normal), checked with numbers: ink only along a cube's outline, as wide as
// asked, no crease, OpenGL state restored; the mask; each encoding's lines against the float
// lines; the storage formats; quantisation noise of the 8-bit packed buffer against its
// threshold; windows, resizes and releases; and baseline images.
//
// usage: TestInkEncodings CASE [DATA_DIR]   (CASE: see the table at the end of this file)
#include "nprTesting.h"

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
using Scene = nprPassScene;

// A unit cube seen from a corner direction: a hexagonal outline and three visible creases.
vtkSmartPointer<vtkActor> AddCubeSeenFromCorner(Scene& scene, bool parallel)
{
  vtkNew<vtkCubeSource> cube;
  const double color[3] = { 0.6, 0.7, 0.9 };
  vtkSmartPointer<vtkActor> actor = nprAddActor(scene.Renderer, cube->GetOutputPort(), color);
  scene.Camera()->SetFocalPoint(0, 0, 0);
  scene.Camera()->SetPosition(2.2, 1.7, 2.6);
  scene.Camera()->SetViewUp(0, 1, 0);
  scene.Camera()->SetParallelProjection(parallel);
  scene.Camera()->SetParallelScale(0.9);
  scene.Renderer->ResetCameraClippingRange();
  return actor;
}

// Pixel masks as flat vectors, row 0 at the bottom.
using Mask = std::vector<char>;

Mask Threshold(vtkImageData* image, const std::function<bool(int, int, int)>& test)
{
  const int* dims = image->GetDimensions();
  Mask mask(static_cast<size_t>(dims[0]) * dims[1], 0);
  for (int y = 0; y < dims[1]; ++y)
  {
    for (int x = 0; x < dims[0]; ++x)
    {
      mask[static_cast<size_t>(y) * dims[0] + x] =
        test(nprPixel(image, x, y, 0), nprPixel(image, x, y, 1), nprPixel(image, x, y, 2));
    }
  }
  return mask;
}

// Distance from every pixel to the nearest set pixel of a mask (brute force over a window of
// radius r; r + 1 when none is that near). Small images only.
std::vector<double> DistanceTo(const Mask& mask, int width, int height, int r)
{
  std::vector<double> distance(mask.size(), r + 1.0);
  for (int y = 0; y < height; ++y)
  {
    for (int x = 0; x < width; ++x)
    {
      if (!mask[static_cast<size_t>(y) * width + x])
      {
        continue;
      }
      for (int j = std::max(0, y - r); j <= std::min(height - 1, y + r); ++j)
      {
        for (int i = std::max(0, x - r); i <= std::min(width - 1, x + r); ++i)
        {
          double& d = distance[static_cast<size_t>(j) * width + i];
          d = std::min(d, std::hypot(i - x, j - y));
        }
      }
    }
  }
  return distance;
}

// The pixels of a mask with a pixel not in it among their 4 neighbours.
Mask Boundary(const Mask& mask, int width, int height)
{
  Mask boundary(mask.size(), 0);
  for (int y = 1; y < height - 1; ++y)
  {
    for (int x = 1; x < width - 1; ++x)
    {
      const size_t i = static_cast<size_t>(y) * width + x;
      boundary[i] =
        mask[i] && (!mask[i - 1] || !mask[i + 1] || !mask[i - width] || !mask[i + width]);
    }
  }
  return boundary;
}

long long Count(const Mask& mask)
{
  return std::count(mask.begin(), mask.end(), 1);
}

// F1 of mask a against mask b at a tolerance in pixels.
double F1(const Mask& a, const Mask& b, int width, int height, double tolerance)
{
  const std::vector<double> toA = DistanceTo(a, width, height, 4);
  const std::vector<double> toB = DistanceTo(b, width, height, 4);
  long long aNearB = 0, bNearA = 0;
  for (size_t i = 0; i < a.size(); ++i)
  {
    aNearB += a[i] && toB[i] <= tolerance;
    bNearA += b[i] && toA[i] <= tolerance;
  }
  const double precision = Count(a) ? static_cast<double>(aNearB) / Count(a) : 0.0;
  const double recall = Count(b) ? static_cast<double>(bNearA) / Count(b) : 0.0;
  return precision + recall > 0.0 ? 2.0 * precision * recall / (precision + recall) : 0.0;
}

bool IsInk(int r, int g, int b)
{
  return r < 60 && g < 60 && b < 60;
}

bool IsObject(int r, int g, int b)
{
  return r < 225 || g < 225 || b < 225;
}

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
    const std::vector<double> toOutline = DistanceTo(outline, size, size, 8);
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
    const std::vector<double> toInk = DistanceTo(ink, size, size, 4);
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

// ---- Encodings ----
// Each encoding's lines of a cube against the float lines: half gives the same, packed ones
// nearly the same (they straddle steps, so they are compared with a 2-pixel tolerance).
int EncodingsCube()
{
  const int size = 200;
  Scene scene(size, size);
  AddCubeSeenFromCorner(scene, false);
  scene.Pass->SetStyleToEdges();
  scene.Edges()->SetAntiAliasing(false);
  scene.Edges()->CoverageOnlyOn();
  auto white = [](int r, int, int) { return r > 127; };
  std::map<int, Mask> masks;
  for (int encoding : { vtkNPREdgePass::FLOAT, vtkNPREdgePass::HALF, vtkNPREdgePass::PACKED8,
         vtkNPREdgePass::PACKED16 })
  {
    scene.Edges()->SetEncoding(encoding);
    masks[encoding] = Threshold(scene.Render(), white);
    NPR_CHECK(scene.Pass->GetGBufferPass()->GetWrittenEncoding() == encoding,
      "the G-buffer holds " << vtkNPREdgePass::GetEncodingName(encoding));
  }
  const Mask& reference = masks[vtkNPREdgePass::FLOAT];
  NPR_CHECK(Count(reference) > 400, Count(reference) << " float line pixels");
  for (const auto& entry : masks)
  {
    const double f1 = F1(entry.second, reference, size, size, 2.0);
    const double f1Exact = F1(entry.second, reference, size, size, 0.0);
    std::cout << vtkNPREdgePass::GetEncodingName(entry.first) << ": " << Count(entry.second)
              << " line pixels, F1 against float " << f1Exact << " exact, " << f1 << " at 2 px\n";
    NPR_CHECK(f1 > 0.95, vtkNPREdgePass::GetEncodingName(entry.first) << " F1 " << f1);
  }
  NPR_CHECK(F1(masks[vtkNPREdgePass::HALF], reference, size, size, 0.0) > 0.99,
    "half gives the float lines");
  NPR_CHECK(masks[vtkNPREdgePass::PACKED8] != reference, "packed8 finds its own lines");
  return nprTestResult();
}

// The geometry attachment's storage: RG32F, RGBA16F, R8, R16.
int EncodingStorage()
{
  Scene scene(64, 64);
  AddCubeSeenFromCorner(scene, false);
  scene.Pass->SetStyleToEdges();
  scene.Edges()->ContoursOff(); // one prop: no ids anyway
  const std::map<int, unsigned int> formats = { { vtkNPREdgePass::FLOAT, GL_RG32F },
    { vtkNPREdgePass::HALF, GL_RGBA16F }, { vtkNPREdgePass::PACKED8, GL_R8 },
    { vtkNPREdgePass::PACKED16, GL_R16 } };
  for (const auto& entry : formats)
  {
    scene.Edges()->SetEncoding(entry.first);
    scene.Render();
    vtkTextureObject* geometry = scene.Pass->GetGBufferPass()->GetGeometryTexture();
    const unsigned int format = geometry ? geometry->GetInternalFormat(VTK_FLOAT, 1, false) : 0;
    NPR_CHECK(format == entry.second,
      vtkNPREdgePass::GetEncodingName(entry.first) << ": internal format 0x" << std::hex << format
                                                   << " instead of 0x" << entry.second << std::dec);
  }
  NPR_CHECK(vtkNPREdgePass::GetEncodingFromName("packed16") == vtkNPREdgePass::PACKED16 &&
      vtkNPREdgePass::GetEncodingFromName("packed4") == -1,
    "encoding names");
  return nprTestResult();
}

// A sphere in the 8-bit packed buffer: each quantised component steps by one level somewhere, so
// a low threshold draws that noise all over the surface; the default threshold does not, and the
// outline stays.
int PackedQuantisation()
{
  const int size = 200;
  Scene scene(size, size);
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(96);
  sphere->SetPhiResolution(96);
  const double color[3] = { 0.8, 0.8, 0.8 };
  nprAddActor(scene.Renderer, sphere->GetOutputPort(), color);
  scene.Camera()->SetPosition(0, 0, 2.5);
  scene.Camera()->SetFocalPoint(0, 0, 0);
  scene.Renderer->ResetCameraClippingRange();
  scene.Pass->SetStyleToShaded();
  const Mask object = Threshold(scene.Render(), IsObject);
  const std::vector<double> toOutline = DistanceTo(Boundary(object, size, size), size, size, 8);

  scene.Pass->SetStyleToEdges();
  scene.Edges()->SetEncoding(vtkNPREdgePass::PACKED8);
  scene.Edges()->CoverageOnlyOn();
  scene.Edges()->SetAntiAliasing(false);
  std::map<double, std::pair<long long, long long>> found; // threshold: interior, outline
  for (double threshold : { 0.02, 0.1 })
  {
    scene.Edges()->SetPackedThreshold(threshold);
    const Mask lines = Threshold(scene.Render(), [](int r, int, int) { return r > 127; });
    long long interior = 0, outline = 0;
    for (size_t i = 0; i < lines.size(); ++i)
    {
      interior += lines[i] && object[i] && toOutline[i] > 4.0;
      outline += lines[i] && toOutline[i] <= 2.0;
    }
    found[threshold] = { interior, outline };
    std::cout << "threshold " << threshold << ": " << interior << " interior line pixels of "
              << Count(object) << ", " << outline << " on the outline\n";
  }
  NPR_CHECK(found[0.02].first > Count(object) / 20, "quantisation noise at a low threshold");
  NPR_CHECK(found[0.1].first < Count(object) / 100, "no noise at the default threshold");
  NPR_CHECK(found[0.1].second > 300, "the outline is found");
  return nprTestResult();
}

// ---- Log depth for extreme near/far ratios ----
// A perspective camera with near = far / 1e6: the G-buffer holds log depth (the usual depth
// would let back faces through), and the depth sprite written from it equals, within the
// window's 24-bit depth, the depth VTK's own drawing writes; at a ratio of 1e3 nothing changes.
int DepthRemap()
{
  const int size = 160;
  Scene scene(size, size);
  AddCubeSeenFromCorner(scene, false);
  const double distance = scene.Camera()->GetDistance();
  for (double ratio : { 1e3, 1e6 })
  {
    scene.Camera()->SetClippingRange(2.0 * distance / ratio, 2.0 * distance);
    std::vector<float> depth[2];
    for (int style : { vtkNPRPass::SHADED, vtkNPRPass::EDGES })
    {
      scene.Pass->SetStyle(style);
      scene.Window->Render();
      std::vector<float>& values = depth[style == vtkNPRPass::EDGES];
      values.resize(static_cast<size_t>(size) * size);
      scene.Window->GetZbufferData(0, 0, size - 1, size - 1, values.data());
    }
    const bool remapped = scene.Pass->GetGBufferPass()->GetDepthRemapped();
    NPR_CHECK(remapped == (ratio > 1e4), "ratio " << ratio << ": remapped " << remapped);
    long long covered = 0, differing = 0;
    double largest = 0.0;
    for (size_t i = 0; i < depth[0].size(); ++i)
    {
      if (depth[0][i] < 1.0f && depth[1][i] < 1.0f)
      {
        ++covered;
        const double difference = std::abs(static_cast<double>(depth[0][i]) - depth[1][i]);
        largest = std::max(largest, difference);
        differing += difference > 4.0 / (1 << 24) ? 1 : 0;
      }
    }
    std::cout << "ratio " << ratio << ": " << covered << " covered pixels, " << differing
              << " with depths more than 4 steps of 2^-24 apart, largest difference " << largest
              << "\n";
    NPR_CHECK(covered > 5000, "the cube covers the image");
    NPR_CHECK(differing <= covered / 200, differing << " sprite depths differ from VTK's");
  }
  return nprTestResult();
}

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
}

int main(int argc, char* argv[])
{
  const std::map<std::string, std::function<int()>> cases = {
    { "inked-cube", InkedCube },
    { "inked-width-mask", InkedWidthAndMask },
    { "encodings-cube", EncodingsCube },
    { "encoding-storage", EncodingStorage },
    { "packed-quantisation", PackedQuantisation },
    { "depth-remap", DepthRemap },
    { "windows", Windows },
    { "baseline-inked-bunny",
      []
      { return Baseline("bunny.ply", "inked_bunny", vtkNPRPass::INKED, vtkNPREdgePass::FLOAT); } },
    { "baseline-inked-cad",
      [] {
        return Baseline("cad_part.vtp", "inked_cad_part", vtkNPRPass::INKED, vtkNPREdgePass::FLOAT);
      } },
    { "baseline-packed8-cad",
      []
      {
        return Baseline(
          "cad_part.vtp", "packed8_cad_part", vtkNPRPass::EDGES, vtkNPREdgePass::PACKED8);
      } },
    { "baseline-packed16-bunny",
      [] {
        return Baseline("bunny.ply", "packed16_bunny", vtkNPRPass::EDGES, vtkNPREdgePass::PACKED16);
      } },
    { "baseline-half-cad",
      [] {
        return Baseline("cad_part.vtp", "half_cad_part", vtkNPRPass::EDGES, vtkNPREdgePass::HALF);
      } },
  };
  return nprRunTestCase(argc, argv, cases);
}
