// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nprBenchmarkStage.h"

#include "nprModel.h"
#include "nprPassSettings.h"
#include "nprTiming.h"
#include "nprWindowImage.h"

#include "vtkImageData.h"
#include "vtkMapper.h"
#include "vtkNPRInkPass.h"
#include "vtkNPRPass.h"
#include "vtkNPRRenderWindowFactory.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"

#include <algorithm>
#include <stdexcept>

nprMask nprReadMask(vtkRenderWindow* window)
{
  vtkSmartPointer<vtkImageData> image = nprReadWindowImage(window, false);
  nprMask mask;
  const int* dims = image->GetDimensions();
  mask.Width = dims[0];
  mask.Height = dims[1];
  mask.Pixels.resize(static_cast<size_t>(dims[0]) * dims[1]);
  const auto* rgb = static_cast<const unsigned char*>(image->GetScalarPointer());
  for (size_t i = 0; i < mask.Pixels.size(); ++i)
  {
    mask.Pixels[i] = rgb[3 * i] >= 128 ? 255 : 0;
  }
  return mask;
}

void nprWriteMaskPNG(const nprMask& mask, const std::string& path)
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(mask.Width, mask.Height, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
  std::copy(
    mask.Pixels.begin(), mask.Pixels.end(), static_cast<unsigned char*>(image->GetScalarPointer()));
  nprWritePNG(image, path);
}

nprBenchmarkStage::nprBenchmarkStage(double lineWidth)
  : LineWidth(lineWidth)
  , DefaultResolve(vtkMapper::GetResolveCoincidentTopology())
{
  this->Window =
    vtkSmartPointer<vtkRenderWindow>::Take(vtkNPRRenderWindowFactory::CreateRenderWindow());
  if (!this->Window)
  {
    throw std::runtime_error("no headless render window (see the message above)");
  }
  this->Window->AddRenderer(this->Renderer);
  this->MeshMapper->ScalarVisibilityOff();
  this->MeshActor->SetMapper(this->MeshMapper);
  this->Renderer->AddActor(this->MeshActor);
  this->LineMapper->SetInputConnection(this->FeatureLines->GetOutputPort());
  this->LineMapper->ScalarVisibilityOff();
  this->LineActor->SetMapper(this->LineMapper);
  this->LineActor->GetProperty()->SetLineWidth(static_cast<float>(lineWidth));
  this->LineActor->GetProperty()->LightingOff();
  this->LineActor->VisibilityOff();
  this->Renderer->AddActor(this->LineActor);
  this->ShadeMesh();
  this->Reference->SetRenderer(this->Renderer); // visible actors only: the mesh
}

void nprBenchmarkStage::ShadeMesh()
{
  vtkProperty* property = this->MeshActor->GetProperty();
  nprApplyModelLook(property, 0);
  property->LightingOn();
  this->LineActor->GetProperty()->SetColor(0.0, 0.0, 0.0);
  this->Renderer->SetBackground(1.0, 1.0, 1.0);
}

void nprBenchmarkStage::SetMesh(vtkPolyData* mesh, vtkPolyData* topology)
{
  this->MeshMapper->SetInputData(mesh);
  this->FeatureLines->SetInputData(topology);
}

vtkCamera* nprBenchmarkStage::Camera()
{
  return this->Renderer->GetActiveCamera();
}

vtkSmartPointer<vtkNPRPass> nprBenchmarkStage::MakePass(const nprBenchmarkMethod& method) const
{
  if (method.Family == nprBenchmarkMethod::ObjectLines)
  {
    return nullptr;
  }
  nprPassSettings settings = method.Pass;
  settings.Style = method.Family == nprBenchmarkMethod::Edges ? "edges" : "inked";
  settings.LineWidth = this->LineWidth;
  return nprMakePass(settings);
}

void nprBenchmarkStage::Activate(vtkNPRPass* pass, bool objectLines)
{
  this->Renderer->SetPass(pass);
  this->LineActor->SetVisibility(objectLines);
  // Object-space lines lie on the mesh: VTK's coincident-topology resolution (polygon
  // offset) lets them win the depth test. The other methods draw as users get them, without.
  vtkMapper::SetResolveCoincidentTopology(
    objectLines ? VTK_RESOLVE_POLYGON_OFFSET : this->DefaultResolve);
}

void nprBenchmarkStage::UpdateFeatureLines()
{
  this->FeatureLines->SetCamera(this->Camera());
  this->FeatureLines->Modified(); // the extraction is part of every frame of the method
}

double nprBenchmarkStage::TimedFrame(bool objectLines)
{
  return nprTimeFrame(this->Window, this->Camera(),
    [&]()
    {
      if (objectLines)
      {
        this->UpdateFeatureLines();
      }
    });
}

nprMask nprBenchmarkStage::MethodMask(const nprBenchmarkMethod& method, vtkNPRPass* pass)
{
  nprMask mask;
  if (method.Family == nprBenchmarkMethod::Edges)
  {
    this->Activate(pass, false);
    pass->GetEdgePass()->CoverageOnlyOn();
    this->Window->Render();
    mask = nprReadMask(this->Window);
    pass->GetEdgePass()->CoverageOnlyOff();
  }
  else if (method.Family == nprBenchmarkMethod::Inked)
  {
    this->Activate(pass, false);
    pass->GetInkPass()->CoverageOnlyOn();
    this->Window->Render();
    mask = nprReadMask(this->Window);
    pass->GetInkPass()->CoverageOnlyOff();
  }
  else
  {
    // The lines white over the mesh black on black: what the lines leave visible.
    this->Activate(nullptr, true);
    this->UpdateFeatureLines();
    vtkProperty* property = this->MeshActor->GetProperty();
    property->SetColor(0.0, 0.0, 0.0);
    property->LightingOff();
    this->LineActor->GetProperty()->SetColor(1.0, 1.0, 1.0);
    this->Renderer->SetBackground(0.0, 0.0, 0.0);
    this->Window->Render();
    mask = nprReadMask(this->Window);
    this->ShadeMesh();
  }
  this->Activate(nullptr, false);
  return mask;
}

nprMask nprBenchmarkStage::ReferenceMask()
{
  this->Activate(nullptr, false);
  if (!this->Reference->Update())
  {
    throw std::runtime_error("vtkNPRReferenceMask failed (see the message above)");
  }
  vtkImageData* image = this->Reference->GetMask();
  nprMask mask;
  const int* dims = image->GetDimensions();
  mask.Width = dims[0];
  mask.Height = dims[1];
  const auto* pixels = static_cast<const unsigned char*>(image->GetScalarPointer());
  mask.Pixels.assign(pixels, pixels + static_cast<size_t>(dims[0]) * dims[1]);
  return mask;
}
