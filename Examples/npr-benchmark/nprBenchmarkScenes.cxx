// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nprBenchmarkScenes.h"

#include "nprBenchmarkOptions.h"
#include "nprBenchmarkReport.h"
#include "nprMeshes.h"
#include "nprModel.h"
#include "nprTiming.h"

#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkFlyingEdges3D.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkRTAnalyticSource.h"
#include "vtkRenderer.h"
#include "vtkTessellatedBoxSource.h"
#include "vtkTriangleFilter.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <functional>
#include <iostream>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace
{
// Only the geometry and the triangles: colours and other arrays play no part in the benchmark,
// and double-precision points keep the stress variants' transforms exact in memory.
vtkSmartPointer<vtkPolyData> Geometry(vtkPolyData* input)
{
  vtkNew<vtkTriangleFilter> triangles; // strips and polygons as triangles, no verts or lines
  triangles->SetInputData(input);
  triangles->PassVertsOff();
  triangles->PassLinesOff();
  triangles->Update();
  vtkPolyData* output = triangles->GetOutput();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->DeepCopy(output->GetPoints());
  return nprMesh(points, output->GetPolys());
}

vtkSmartPointer<vtkPolyData> ReadModel(const std::string& path)
{
  if (!std::ifstream(path))
  {
    throw std::runtime_error(path + ": no such file");
  }
  return Geometry(nprReadModel(path));
}

// A closed, wavy isosurface of VTK's analytic wavelet: 101^3 samples, value 200 (about 103k
// triangles in 10 closed pieces, no boundary).
vtkSmartPointer<vtkPolyData> Isosurface()
{
  vtkNew<vtkRTAnalyticSource> wavelet;
  wavelet->SetWholeExtent(-50, 50, -50, 50, -50, 50);
  vtkNew<vtkFlyingEdges3D> contour;
  contour->SetInputConnection(wavelet->GetOutputPort());
  contour->SetValue(0, 200.0);
  contour->ComputeNormalsOff(); // normals as for the files, below
  contour->ComputeScalarsOff();
  contour->Update();
  return Geometry(contour->GetOutput());
}

// A creature of blended blobs (a body, a head, four legs, a tail; metaballs) with a fine ripple:
// the isosurface at 0.5 of a sum of Gaussians sampled on 128^3 points, smooth and closed, with
// folds whose contours end inside the outline.
vtkSmartPointer<vtkPolyData> Blobs()
{
  struct Blob
  {
    double Centre[3];
    double Radius;
  };
  const Blob blobs[] = { { { 0.0, 0.0, 0.0 }, 0.62 }, { { 1.05, 0.45, 0.0 }, 0.42 },
    { { 0.55, -0.7, 0.42 }, 0.24 }, { { 0.55, -0.7, -0.42 }, 0.24 },
    { { -0.55, -0.7, 0.42 }, 0.24 }, { { -0.55, -0.7, -0.42 }, 0.24 },
    { { -1.15, 0.25, 0.0 }, 0.22 }, { { -1.6, 0.55, 0.0 }, 0.16 } };
  const int n = 128;
  const double low = -2.2, spacing = 4.4 / (n - 1);
  vtkNew<vtkImageData> field;
  field->SetDimensions(n, n, n);
  field->SetOrigin(low, low, low);
  field->SetSpacing(spacing, spacing, spacing);
  vtkNew<vtkDoubleArray> values;
  values->SetNumberOfValues(static_cast<vtkIdType>(n) * n * n);
  for (int k = 0; k < n; ++k)
  {
    for (int j = 0; j < n; ++j)
    {
      for (int i = 0; i < n; ++i)
      {
        const double x[3] = { low + i * spacing, low + j * spacing, low + k * spacing };
        double value = 0.06 * std::sin(6.0 * x[0]) * std::sin(6.0 * x[1]) * std::sin(6.0 * x[2]);
        for (const Blob& blob : blobs)
        {
          const double d2 = vtkMath::Distance2BetweenPoints(x, blob.Centre);
          value += std::exp(-d2 / (2.0 * blob.Radius * blob.Radius));
        }
        values->SetValue((static_cast<vtkIdType>(k) * n + j) * n + i, value);
      }
    }
  }
  field->GetPointData()->SetScalars(values);
  vtkNew<vtkFlyingEdges3D> contour;
  contour->SetInputData(field);
  contour->SetValue(0, 0.5);
  contour->ComputeNormalsOff();
  contour->ComputeScalarsOff();
  contour->Update();
  return Geometry(contour->GetOutput());
}

// A trefoil knot as a closed tube whose radius swells and narrows along it (a streamtube): the
// tube passes in front of itself, so interior contours end where it dips behind. 600 x 48
// quads along its Frenet frame, as triangles.
vtkSmartPointer<vtkPolyData> Knot()
{
  const int along = 600, around = 48;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (int i = 0; i < along; ++i)
  {
    const double t = 2.0 * vtkMath::Pi() * i / along;
    const double c[3] = { std::sin(t) + 2.0 * std::sin(2.0 * t),
      std::cos(t) - 2.0 * std::cos(2.0 * t), -std::sin(3.0 * t) };
    double tangent[3] = { std::cos(t) + 4.0 * std::cos(2.0 * t),
      -std::sin(t) + 4.0 * std::sin(2.0 * t), -3.0 * std::cos(3.0 * t) };
    double normal[3] = { -std::sin(t) - 8.0 * std::sin(2.0 * t),
      -std::cos(t) + 8.0 * std::cos(2.0 * t), 9.0 * std::sin(3.0 * t) };
    vtkMath::Normalize(tangent);
    const double along2 = vtkMath::Dot(normal, tangent);
    for (int j = 0; j < 3; ++j)
    {
      normal[j] -= along2 * tangent[j];
    }
    if (vtkMath::Normalize(normal) < 1e-6)
    {
      throw std::runtime_error("knot: no Frenet frame"); // never for this curve
    }
    double binormal[3];
    vtkMath::Cross(tangent, normal, binormal);
    const double radius = 0.4 * (1.0 + 0.25 * std::sin(5.0 * t));
    for (int j = 0; j < around; ++j)
    {
      const double s = 2.0 * vtkMath::Pi() * j / around;
      double p[3];
      for (int k = 0; k < 3; ++k)
      {
        p[k] = c[k] + radius * (std::cos(s) * normal[k] + std::sin(s) * binormal[k]);
      }
      points->InsertNextPoint(p);
    }
  }
  return nprMesh(points, nprTubeTriangles(along, around));
}

// Copies a mesh with each point moved by move(double p[3]) (same cells, double precision).
template <typename Move>
vtkSmartPointer<vtkPolyData> WithMovedPoints(vtkPolyData* raw, Move move)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(raw->GetNumberOfPoints());
  for (vtkIdType i = 0; i < raw->GetNumberOfPoints(); ++i)
  {
    double p[3];
    raw->GetPoint(i, p);
    move(p);
    points->SetPoint(i, p);
  }
  return nprMesh(points, raw->GetPolys());
}

// The generated set (nprMeshes), in its order.
struct GeneratedScene
{
  std::string Name;
  std::string Description;
  std::function<vtkSmartPointer<vtkPolyData>()> Make;
};

const std::vector<GeneratedScene>& GeneratedScenes()
{
  static const std::vector<GeneratedScene> scenes = {
    { "cone-flange", "generated: cone on a flange, 35-degree concave and convex circular creases",
      [] { return nprConeOnFlange(35.0); } },
    { "steep-cone", "generated: cone on a flange, 60-degree concave and convex circular creases",
      [] { return nprConeOnFlange(60.0); } },
    { "filleted-cylinder", "generated: cylinder with a chamfer, a fillet and a filleted boss",
      [] { return nprFilletedCylinder(); } },
    { "boss-pocket", "generated: plate with a boss and a pocket (90-degree creases)",
      [] { return nprBossAndPocket(); } },
    { "bumpy-torus", "generated, scan-like: torus displaced by bumps of three sizes",
      [] { return nprBumpyTorus(); } }
  };
  return scenes;
}
}

const std::vector<std::string>& nprBenchmarkSceneNames()
{
  static const std::vector<std::string> names = { "cad", "rotor", "bunny", "isosurface", "blobs",
    "knot", "bunny1m" };
  return names;
}

const std::vector<std::string>& nprBenchmarkGeneratedSceneNames()
{
  static const std::vector<std::string> names = []
  {
    std::vector<std::string> all;
    for (const GeneratedScene& scene : GeneratedScenes())
    {
      all.push_back(scene.Name);
    }
    return all;
  }();
  return names;
}

bool nprIsGeneratedScene(const std::string& name)
{
  const std::vector<std::string>& names = nprBenchmarkGeneratedSceneNames();
  return std::find(names.begin(), names.end(), name) != names.end();
}

nprBenchmarkScene nprLoadBenchmarkScene(
  const std::string& name, const std::string& dataDir, const std::string& denseMesh)
{
  nprBenchmarkScene scene;
  scene.Name = name;
  const auto generated = std::find_if(GeneratedScenes().begin(), GeneratedScenes().end(),
    [&](const GeneratedScene& candidate) { return candidate.Name == name; });
  if (generated != GeneratedScenes().end())
  {
    scene.Raw = generated->Make();
    scene.Description = generated->Description;
  }
  else if (name == "cad")
  {
    scene.Raw = ReadModel(dataDir + "/cad_part.vtp");
    scene.Description = "CAD part (cad_part.vtp)";
  }
  else if (name == "rotor")
  {
    scene.Raw = ReadModel(dataDir + "/rotor.ply");
    scene.Description = "rotor (rotor.ply)";
  }
  else if (name == "bunny")
  {
    scene.Raw = ReadModel(dataDir + "/bunny.ply");
    scene.Description = "Stanford bunny (bunny.ply)";
  }
  else if (name == "isosurface")
  {
    scene.Raw = Isosurface();
    scene.Description = "isosurface of vtkRTAnalyticSource, extent [-50,50]^3, value 200";
  }
  else if (name == "blobs")
  {
    scene.Raw = Blobs();
    scene.Description = "creature of eight blended blobs with a ripple (metaball isosurface, "
                        "128^3 samples)";
  }
  else if (name == "knot")
  {
    scene.Raw = Knot();
    scene.Description = "trefoil knot as a swelling tube (600 x 48 quads as triangles)";
  }
  else if (name == "box")
  {
    // The small end of the scale: per-frame cost with next to no geometry.
    vtkNew<vtkTessellatedBoxSource> box;
    box->SetBounds(-0.5, 0.5, -0.4, 0.4, -0.3, 0.3);
    box->SetLevel(2);
    box->QuadsOff();
    box->Update();
    scene.Raw = Geometry(box->GetOutput());
    scene.Description = "box (vtkTessellatedBoxSource, level 2, triangles)";
  }
  else if (name == "bunny1m")
  {
    scene.Raw = ReadModel(denseMesh);
    scene.Description = "bunny refined twice by Loop subdivision (bunny_1m.ply)";
  }
  else
  {
    throw std::runtime_error("unknown scene '" + name + "'");
  }
  scene.Mesh = nprPrepareMesh(scene.Raw);
  scene.Triangles = nprCountTriangles(scene.Mesh);
  return scene;
}

std::vector<nprBenchmarkScene> nprLoadBenchmarkScenes(const std::vector<std::string>& names,
  const std::string& dataDir, const std::string& denseMesh, bool namesGiven)
{
  std::vector<nprBenchmarkScene> scenes;
  for (const std::string& name : names)
  {
    const nprClock::time_point start = nprClock::now();
    try
    {
      scenes.push_back(nprLoadBenchmarkScene(name, dataDir, denseMesh));
    }
    catch (const std::runtime_error& error)
    {
      // The dense mesh is made by the build (target `benchmark`); without it, a default run
      // goes on with the other scenes.
      if (name == "bunny1m" && !namesGiven)
      {
        std::cerr << "npr-benchmark: warning: scene bunny1m left out: " << error.what() << "\n";
        continue;
      }
      throw;
    }
    std::cerr << "npr-benchmark: scene " << name << ": " << scenes.back().Triangles
              << " triangles, prepared in " << nprFormat(nprSecondsSince(start), 3) << " s\n";
  }
  return scenes;
}

std::vector<nprBenchmarkScene> nprStartBenchmarkRun(const nprBenchmarkOptions& options)
{
  nprMakeBenchmarkFolders(options);
  return nprLoadBenchmarkScenes(
    options.Scenes, options.Data, options.DenseMesh, options.ScenesGiven);
}

std::string nprBenchmarkSceneLines(const std::vector<nprBenchmarkScene>& scenes)
{
  std::ostringstream text;
  for (const nprBenchmarkScene& scene : scenes)
  {
    text << "- " << scene.Name << ": " << scene.Description << ", " << scene.Triangles
         << " triangles\n";
  }
  return text.str();
}

std::string nprBenchmarkCameraLine(int count)
{
  std::string text;
  for (int i = 0; i < count; ++i)
  {
    const nprBenchmarkCamera& camera = nprBenchmarkCameras()[i];
    std::ostringstream one;
    one << camera.Name << " (azimuth " << camera.Azimuth << ", elevation " << camera.Elevation
        << ")";
    text += (i ? ", " : "") + one.str();
  }
  return text;
}

const std::vector<nprBenchmarkCamera>& nprBenchmarkCameras()
{
  static const std::vector<nprBenchmarkCamera> cameras = { { "a30e20", 30.0, 20.0 },
    { "a-60e35", -60.0, 35.0 }, { "a160e-15", 160.0, -15.0 } };
  return cameras;
}

std::vector<nprBenchmarkCamera> nprBenchmarkOrbitCameras(int step)
{
  std::vector<nprBenchmarkCamera> cameras;
  for (const nprBenchmarkCamera& preset : nprBenchmarkCameras())
  {
    for (int azimuth = -180; azimuth < 180; azimuth += step)
    {
      const int elevation = static_cast<int>(preset.Elevation);
      cameras.push_back({ "a" + std::to_string(azimuth) + "e" + std::to_string(elevation),
        static_cast<double>(azimuth), preset.Elevation });
    }
  }
  return cameras;
}

void nprApplyBenchmarkCamera(vtkRenderer* renderer, const nprBenchmarkCamera& preset)
{
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(0.0, 0.0, 1.0);
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  camera->SetViewUp(0.0, 1.0, 0.0);
  camera->ParallelProjectionOff();
  renderer->ResetCamera();
  camera->Azimuth(preset.Azimuth);
  camera->Elevation(preset.Elevation);
  camera->OrthogonalizeViewUp();
  renderer->ResetCameraClippingRange();
}

double nprModelSize(vtkPolyData* mesh)
{
  double bounds[6];
  mesh->GetPoints()->GetBounds(bounds);
  return std::sqrt(
    vtkMath::Distance2BetweenPoints(std::array<double, 3>{ bounds[0], bounds[2], bounds[4] }.data(),
      std::array<double, 3>{ bounds[1], bounds[3], bounds[5] }.data()));
}

vtkSmartPointer<vtkPolyData> nprScaledMesh(vtkPolyData* raw, double factor)
{
  return WithMovedPoints(raw,
    [factor](double p[3])
    {
      for (int c = 0; c < 3; ++c)
      {
        p[c] *= factor;
      }
    });
}

vtkSmartPointer<vtkPolyData> nprTranslatedMesh(vtkPolyData* raw, double distance)
{
  double direction[3] = { 1.0, 0.7, 0.4 };
  vtkMath::Normalize(direction);
  return WithMovedPoints(raw,
    [&](double p[3])
    {
      for (int c = 0; c < 3; ++c)
      {
        p[c] += distance * direction[c];
      }
    });
}

vtkSmartPointer<vtkPolyData> nprSliverMesh(vtkPolyData* raw)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->DeepCopy(raw->GetPoints());
  vtkNew<vtkCellArray> polys;
  nprForEachCell(raw->GetPolys(),
    [&](vtkIdType index, vtkIdType size, const vtkIdType* ids)
    {
      if (index % 5 != 0 || size != 3)
      {
        polys->InsertNextCell(size, ids);
        return;
      }
      // Split (a, b, c) at a point p inside it, 1e-6 of the edge's length from the middle of
      // a-b: (a, b, p) is a needle, (b, c, p) and (c, a, p) are ordinary. The mesh stays
      // manifold (no T-junction) and covers the same surface.
      double a[3], b[3], c[3], p[3];
      points->GetPoint(ids[0], a);
      points->GetPoint(ids[1], b);
      points->GetPoint(ids[2], c);
      const double length = std::sqrt(vtkMath::Distance2BetweenPoints(a, b));
      double towards[3];
      for (int k = 0; k < 3; ++k)
      {
        p[k] = 0.5 * (a[k] + b[k]);
        towards[k] = c[k] - p[k];
      }
      vtkMath::Normalize(towards);
      for (int k = 0; k < 3; ++k)
      {
        p[k] += 1e-6 * length * towards[k];
      }
      const vtkIdType apex = points->InsertNextPoint(p);
      const vtkIdType needle[3] = { ids[0], ids[1], apex };
      const vtkIdType second[3] = { ids[1], ids[2], apex };
      const vtkIdType third[3] = { ids[2], ids[0], apex };
      polys->InsertNextCell(3, needle);
      polys->InsertNextCell(3, second);
      polys->InsertNextCell(3, third);
    });
  return nprMesh(points, polys);
}

vtkSmartPointer<vtkPolyData> nprNaNPointsMesh(vtkPolyData* raw)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->DeepCopy(raw->GetPoints());
  vtkNew<vtkCellArray> polys;
  polys->DeepCopy(raw->GetPolys());
  const double nan = std::numeric_limits<double>::quiet_NaN();
  // One NaN point (all coordinates, or one) per 50 triangles, joined to a real edge.
  nprForEachCell(raw->GetPolys(),
    [&](vtkIdType index, vtkIdType, const vtkIdType* ids)
    {
      if (index % 50 != 0)
      {
        return;
      }
      double p[3];
      points->GetPoint(ids[0], p);
      if (index % 100 == 0)
      {
        p[0] = p[1] = p[2] = nan;
      }
      else
      {
        p[1] = nan;
      }
      const vtkIdType triangle[3] = { ids[1], ids[0], points->InsertNextPoint(p) };
      polys->InsertNextCell(3, triangle);
    });
  return nprMesh(points, polys);
}

vtkSmartPointer<vtkPolyData> nprZeroNormalsMesh(vtkPolyData* prepared)
{
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->ShallowCopy(prepared);
  vtkDataArray* given = prepared->GetPointData()->GetNormals();
  vtkNew<vtkFloatArray> normals;
  normals->DeepCopy(given);
  normals->SetName(given->GetName());
  for (vtkIdType i = 0; i < normals->GetNumberOfTuples(); i += 7)
  {
    normals->SetTuple3(i, 0.0, 0.0, 0.0);
  }
  mesh->GetPointData()->SetNormals(normals);
  return mesh;
}
