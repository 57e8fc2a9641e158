// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNPRShadingNormals.h"

#include "vtkDataArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNPRCoincidentPoints.h"
#include "vtkNPRSplitNormals.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataNormals.h"
#include "vtkTimerLog.h"

#include <cmath>
#include <string>

vtkStandardNewMacro(vtkNPRShadingNormals);

int vtkNPRShadingNormals::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  this->ComputedNormals = false;
  this->NumberOfInvalidNormals = 0;
  if (!input || !output)
  {
    return 0;
  }

  vtkDataArray* given = input->GetPointData()->GetNormals();
  if (given)
  {
    for (vtkIdType i = 0; i < given->GetNumberOfTuples(); ++i)
    {
      double n[3];
      given->GetTuple(i, n);
      const double length2 = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
      this->NumberOfInvalidNormals += (std::isfinite(length2) && length2 > 1e-24) ? 0 : 1;
    }
    if (this->NumberOfInvalidNormals == 0)
    {
      output->ShallowCopy(input);
      return 1;
    }
    vtkWarningMacro(<< this->NumberOfInvalidNormals << " of " << given->GetNumberOfTuples()
                    << " point normals are zero-length or not finite: normals recomputed");
  }
  if (input->GetNumberOfPolys() + input->GetNumberOfStrips() == 0)
  {
    output->ShallowCopy(input); // nothing to shade: no normals to make
    if (given)
    {
      output->GetPointData()->SetNormals(nullptr);
    }
    return 1;
  }

  vtkNew<vtkPolyData> withoutNormals;
  withoutNormals->ShallowCopy(input);
  if (given)
  {
    // A shallow copy shares the point data object: give this one its own before removing.
    vtkNew<vtkPointData> pointData;
    pointData->ShallowCopy(input->GetPointData());
    pointData->SetNormals(nullptr);
    withoutNormals->GetPointData()->ShallowCopy(pointData);
  }
  vtkTimerLog::MarkStartEvent("vtkNPRShadingNormals: merge");
  vtkNew<vtkPolyData> merged;
  const std::string mergeError = vtkNPRCoincidentPoints::Merge(withoutNormals, merged);
  vtkTimerLog::MarkEndEvent("vtkNPRShadingNormals: merge");
  if (!mergeError.empty())
  {
    vtkErrorMacro(<< "cannot compute normals: " << mergeError);
    return 0;
  }
  vtkTimerLog::MarkStartEvent("vtkNPRShadingNormals: normals");
  if (vtkNPRSplitNormals::Compute(merged, this->FeatureAngle, output))
  {
    vtkTimerLog::MarkEndEvent("vtkNPRShadingNormals: normals");
    this->ComputedNormals = true;
    return 1;
  }
  vtkNew<vtkPolyDataNormals> normals; // triangle strips
  normals->SetInputData(merged);
  normals->SetFeatureAngle(this->FeatureAngle);
  normals->SplittingOn();
  normals->ConsistencyOff();
  normals->Update();
  vtkTimerLog::MarkEndEvent("vtkNPRShadingNormals: normals");
  output->ShallowCopy(normals->GetOutput());
  this->ComputedNormals = true;
  return 1;
}

void vtkNPRShadingNormals::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FeatureAngle: " << this->FeatureAngle << "\n";
  os << indent << "ComputedNormals: " << this->ComputedNormals << "\n";
  os << indent << "NumberOfInvalidNormals: " << this->NumberOfInvalidNormals << "\n";
}
