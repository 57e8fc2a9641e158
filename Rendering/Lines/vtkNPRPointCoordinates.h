// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// A point's coordinates as doubles, read straight from a plain float or double array (what the
// readers make) instead of through a virtual GetTuple per point: at 16M triangles GetTuple was
// a tenth of the model input's time. Any other array goes through GetTuple. The values are the
// same either way (float to double is exact). Private to the module.
#ifndef vtkNPRPointCoordinates_h
#define vtkNPRPointCoordinates_h

#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"

class vtkNPRPointCoordinates
{
public:
  explicit vtkNPRPointCoordinates(vtkDataArray* data)
    : Data(data)
  {
    vtkFloatArray* floats = vtkFloatArray::FastDownCast(data);
    vtkDoubleArray* doubles = vtkDoubleArray::FastDownCast(data);
    if (data->GetNumberOfComponents() == 3 && data->GetNumberOfTuples() > 0)
    {
      this->Floats = floats ? floats->GetPointer(0) : nullptr;
      this->Doubles = doubles ? doubles->GetPointer(0) : nullptr;
    }
  }

  void Get(vtkIdType id, double p[3]) const
  {
    if (this->Floats)
    {
      const float* f = this->Floats + 3 * id;
      p[0] = f[0];
      p[1] = f[1];
      p[2] = f[2];
    }
    else if (this->Doubles)
    {
      const double* d = this->Doubles + 3 * id;
      p[0] = d[0];
      p[1] = d[1];
      p[2] = d[2];
    }
    else
    {
      this->Data->GetTuple(id, p);
    }
  }

private:
  vtkDataArray* Data;
  const float* Floats = nullptr;
  const double* Doubles = nullptr;
};

#endif
