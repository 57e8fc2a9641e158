// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// The G-buffer encodings of the edge pass (half, packed 8- and 16-bit depth+normal), part of the
// TestInkEncodings program: each encoding's lines against the float lines; the storage formats;
// quantisation noise of the 8-bit packed buffer against its threshold; the log depth remap.
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
NPR_TEST_CASE("encodings-cube", EncodingsCube);

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
NPR_TEST_CASE("encoding-storage", EncodingStorage);

// A sphere in the 8-bit packed buffer: each quantised component steps by one level somewhere, so
// a low threshold draws that noise all over the surface; the default threshold does not, and the
// outline stays.
int PackedQuantisation()
{
  const int size = 200;
  Scene scene(size, size);
  auto sphere = nprSphereSource(0.5, 96, 96);
  const double color[3] = { 0.8, 0.8, 0.8 };
  nprAddActor(scene.Renderer, sphere->GetOutputPort(), color);
  scene.Camera()->SetPosition(0, 0, 2.5);
  scene.Camera()->SetFocalPoint(0, 0, 0);
  scene.Renderer->ResetCameraClippingRange();
  scene.Pass->SetStyleToShaded();
  const Mask object = Threshold(scene.Render(), IsObject);
  const std::vector<double> toOutline = DistanceTo(Boundary(object, size, size), size, size);

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
NPR_TEST_CASE("packed-quantisation", PackedQuantisation);

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
NPR_TEST_CASE("depth-remap", DepthRemap);
}
