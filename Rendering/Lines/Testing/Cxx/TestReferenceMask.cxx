// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// The ground-truth mask of the visible feature lines (vtkNPRReferenceMask): a cube's mask against
// an independent projection of its visible edges, in perspective and parallel; occlusion by
// another object; what is rebuilt between updates; the same lines and mask far from the origin
// and at any scale; the grouping of the occluders changes nothing; a sphere's smooth contours
// against its analytic outline, without gaps, and still hidden by real occluders; the curves
// where surfaces cross.
//
// usage: TestReferenceMask CASE [DATA_DIR]   (CASE: see the table at the end of this file)
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

// A unit cube from a known camera: the mask against the analytic visible edges.
int MaskCube(bool parallel)
{
  MaskScene scene(400, 300);
  const double origin[3] = { 0, 0, 0 };
  nprAddCube(scene.Renderer, origin, 1.0);
  const double eye[3] = { 2.2, 1.7, 2.9 };
  nprViewFromCorner(scene.Camera(), eye, parallel);
  vtkImageData* mask = scene.Mask();
  NPR_CHECK(mask->GetDimensions()[0] == 400 && mask->GetDimensions()[1] == 300 &&
      mask->GetNumberOfScalarComponents() == 1 && mask->GetScalarType() == VTK_UNSIGNED_CHAR,
    "the mask is not 400x300 unsigned char");

  // Visible edges of a convex box: at least one face towards the viewer.
  double toward[3];
  for (int i = 0; i < 3; ++i)
  {
    toward[i] = -eye[i]; // direction of projection (focal point at the origin)
  }
  std::vector<std::array<double, 4>> visible, hidden;
  for (const BoxEdge& edge : BoxEdges())
  {
    const bool seen =
      BoxFaceFront(edge.Faces[0][0], edge.Faces[0][1], parallel, parallel ? toward : eye) ||
      BoxFaceFront(edge.Faces[1][0], edge.Faces[1][1], parallel, parallel ? toward : eye);
    const auto a = scene.Project(edge.Ends.first), b = scene.Project(edge.Ends.second);
    (seen ? visible : hidden).push_back({ a[0], a[1], b[0], b[1] });
  }
  NPR_CHECK(visible.size() == 9 && hidden.size() == 3, "a cube seen from a corner shows 9 edges");
  auto nearest = [](const std::vector<std::array<double, 4>>& edges, const double p[2])
  {
    double best = 1e300;
    for (const auto& e : edges)
    {
      best = std::min(best, nprSegmentDistance(p, &e[0], &e[2]));
    }
    return best;
  };

  // Precision: every mask pixel's centre lies within half a pixel diagonal of a visible edge.
  double worst = 0.0;
  long long pixels = 0, onHidden = 0;
  for (int y = 0; y < scene.Height; ++y)
  {
    for (int x = 0; x < scene.Width; ++x)
    {
      const double p[2] = { x + 0.5, y + 0.5 };
      const int value = nprPixel(mask, x, y);
      NPR_CHECK(value == 0 || value == 255, "mask value " << value);
      if (value)
      {
        ++pixels;
        worst = std::max(worst, nearest(visible, p));
      }
      if (value && nearest(hidden, p) <= 0.5 && nearest(visible, p) > 1.5)
      {
        ++onHidden;
      }
    }
  }
  // Recall: along every visible edge, a mask pixel in the 3x3 pixels around each point.
  long long samples = 0, found = 0;
  for (const auto& e : visible)
  {
    const double length = std::hypot(e[2] - e[0], e[3] - e[1]);
    const int steps = static_cast<int>(length / 0.1);
    for (int s = 0; s <= steps; ++s)
    {
      const double px = e[0] + (e[2] - e[0]) * s / steps, py = e[1] + (e[3] - e[1]) * s / steps;
      const int x = static_cast<int>(std::floor(px)), y = static_cast<int>(std::floor(py));
      if (x < 2 || y < 2 || x >= scene.Width - 2 || y >= scene.Height - 2)
      {
        continue;
      }
      bool hit = false;
      for (int oy = -1; oy <= 1 && !hit; ++oy)
      {
        for (int ox = -1; ox <= 1 && !hit; ++ox)
        {
          hit = nprPixel(mask, x + ox, y + oy) != 0;
        }
      }
      ++samples;
      found += hit ? 1 : 0;
    }
  }
  vtkNPRReferenceMask* reference = scene.Reference;
  std::cout << (parallel ? "parallel" : "perspective") << ": " << pixels
            << " mask pixels, farthest centre " << worst << " px from a visible edge, " << onHidden
            << " on hidden edges, " << found << "/" << samples << " edge points found; "
            << reference->GetNumberOfFeatureEdges() << " edges, " << reference->GetNumberOfSamples()
            << " samples, " << reference->GetNumberOfRayCasts() << " rays, "
            << reference->GetNumberOfVisibleSamples() << " visible\n";
  NPR_CHECK(pixels > 900, "too few mask pixels: " << pixels);
  NPR_CHECK(pixels == reference->GetNumberOfLinePixels(), "GetNumberOfLinePixels is wrong");
  NPR_CHECK(worst <= std::sqrt(0.5) + 1e-6, "a mask pixel lies " << worst << " px from the edges");
  NPR_CHECK(onHidden == 0, onHidden << " mask pixels on hidden edges");
  NPR_CHECK(found == samples,
    "visible edges missed at " << samples - found << " of " << samples << " points");
  NPR_CHECK(reference->GetNumberOfFeatureEdges() == 12, "the cube's 12 edges are feature lines");

  // The visible lines: the same mask with them on, and every visible point in a mask pixel.
  std::vector<unsigned char> first(static_cast<unsigned char*>(mask->GetScalarPointer()),
    static_cast<unsigned char*>(mask->GetScalarPointer()) + scene.Width * scene.Height);
  reference->GenerateVisibleLinesOn();
  mask = scene.Mask();
  const std::vector<unsigned char> second(static_cast<unsigned char*>(mask->GetScalarPointer()),
    static_cast<unsigned char*>(mask->GetScalarPointer()) + scene.Width * scene.Height);
  NPR_CHECK(first == second, "the mask changed with GenerateVisibleLines");
  vtkPolyData* lines = reference->GetVisibleLines();
  NPR_CHECK(lines->GetNumberOfCells() >= 9 && lines->GetCellData()->GetArray("FeatureType"),
    "visible lines: " << lines->GetNumberOfCells() << " polylines");
  NPR_CHECK(reference->GetNumberOfRayCasts() == reference->GetNumberOfSamples(),
    "with visible lines every sample needs a ray");
  long long outside = 0;
  for (vtkIdType i = 0; i < lines->GetNumberOfPoints(); ++i)
  {
    Point p;
    lines->GetPoint(i, p.data());
    const auto d = scene.Project(p);
    outside +=
      nprPixel(mask, static_cast<int>(std::floor(d[0])), static_cast<int>(std::floor(d[1]))) ? 0
                                                                                             : 1;
  }
  NPR_CHECK(outside <= 2, outside << " visible-line points outside the mask's pixels");
  return nprTestResult();
}

// ---- A small cube behind a big one: hidden entirely, then in part ----
int MaskOcclusion()
{
  MaskScene scene(400, 300);
  const double origin[3] = { 0, 0, 0 };
  vtkSmartPointer<vtkActor> big = nprAddCube(scene.Renderer, origin, 2.0);
  vtkCamera* camera = scene.Camera();
  camera->SetPosition(0.5, 0.4, 8.0);
  camera->SetFocalPoint(0, 0, 0);
  camera->SetViewUp(0, 1, 0);
  camera->SetClippingRange(1.0, 20.0);
  auto copy = [&](vtkImageData* mask)
  {
    const unsigned char* p = static_cast<unsigned char*>(mask->GetScalarPointer());
    return std::vector<unsigned char>(p, p + scene.Width * scene.Height);
  };
  const std::vector<unsigned char> bigOnly = copy(scene.Mask());

  const double behind[3] = { 0, 0, -3 };
  vtkSmartPointer<vtkActor> small = nprAddCube(scene.Renderer, behind, 0.5);
  const std::vector<unsigned char> both = copy(scene.Mask());
  big->VisibilityOff();
  const std::vector<unsigned char> smallOnly = copy(scene.Mask());
  big->VisibilityOn();
  long long smallPixels = 0;
  for (unsigned char v : smallOnly)
  {
    smallPixels += v ? 1 : 0;
  }
  std::cout << "small cube alone: " << smallPixels
            << " pixels; behind the big one: " << (both == bigOnly ? "hidden" : "visible in part")
            << "\n";
  NPR_CHECK(smallPixels > 100, "the small cube alone has no lines");
  NPR_CHECK(both == bigOnly, "the hidden cube changed the mask");

  // Moved half out from behind: new pixels appear, none inside the big cube's outline.
  small->SetPosition(1.45, 0.0, 0.0);
  const std::vector<unsigned char> partly = copy(scene.Mask());
  std::vector<std::array<double, 2>> corners;
  for (int c = 0; c < 8; ++c)
  {
    corners.push_back(scene.Project(Corner(c, 1.0)));
  }
  const auto hull = ConvexHull(corners);
  long long added = 0, inside = 0;
  for (int y = 0; y < scene.Height; ++y)
  {
    for (int x = 0; x < scene.Width; ++x)
    {
      const size_t i = static_cast<size_t>(y) * scene.Width + x;
      if (!partly[i] || bigOnly[i])
      {
        NPR_CHECK(partly[i] || !bigOnly[i], "the big cube's line pixel lost at " << x << "," << y);
        continue;
      }
      ++added;
      // Inside the hull by more than a pixel: hidden by the big cube.
      double depth = 1e300;
      for (size_t k = 0; k < hull.size(); ++k)
      {
        const auto& a = hull[k];
        const auto& b = hull[(k + 1) % hull.size()];
        const double length = std::hypot(b[0] - a[0], b[1] - a[1]);
        depth = std::min(
          depth, ((b[0] - a[0]) * (y + 0.5 - a[1]) - (b[1] - a[1]) * (x + 0.5 - a[0])) / length);
      }
      inside += depth > 1.0 ? 1 : 0;
    }
  }
  std::cout << "small cube half out: " << added << " new pixels, " << inside
            << " inside the big cube's outline\n";
  NPR_CHECK(added > 50, "the part of the small cube out from behind has no lines");
  NPR_CHECK(inside == 0, inside << " pixels of the hidden part in the mask");
  return nprTestResult();
}

// ---- What the mask reuses between updates ----
int MaskReuse()
{
  MaskScene scene(200, 150);
  vtkNew<vtkCubeSource> cube;
  vtkSmartPointer<vtkActor> actor = nprAddActor(scene.Renderer, cube->GetOutputPort());
  vtkCamera* camera = scene.Camera();
  camera->SetPosition(2.2, 1.7, 2.9);
  camera->SetFocalPoint(0, 0, 0);
  camera->SetClippingRange(1.0, 10.0);
  vtkNPRReferenceMask* reference = scene.Reference;
  const long long first = nprCountAbove(scene.Mask(), 0);
  camera->Azimuth(20);
  const long long turned = nprCountAbove(scene.Mask(), 0);
  NPR_CHECK(
    reference->GetNumberOfAdjacencyBuilds() == 1 && reference->GetNumberOfLocatorBuilds() == 1,
    "a camera move rebuilt: adjacency " << reference->GetNumberOfAdjacencyBuilds() << ", locator "
                                        << reference->GetNumberOfLocatorBuilds());
  NPR_CHECK(first > 100 && turned > 100, "no lines");
  actor->SetPosition(0.2, 0, 0);
  scene.Mask();
  NPR_CHECK(
    reference->GetNumberOfAdjacencyBuilds() == 1 && reference->GetNumberOfLocatorBuilds() == 2,
    "an actor move: adjacency " << reference->GetNumberOfAdjacencyBuilds() << ", locator "
                                << reference->GetNumberOfLocatorBuilds());
  cube->SetXLength(1.5);
  scene.Mask();
  NPR_CHECK(
    reference->GetNumberOfAdjacencyBuilds() == 2 && reference->GetNumberOfLocatorBuilds() == 3,
    "a new mesh: adjacency " << reference->GetNumberOfAdjacencyBuilds() << ", locator "
                             << reference->GetNumberOfLocatorBuilds());
  // Translucent actors neither draw lines nor hide them; the explicit size wins.
  actor->GetProperty()->SetOpacity(0.5);
  NPR_CHECK(nprCountAbove(scene.Mask(), 0) == 0, "a translucent actor has lines");
  actor->GetProperty()->SetOpacity(1.0);
  reference->SetSize(64, 48);
  NPR_CHECK(scene.Mask()->GetDimensions()[0] == 64 && nprCountAbove(reference->GetMask(), 0) > 20,
    "an explicit size");
  reference->CreasesOff();
  reference->SilhouettesOff();
  NPR_CHECK(nprCountAbove(scene.Mask(), 0) == 0, "no line types, still lines");
  return nprTestResult();
}

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

// ---- Smooth contours: a sphere's mask against its analytic outline ----
// The outline of a sphere (centre c, radius r) seen from eye: the circle where the tangent cone
// touches it, projected through the renderer, as a closed polyline in window coordinates.
std::vector<std::array<double, 2>> SphereOutline(
  MaskScene& scene, const double c[3], double r, const double eye[3])
{
  double e[3] = { eye[0] - c[0], eye[1] - c[1], eye[2] - c[2] };
  const double distance = vtkMath::Norm(e);
  vtkMath::Normalize(e);
  double u[3], v[3];
  vtkMath::Perpendiculars(e, u, v, 0.0);
  const double offset = r * r / distance,
               radius = r * std::sqrt(1.0 - (r / distance) * (r / distance));
  std::vector<std::array<double, 2>> outline;
  for (int i = 0; i < 7200; ++i)
  {
    const double a = 2.0 * vtkMath::Pi() * i / 7200;
    Point p;
    for (int k = 0; k < 3; ++k)
    {
      p[k] = c[k] + offset * e[k] + radius * (std::cos(a) * u[k] + std::sin(a) * v[k]);
    }
    outline.push_back(scene.Project(p));
  }
  return outline;
}

double OutlineDistance(const std::vector<std::array<double, 2>>& outline, const double p[2])
{
  double best = 1e300;
  for (size_t i = 0; i < outline.size(); ++i)
  {
    best = std::min(
      best, nprSegmentDistance(p, outline[i].data(), outline[(i + 1) % outline.size()].data()));
  }
  return best;
}

// Precision (every mask pixel's centre within 1 px of the outline) and no gap (at every pixel
// column's centre line, each crossing of the outline has a mask pixel within 1 px): the
// worst distance, and the crossings without a pixel.
void OutlineMatch(vtkImageData* mask, int width, int height,
  const std::vector<std::array<double, 2>>& outline, double& worst, long long& pixels,
  long long& crossings, long long& gaps, const std::function<bool(double, double)>& counted)
{
  worst = 0.0;
  pixels = crossings = gaps = 0;
  for (int y = 0; y < height; ++y)
  {
    for (int x = 0; x < width; ++x)
    {
      const double p[2] = { x + 0.5, y + 0.5 };
      if (nprPixel(mask, x, y) && counted(p[0], p[1]))
      {
        ++pixels;
        worst = std::max(worst, OutlineDistance(outline, p));
      }
    }
  }
  for (size_t i = 0; i < outline.size(); ++i)
  {
    const auto& a = outline[i];
    const auto& b = outline[(i + 1) % outline.size()];
    for (int x = static_cast<int>(std::ceil(std::min(a[0], b[0]) - 0.5));
         x + 0.5 < std::max(a[0], b[0]); ++x)
    {
      const double cx = x + 0.5;
      if (cx < std::min(a[0], b[0]) || a[0] == b[0])
      {
        continue;
      }
      const double cy = a[1] + (b[1] - a[1]) * (cx - a[0]) / (b[0] - a[0]);
      if (!counted(cx, cy))
      {
        continue;
      }
      ++crossings;
      bool hit = false;
      for (int oy = -1; oy <= 1 && !hit; ++oy)
      {
        for (int ox = -1; ox <= 1 && !hit; ++ox)
        {
          const int px = x + ox, py = static_cast<int>(std::floor(cy)) + oy;
          const double q[2] = { px + 0.5, py + 0.5 };
          hit = px >= 0 && py >= 0 && px < width && py < height && nprPixel(mask, px, py) &&
            std::hypot(q[0] - cx, q[1] - cy) <= 1.0 + std::sqrt(0.5);
        }
      }
      gaps += hit ? 0 : 1;
    }
  }
}

vtkSmartPointer<vtkActor> AddSphere(MaskScene& scene, const double c[3], double r, int resolution)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(c[0], c[1], c[2]);
  sphere->SetRadius(r);
  sphere->SetThetaResolution(resolution);
  sphere->SetPhiResolution(resolution);
  return nprAddActor(scene.Renderer, sphere->GetOutputPort());
}

// A sphere with normals at 400x400: with and without smooth contours, the mask within 1 px of
// the analytic outline and without gaps along it (the faces next to the contour's triangle
// would hide most of the smooth contour under the mesh-silhouette ray test).
int MaskSmoothSphere()
{
  const int resolution = 64;
  MaskScene scene(400, 400);
  const double centre[3] = { 0, 0, 0 };
  AddSphere(scene, centre, 1.0, resolution);
  const double eye[3] = { 2.6, 1.5, 3.1 };
  nprViewFromCorner(scene.Camera(), eye, false);
  const auto outline = SphereOutline(scene, centre, 1.0, eye);
  vtkNPRReferenceMask* reference = scene.Reference;
  reference->GenerateVisibleLinesOn();
  for (bool smooth : { false, true })
  {
    reference->SetSmoothContours(smooth);
    vtkImageData* mask = scene.Mask();
    double worst;
    long long pixels, crossings, gaps;
    OutlineMatch(mask, scene.Width, scene.Height, outline, worst, pixels, crossings, gaps,
      [](double, double) { return true; });
    long long smoothLines = 0;
    auto* types = vtkUnsignedCharArray::SafeDownCast(
      reference->GetVisibleLines()->GetCellData()->GetArray("FeatureType"));
    for (vtkIdType i = 0; types && i < types->GetNumberOfValues(); ++i)
    {
      smoothLines += (types->GetValue(i) & vtkNPRFeatureLines::SMOOTH_CONTOUR) ? 1 : 0;
    }
    const std::string name = "sphere " + std::to_string(resolution) +
      (smooth ? ", smooth contours" : ", mesh silhouettes");
    std::cout << name << ": " << pixels << " pixels, farthest " << worst
              << " px from the analytic outline, " << gaps << " of " << crossings
              << " column crossings without a pixel within 1 px; "
              << reference->GetNumberOfFeatureEdges() << " lines, "
              << reference->GetNumberOfVisibleSamples() << " of "
              << reference->GetNumberOfRayCasts() << " samples visible, " << smoothLines
              << " visible smooth polylines\n";
    NPR_CHECK(pixels > 600 && worst <= 1.0, name << ": a pixel " << worst << " px off");
    NPR_CHECK(gaps == 0, name << ": " << gaps << " gaps along the outline");
    NPR_CHECK((smoothLines > 0) == smooth, name << ": " << smoothLines << " smooth polylines");
  }
  return nprTestResult();
}

// Real occluders still hide a smooth contour: a small sphere in front of the big one's outline
// (another actor), and the big sphere hiding the small one's outline behind it.
int MaskSmoothOcclusion()
{
  MaskScene scene(400, 400);
  const double big[3] = { 0, 0, 0 }, small[3] = { 0.75, 0.75, 1.2 };
  AddSphere(scene, big, 1.0, 48);
  AddSphere(scene, small, 0.3, 32);
  const double eye[3] = { 0, 0, 6 };
  nprViewFromCorner(scene.Camera(), eye, false);
  scene.Camera()->SetClippingRange(0.5, 20);
  scene.Reference->SmoothContoursOn();
  vtkImageData* mask = scene.Mask();
  const auto bigOutline = SphereOutline(scene, big, 1.0, eye);
  const auto smallOutline = SphereOutline(scene, small, 0.3, eye);
  auto inside = [](const std::vector<std::array<double, 2>>& outline, double x, double y)
  {
    bool in = false;
    for (size_t i = 0, j = outline.size() - 1; i < outline.size(); j = i++)
    {
      const auto& a = outline[i];
      const auto& b = outline[j];
      if ((a[1] > y) != (b[1] > y) && x < (b[0] - a[0]) * (y - a[1]) / (b[1] - a[1]) + a[0])
      {
        in = !in;
      }
    }
    return in;
  };
  // The big outline: no pixel deep inside the small disk, none missing outside it.
  double worst;
  long long pixels, crossings, gaps;
  OutlineMatch(mask, scene.Width, scene.Height, bigOutline, worst, pixels, crossings, gaps,
    [&](double x, double y)
    {
      const double p[2] = { x, y };
      return !inside(smallOutline, x, y) && OutlineDistance(smallOutline, p) > 1.5;
    });
  long long hidden = 0, covered = 0;
  for (int y = 0; y < scene.Height; ++y)
  {
    for (int x = 0; x < scene.Width; ++x)
    {
      const double p[2] = { x + 0.5, y + 0.5 };
      if (inside(smallOutline, p[0], p[1]) && OutlineDistance(smallOutline, p) > 1.5 &&
        OutlineDistance(bigOutline, p) <= 3.0)
      {
        ++covered;
        hidden += nprPixel(mask, x, y) ? 1 : 0;
      }
    }
  }
  // The small sphere's outline is whole (it is in front).
  double smallWorst;
  long long smallPixels, smallCrossings, smallGaps;
  OutlineMatch(mask, scene.Width, scene.Height, smallOutline, smallWorst, smallPixels,
    smallCrossings, smallGaps, [](double, double) { return true; });
  std::cout << "big outline outside the small sphere: " << gaps << " gaps of " << crossings << "; "
            << hidden << " mask pixels of " << covered
            << " on the big outline behind the small sphere; small outline: " << smallGaps
            << " gaps of " << smallCrossings << "\n";
  NPR_CHECK(covered > 20 && hidden == 0, hidden << " pixels of the hidden outline in the mask");
  NPR_CHECK(crossings > 200 && gaps == 0, gaps << " gaps in the visible outline");
  NPR_CHECK(smallCrossings > 50 && smallGaps == 0, smallGaps << " gaps in the small outline");

  // Behind: the small sphere moved behind the big one is hidden entirely.
  vtkActor* second = vtkActor::SafeDownCast(scene.Renderer->GetActors()->GetItemAsObject(1));
  const long long before = nprCountAbove(scene.Mask(), 0);
  second->SetPosition(-0.75, -0.75, -2.6);
  const long long behind = nprCountAbove(scene.Mask(), 0);
  second->VisibilityOff();
  const long long alone = nprCountAbove(scene.Mask(), 0);
  std::cout << "mask pixels: " << before << " with the small sphere in front, " << behind
            << " with it behind, " << alone << " without it\n";
  NPR_CHECK(behind == alone, "the sphere behind shows " << behind - alone << " pixels");
  return nprTestResult();
}
// ---- Where surfaces cross: a post through a plate ----
// The post's sides cross the plate's top face along a square (at 90 degrees): creases of no mesh,
// in the mask with IntersectionCurves on (the default), not with it off or under a crease angle
// above 90 degrees.
int MaskIntersections()
{
  MaskScene scene(400, 300);
  vtkNew<vtkCubeSource> plate;
  plate->SetXLength(2.0);
  plate->SetYLength(0.2);
  plate->SetZLength(2.0);
  vtkNew<vtkCubeSource> post;
  post->SetXLength(0.4);
  post->SetYLength(1.6);
  post->SetZLength(0.4);
  nprAddActor(scene.Renderer, plate->GetOutputPort());
  nprAddActor(scene.Renderer, post->GetOutputPort());
  vtkCamera* camera = scene.Camera();
  camera->SetPosition(2.5, 3.0, 4.0);
  camera->SetFocalPoint(0, 0, 0);
  camera->SetViewUp(0, 1, 0);
  camera->SetClippingRange(1.0, 20.0);
  scene.Reference->SilhouettesOff();
  scene.Reference->BoundariesOff();
  // The square's two edges that face the camera, sampled away from their ends (where the post's
  // and the plate's own creases come near).
  auto pixelsOnSquare = [&](vtkImageData* mask, int& samples)
  {
    int found = 0;
    samples = 0;
    for (int edge = 0; edge < 2; ++edge)
    {
      for (int i = 2; i <= 18; ++i)
      {
        const double s = -0.2 + 0.4 * i / 20.0;
        const Point point = edge == 0 ? Point{ 0.2, 0.1, s } : Point{ s, 0.1, 0.2 };
        const auto display = scene.Project(point);
        bool near = false;
        for (int dy = -1; dy <= 1; ++dy)
        {
          for (int dx = -1; dx <= 1; ++dx)
          {
            near = near ||
              nprPixel(mask, static_cast<int>(display[0]) + dx, static_cast<int>(display[1]) + dy) >
                0;
          }
        }
        found += near ? 1 : 0;
        ++samples;
      }
    }
    return found;
  };
  int samples = 0;
  const int on = pixelsOnSquare(scene.Mask(), samples);
  scene.Reference->IntersectionCurvesOff();
  const int off = pixelsOnSquare(scene.Mask(), samples);
  scene.Reference->IntersectionCurvesOn();
  scene.Reference->SetCreaseAngle(95.0);
  const int steep = pixelsOnSquare(scene.Mask(), samples);
  std::cout << "samples of the crossing square with a line pixel: " << on << " of " << samples
            << " (IntersectionCurves off: " << off << ", crease angle 95: " << steep << ")\n";
  NPR_CHECK(on == samples, "the crossing is missing from the mask");
  NPR_CHECK(off == 0 && steep == 0, "a crossing drawn where it should not be");
  return nprTestResult();
}
}

int main(int argc, char* argv[])
{
  const std::map<std::string, std::function<int()>> cases = {
    { "mask-cube", [] { return MaskCube(false); } },
    { "mask-cube-parallel", [] { return MaskCube(true); } },
    { "mask-occlusion", MaskOcclusion },
    { "mask-reuse", MaskReuse },
    { "mask-stability", Stability },
    { "mask-locator-groups", MaskLocatorGroups },
    { "mask-smooth-sphere", MaskSmoothSphere },
    { "mask-smooth-occlusion", MaskSmoothOcclusion },
    { "mask-intersections", MaskIntersections },
  };
  return nprRunTestCase(argc, argv, cases);
}
