# SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
# SPDX-License-Identifier: BSD-3-Clause
# What the installed VTK provides, decided once for the module, its tests, the CLI and the
# ParaView plugin. Expects find_package(VTK) (or ParaView's) to have run. Sets:
#   NPR_OWN_HEADLESS_WINDOWS  ON when the module compiles its own EGL and OSMesa windows: VTK 9.1
#                             to 9.3 (Debian 12 and 13) are built for X only and load OpenGL
#                             through GLEW. VTK 9.4 and later install vtkEGLRenderWindow and
#                             vtkOSOpenGLRenderWindow (X, EGL or OSMesa picked at run time, glad
#                             as the loader), and the factory uses those.
#   NPR_HAS_OSMESA            ON when the osmesa backend is built (NPR_ENABLE_OSMESA below).
#   NPR_OSMESA_LIBRARY        libOSMesa, when found.
if (NOT VTK_VERSION)
  message(FATAL_ERROR "vtkNPR: find_package(VTK) (or ParaView) did not set VTK_VERSION")
endif ()
if (VTK_VERSION VERSION_LESS "9.4")
  set(NPR_OWN_HEADLESS_WINDOWS ON)
else ()
  set(NPR_OWN_HEADLESS_WINDOWS OFF)
endif ()

# Mesa removed OSMesa in 25.1 (Debian unstable has none): the backend is optional.
set(NPR_ENABLE_OSMESA "AUTO" CACHE STRING
  "The osmesa backend: AUTO (when libOSMesa is found), ON (required) or OFF")
set_property(CACHE NPR_ENABLE_OSMESA PROPERTY STRINGS AUTO ON OFF)
set(NPR_HAS_OSMESA OFF)
if (NOT NPR_ENABLE_OSMESA STREQUAL "OFF")
  find_library(NPR_OSMESA_LIBRARY NAMES OSMesa OSMesa32 DOC "Mesa's off-screen OpenGL library")
  if (NPR_OSMESA_LIBRARY)
    set(NPR_HAS_OSMESA ON)
  elseif (NPR_ENABLE_OSMESA STREQUAL "ON")
    message(FATAL_ERROR "NPR_ENABLE_OSMESA is ON but libOSMesa was not found "
      "(Debian: apt-get install libosmesa6-dev; Mesa 25.1 and later ship no OSMesa)")
  endif ()
endif ()
if (NPR_HAS_OSMESA)
  message(STATUS "vtkNPR: osmesa backend ON (${NPR_OSMESA_LIBRARY})")
elseif (NPR_ENABLE_OSMESA STREQUAL "OFF")
  message(STATUS "vtkNPR: osmesa backend OFF (NPR_ENABLE_OSMESA=OFF)")
else ()
  message(STATUS "vtkNPR: osmesa backend left out: libOSMesa was not found (Mesa 25.1 and "
    "later ship none). egl and x are built; NPR_BACKEND=osmesa reports that it is not "
    "available in this build.")
endif ()
if (NPR_OWN_HEADLESS_WINDOWS)
  message(STATUS "vtkNPR: VTK ${VTK_VERSION}: the module's own EGL/OSMesa windows (GLEW)")
else ()
  message(STATUS "vtkNPR: VTK ${VTK_VERSION}: VTK's vtkEGLRenderWindow/vtkOSOpenGLRenderWindow")
endif ()
