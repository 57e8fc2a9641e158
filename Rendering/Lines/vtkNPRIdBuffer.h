// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// Point ids appended straight into a vtkIdTypeArray, which a vtkCellArray then takes as it is: no
// std::vector filled first and copied (at 13M triangles that copy was 300 MB more at the peak).
// Private to the module.
#ifndef vtkNPRIdBuffer_h
#define vtkNPRIdBuffer_h

#include "vtkIdTypeArray.h"
#include "vtkNew.h"

#include <algorithm>

class vtkNPRIdBuffer
{
public:
  // Room for count more ids without growing.
  void Reserve(vtkIdType count) { this->Grow(this->Used + count); }

  void Append(const vtkIdType* ids, vtkIdType count)
  {
    if (this->Used + count > this->Capacity)
    {
      this->Grow(std::max(2 * this->Capacity, this->Used + count));
    }
    std::copy(ids, ids + count, this->Array->GetPointer(0) + this->Used);
    this->Used += count;
  }

  void Append(vtkIdType id) { this->Append(&id, 1); }

  vtkIdType Size() const { return this->Used; }

  // The array, holding the ids appended.
  vtkIdTypeArray* Finish()
  {
    this->Array->SetNumberOfValues(this->Used);
    return this->Array;
  }

private:
  void Grow(vtkIdType capacity)
  {
    if (capacity > this->Capacity)
    {
      this->Array->Resize(capacity);
      this->Array->SetNumberOfValues(capacity);
      this->Capacity = capacity;
    }
  }

  vtkNew<vtkIdTypeArray> Array;
  vtkIdType Used = 0;
  vtkIdType Capacity = 0;
};

#endif
