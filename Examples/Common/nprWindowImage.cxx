// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nprWindowImage.h"

#include "nprFiles.h"

#include "vtkImageData.h"
#include "vtkImageExtractComponents.h"
#include "vtkNPRDrawingExporter.h"
#include "vtkNew.h"
#include "vtkPNGWriter.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkWindowToImageFilter.h"

#include <stdexcept>

vtkSmartPointer<vtkImageData> nprReadWindowImage(vtkRenderWindow* window, bool rerender)
{
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();
  grab->SetShouldRerender(rerender);
  grab->Update();
  return grab->GetOutput();
}

void nprWritePNG(vtkImageData* image, const std::string& path)
{
  nprMakeOutputFolders(path);
  vtkNew<vtkPNGWriter> writer;
  writer->SetFileName(path.c_str());
  writer->SetInputData(image);
  writer->Write();
  if (writer->GetErrorCode() != 0)
  {
    throw nprCannotWrite(path, "PNG");
  }
}

void nprWriteWindowPNG(vtkRenderWindow* window, const std::string& path, bool grey, bool rerender)
{
  vtkSmartPointer<vtkImageData> image = nprReadWindowImage(window, rerender);
  if (grey)
  {
    vtkNew<vtkImageExtractComponents> first;
    first->SetInputData(image);
    first->SetComponents(0);
    first->Update();
    image = first->GetOutput();
  }
  nprWritePNG(image, path);
}

bool nprIsDrawingFile(const std::string& path)
{
  return vtkNPRDrawingExporter::GetFormatFromFileName(path.c_str()) >= 0;
}

std::string nprOutputExtensions()
{
  return std::string(".png, ") + vtkNPRDrawingExporter::GetSupportedExtensions();
}

void nprWriteDrawing(vtkRenderer* renderer, const std::string& path, bool fillFaces, int fillColors)
{
  vtkNew<vtkNPRDrawingExporter> exporter;
  exporter->SetRenderer(renderer);
  exporter->SetFillFaces(fillFaces);
  exporter->SetFillColors(fillColors);
  exporter->SetFileName(path.c_str());
  if (!exporter->Write())
  {
    throw std::runtime_error(exporter->GetErrorMessage());
  }
}
