// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// Uses only the render passes (NPR::Passes): builds the chain of every style, and checks
// that the styles' names round-trip. Renders nothing: it brings no window of its own.
#include "vtkNPRPass.h"
#include "vtkNew.h"

#include <cstring>
#include <iostream>

int main()
{
  vtkNew<vtkNPRPass> pass;
  for (int style = vtkNPRPass::SHADED; style <= vtkNPRPass::INKED; ++style)
  {
    pass->SetStyle(style);
    const char* name = vtkNPRPass::GetStyleName(style);
    if (pass->GetStyle() != style || vtkNPRPass::GetStyleFromName(name) != style)
    {
      std::cerr << "style " << style << " (" << name << ") does not round-trip\n";
      return 1;
    }
  }
  std::cout << "passes_only: " << vtkNPRPass::INKED + 1 << " styles\n";
  return 0;
}
