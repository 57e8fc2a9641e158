// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNPRFrameSignature.h"

#include "vtkCamera.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkNPRPropParts.h"
#include "vtkProp.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"

#include <algorithm>
#include <cmath>

vtkNPRFrameSignature vtkNPRTakeFrameSignature(
  const vtkRenderState* state, int width, int height, bool normals, bool ids, vtkMTimeType passTime)
{
  vtkNPRFrameSignature now;
  vtkRenderer* renderer = state->GetRenderer();
  for (int i = 0; i < state->GetPropArrayCount(); ++i)
  {
    vtkProp* prop = state->GetPropArray()[i];
    // The redraw time includes the mapper and its input, brought up to date: an assembly's
    // parts' each.
    vtkMTimeType time = prop->GetMTime();
    for (const vtkNPRPropPart& part : vtkNPRPropParts(prop))
    {
      time = std::max({ time, part.Prop->GetMTime(), part.Prop->GetRedrawMTime() });
    }
    now.Props.push_back({ prop, time });
  }
  vtkLightCollection* lights = renderer->GetLights();
  vtkCollectionSimpleIterator it;
  lights->InitTraversal(it);
  while (vtkLight* light = lights->GetNextLight(it))
  {
    now.Lights.push_back(light->GetMTime());
  }
  now.Camera = renderer->GetActiveCamera();
  now.CameraTime = now.Camera->GetMTime();
  now.RendererSettings[0] = renderer->GetTwoSidedLighting();
  now.RendererSettings[1] = renderer->GetLightFollowCamera();
  std::copy_n(renderer->GetAmbient(), 3, now.RendererSettings + 2);
  now.PassTime = passTime;
  now.Size[0] = width;
  now.Size[1] = height;
  now.Normals = normals;
  now.Ids = ids;
  return now;
}

void vtkNPRScreenRectangleOfProps(const vtkRenderState* state, int width, int height, int rect[4])
{
  rect[0] = rect[1] = 0;
  rect[2] = width - 1;
  rect[3] = height - 1;
  double bounds[6] = { VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX,
    VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
  for (int i = 0; i < state->GetPropArrayCount(); ++i)
  {
    vtkProp* prop = state->GetPropArray()[i];
    if (!prop->HasOpaqueGeometry())
    {
      continue;
    }
    const double* propBounds = prop->GetBounds();
    if (!propBounds)
    {
      return; // unknown extent: the whole buffer
    }
    if (!vtkMath::AreBoundsInitialized(propBounds))
    {
      continue;
    }
    for (int j = 0; j < 3; ++j)
    {
      bounds[2 * j] = std::min(bounds[2 * j], propBounds[2 * j]);
      bounds[2 * j + 1] = std::max(bounds[2 * j + 1], propBounds[2 * j + 1]);
    }
  }
  if (!vtkMath::AreBoundsInitialized(bounds))
  {
    return;
  }
  vtkCamera* camera = state->GetRenderer()->GetActiveCamera();
  vtkMatrix4x4* toClip =
    camera->GetCompositeProjectionTransformMatrix(static_cast<double>(width) / height, -1.0, 1.0);
  double box[4] = { VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
  for (int corner = 0; corner < 8; ++corner)
  {
    double point[4] = { bounds[corner & 1], bounds[2 + ((corner >> 1) & 1)],
      bounds[4 + ((corner >> 2) & 1)], 1.0 };
    toClip->MultiplyPoint(point, point);
    if (!(point[3] > 1e-9) || !std::isfinite(point[0]) || !std::isfinite(point[1]))
    {
      return; // a corner behind the eye: the projection of the box is unbounded
    }
    const double x = (point[0] / point[3] * 0.5 + 0.5) * width;
    const double y = (point[1] / point[3] * 0.5 + 0.5) * height;
    box[0] = std::min(box[0], x);
    box[1] = std::min(box[1], y);
    box[2] = std::max(box[2], x);
    box[3] = std::max(box[3], y);
  }
  // A margin for rasterisation and for lines wider than the props (up to 32 pixels).
  const double margin = 40.0;
  rect[0] = static_cast<int>(std::max(0.0, std::floor(box[0] - margin)));
  rect[1] = static_cast<int>(std::max(0.0, std::floor(box[1] - margin)));
  rect[2] = static_cast<int>(std::min(width - 1.0, std::ceil(box[2] + margin)));
  rect[3] = static_cast<int>(std::min(height - 1.0, std::ceil(box[3] + margin)));
  if (rect[2] < rect[0] || rect[3] < rect[1])
  {
    rect[0] = rect[1] = 0;
    rect[2] = rect[3] = -1; // off screen: nothing to do
  }
}
