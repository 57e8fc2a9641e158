# SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
# SPDX-License-Identifier: BSD-3-Clause
# The ParaView plugin "Render View (NPR)" (Plugin/), built against ParaView's own VTK; the passes
# module (NPR::Passes) is compiled into it from Rendering/Passes, with the object-space lines
# it depends on (NPR::Lines, Rendering/Lines) and Cairo (found by cmake/FindCairo.cmake).
set(CMAKE_LIBRARY_OUTPUT_DIRECTORY "${CMAKE_BINARY_DIR}/${CMAKE_INSTALL_LIBDIR}")
set(CMAKE_ARCHIVE_OUTPUT_DIRECTORY "${CMAKE_BINARY_DIR}/${CMAKE_INSTALL_LIBDIR}")
set(CMAKE_RUNTIME_OUTPUT_DIRECTORY "${CMAKE_BINARY_DIR}/${CMAKE_INSTALL_BINDIR}")
set(CMAKE_POSITION_INDEPENDENT_CODE ON)
# Only the components used: a bare find_package(ParaView) also wants Qt, GDAL, FFMPEG... -dev
# packages. Debian's ParaView links VTK::Python -> Python3::Module, which a component-limited
# find_package(ParaView) does not look up itself.
find_package(Python3 REQUIRED COMPONENTS Interpreter Development)
# ParaView 5.13's VTK module functions are defined under cmake_policy(VERSION 3.12) and pass empty
# keyword values, for which CMake 3.31 warns at every call (CMP0174); OLD is what they expect.
set(CMAKE_POLICY_DEFAULT_CMP0174 OLD)
include("${CMAKE_CURRENT_LIST_DIR}/vtkNPRParaViewPythonTargets.cmake") # Debian's ParaView 5.13
npr_predefine_missing_paraview_python_targets()
find_package(ParaView 5.11 REQUIRED COMPONENTS RemotingViews)
# ParaView's package finds VTK with the modules RemotingViews names, but from 5.13 the libraries
# behind RemotingServerManager (VTK::IOIOSS -> ioss -> exodusII) reach VTK::hdf5 and VTK::netcdf,
# whose link interfaces name hdf5::hdf5 and NetCDF::NetCDF: targets VTK's package defines only when
# these components are asked for (else generation fails).
if (ParaView_VERSION VERSION_GREATER_EQUAL 5.13)
  set(npr_vtk_external_modules)
  foreach (module IN ITEMS hdf5 netcdf)
    if (TARGET "VTK::${module}")
      list(APPEND npr_vtk_external_modules "${module}")
    endif ()
  endforeach ()
  if (npr_vtk_external_modules)
    find_package(VTK REQUIRED PATHS "${VTK_DIR}" NO_DEFAULT_PATH
      COMPONENTS ${npr_vtk_external_modules})
  endif ()
endif ()
paraview_plugin_scan(
  PLUGIN_FILES      "${CMAKE_CURRENT_SOURCE_DIR}/Plugin/paraview.plugin"
  PROVIDES_PLUGINS  npr_plugins
  ENABLE_BY_DEFAULT ON)
paraview_plugin_build(
  RUNTIME_DESTINATION  "${CMAKE_INSTALL_BINDIR}"
  LIBRARY_DESTINATION  "${CMAKE_INSTALL_LIBDIR}"
  LIBRARY_SUBDIRECTORY "${PARAVIEW_PLUGIN_SUBDIR}"
  INSTALL_HEADERS OFF
  PLUGINS ${npr_plugins})

# The folders of ParaView's libraries (Debian keeps them apart, in paraview-X.Y/), where
# dpkg-shlibdeps finds what the plugin links when it makes the package's dependencies.
set(npr_paraview_library_dirs)
foreach (npr_target IN ITEMS ParaView::RemotingViews VTK::RenderingOpenGL2)
  if (TARGET "${npr_target}")
    get_target_property(npr_location "${npr_target}" LOCATION)
    if (npr_location)
      get_filename_component(npr_location "${npr_location}" DIRECTORY)
      list(APPEND npr_paraview_library_dirs "${npr_location}")
    endif ()
  endif ()
endforeach ()
list(REMOVE_DUPLICATES npr_paraview_library_dirs)
# Debian package: cpack -G DEB (Documentation/packages.md).
include("${CMAKE_CURRENT_LIST_DIR}/vtkNPRPackaging.cmake")
