# SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
# SPDX-License-Identifier: BSD-3-Clause
# find_package(Cairo): Cairo through pkg-config (Debian's libcairo2-dev), as the imported target
# Cairo::Cairo. NPR::Passes links it privately (the stroke painter of the drawing style and
# vtkNPRDrawingExporter's SVG, PDF and PostScript files), through vtk_module_find_package(PRIVATE):
# the installed vtkNPR package does not look for it, so consumers need no libcairo2-dev. Only API of Cairo 1.16 (Debian 12) is used.
# Sets Cairo_FOUND, Cairo_VERSION.
find_package(PkgConfig QUIET)
if (PkgConfig_FOUND)
  pkg_check_modules(NPR_PC_CAIRO QUIET cairo>=1.16)
endif ()
set(Cairo_VERSION "${NPR_PC_CAIRO_VERSION}")
if (NPR_PC_CAIRO_FOUND)
  find_library(NPR_CAIRO_LIBRARY NAMES cairo HINTS ${NPR_PC_CAIRO_LIBRARY_DIRS})
endif ()
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(Cairo
  REQUIRED_VARS NPR_CAIRO_LIBRARY NPR_PC_CAIRO_FOUND
  VERSION_VAR   Cairo_VERSION
  REASON_FAILURE_MESSAGE "pkg-config finds no cairo >= 1.16 (Debian: apt-get install libcairo2-dev)")
if (Cairo_FOUND AND NOT TARGET Cairo::Cairo)
  # GLOBAL: where the module is static (compiled into the ParaView plugin) the plugin's target,
  # in another directory, links Cairo::Cairo too.
  add_library(Cairo::Cairo UNKNOWN IMPORTED GLOBAL)
  set_target_properties(Cairo::Cairo PROPERTIES
    IMPORTED_LOCATION "${NPR_CAIRO_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${NPR_PC_CAIRO_INCLUDE_DIRS}"
    INTERFACE_COMPILE_OPTIONS "${NPR_PC_CAIRO_CFLAGS_OTHER}")
endif ()
