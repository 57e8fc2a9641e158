# SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
# SPDX-License-Identifier: BSD-3-Clause
"""vtknpr: non-photorealistic rendering for VTK.

One submodule per VTK module of vtkNPR:
  vtknpr.vtkNPRPasses    the render passes (vtkNPRPass, vtkNPREdgePass, ...)
  vtknpr.vtkNPRLines     object-space lines (vtkNPRFeatureLines, vtkNPRReferenceMask) and
                         the shading normals (vtkNPRShadingNormals)
  vtknpr.vtkNPRIO        model input (vtkNPRModelReader, vtkNPROFFReader)
  vtknpr.vtkNPRHeadless  vtkNPRRenderWindowFactory (and its windows on VTK 9.1-9.3)
Every class is also available from vtknpr itself (`from vtknpr import vtkNPRPass`).
"""
__version__ = "@PROJECT_VERSION@"  # filled in by CMake from the top CMakeLists.txt
from .vtkNPRPasses import *  # noqa: F401,F403
from .vtkNPRLines import *  # noqa: F401,F403
from .vtkNPRIO import *  # noqa: F401,F403
from .vtkNPRHeadless import *  # noqa: F401,F403
