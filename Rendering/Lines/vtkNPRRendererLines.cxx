// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNPRRendererLines.h"

#include "vtkNPRSceneLines.h"
#include "vtkObjectFactory.h"
#include "vtkRenderer.h"

vtkCxxSetObjectMacro(vtkNPRRendererLines, Renderer, vtkRenderer);

vtkNPRRendererLines::vtkNPRRendererLines()
  : Scene(new vtkNPRSceneLines)
{
}

vtkNPRRendererLines::~vtkNPRRendererLines()
{
  this->SetRenderer(nullptr);
}

vtkIdType vtkNPRRendererLines::GetNumberOfLocatorBuilds() const
{
  return this->Scene->GetNumberOfLocatorBuilds();
}

bool vtkNPRRendererLines::StartUpdate(int& width, int& height)
{
  this->FeatureEdges = this->RayCasts = 0;
  this->LinesTime = this->LocatorTime = this->VisibilityTime = 0.0;
  if (!this->Renderer)
  {
    vtkErrorMacro("no renderer");
    return false;
  }
  if (!vtkNPRImageSize(this->Renderer, this->Size, width, height))
  {
    vtkErrorMacro("no size: set Size or put the renderer in a window with a size");
    return false;
  }
  return true;
}

void vtkNPRRendererLines::UpdateScene(int trianglesPerLocator)
{
  vtkNPRSceneLines::Settings settings;
  settings.Silhouettes = this->LineSettings->GetSilhouettes();
  settings.Creases = this->LineSettings->GetCreases();
  settings.Boundaries = this->LineSettings->GetBoundaries();
  settings.NonManifoldEdges = this->LineSettings->GetNonManifoldEdges();
  settings.CreaseAngle = this->LineSettings->GetCreaseAngle();
  settings.SmoothContours = this->SmoothContours;
  settings.LinePrimitives = this->LinePrimitives;
  settings.Intersections = settings.Creases && this->IntersectionCurves;
  this->Scene->Update(this->Renderer, settings, trianglesPerLocator);
  this->FeatureEdges = static_cast<vtkIdType>(this->Scene->GetSegments().size());
  this->LinesTime = this->Scene->GetLinesTime();
  this->LocatorTime = this->Scene->GetLocatorTime();
}

void vtkNPRRendererLines::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Renderer: " << this->Renderer << "\n";
  os << indent << "Size: " << this->Size[0] << " x " << this->Size[1] << "\n";
  this->LineSettings->PrintSettings(os, indent, "CreaseAngle");
  os << indent << "OcclusionEpsilon: " << this->OcclusionEpsilon << "\n";
  os << indent << "IntersectionCurves: " << this->IntersectionCurves << "\n";
  os << indent << "SmoothContours: " << this->SmoothContours << "\n";
  os << indent << "NumberOfLocatorBuilds: " << this->GetNumberOfLocatorBuilds() << "\n";
}
