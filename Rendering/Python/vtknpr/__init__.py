# SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
# SPDX-License-Identifier: BSD-3-Clause
"""vtknpr: non-photorealistic rendering for VTK.

One submodule per VTK module of vtkNPR:
  vtknpr.vtkRenderingNPR          the render passes (vtkNPRPass, vtkNPREdgePass, ...)
  vtknpr.vtkFiltersNPR            object-space lines (vtkNPRFeatureLines, vtkNPRReferenceMask)
  vtknpr.vtkIONPR                 model input (vtkNPRModelReader, vtkNPRShadingNormals, ...)
  vtknpr.vtkRenderingHeadlessNPR  vtkNPRRenderWindowFactory (and its windows on VTK 9.1-9.3)
Every class is also available from vtknpr itself (`from vtknpr import vtkNPRPass`).
"""
__version__ = "@PROJECT_VERSION@"  # filled in by CMake from the top CMakeLists.txt
from .vtkRenderingNPR import *  # noqa: F401,F403
from .vtkFiltersNPR import *  # noqa: F401,F403
from .vtkIONPR import *  # noqa: F401,F403
from .vtkRenderingHeadlessNPR import *  # noqa: F401,F403
