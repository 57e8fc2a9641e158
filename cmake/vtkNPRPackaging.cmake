# SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
# SPDX-License-Identifier: BSD-3-Clause
# Debian packages of a build folder: `cpack -G DEB` (or `cmake --build . --target package`)
# writes them to <build>/packages (Documentation/packages.md).
#
# CPack's DEB generator rather than debian/ and debhelper: the packages come from the same
# install rules and components the build already has, on each Debian release's own CMake, with
# no second description of the files to keep in step; dpkg-shlibdeps computes the dependencies
# on that release's VTK and ParaView libraries, as debhelper would.
#
# The module build gives four packages, one per install component:
#   libvtknpr0.1    runtime      the shared libraries (NPR::Passes, Lines, IO,
#                                Headless), soname libvtkNPR*.so.0.1 (a 0.x ABI
#                                changes with the minor version), and the licence
#   libvtknpr-dev   development  headers, the CMake package (find_package(vtkNPR)), wrapping
#                                hierarchy files
#   python3-vtknpr  python       the `vtknpr` Python package
#   vtknpr-tools    programs     npr-render (and npr-render-osmesa where built), npr-view
# The plugin build (NPR_BUILD_PARAVIEW_PLUGIN) gives one: paraview-vtknpr.
#
# NPR_DEBIAN_RELEASE names the Debian release in the package version (0.1.0-1+deb12); by default
# it is read from the build machine's /etc/os-release (debNN, or sid for unstable).

if (NOT CMAKE_SYSTEM_NAME STREQUAL "Linux")
  return()
endif ()

if (NOT NPR_DEBIAN_RELEASE)
  set(npr_debian_release "")
  if (EXISTS "/etc/os-release")
    file(STRINGS "/etc/os-release" npr_os_version_id REGEX "^VERSION_ID=")
    if (npr_os_version_id MATCHES "^VERSION_ID=\"?([0-9]+)")
      set(npr_debian_release "deb${CMAKE_MATCH_1}")
    else ()
      # Debian unstable's os-release has no VERSION_ID.
      set(npr_debian_release "sid")
    endif ()
  endif ()
  set(NPR_DEBIAN_RELEASE "${npr_debian_release}" CACHE STRING
    "Debian release named in the packages' version (deb12, deb13, sid)")
endif ()

set(CPACK_GENERATOR "DEB")
set(CPACK_PACKAGE_NAME "vtknpr")
set(CPACK_PACKAGE_VENDOR "the vtkNPR developers")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
  "Non-photorealistic rendering for VTK: line drawings, toon shading, sketchy drawings")
set(CPACK_PACKAGE_DIRECTORY "${CMAKE_BINARY_DIR}/packages")
set(CPACK_PACKAGING_INSTALL_PREFIX "/usr")

set(CPACK_DEBIAN_PACKAGE_MAINTAINER "the vtkNPR developers <vtknpr@invalid>")
set(CPACK_DEBIAN_PACKAGE_SECTION "graphics")
set(CPACK_DEBIAN_PACKAGE_PRIORITY "optional")
set(CPACK_DEBIAN_PACKAGE_RELEASE "1")
if (NPR_DEBIAN_RELEASE)
  string(APPEND CPACK_DEBIAN_PACKAGE_RELEASE "+${NPR_DEBIAN_RELEASE}")
endif ()
set(CPACK_DEBIAN_FILE_NAME "DEB-DEFAULT") # name_version-release_arch.deb
set(CPACK_DEBIAN_COMPRESSION_TYPE "xz")
# Dependencies on the release's shared libraries (VTK's, ParaView's, EGL, libc), by dpkg-shlibdeps;
# our own libraries are looked up in the build tree and named below instead.
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS_PRIVATE_DIRS "${CMAKE_BINARY_DIR}/${CMAKE_INSTALL_LIBDIR}")
set(npr_debian_version "${PROJECT_VERSION}-${CPACK_DEBIAN_PACKAGE_RELEASE}")
# The library package is named after the soname, as Debian's policy has it.
set(npr_runtime_package "libvtknpr${PROJECT_VERSION_MAJOR}.${PROJECT_VERSION_MINOR}")

if (NPR_BUILD_PARAVIEW_PLUGIN)
  # The plugin, bound to the ParaView release it was built against (plugins have no stable ABI).
  math(EXPR npr_paraview_next_minor "${ParaView_VERSION_MINOR} + 1")
  set(CPACK_DEB_COMPONENT_INSTALL OFF)
  set(CPACK_DEBIAN_PACKAGE_NAME "paraview-vtknpr")
  set(CPACK_DEBIAN_PACKAGE_DEPENDS
    "paraview (>= ${ParaView_VERSION_MAJOR}.${ParaView_VERSION_MINOR}), paraview (<< ${ParaView_VERSION_MAJOR}.${npr_paraview_next_minor})")
  set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS_PRIVATE_DIRS
    "${CMAKE_BINARY_DIR}/${CMAKE_INSTALL_LIBDIR}" ${npr_paraview_library_dirs})
  set(CPACK_DEBIAN_PACKAGE_DESCRIPTION
    "ParaView plugin of vtkNPR: the Render View (NPR)\n The view type \"Render View (NPR)\" with vtkNPR's styles (edges, toon, sketch,\n inked) for ParaView ${ParaView_VERSION_MAJOR}.${ParaView_VERSION_MINOR}. Load it from Tools > Manage Plugins, or set\n PV_PLUGIN_PATH to its folder to load it at start-up.")
  set(CPACK_PRE_BUILD_SCRIPTS "${CMAKE_CURRENT_LIST_DIR}/vtkNPRPackagingPrune.cmake")
  install(FILES "${PROJECT_SOURCE_DIR}/LICENSE"
    DESTINATION "${CMAKE_INSTALL_DATAROOTDIR}/doc/paraview-vtknpr" COMPONENT runtime)
else ()
  set(CPACK_DEB_COMPONENT_INSTALL ON)
  set(CPACK_COMPONENTS_ALL runtime development programs)
  if (NPR_WRAP_PYTHON)
    list(APPEND CPACK_COMPONENTS_ALL python)
  endif ()
  set(CPACK_DEBIAN_RUNTIME_PACKAGE_NAME "${npr_runtime_package}")
  set(CPACK_DEBIAN_DEVELOPMENT_PACKAGE_NAME "libvtknpr-dev")
  set(CPACK_DEBIAN_PYTHON_PACKAGE_NAME "python3-vtknpr")
  set(CPACK_DEBIAN_PROGRAMS_PACKAGE_NAME "vtknpr-tools")
  set(CPACK_DEBIAN_RUNTIME_PACKAGE_SECTION "libs")
  set(CPACK_DEBIAN_DEVELOPMENT_PACKAGE_SECTION "libdevel")
  set(CPACK_DEBIAN_PYTHON_PACKAGE_SECTION "python")
  # A shlibs file, so that other packages' dpkg-shlibdeps can depend on the library package.
  set(CPACK_DEBIAN_RUNTIME_PACKAGE_GENERATE_SHLIBS ON)
  set(CPACK_DEBIAN_RUNTIME_PACKAGE_GENERATE_SHLIBS_POLICY "=")

  # The consumer's find_package(vtkNPR) finds VTK (libvtk9-dev) and, for the targets the
  # libraries link, EGL and OSMesa where the module has its own windows.
  set(npr_dev_depends "${npr_runtime_package} (= ${npr_debian_version}), libvtk9-dev")
  if (NPR_OWN_HEADLESS_WINDOWS)
    string(APPEND npr_dev_depends ", libegl-dev")
    if (NPR_HAS_OSMESA)
      string(APPEND npr_dev_depends ", libosmesa6-dev")
    endif ()
  endif ()
  set(CPACK_DEBIAN_DEVELOPMENT_PACKAGE_DEPENDS "${npr_dev_depends}")
  # Headless rendering needs a GL driver behind libEGL/libGL: Mesa's (llvmpipe on a machine
  # without a GPU) unless the machine has a vendor's.
  set(npr_driver_depends "libegl-mesa0 | libegl-vendor, libgl1-mesa-dri")
  set(CPACK_DEBIAN_RUNTIME_PACKAGE_DEPENDS "${npr_driver_depends}")
  set(CPACK_DEBIAN_PYTHON_PACKAGE_DEPENDS
    "${npr_runtime_package} (= ${npr_debian_version}), python3, python3-vtk9")
  set(CPACK_DEBIAN_PROGRAMS_PACKAGE_DEPENDS "${npr_runtime_package} (= ${npr_debian_version})")

  set(CPACK_DEBIAN_RUNTIME_DESCRIPTION
    "Non-photorealistic rendering for VTK: libraries\n vtkNPR's render passes (G-buffer, edges, toon, sketch, ink and the vtkNPRPass facade),\n object-space feature lines, strict model readers and headless render windows, as VTK\n modules for the release's VTK.")
  set(CPACK_DEBIAN_DEVELOPMENT_DESCRIPTION
    "Non-photorealistic rendering for VTK: development files\n Headers and the CMake package of vtkNPR: find_package(vtkNPR) gives the targets\n NPR::Passes, NPR::Lines, NPR::IO and NPR::Headless.")
  set(CPACK_DEBIAN_PYTHON_DESCRIPTION
    "Non-photorealistic rendering for VTK: Python module\n The vtknpr package: every vtkNPR class for VTK's Python (vtkmodules), and\n vtknpr.pyvista.enable_npr for PyVista plotters.")
  set(CPACK_DEBIAN_PROGRAMS_DESCRIPTION
    "Non-photorealistic rendering for VTK: command-line renderer\n npr-render renders model files (STL, OBJ, PLY, VTP, VTK, glTF, OFF) in vtkNPR's styles\n to PNG images, headless through EGL; npr-view shows them in an X window.")
endif ()

include(CPack)
