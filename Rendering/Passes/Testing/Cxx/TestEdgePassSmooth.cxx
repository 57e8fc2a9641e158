// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// The edge pass on smooth surfaces, against analytic answers: a torus seen obliquely has its
// interior contour drawn to its ending (the cusp, found from the torus's equations and the
// visibility of each contour point), and not much further; a sphere has no line inside its outline,
// even with suggestive contours on; suggestive contours appear on a bumpy sphere and not on a
// smooth one. The program's other case: TestEdgePassSmoothCrease.cxx.
//
// usage: TestEdgePassSmooth CASE [DATA_DIR]   (CASE: the NPR_TEST_CASE names below)
#include "nprTesting.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkNPREdgePass.h"
#include "vtkNPRReferenceMask.h"
#include "vtkNPRShadingNormals.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace
{
using Scene = nprPassScene;

const double Pi = vtkMath::Pi();

// The pixels of a mask (white on black) above half coverage.
std::vector<std::array<double, 2>> LinePixels(vtkImageData* mask)
{
  std::vector<std::array<double, 2>> pixels;
  const int* dims = mask->GetDimensions();
  for (int y = 0; y < dims[1]; ++y)
  {
    for (int x = 0; x < dims[0]; ++x)
    {
      if (nprPixel(mask, x, y) >= 128)
      {
        pixels.push_back({ x + 0.5, y + 0.5 });
      }
    }
  }
  return pixels;
}

double Distance(const std::array<double, 2>& a, const double b[2])
{
  return std::hypot(a[0] - b[0], a[1] - b[1]);
}

// ---- A torus seen obliquely: the interior contour reaches its ending, and goes no further ----
// The contour generator of the torus p(u, v) = ((R + r cos v) cos u, (R + r cos v) sin u, r sin v)
// with normal n = (cos u cos v, sin u cos v, sin v), seen from an eye E: n . (p - E) = 0, that is
// A cos v + B sin v = -r with A = R - (Ex cos u + Ey sin u), B = -Ez, two solutions v per u. A
// contour point is visible where the segment from the eye to it stays outside the solid torus.
struct CuspView
{
  double R, r;
  double Eye[3];
};

struct ContourPoint
{
  double Display[2];
  bool Visible;
};

// Whether the segment from the eye to p stays outside the solid torus: sampled, short of p (the
// ray is tangent there).
bool VisibleFromEye(const CuspView& view, const double p[3])
{
  const double R = view.R, r = view.r;
  const double* eye = view.Eye;
  auto solid = [&](const double x[3])
  {
    const double q = x[0] * x[0] + x[1] * x[1] + x[2] * x[2] + R * R - r * r;
    return q * q - 4.0 * R * R * (x[0] * x[0] + x[1] * x[1]); // < 0 inside
  };
  for (int k = 1; k < 20000; ++k)
  {
    const double t = k / 20000.0 * (1.0 - 1e-4);
    const double x[3] = { eye[0] + t * (p[0] - eye[0]), eye[1] + t * (p[1] - eye[1]),
      eye[2] + t * (p[2] - eye[2]) };
    if (solid(x) < -1e-9)
    {
      return false;
    }
  }
  return true;
}

// Each branch of the contour generator, sampled along u: projected points and visibility.
void SampleBranches(
  Scene& scene, const CuspView& view, int samples, std::vector<ContourPoint> branches[2])
{
  const double R = view.R, r = view.r;
  const double* eye = view.Eye;
  for (int i = 0; i < samples; ++i)
  {
    const double u = 2.0 * Pi * i / samples;
    const double A = R - (eye[0] * std::cos(u) + eye[1] * std::sin(u)), B = -eye[2];
    const double base = std::atan2(B, A), spread = std::acos(-r / std::hypot(A, B));
    for (int b = 0; b < 2; ++b)
    {
      const double v = base + (b ? spread : -spread);
      const double p[3] = { (R + r * std::cos(v)) * std::cos(u),
        (R + r * std::cos(v)) * std::sin(u), r * std::sin(v) };
      ContourPoint point;
      scene.Project(p, point.Display);
      point.Visible = VisibleFromEye(view, p);
      branches[b].push_back(point);
    }
  }
}

// The contour's endings inside the outline: where a branch turns hidden while no other visible
// contour passes within 6 px (else the contour goes behind another one: a T-junction).
std::vector<std::array<double, 2>> FindEndings(
  const std::vector<ContourPoint> branches[2], int samples)
{
  std::vector<std::array<double, 2>> endings;
  for (int b = 0; b < 2; ++b)
  {
    for (int i = 0; i < samples; ++i)
    {
      const ContourPoint& here = branches[b][i];
      const ContourPoint& next = branches[b][(i + 1) % samples];
      if (here.Visible == next.Visible)
      {
        continue;
      }
      const ContourPoint& last = here.Visible ? here : next;
      bool junction = false;
      for (int o = 0; o < 2 && !junction; ++o)
      {
        for (int j = 0; j < samples && !junction; ++j)
        {
          const ContourPoint& other = branches[o][j];
          const int step = std::abs(j - i);
          const bool sameStretch = o == b && std::min(step, samples - step) < 200;
          junction = other.Visible && !sameStretch &&
            std::hypot(other.Display[0] - last.Display[0], other.Display[1] - last.Display[1]) <
              6.0;
        }
      }
      if (!junction)
      {
        endings.push_back({ last.Display[0], last.Display[1] });
      }
    }
  }
  return endings;
}

// A line pixel within 2 px of the ending: the line does not fade out before it. Past the ending
// the depth operator still sees the fold, seen nearly edge-on, for a few pixels: how far the line
// runs on (line pixels near the ending but off the visible contour) is bounded.
void CheckEnding(const std::vector<std::array<double, 2>>& pixels,
  const std::vector<const ContourPoint*>& visiblePoints, const std::array<double, 2>& ending)
{
  double nearest = 1e30, runOn = 0.0;
  for (const auto& pixel : pixels)
  {
    const double d = Distance(pixel, ending.data());
    nearest = std::min(nearest, d);
    if (d < 20.0)
    {
      double toContour = 1e30;
      for (const ContourPoint* point : visiblePoints)
      {
        toContour = std::min(toContour, Distance(pixel, point->Display));
      }
      runOn = toContour > 2.0 ? std::max(runOn, d) : runOn;
    }
  }
  std::cout << "ending at " << ending[0] << ", " << ending[1] << ": nearest line pixel " << nearest
            << " px; the line runs on " << runOn << " px past it\n";
  NPR_CHECK(nearest <= 2.0, "the interior contour stops " << nearest << " px short of its end");
  NPR_CHECK(runOn <= 12.0, "the line runs on " << runOn << " px past the contour's end");
}

int TorusCusp()
{
  const double elevation = vtkMath::RadiansFromDegrees(20.0);
  const CuspView view{ 1.0, 0.4, { 0.0, -4.0 * std::cos(elevation), 4.0 * std::sin(elevation) } };
  Scene scene(800, 600);
  nprAddMesh(scene.Renderer, nprMakeTorus(view.R, view.r, 720, 360));
  vtkCamera* camera = scene.Camera();
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  camera->SetPosition(view.Eye);
  camera->SetViewUp(0.0, 0.0, 1.0);
  camera->SetClippingRange(1.0, 10.0);
  scene.Edges()->CreasesOff();
  scene.Edges()->ContoursOff();
  auto mask = scene.Mask();
  const auto pixels = LinePixels(mask);
  const int samples = 4000;
  std::vector<ContourPoint> branches[2];
  SampleBranches(scene, view, samples, branches);
  std::vector<const ContourPoint*> visiblePoints;
  for (const auto& branch : branches)
  {
    for (const ContourPoint& point : branch)
    {
      if (point.Visible)
      {
        visiblePoints.push_back(&point);
      }
    }
  }
  const std::vector<std::array<double, 2>> endings = FindEndings(branches, samples);
  std::cout << "contour endings (analytic): " << endings.size() << "\n";
  NPR_CHECK(endings.size() == 2, "this view has two endings, found " << endings.size());
  for (const auto& ending : endings)
  {
    CheckEnding(pixels, visiblePoints, ending);
  }
  return nprTestResult();
}
NPR_TEST_CASE("torus-cusp", TorusCusp);

// ---- A sphere: lines on its outline only, smooth silhouettes and suggestive contours on ----
int SphereOutlineOnly()
{
  Scene scene(400, 400);
  const double centre[3] = { 0.0, 0.0, 0.0 };
  nprAddSphere(scene.Renderer, centre, 1.0, nprGrey);
  scene.LookAtOrigin(4.0);
  scene.Edges()->SuggestiveContoursOn();
  auto mask = scene.Mask();
  // The outline: the projection of the circle where the view ray grazes the sphere.
  const double rim = std::sqrt(1.0 - 1.0 / 16.0), height = 1.0 / 4.0;
  std::vector<std::array<double, 2>> outline;
  for (int i = 0; i < 720; ++i)
  {
    const double a = 2.0 * Pi * i / 720;
    const double p[3] = { rim * std::cos(a), rim * std::sin(a), height };
    double display[2];
    scene.Project(p, display);
    outline.push_back({ display[0], display[1] });
  }
  int inside = 0, total = 0;
  for (const auto& pixel : LinePixels(mask))
  {
    double d = 1e30;
    for (const auto& point : outline)
    {
      d = std::min(d, Distance(pixel, point.data()));
    }
    ++total;
    inside += d > 2.0 ? 1 : 0;
  }
  std::cout << total << " line pixels, " << inside << " more than 2 px from the outline\n";
  NPR_CHECK(total > 500, "the outline is missing (" << total << " line pixels)");
  NPR_CHECK(inside == 0, inside << " line pixels inside the sphere's outline");
  return nprTestResult();
}
NPR_TEST_CASE("sphere-outline-only", SphereOutlineOnly);

// ---- Suggestive contours: on a bumpy sphere, not on a smooth one ----
int Suggestive()
{
  auto count = [](bool bumpy)
  {
    Scene scene(400, 400);
    auto source = nprSphereSource(0.5, 256, 128);
    source->Update();
    vtkNew<vtkPolyData> sphere;
    sphere->DeepCopy(source->GetOutput());
    if (bumpy)
    {
      // Radial bumps: the valleys between them, seen from the side, are suggestive contours.
      vtkPoints* points = sphere->GetPoints();
      for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
      {
        double p[3];
        points->GetPoint(i, p);
        const double s =
          1.0 + 0.12 * std::sin(10.0 * p[0]) * std::sin(10.0 * p[1]) * std::sin(10.0 * p[2]);
        points->SetPoint(i, s * p[0], s * p[1], s * p[2]);
      }
      sphere->GetPointData()->SetNormals(nullptr);
    }
    vtkNew<vtkNPRShadingNormals> normals;
    normals->SetInputData(sphere);
    normals->Update();
    nprAddMesh(scene.Renderer, normals->GetOutput());
    scene.LookAtOrigin(4.0);
    scene.Edges()->SilhouettesOff();
    scene.Edges()->CreasesOff();
    scene.Edges()->ContoursOff();
    scene.Edges()->SuggestiveContoursOn();
    return nprCountAbove(scene.Mask(), 127);
  };
  const long long smooth = count(false), bumpy = count(true);
  std::cout << "suggestive contour pixels: sphere " << smooth << ", bumpy sphere " << bumpy << "\n";
  NPR_CHECK(smooth == 0, "suggestive contours on a sphere: " << smooth << " pixels");
  NPR_CHECK(bumpy > 20, "too few suggestive contours on the bumpy sphere: " << bumpy);
  return nprTestResult();
}
NPR_TEST_CASE("suggestive", Suggestive);
}
