// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// The ground-truth mask of the visible feature lines (vtkNPRReferenceMask), part of the
// TestReferenceMask program: the same lines and mask far from the origin and at any scale; the
// grouping of the occluders changes nothing.
//
// usage: TestReferenceMask CASE [DATA_DIR]   (CASE: the NPR_TEST_CASE names below)
#include "nprFeatureLineTesting.h"

#include "vtkActor.h"
#include "vtkActorCollection.h"
#include "vtkCamera.h"
#include "vtkCellData.h"
#include "vtkCubeSource.h"
#include "vtkIdTypeArray.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkNPRModelReader.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkSphereSource.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <numeric>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace
{
using namespace nprFeatureLineTesting;
// ---- Far from the origin and at any scale: the same lines and the same mask ----
int Stability()
{
  // The filter on a double-precision box moved 1e7 away, the eye moved with it.
  const double eye[3] = { 2.2, 1.7, 2.9 };
  std::set<std::pair<vtkIdType, vtkIdType>> reference;
  for (double offset : { 0.0, 1e7 })
  {
    vtkSmartPointer<vtkPolyData> box = Triangulated(MakeBox());
    vtkNew<vtkPoints> moved;
    moved->SetDataTypeToDouble();
    for (vtkIdType i = 0; i < box->GetNumberOfPoints(); ++i)
    {
      double p[3];
      box->GetPoint(i, p);
      moved->InsertNextPoint(p[0] + offset, p[1] - offset, p[2] + offset);
    }
    box->SetPoints(moved);
    auto filter = MakeFilter(AllTypes);
    filter->SetInputData(box);
    filter->SetEyePosition(eye[0] + offset, eye[1] - offset, eye[2] + offset);
    filter->Update();
    std::set<std::pair<vtkIdType, vtkIdType>> lines;
    auto* ids =
      vtkIdTypeArray::SafeDownCast(filter->GetOutput()->GetCellData()->GetArray("InputPointIds"));
    auto* types = vtkUnsignedCharArray::SafeDownCast(
      filter->GetOutput()->GetCellData()->GetArray("FeatureType"));
    for (vtkIdType i = 0; ids && types && i < ids->GetNumberOfTuples(); ++i)
    {
      lines.insert(
        { ids->GetTypedComponent(i, 0) * 16 + types->GetValue(i), ids->GetTypedComponent(i, 1) });
    }
    if (offset == 0.0)
    {
      reference = lines;
    }
    NPR_CHECK(lines == reference && lines.size() == 12,
      "offset " << offset << ": " << lines.size() << " lines, not those at the origin");
  }

  // The mask of a cube moved by an actor position and scaled, the camera with it.
  std::vector<unsigned char> first;
  const double cases[][2] = { { 0.0, 1.0 }, { 1e5, 1.0 }, { 1e7, 1.0 }, { 0.0, 1e-6 }, { 0.0, 1e6 },
    { 1e7, 1e3 } };
  for (const auto& c : cases)
  {
    const double offset = c[0], scale = c[1];
    MaskScene scene(400, 300);
    const double origin[3] = { 0, 0, 0 };
    vtkSmartPointer<vtkActor> cube = nprAddCube(scene.Renderer, origin, scale);
    cube->SetPosition(offset, offset, offset);
    vtkCamera* camera = scene.Camera();
    camera->SetPosition(offset + 2.2 * scale, offset + 1.7 * scale, offset + 2.9 * scale);
    camera->SetFocalPoint(offset, offset, offset);
    camera->SetViewUp(0, 1, 0);
    camera->SetClippingRange(scale, 10 * scale);
    vtkImageData* mask = scene.Mask();
    const unsigned char* p = static_cast<unsigned char*>(mask->GetScalarPointer());
    const std::vector<unsigned char> pixels(p, p + scene.Width * scene.Height);
    if (first.empty())
    {
      first = pixels;
    }
    const long long differ = std::inner_product(pixels.begin(), pixels.end(), first.begin(), 0LL,
      std::plus<long long>(), [](unsigned char a, unsigned char b) { return a != b ? 1LL : 0LL; });
    std::cout << "offset " << offset << ", scale " << scale << ": "
              << scene.Reference->GetNumberOfLinePixels() << " pixels, " << differ
              << " differ from the unit cube at the origin\n";
    NPR_CHECK(differ == 0 && scene.Reference->GetNumberOfLinePixels() > 900,
      "offset " << offset << ", scale " << scale << ": " << differ << " pixels differ");
  }
  return nprTestResult();
}
NPR_TEST_CASE("mask-stability", Stability);

// ---- The groups of triangles the occlusion structure is split into change nothing ----
int MaskLocatorGroups()
{
  MaskScene scene(640, 480);
  vtkNew<vtkNPRModelReader> reader;
  reader->SetFileName((nprTestDataDir() + "/bunny.ply").c_str());
  nprAddActor(scene.Renderer, reader->GetOutputPort());
  scene.Renderer->ResetCamera();
  scene.Camera()->Azimuth(30);
  scene.Camera()->Elevation(20);
  scene.Camera()->OrthogonalizeViewUp();
  scene.Renderer->ResetCameraClippingRange();
  vtkNPRReferenceMask* reference = scene.Reference;
  reference->GenerateVisibleLinesOn(); // every sample's visibility counts, not only the pixels'
  std::vector<unsigned char> first;
  vtkIdType visible = -1;
  for (int group : { VTK_INT_MAX, 16384, 1000, 7 })
  {
    reference->SetTrianglesPerLocator(group);
    vtkImageData* mask = scene.Mask();
    const unsigned char* p = static_cast<unsigned char*>(mask->GetScalarPointer());
    const std::vector<unsigned char> pixels(p, p + scene.Width * scene.Height);
    std::cout << "groups of " << group << " triangles: " << reference->GetNumberOfVisibleSamples()
              << " of " << reference->GetNumberOfRayCasts() << " samples visible, "
              << reference->GetNumberOfLinePixels() << " pixels, visibility "
              << reference->GetVisibilityTime() << " s\n";
    if (first.empty())
    {
      first = pixels;
      visible = reference->GetNumberOfVisibleSamples();
      NPR_CHECK(reference->GetNumberOfLinePixels() > 1000, "too few line pixels on the bunny");
    }
    NPR_CHECK(pixels == first && reference->GetNumberOfVisibleSamples() == visible,
      "groups of " << group << " triangles changed the result");
  }
  NPR_CHECK(
    reference->GetNumberOfLocatorBuilds() == 4 && reference->GetNumberOfAdjacencyBuilds() == 1,
    "builds: locator " << reference->GetNumberOfLocatorBuilds() << ", adjacency "
                       << reference->GetNumberOfAdjacencyBuilds());
  return nprTestResult();
}
NPR_TEST_CASE("mask-locator-groups", MaskLocatorGroups);
}
