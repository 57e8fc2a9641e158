// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNPRFaceShading.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMath.h"
#include "vtkNPRDrawingExporter.h"
#include "vtkNPRPass.h"
#include "vtkNPRToonPass.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkRenderer.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace
{
// A light as the toon shader sees it, in world coordinates.
struct ToonLight
{
  double Intensity;    // intensity x luminance of its colour
  double Direction[3]; // the way it shines
  double Position[3];
  bool Positional;
  double Attenuation[3];
  double ConeCosine; // -2: no cone
  double Exponent;
};

std::vector<ToonLight> ToonLights(vtkRenderer* renderer)
{
  std::vector<ToonLight> lights;
  vtkCollectionSimpleIterator it;
  renderer->GetLights()->InitTraversal(it);
  while (vtkLight* light = renderer->GetLights()->GetNextLight(it))
  {
    if (light->GetSwitch() == 0 || light->GetIntensity() <= 0.0 ||
      lights.size() >= static_cast<size_t>(vtkNPRToonPass::MaximumNumberOfLights))
    {
      continue;
    }
    ToonLight l;
    const double* color = light->GetDiffuseColor();
    l.Intensity =
      light->GetIntensity() * (0.2126 * color[0] + 0.7152 * color[1] + 0.0722 * color[2]);
    double focal[3];
    light->GetTransformedFocalPoint(focal);
    light->GetTransformedPosition(l.Position);
    vtkMath::Subtract(focal, l.Position, l.Direction);
    if (vtkMath::Normalize(l.Direction) == 0.0)
    {
      l.Direction[0] = l.Direction[1] = 0.0;
      l.Direction[2] = -1.0;
    }
    l.Positional = light->GetPositional() != 0;
    std::copy_n(light->GetAttenuationValues(), 3, l.Attenuation);
    l.ConeCosine = light->GetConeAngle() < 90.0
      ? std::cos(vtkMath::RadiansFromDegrees(light->GetConeAngle()))
      : -2.0;
    l.Exponent = light->GetExponent();
    lights.push_back(l);
  }
  return lights;
}

// The light reaching a point p of normal n, summed and clamped to [0, 1].
double Intensity(const std::vector<ToonLight>& lights, const double n[3], const double p[3])
{
  double sum = 0.0;
  for (const ToonLight& light : lights)
  {
    double l[3] = { -light.Direction[0], -light.Direction[1], -light.Direction[2] };
    double attenuation = 1.0;
    if (light.Positional)
    {
      vtkMath::Subtract(light.Position, p, l);
      const double distance = vtkMath::Normalize(l);
      const double* k = light.Attenuation;
      attenuation = 1.0 / std::max(k[0] + k[1] * distance + k[2] * distance * distance, 1e-30);
      if (light.ConeCosine > -1.5)
      {
        const double coneDot = -vtkMath::Dot(l, light.Direction);
        attenuation = coneDot >= light.ConeCosine
          ? attenuation * std::pow(std::max(coneDot, 0.0), light.Exponent)
          : 0.0;
      }
    }
    sum += light.Intensity * attenuation * std::max(0.0, vtkMath::Dot(n, l));
  }
  return std::clamp(sum, 0.0, 1.0);
}
}

vtkSmartPointer<vtkUnsignedCharArray> vtkNPRToonFaceColors(
  vtkPolyData* faces, vtkRenderer* renderer, vtkNPRToonPass* toon)
{
  vtkCellArray* polys = faces ? faces->GetPolys() : nullptr;
  vtkDataArray* normals = faces ? faces->GetCellData()->GetNormals() : nullptr;
  vtkDataArray* ambient = faces ? faces->GetCellData()->GetArray("AmbientColors") : nullptr;
  vtkDataArray* diffuse = faces ? faces->GetCellData()->GetArray("DiffuseColors") : nullptr;
  const vtkIdType count = polys ? polys->GetNumberOfCells() : 0;
  if (!polys || !normals || !ambient || !diffuse || normals->GetNumberOfTuples() < count ||
    ambient->GetNumberOfTuples() < count || diffuse->GetNumberOfTuples() < count)
  {
    return nullptr;
  }
  const std::vector<ToonLight> lights = ToonLights(renderer);
  auto colors = vtkSmartPointer<vtkUnsignedCharArray>::New();
  colors->SetNumberOfComponents(3);
  colors->SetNumberOfTuples(count);
  auto iterator = vtk::TakeSmartPointer(polys->NewIterator());
  for (iterator->GoToFirstCell(); !iterator->IsDoneWithTraversal(); iterator->GoToNextCell())
  {
    vtkIdType size;
    const vtkIdType* ids;
    iterator->GetCurrentCell(size, ids);
    const vtkIdType cell = iterator->GetCurrentCellId();
    double centroid[3] = { 0.0, 0.0, 0.0 }, n[3], shade[3];
    for (vtkIdType k = 0; k < size; ++k)
    {
      double x[3];
      faces->GetPoint(ids[k], x);
      vtkMath::Add(centroid, x, centroid);
    }
    vtkMath::MultiplyScalar(centroid, 1.0 / std::max<vtkIdType>(size, 1));
    normals->GetTuple(cell, n);
    toon->GetShade(Intensity(lights, n, centroid), shade);
    for (int c = 0; c < 3; ++c)
    {
      const double value =
        ambient->GetComponent(cell, c) + diffuse->GetComponent(cell, c) * shade[c];
      colors->SetValue(
        3 * cell + c, static_cast<unsigned char>(std::lround(std::clamp(value, 0.0, 255.0))));
    }
  }
  return colors;
}

vtkSmartPointer<vtkDataArray> vtkNPRFillColors(vtkPolyData* faces, int mode, vtkRenderer* renderer)
{
  if (mode == vtkNPRDrawingExporter::SURFACE_COLORS)
  {
    return faces->GetCellData()->GetArray("Colors");
  }
  if (mode != vtkNPRDrawingExporter::TOON_BANDS)
  {
    return nullptr;
  }
  vtkNPRPass* npr = vtkNPRPass::SafeDownCast(renderer->GetPass());
  vtkNew<vtkNPRToonPass> bands; // the default bands where the renderer has no vtkNPRPass
  return vtkNPRToonFaceColors(faces, renderer, npr ? npr->GetToonPass() : bands.Get());
}
