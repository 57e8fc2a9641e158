// The edge-enhancement passes (vtkNPRPass, vtkNPRGBufferPass, vtkNPREdgePass), checked with
// numbers: line positions against analytically projected edges, no false lines, contours,
// compositing with translucency and layers, picking, reuse of unchanged frames, the G-buffer
// channels, anti-aliasing, every kind of actor, resizes and releases, and baseline images.
//
// usage: TestEdgePass CASE [DATA_DIR]   (CASE: see the table at the end of this file)
#include "nprTesting.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellData.h"
#include "vtkCompositeDataDisplayAttributes.h"
#include "vtkVersionMacros.h"
#if VTK_VERSION_NUMBER >= VTK_VERSION_CHECK(9, 3, 0)
#include "vtkCompositePolyDataMapper.h" // VTK 9.3 replaced Mapper2 with it (removed in 9.5)
using nprCompositeMapper = vtkCompositePolyDataMapper;
#else
#include "vtkCompositePolyDataMapper2.h"
using nprCompositeMapper = vtkCompositePolyDataMapper2;
#endif
#include "vtkConeSource.h"
#include "vtkCubeSource.h"
#include "vtkElevationFilter.h"
#include "vtkFloatArray.h"
#include "vtkGlyph3DMapper.h"
#include "vtkHardwareSelector.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkLightCollection.h"
#include "vtkMath.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNPREdgePass.h"
#include "vtkNPRGBufferPass.h"
#include "vtkNPRModelReader.h"
#include "vtkNPRPass.h"
#include "vtkNew.h"
#include "vtkOutputWindow.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkPolyDataNormals.h"
#include "vtkPropPicker.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSelection.h"
#include "vtkSelectionNode.h"
#include "vtkSphereSource.h"
#include "vtkTexture.h"
#include "vtkTextureObject.h"
#include "vtkTextureMapToSphere.h"
#include "vtkTransform.h"
#include "vtkTransformPolyDataFilter.h"
#include "vtkUnsignedCharArray.h"
#include "vtkWorldPointPicker.h"
#include "vtkColorTransferFunction.h"
#include "vtkGPUVolumeRayCastMapper.h"
#include "vtkPiecewiseFunction.h"
#include "vtkTextActor.h"
#include "vtkTextProperty.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace
{
struct Scene : nprPassScene
{
  using nprPassScene::nprPassScene;
  // The line coverage alone: white lines on black.
  vtkSmartPointer<vtkImageData> Mask()
  {
    this->Edges()->CoverageOnlyOn();
    auto image = this->Render();
    this->Edges()->CoverageOnlyOff();
    if (const char* dump = std::getenv("NPR_TEST_DUMP")) // NPR_TEST_DUMP=prefix: keep the masks
    {
      static int count = 0;
      nprWritePNG(image, std::string(dump) + std::to_string(count++) + ".png");
    }
    return image;
  }
  // Window coordinates (pixel centres at +0.5) of a world point.
  void Project(const double world[3], double display[2])
  {
    this->Renderer->SetWorldPoint(world[0], world[1], world[2], 1.0);
    this->Renderer->WorldToDisplay();
    const double* point = this->Renderer->GetDisplayPoint();
    display[0] = point[0];
    display[1] = point[1];
  }
};

vtkSmartPointer<vtkActor> AddCube(vtkRenderer* renderer, const double center[3], double size = 1.0)
{
  vtkNew<vtkCubeSource> cube;
  cube->SetCenter(center[0], center[1], center[2]);
  cube->SetXLength(size);
  cube->SetYLength(size);
  cube->SetZLength(size);
  const double grey[3] = { 0.8, 0.8, 0.8 };
  return nprAddActor(renderer, cube->GetOutputPort(), grey);
}

long long CountAbove(vtkImageData* image, int threshold)
{
  const int* dims = image->GetDimensions();
  long long count = 0;
  for (int y = 0; y < dims[1]; ++y)
  {
    for (int x = 0; x < dims[0]; ++x)
    {
      count += nprPixel(image, x, y) > threshold ? 1 : 0;
    }
  }
  return count;
}

double SegmentDistance(const double p[2], const double a[2], const double b[2])
{
  const double abx = b[0] - a[0], aby = b[1] - a[1];
  const double length2 = abx * abx + aby * aby;
  double t = length2 > 0 ? ((p[0] - a[0]) * abx + (p[1] - a[1]) * aby) / length2 : 0.0;
  t = std::min(1.0, std::max(0.0, t));
  const double dx = p[0] - (a[0] + t * abx), dy = p[1] - (a[1] + t * aby);
  return std::sqrt(dx * dx + dy * dy);
}

// ---- A unit cube from a known camera: line pixels on its visible edges and nowhere else ----
int CubeEdges(bool parallel)
{
  Scene scene(400, 400);
  const double origin[3] = { 0, 0, 0 };
  AddCube(scene.Renderer, origin);
  vtkCamera* camera = scene.Camera();
  const double eye[3] = { 2.2, 1.7, 2.9 };
  camera->SetPosition(eye[0], eye[1], eye[2]);
  camera->SetFocalPoint(0, 0, 0);
  camera->SetViewUp(0, 1, 0);
  camera->SetViewAngle(30);
  camera->SetParallelProjection(parallel);
  camera->SetParallelScale(1.0);
  camera->SetClippingRange(1.0, 10.0);
  scene.Edges()->SetLineWidth(1.0);
  scene.Edges()->AntiAliasingOff();
  auto mask = scene.Mask();

  // Visible edges of a convex box: those with at least one face turned towards the eye.
  const double h = 0.5;
  const int normals[6][3] = { { 1, 0, 0 }, { -1, 0, 0 }, { 0, 1, 0 }, { 0, -1, 0 }, { 0, 0, 1 },
    { 0, 0, -1 } };
  auto facing = [&](int face) {
    double toEye[3];
    for (int i = 0; i < 3; ++i)
    {
      // For a parallel camera every point sees the eye along the direction of projection.
      toEye[i] = parallel ? eye[i] : eye[i] - h * normals[face][i];
    }
    return normals[face][0] * toEye[0] + normals[face][1] * toEye[1] + normals[face][2] * toEye[2] >
      0;
  };
  std::vector<std::pair<std::array<double, 2>, std::array<double, 2>>> visible;
  for (int a = 0; a < 8; ++a)
  {
    for (int axis = 0; axis < 3; ++axis)
    {
      if (a & (1 << axis))
      {
        continue;
      }
      const int b = a | (1 << axis);
      // The two faces of the edge: the other two axes at the edge's sides.
      bool seen = false;
      for (int other = 0; other < 3; ++other)
      {
        if (other != axis)
        {
          seen = seen || facing(2 * other + ((a >> other) & 1 ? 0 : 1));
        }
      }
      if (!seen)
      {
        continue;
      }
      double pa[3], pb[3];
      for (int i = 0; i < 3; ++i)
      {
        pa[i] = (a >> i) & 1 ? h : -h;
        pb[i] = (b >> i) & 1 ? h : -h;
      }
      std::array<double, 2> da, db;
      scene.Project(pa, da.data());
      scene.Project(pb, db.data());
      visible.push_back({ da, db });
    }
  }
  NPR_CHECK(visible.size() == 9, "a cube seen from a corner shows 9 edges, got " << visible.size());

  double worst = 0.0;
  long long linePixels = 0, falsePixels = 0;
  for (int y = 0; y < 400; ++y)
  {
    for (int x = 0; x < 400; ++x)
    {
      const double p[2] = { x + 0.5, y + 0.5 };
      double nearest = 1e9;
      for (const auto& edge : visible)
      {
        nearest = std::min(nearest, SegmentDistance(p, edge.first.data(), edge.second.data()));
      }
      if (nprPixel(mask, x, y) > 127)
      {
        ++linePixels;
        worst = std::max(worst, nearest);
      }
      if (nearest > 2.0 && nprPixel(mask, x, y) > 0)
      {
        ++falsePixels;
      }
    }
  }
  // Recall: every visible edge is drawn along its length.
  long long samples = 0, found = 0;
  for (const auto& edge : visible)
  {
    const double dx = edge.second[0] - edge.first[0], dy = edge.second[1] - edge.first[1];
    const int steps = static_cast<int>(std::sqrt(dx * dx + dy * dy));
    for (int s = 2; s < steps - 2; ++s)
    {
      const double px = edge.first[0] + dx * s / steps, py = edge.first[1] + dy * s / steps;
      bool hit = false;
      for (int oy = -2; oy <= 2 && !hit; ++oy)
      {
        for (int ox = -2; ox <= 2 && !hit; ++ox)
        {
          const int x = static_cast<int>(std::floor(px)) + ox, y = static_cast<int>(std::floor(py)) + oy;
          const double c[2] = { x + 0.5, y + 0.5 };
          const double d = std::hypot(c[0] - px, c[1] - py);
          hit = d <= 1.0 && nprPixel(mask, x, y) > 127;
        }
      }
      ++samples;
      found += hit ? 1 : 0;
    }
  }
  const double recall = samples ? static_cast<double>(found) / samples : 0.0;
  std::cout << (parallel ? "parallel" : "perspective") << ": " << linePixels
            << " line pixels, farthest " << worst << " px from an edge, " << falsePixels
            << " pixels lit inside faces, recall " << recall << "\n";
  NPR_CHECK(linePixels > 500, "too few line pixels: " << linePixels);
  NPR_CHECK(worst <= 1.0, "a line pixel lies " << worst << " px from every visible edge");
  NPR_CHECK(falsePixels == 0, falsePixels << " line pixels inside the faces");
  NPR_CHECK(recall >= 0.98, "visible edges drawn along only " << recall << " of their length");
  return nprTestResult();
}

// ---- A plane at a grazing angle: its far border is a silhouette, its inside has no line ----
int GrazingPlane()
{
  Scene scene(400, 300);
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-50, 0, -50);
  plane->SetPoint1(50, 0, -50);
  plane->SetPoint2(-50, 0, 50);
  plane->SetResolution(20, 20);
  const double grey[3] = { 0.7, 0.7, 0.7 };
  nprAddActor(scene.Renderer, plane->GetOutputPort(), grey);
  vtkCamera* camera = scene.Camera();
  camera->SetPosition(0, 0.3, 30);
  camera->SetFocalPoint(0, -0.5, -50);
  camera->SetViewUp(0, 1, 0);
  camera->SetViewAngle(30);
  camera->SetClippingRange(0.1, 200);
  auto mask = scene.Mask();
  const double farEdge[3] = { 0, 0, -50 };
  double horizon[2];
  scene.Project(farEdge, horizon);
  long long far = 0, inside = 0;
  for (int y = 0; y < 300; ++y)
  {
    for (int x = 0; x < 400; ++x)
    {
      if (nprPixel(mask, x, y) > 0)
      {
        (std::abs(y + 0.5 - horizon[1]) <= 3.0 ? far : inside)++;
      }
    }
  }
  std::cout << "far border row " << horizon[1] << ": " << far << " line pixels there, " << inside
            << " elsewhere\n";
  NPR_CHECK(far > 300, "the far border should be a silhouette line: " << far << " pixels");
  NPR_CHECK(inside == 0, inside << " false line pixels on the grazing plane");
  return nprTestResult();
}

// ---- Two cubes touching face to face, seen straight on: only the id contour separates them ----
int TouchingObjects()
{
  Scene scene(400, 300);
  const double left[3] = { -0.5, 0, 0 }, right[3] = { 0.5, 0, 0 };
  AddCube(scene.Renderer, left);
  AddCube(scene.Renderer, right);
  vtkCamera* camera = scene.Camera();
  camera->SetPosition(0, 0, 5);
  camera->SetFocalPoint(0, 0, 0);
  camera->SetViewUp(0, 1, 0);
  camera->SetClippingRange(1, 10);
  const double top[3] = { 0, 0.5, 0.5 }, bottom[3] = { 0, -0.5, 0.5 };
  double t[2], b[2];
  scene.Project(top, t);
  scene.Project(bottom, b);
  auto countOnSeam = [&](vtkImageData* mask) {
    long long count = 0, rows = 0;
    for (int y = static_cast<int>(b[1]) + 4; y < static_cast<int>(t[1]) - 4; ++y)
    {
      bool row = false;
      for (int x = static_cast<int>(t[0]) - 2; x <= static_cast<int>(t[0]) + 2; ++x)
      {
        count += nprPixel(mask, x, y) > 127 ? 1 : 0;
        row = row || nprPixel(mask, x, y) > 127;
      }
      rows += row ? 1 : 0;
    }
    return std::make_pair(count, rows);
  };
  const int seamRows = static_cast<int>(t[1]) - static_cast<int>(b[1]) - 8;

  auto with = countOnSeam(scene.Mask());
  NPR_CHECK(scene.GBuffer()->GetWritesObjectIds(), "two props and contours: ids expected");
  scene.Edges()->ContoursOff();
  auto without = countOnSeam(scene.Mask());
  std::cout << "seam: contour on " << with.second << "/" << seamRows << " rows, off "
            << without.first << " pixels\n";
  NPR_CHECK(with.second >= seamRows, "the contour misses rows of the seam");
  NPR_CHECK(without.first == 0, "silhouettes or creases fired on a flat seam");

  // Both sides: a line twice as wide as inside or outside alone.
  scene.Edges()->ContoursOn();
  scene.Edges()->SetLineWidth(1.0);
  scene.Edges()->AntiAliasingOff();
  scene.Edges()->SetContourSideToInside();
  const long long inside = countOnSeam(scene.Mask()).first;
  scene.Edges()->SetContourSideToBoth();
  const long long both = countOnSeam(scene.Mask()).first;
  std::cout << "contour pixels on the seam: inside " << inside << ", both " << both << "\n";
  NPR_CHECK(both >= 2 * inside - 4 && inside > 0, "both sides should double the seam's line");
  return nprTestResult();
}

// ---- A translucent plane in front tints the lines; behind the surface it does not ----
int Translucency()
{
  Scene scene(400, 300);
  const double origin[3] = { 0, 0, 0 };
  AddCube(scene.Renderer, origin);
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-2, -2, 1);
  plane->SetPoint1(0, -2, 1);
  plane->SetPoint2(-2, 2, 1);
  const double red[3] = { 1, 0, 0 };
  vtkSmartPointer<vtkActor> glass = nprAddActor(scene.Renderer, plane->GetOutputPort(), red);
  glass->GetProperty()->SetOpacity(0.5);
  glass->GetProperty()->LightingOff();
  vtkCamera* camera = scene.Camera();
  camera->SetPosition(0, 0, 5);
  camera->SetFocalPoint(0, 0, 0);
  camera->SetViewUp(0, 1, 0);
  camera->SetClippingRange(1, 10);
  scene.Edges()->SetLineWidth(2.0);

  auto lineColumns = [&](vtkImageData* mask, int y, int& first, int& last) {
    first = last = -1;
    for (int x = 0; x < 400; ++x)
    {
      if (nprPixel(mask, x, y) == 255)
      {
        first = first < 0 ? x : first;
        last = x;
      }
    }
  };
  for (int depthPeeling = 0; depthPeeling < 2; ++depthPeeling)
  {
    scene.Renderer->SetUseDepthPeeling(depthPeeling);
    glass->SetPosition(0, 0, 0);
    auto mask = scene.Mask();
    auto image = scene.Render();
    int first, last;
    lineColumns(mask, 150, first, last);
    NPR_CHECK(first > 0 && last > first, "no silhouette found on the middle row");
    const int r = nprPixel(image, first, 150, 0), g = nprPixel(image, first, 150, 1);
    const int rr = nprPixel(image, last, 150, 0), rg = nprPixel(image, last, 150, 1);
    std::cout << "peeling " << depthPeeling << ": left line under the glass (" << r << "," << g
              << "), right line (" << rr << "," << rg << ")\n";
    NPR_CHECK(r > 90 && r < 200 && g < 40, "the line under the glass should be tinted red");
    NPR_CHECK(rr < 60 && rg < 60, "the line beside the glass should stay black");
    // Behind the cube, the glass covers the background only.
    glass->SetPosition(0, 0, -2);
    image = scene.Render();
    const int br = nprPixel(image, first, 150, 0);
    NPR_CHECK(br < 60, "glass behind the cube tinted its line: red " << br);
    NPR_CHECK(nprPixel(image, 80, 150, 0) > 200 && nprPixel(image, 80, 150, 1) < 200,
      "the glass behind the cube should still tint the background");
  }
  return nprTestResult();
}

// ---- A renderer on a higher layer is depth-tested against the sprite ----
int Layers()
{
  Scene scene(400, 300);
  const double origin[3] = { 0, 0, 0 };
  AddCube(scene.Renderer, origin);
  vtkCamera* camera = scene.Camera();
  camera->SetPosition(0, 0, 5);
  camera->SetFocalPoint(0, 0, 0);
  camera->SetViewUp(0, 1, 0);
  camera->SetClippingRange(1, 10);

  vtkNew<vtkRenderer> overlay;
  overlay->SetLayer(1);
  overlay->PreserveDepthBufferOn();
  overlay->SetActiveCamera(camera);
  overlay->InteractiveOff();
  scene.Window->SetNumberOfLayers(2);
  scene.Window->AddRenderer(overlay);
  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(0.6, 0, -1.5);
  sphere->SetRadius(0.6);
  sphere->SetThetaResolution(32);
  sphere->SetPhiResolution(16);
  const double red[3] = { 1, 0, 0 };
  vtkSmartPointer<vtkActor> ball = nprAddActor(overlay, sphere->GetOutputPort(), red);
  ball->GetProperty()->LightingOff();
  auto image = scene.Render();

  const double corner0[3] = { -0.5, -0.5, 0.5 }, corner1[3] = { 0.5, 0.5, 0.5 };
  double a[2], b[2];
  scene.Project(corner0, a);
  scene.Project(corner1, b);
  long long redInside = 0, redOutside = 0;
  for (int y = 0; y < 300; ++y)
  {
    for (int x = 0; x < 400; ++x)
    {
      const bool red = nprPixel(image, x, y, 0) > 200 && nprPixel(image, x, y, 1) < 60;
      const bool inside = x > a[0] + 3 && x < b[0] - 3 && y > a[1] + 3 && y < b[1] - 3;
      (inside ? redInside : redOutside) += red ? 1 : 0;
    }
  }
  std::cout << "red pixels of the layer-1 sphere: " << redInside << " over the cube, " << redOutside
            << " beside it\n";
  NPR_CHECK(redInside == 0, "the sphere behind the cube shows through it");
  NPR_CHECK(redOutside > 100, "the part of the sphere beside the cube should be drawn");
  return nprTestResult();
}

// ---- A volume behind the surface is hidden by it; a 2D actor is drawn over everything ----
int VolumeAndOverlay()
{
  Scene scene(400, 300);
  const double origin[3] = { 0, 0, 0 };
  AddCube(scene.Renderer, origin);
  vtkNew<vtkImageData> block;
  block->SetDimensions(16, 16, 16);
  block->SetSpacing(0.2, 0.1, 0.1);
  block->SetOrigin(-0.9, -0.75, -3.0); // x -0.9..2.1, behind the cube
  block->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
  std::fill_n(static_cast<unsigned char*>(block->GetScalarPointer()), 16 * 16 * 16, 200);
  vtkNew<vtkGPUVolumeRayCastMapper> volumeMapper;
  volumeMapper->SetInputData(block);
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(0, 1, 0, 0);
  color->AddRGBPoint(255, 1, 0, 0);
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0, 1.0);
  opacity->AddPoint(255, 1.0);
  vtkNew<vtkVolume> volume;
  volume->SetMapper(volumeMapper);
  volume->GetProperty()->SetColor(color);
  volume->GetProperty()->SetScalarOpacity(opacity);
  volume->GetProperty()->ShadeOff();
  scene.Renderer->AddVolume(volume);
  vtkNew<vtkTextActor> label;
  label->SetInput("NPR");
  label->GetTextProperty()->SetFontSize(40);
  label->GetTextProperty()->SetColor(0, 0, 1);
  label->SetDisplayPosition(10, 10);
  scene.Renderer->AddActor2D(label);
  vtkCamera* camera = scene.Camera();
  camera->SetPosition(0, 0, 5);
  camera->SetFocalPoint(0, 0, 0);
  camera->SetViewUp(0, 1, 0);
  camera->SetClippingRange(1, 10);
  auto image = scene.Render();
  const double corner0[3] = { -0.5, -0.5, 0.5 }, corner1[3] = { 0.5, 0.5, 0.5 };
  double a[2], b[2];
  scene.Project(corner0, a);
  scene.Project(corner1, b);
  long long redOver = 0, redBeside = 0, blue = 0;
  for (int y = 0; y < 300; ++y)
  {
    for (int x = 0; x < 400; ++x)
    {
      const int r = nprPixel(image, x, y, 0), g = nprPixel(image, x, y, 1), bl = nprPixel(image, x, y, 2);
      const bool inside = x > a[0] + 3 && x < b[0] - 3 && y > a[1] + 3 && y < b[1] - 3;
      if (r > 150 && g < 80 && bl < 80)
      {
        (inside ? redOver : redBeside)++;
      }
      blue += (x < 150 && y < 70 && bl > 150 && r < 80) ? 1 : 0;
    }
  }
  std::cout << "volume: " << redOver << " red pixels over the cube, " << redBeside
            << " beside it; text: " << blue << " blue pixels\n";
  NPR_CHECK(redOver == 0, "the volume behind the cube shows through it");
  NPR_CHECK(redBeside > 1000, "the volume beside the cube should be drawn");
  NPR_CHECK(blue > 100, "the 2D text actor should be drawn");
  return nprTestResult();
}

// ---- Picking with the pass installed ----
int Picking()
{
  Scene scene(400, 300);
  const double left[3] = { -1, 0, 0 }, right[3] = { 1, 0, 0 };
  vtkSmartPointer<vtkActor> a = AddCube(scene.Renderer, left);
  vtkSmartPointer<vtkActor> b = AddCube(scene.Renderer, right);
  vtkCamera* camera = scene.Camera();
  camera->SetPosition(0, 0, 5);
  camera->SetFocalPoint(0, 0, 0);
  camera->SetViewUp(0, 1, 0);
  camera->SetClippingRange(1, 10);
  scene.Render();
  const double frontA[3] = { -1, 0, 0.5 }, frontB[3] = { 1, 0, 0.5 };
  double pa[2], pb[2];
  scene.Project(frontA, pa);
  scene.Project(frontB, pb);

  vtkNew<vtkPropPicker> propPicker;
  propPicker->Pick(pa[0], pa[1], 0, scene.Renderer);
  NPR_CHECK(propPicker->GetViewProp() == a, "vtkPropPicker missed the left cube");
  propPicker->Pick(pb[0], pb[1], 0, scene.Renderer);
  NPR_CHECK(propPicker->GetViewProp() == b, "vtkPropPicker missed the right cube");
  propPicker->Pick(5, 5, 0, scene.Renderer);
  NPR_CHECK(propPicker->GetViewProp() == nullptr, "vtkPropPicker picked the background");

  vtkNew<vtkWorldPointPicker> worldPicker;
  worldPicker->Pick(pa[0], pa[1], 0, scene.Renderer);
  const double* world = worldPicker->GetPickPosition();
  std::cout << "world point on the left cube's front face: " << world[0] << " " << world[1] << " "
            << world[2] << "\n";
  NPR_CHECK(std::abs(world[2] - 0.5) < 0.01 && std::abs(world[0] + 1) < 0.02,
    "vtkWorldPointPicker should find the front face at z = 0.5");

  vtkNew<vtkHardwareSelector> selector;
  selector->SetRenderer(scene.Renderer);
  selector->SetArea(0, 0, 399, 299);
  selector->SetFieldAssociation(vtkDataObject::FIELD_ASSOCIATION_CELLS);
  vtkSmartPointer<vtkSelection> selection = vtkSmartPointer<vtkSelection>::Take(selector->Select());
  bool foundA = false, foundB = false;
  for (unsigned int i = 0; selection && i < selection->GetNumberOfNodes(); ++i)
  {
    vtkObjectBase* prop = selection->GetNode(i)->GetProperties()->Get(vtkSelectionNode::PROP());
    foundA = foundA || prop == a;
    foundB = foundB || prop == b;
  }
  NPR_CHECK(foundA && foundB, "vtkHardwareSelector should select both cubes");

  // Lines are still drawn after the selection renders.
  NPR_CHECK(CountAbove(scene.Mask(), 127) > 400, "no lines after picking");
  return nprTestResult();
}

// ---- Unchanged frames reuse the G-buffer and line image; every kind of change redraws ----
int Reuse()
{
  Scene scene(300, 200);
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(32);
  sphere->SetPhiResolution(16);
  const double grey[3] = { 0.8, 0.8, 0.8 };
  vtkSmartPointer<vtkActor> actor = nprAddActor(scene.Renderer, sphere->GetOutputPort(), grey);
  vtkNPRGBufferPass* gbuffer = scene.GBuffer();
  auto first = scene.Render();
  NPR_CHECK(gbuffer->GetNumberOfGeometryDraws() == 1, "first frame: one draw");
  auto second = scene.Render();
  NPR_CHECK(gbuffer->GetNumberOfGeometryDraws() == 1,
    "nothing changed: no redraw, got " << gbuffer->GetNumberOfGeometryDraws());
  NPR_CHECK(scene.Edges()->GetNumberOfLineImageUpdates() == 1, "line image recomputed");
  const nprImageDifference same = nprCompareImages(second, first, { 0, 0.0 });
  NPR_CHECK(same.DifferingPixels == 0, "a reused frame differs from the drawn one");

  int expected = 1;
  const std::pair<const char*, std::function<void()>> changes[] = {
    { "camera", [&] { scene.Camera()->Azimuth(10); } },
    { "actor colour", [&] { actor->GetProperty()->SetColor(0.5, 0.6, 0.7); } },
    { "actor position", [&] { actor->SetPosition(0.1, 0, 0); } },
    { "source", [&] { sphere->SetRadius(0.4); } },
    { "visibility of a new actor",
      [&] { nprAddActor(scene.Renderer, sphere->GetOutputPort(), grey)->SetPosition(1, 0, 0); } },
    { "light", [&] { scene.Renderer->GetLights()->GetItemAsObject(0)->Modified(); } },
    { "size", [&] { scene.Window->SetSize(320, 200); } },
    { "line types", [&] { scene.Edges()->CreasesOff(); } },
  };
  for (const auto& change : changes)
  {
    change.second();
    scene.Render();
    ++expected;
    NPR_CHECK(gbuffer->GetNumberOfGeometryDraws() == expected,
      "a change of " << change.first << " did not redraw");
    scene.Render();
    NPR_CHECK(gbuffer->GetNumberOfGeometryDraws() == expected,
      "after a change of " << change.first << ", the next unchanged frame redrew");
  }
  // A line setting only recomputes the lines.
  const int updates = scene.Edges()->GetNumberOfLineImageUpdates();
  scene.Edges()->SetSilhouetteThreshold(0.01);
  scene.Render();
  NPR_CHECK(gbuffer->GetNumberOfGeometryDraws() == expected, "a line setting redrew geometry");
  NPR_CHECK(scene.Edges()->GetNumberOfLineImageUpdates() == updates + 1, "line image not updated");
  // And the cache can be turned off.
  gbuffer->ReuseUnchangedFramesOff();
  scene.Render();
  NPR_CHECK(gbuffer->GetNumberOfGeometryDraws() == expected + 1, "ReuseUnchangedFramesOff ignored");
  return nprTestResult();
}

// ---- Only the channels the lines need; nothing for an empty renderer ----
int Channels()
{
  Scene scene(200, 150);
  vtkNPRGBufferPass* gbuffer = scene.GBuffer();
  // Empty renderer.
  auto empty = scene.Render();
  NPR_CHECK(gbuffer->GetNumberOfGeometryDraws() == 0, "an empty renderer drew a G-buffer");
  NPR_CHECK(!gbuffer->GetHasContent() && !gbuffer->GetGeometryTexture() &&
      !gbuffer->GetColorTexture(),
    "an empty renderer allocated G-buffer textures");
  NPR_CHECK(nprPixel(empty, 100, 75, 0) == 255, "the empty renderer's background is not white");

  const double origin[3] = { 0, 0, 0 }, beside[3] = { 1.5, 0, 0 };
  AddCube(scene.Renderer, origin);
  scene.Renderer->ResetCamera();
  struct Case
  {
    bool Creases, Contours, TwoProps;
    bool Normals, Ids;
    int Components;
  };
  const Case cases[] = {
    { true, true, false, true, false, 2 },   // one prop: coverage replaces ids
    { false, true, false, false, false, 1 }, // depth only
    { false, false, false, false, false, 1 },
    { true, false, true, true, false, 2 },   // contours off: no ids
    { false, true, true, false, true, 4 },   // ids, no normals
    { true, true, true, true, true, 4 },
  };
  vtkSmartPointer<vtkActor> second;
  for (const Case& c : cases)
  {
    if (c.TwoProps && !second)
    {
      second = AddCube(scene.Renderer, beside);
      scene.Renderer->ResetCamera();
    }
    scene.Edges()->SetCreases(c.Creases);
    scene.Edges()->SetContours(c.Contours);
    scene.Render();
    vtkTextureObject* geometry = gbuffer->GetGeometryTexture();
    NPR_CHECK(gbuffer->GetWritesNormals() == c.Normals,
      "creases " << c.Creases << ": normals written " << gbuffer->GetWritesNormals());
    NPR_CHECK(gbuffer->GetWritesObjectIds() == c.Ids,
      "contours " << c.Contours << ", two props " << c.TwoProps << ": ids written "
                  << gbuffer->GetWritesObjectIds());
    NPR_CHECK(geometry && geometry->GetComponents() == c.Components,
      "geometry attachment has " << (geometry ? geometry->GetComponents() : 0)
                                 << " components, expected " << c.Components);
  }
  // The shaded style makes no G-buffer at all.
  const int draws = gbuffer->GetNumberOfGeometryDraws();
  scene.Pass->SetStyleToShaded();
  scene.Camera()->Azimuth(5);
  scene.Render();
  NPR_CHECK(gbuffer->GetNumberOfGeometryDraws() == draws, "the shaded style drew a G-buffer");
  return nprTestResult();
}

// ---- Anti-aliasing: intermediate coverage along slanted lines, and less staircase ----
int AntiAliasing()
{
  Scene scene(400, 300);
  vtkNew<vtkCubeSource> cube;
  cube->SetXLength(2);
  cube->SetYLength(1);
  vtkNew<vtkTransform> tilt;
  tilt->RotateZ(12);
  vtkNew<vtkTransformPolyDataFilter> tilted;
  tilted->SetTransform(tilt);
  tilted->SetInputConnection(cube->GetOutputPort());
  nprAddActor(scene.Renderer, tilted->GetOutputPort());
  vtkCamera* camera = scene.Camera();
  camera->SetPosition(0, 0, 5);
  camera->SetFocalPoint(0, 0, 0);
  camera->SetViewUp(0, 1, 0);
  camera->SetClippingRange(1, 10);
  scene.Edges()->SetLineWidth(1.5);

  // The top edge runs from (-1, 0.5) to (1, 0.5) turned by 12 degrees; in the middle columns
  // the coverage-weighted row of the line should follow a straight line.
  const double ends[2][3] = { { -1, 0.5, 0.5 }, { 1, 0.5, 0.5 } };
  double e0[2], e1[2], rotated[2][3];
  for (int i = 0; i < 2; ++i)
  {
    tilt->TransformPoint(ends[i], rotated[i]);
  }
  scene.Project(rotated[0], e0);
  scene.Project(rotated[1], e1);
  auto measure = [&](vtkImageData* mask, long long& intermediate, long long& lit) {
    intermediate = lit = 0;
    std::vector<double> xs, ys;
    for (int x = static_cast<int>(e0[0]) + 20; x < static_cast<int>(e1[0]) - 20; ++x)
    {
      const double yEdge = e0[1] + (x + 0.5 - e0[0]) * (e1[1] - e0[1]) / (e1[0] - e0[0]);
      double sum = 0, weighted = 0;
      for (int y = static_cast<int>(yEdge) - 4; y <= static_cast<int>(yEdge) + 4; ++y)
      {
        const int v = nprPixel(mask, x, y);
        lit += v > 0 ? 1 : 0;
        intermediate += v > 25 && v < 230 ? 1 : 0;
        sum += v;
        weighted += v * (y + 0.5);
      }
      if (sum > 0)
      {
        xs.push_back(x + 0.5);
        ys.push_back(weighted / sum);
      }
    }
    // Residual of the line's centre from its least-squares straight line: the staircase.
    const double n = static_cast<double>(xs.size());
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (size_t i = 0; i < xs.size(); ++i)
    {
      sx += xs[i];
      sy += ys[i];
      sxx += xs[i] * xs[i];
      sxy += xs[i] * ys[i];
    }
    const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
    const double offset = (sy - slope * sx) / n;
    double residual = 0;
    for (size_t i = 0; i < xs.size(); ++i)
    {
      const double r = ys[i] - (slope * xs[i] + offset);
      residual += r * r;
    }
    return std::sqrt(residual / std::max(1.0, n));
  };
  long long intermediateOn, litOn, intermediateOff, litOff;
  const double staircaseOn = measure(scene.Mask(), intermediateOn, litOn);
  scene.Edges()->AntiAliasingOff();
  const double staircaseOff = measure(scene.Mask(), intermediateOff, litOff);
  std::cout << "anti-aliasing on: " << intermediateOn << " of " << litOn
            << " line pixels partly covered, centre wobble " << staircaseOn
            << " px; off: " << intermediateOff << " of " << litOff << ", wobble " << staircaseOff
            << " px\n";
  NPR_CHECK(intermediateOn > litOn / 3, "too few partly covered pixels with anti-aliasing");
  NPR_CHECK(intermediateOff == 0, "partly covered pixels without anti-aliasing");
  // The G-buffer has one sample per pixel: the long steps of a shallow line are smoothed, not
  // removed (see Documentation/edges.md).
  NPR_CHECK(staircaseOn < 0.85 * staircaseOff, "anti-aliasing should straighten the staircase");

  // The width is honoured: a width-6 line is about 4 times as heavy as a width-1.5 line.
  scene.Edges()->AntiAliasingOn();
  auto coverageSum = [&](vtkImageData* mask) {
    double sum = 0;
    for (int x = static_cast<int>(e0[0]) + 20; x < static_cast<int>(e1[0]) - 20; ++x)
    {
      for (int y = 0; y < 300; ++y)
      {
        const double yEdge = e0[1] + (x + 0.5 - e0[0]) * (e1[1] - e0[1]) / (e1[0] - e0[0]);
        sum += std::abs(y + 0.5 - yEdge) < 8 ? nprPixel(mask, x, y) / 255.0 : 0.0;
      }
    }
    return sum;
  };
  const double thin = coverageSum(scene.Mask());
  scene.Edges()->SetLineWidth(6.0);
  const double thick = coverageSum(scene.Mask());
  std::cout << "coverage across the edge: width 1.5 -> " << thin << ", width 6 -> " << thick << "\n";
  NPR_CHECK(thick > 3.0 * thin && thick < 5.0 * thin, "line width not honoured");
  // Widths are at 72 DPI: a window at 144 DPI draws them twice as wide.
  scene.Edges()->SetLineWidth(1.5);
  scene.Window->SetDPI(144);
  const double doubled = coverageSum(scene.Mask());
  scene.Window->SetDPI(72);
  std::cout << "width 1.5 at 144 DPI -> " << doubled << "\n";
  NPR_CHECK(doubled > 1.6 * thin && doubled < 2.4 * thin, "the DPI scale is not applied");
  return nprTestResult();
}

// ---- Every kind of opaque actor: lines appear, nothing is reported, nothing crashes ----
int ActorKinds()
{
  struct Kind
  {
    const char* Name;
    std::function<vtkSmartPointer<vtkProp>()> Make;
  };
  auto sphereData = [](bool pointNormals) {
    vtkNew<vtkSphereSource> sphere;
    sphere->SetThetaResolution(24);
    sphere->SetPhiResolution(12);
    sphere->Update();
    auto data = vtkSmartPointer<vtkPolyData>::New();
    data->DeepCopy(sphere->GetOutput());
    if (!pointNormals)
    {
      data->GetPointData()->SetNormals(nullptr);
    }
    return data;
  };
  auto actorFor = [](vtkPolyData* data) {
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputData(data);
    auto actor = vtkSmartPointer<vtkActor>::New();
    actor->SetMapper(mapper);
    return actor;
  };
  const Kind kinds[] = {
    { "point normals", [&] { return actorFor(sphereData(true)); } },
    { "cell normals only",
      [&] {
        vtkNew<vtkPolyDataNormals> normals;
        normals->SetInputData(sphereData(false));
        normals->ComputePointNormalsOff();
        normals->ComputeCellNormalsOn();
        normals->Update();
        return actorFor(normals->GetOutput());
      } },
    { "no normals", [&] { return actorFor(sphereData(false)); } },
    { "flat",
      [&] {
        auto actor = actorFor(sphereData(true));
        actor->GetProperty()->SetInterpolationToFlat();
        return actor;
      } },
    { "unlit",
      [&] {
        auto actor = actorFor(sphereData(true));
        actor->GetProperty()->LightingOff();
        return actor;
      } },
    { "zero-length normals",
      [&] {
        auto data = sphereData(false);
        vtkNew<vtkFloatArray> zero;
        zero->SetNumberOfComponents(3);
        zero->SetNumberOfTuples(data->GetNumberOfPoints());
        zero->Fill(0.0);
        zero->SetName("Normals");
        data->GetPointData()->SetNormals(zero);
        return actorFor(data);
      } },
    { "scalar colours",
      [&] {
        vtkNew<vtkElevationFilter> elevation;
        elevation->SetInputData(sphereData(true));
        elevation->SetLowPoint(0, -0.5, 0);
        elevation->SetHighPoint(0, 0.5, 0);
        elevation->Update();
        auto data = vtkSmartPointer<vtkPolyData>::New();
        data->ShallowCopy(elevation->GetOutput());
        return actorFor(data);
      } },
    { "textured",
      [&] {
        vtkNew<vtkTextureMapToSphere> map;
        map->SetInputData(sphereData(true));
        map->Update();
        auto data = vtkSmartPointer<vtkPolyData>::New();
        data->ShallowCopy(map->GetOutput());
        auto actor = actorFor(data);
        vtkNew<vtkImageData> checker;
        checker->SetDimensions(8, 8, 1);
        checker->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
        for (int y = 0; y < 8; ++y)
        {
          for (int x = 0; x < 8; ++x)
          {
            for (int c = 0; c < 3; ++c)
            {
              checker->SetScalarComponentFromDouble(x, y, 0, c, (x + y) % 2 ? 230 : 60);
            }
          }
        }
        vtkNew<vtkTexture> texture;
        texture->SetInputData(checker);
        actor->SetTexture(texture);
        return actor;
      } },
    { "wireframe lines",
      [&] {
        auto actor = actorFor(sphereData(true));
        actor->GetProperty()->SetRepresentationToWireframe();
        actor->GetProperty()->SetLineWidth(2);
        return actor;
      } },
    { "points",
      [&] {
        auto actor = actorFor(sphereData(true));
        actor->GetProperty()->SetRepresentationToPoints();
        actor->GetProperty()->SetPointSize(6);
        return actor;
      } },
    { "composite (multiblock)",
      [&] {
        vtkNew<vtkMultiBlockDataSet> blocks;
        blocks->SetNumberOfBlocks(2);
        auto left = sphereData(true);
        auto right = sphereData(true);
        vtkNew<vtkTransform> shift;
        shift->Translate(0.8, 0, 0);
        vtkNew<vtkTransformPolyDataFilter> moved;
        moved->SetTransform(shift);
        moved->SetInputData(right);
        moved->Update();
        blocks->SetBlock(0, left);
        blocks->SetBlock(1, moved->GetOutput());
        vtkNew<nprCompositeMapper> mapper;
        mapper->SetInputDataObject(blocks);
        auto actor = vtkSmartPointer<vtkActor>::New();
        actor->SetMapper(mapper);
        return actor;
      } },
    { "glyphs",
      [&] {
        vtkNew<vtkPlaneSource> grid;
        grid->SetResolution(3, 3);
        grid->Update();
        vtkNew<vtkConeSource> cone;
        cone->SetResolution(16);
        cone->SetHeight(0.2);
        cone->SetRadius(0.1);
        vtkNew<vtkGlyph3DMapper> mapper;
        mapper->SetInputConnection(grid->GetOutputPort());
        mapper->SetSourceConnection(cone->GetOutputPort());
        auto actor = vtkSmartPointer<vtkActor>::New();
        actor->SetMapper(mapper);
        return actor;
      } },
  };
  for (const Kind& kind : kinds)
  {
    Scene scene(240, 180);
    scene.Renderer->AddViewProp(kind.Make());
    scene.Renderer->ResetCamera();
    auto image = scene.Render();
    auto mask = scene.Mask();
    const double white[3] = { 1, 1, 1 };
    const nprPixelStatistics stats = nprComputePixelStatistics(image, white);
    const long long lines = CountAbove(mask, 127);
    std::cout << kind.Name << ": " << stats.ObjectPixels << " object pixels, " << lines
              << " line pixels\n";
    NPR_CHECK(stats.ObjectPixels > 500, kind.Name << ": the actor was not drawn");
    NPR_CHECK(lines > 40, kind.Name << ": no lines");
  }
  return nprTestResult();
}

// ---- Resizes, releases and several windows in one process ----
int Windows()
{
  for (int round = 0; round < 2; ++round)
  {
    Scene first(200, 150);
    Scene second(160, 120);
    for (Scene* scene : { &first, &second })
    {
      const double origin[3] = { 0, 0, 0 };
      AddCube(scene->Renderer, origin);
      scene->Camera()->Azimuth(30);
      scene->Camera()->Elevation(30);
      scene->Renderer->ResetCamera();
      NPR_CHECK(CountAbove(scene->Mask(), 127) > 100, "no lines in a window");
    }
    first.Window->SetSize(320, 240);
    auto mask = first.Mask();
    NPR_CHECK(mask->GetDimensions()[0] == 320 && CountAbove(mask, 127) > 150,
      "no lines after a resize");
    first.Renderer->ReleaseGraphicsResources(first.Window);
    first.Camera()->Azimuth(10);
    NPR_CHECK(CountAbove(first.Mask(), 127) > 150, "no lines after ReleaseGraphicsResources");
    NPR_CHECK(CountAbove(second.Mask(), 127) > 100, "the second window lost its lines");
  }
  return nprTestResult();
}

// ---- Baseline images: the CAD part and the bunny ----
int Baseline(const char* model, const char* name)
{
  vtkNew<vtkNPRModelReader> reader;
  reader->SetFileName((nprTestDataDir() + "/" + model).c_str());
  reader->Update();
  NPR_CHECK(!*reader->GetErrorMessage(), reader->GetErrorMessage());
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputConnection(reader->GetOutputPort());
  normals->SetFeatureAngle(30.0);
  normals->SplittingOn();
  Scene scene(400, 300);
  const double color[3] = { 0.85, 0.82, 0.75 };
  nprAddActor(scene.Renderer, normals->GetOutputPort(), color);
  scene.Renderer->ResetCamera();
  scene.Camera()->Azimuth(30);
  scene.Camera()->Elevation(30);
  scene.Camera()->OrthogonalizeViewUp();
  scene.Renderer->ResetCameraClippingRange();
  scene.Edges()->SetCreaseColor(0.1, 0.2, 0.6);
  NPR_CHECK(nprCompareWithBaseline(scene.Render(), name), name << " differs from its baseline");
  return nprTestResult();
}
}

int main(int argc, char* argv[])
{
  const std::map<std::string, std::function<int()>> cases = {
    { "cube", [] { return CubeEdges(false); } },
    { "cube-parallel", [] { return CubeEdges(true); } },
    { "grazing-plane", GrazingPlane },
    { "touching-objects", TouchingObjects },
    { "translucency", Translucency },
    { "layers", Layers },
    { "volume-overlay", VolumeAndOverlay },
    { "picking", Picking },
    { "reuse", Reuse },
    { "channels", Channels },
    { "antialiasing", AntiAliasing },
    { "actor-kinds", ActorKinds },
    { "windows", Windows },
    { "baseline-cad", [] { return Baseline("cad_part.vtp", "edges_cad_part"); } },
    { "baseline-bunny", [] { return Baseline("bunny.ply", "edges_bunny"); } },
  };
  return nprRunTestCase(argc, argv, cases);
}
