// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNPRShadingNormals.h"

#include "vtkCleanPolyData.h"
#include "vtkDataArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataNormals.h"

#include <cmath>

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
  vtkNew<vtkCleanPolyData> merge;
  merge->SetInputData(withoutNormals);
  merge->PointMergingOn();
  merge->ToleranceIsAbsoluteOn();
  merge->SetAbsoluteTolerance(0.0);
  merge->ConvertPolysToLinesOff();
  merge->ConvertLinesToPointsOff();
  merge->ConvertStripsToPolysOff();
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputConnection(merge->GetOutputPort());
  normals->SetFeatureAngle(this->FeatureAngle);
  normals->SplittingOn();
  normals->ConsistencyOff();
  normals->Update();
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
