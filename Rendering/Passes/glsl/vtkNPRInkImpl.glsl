// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
  // vtkNPRInkPass: one shader for both draws; the mode is a uniform, so no rebuild between them.
  if (nprInkMode == 1)
  {
    // The wireframe of the back faces only; culling is the property's, so it is done here.
    if (gl_FrontFacing)
    {
      discard;
    }
    gl_FragData[0] = vec4(nprInkColor, 1.0);
  }
  else if (nprInkMode == 2)
  {
    gl_FragData[0] = vec4(0.0, 0.0, 0.0, 1.0);
  }
  else if (nprInkMode == 3)
  {
    gl_FragData[0] = vec4(0.0, 0.0, 0.0, 0.5); // not 0: VTK's shader discards that
  }
