# SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
# SPDX-License-Identifier: BSD-3-Clause
# Debian's ParaView 5.13 renames its Python extension modules after CMake installed them
# (vtkmodules/vtkCommonCore.so -> vtkCommonCore.cpython-313-x86_64-linux-gnu.so), so the export
# sets VTKPython, ParaViewPython and ParaViewPythonIncubator name files that do not exist, and the
# existence check CMake writes at the end of every targets file stops find_package(ParaView).
# Asking for fewer components does not help: the config files include these sets whenever
# ParaView has Python, and no CMake policy or setting turns that check off.
#
# The plugin uses none of these targets. A targets file returns before its check when all of its
# targets already exist (its guard against a second inclusion), so a set that names a missing
# file is defined here first, as imported targets without a location: anything that links one
# fails at generation (CMP0111) instead of silently. Sets whose files all exist (ParaView 5.11,
# an SDK) are left to ParaView.
function (npr_predefine_missing_paraview_python_targets)
  # The folder find_package(ParaView) will load: the same search, reading only paraview-prefix.cmake
  # (which sets _vtk_module_import_prefix, the prefix the targets files resolve paths against).
  find_package(npr_paraview_location QUIET
    NAMES ParaView CONFIGS paraview-prefix.cmake HINTS "${ParaView_DIR}")
  set(dir "${npr_paraview_location_DIR}")
  unset(npr_paraview_location_DIR CACHE)
  if (NOT dir OR NOT _vtk_module_import_prefix)
    return () # no ParaView here: find_package(ParaView) reports it
  endif ()
  foreach (export_set IN ITEMS vtk/VTKPython ParaViewPython ParaViewPythonIncubator)
    if (NOT EXISTS "${dir}/${export_set}-targets.cmake")
      continue ()
    endif ()
    set(missing "")
    file(GLOB configs "${dir}/${export_set}-targets-*.cmake")
    foreach (config IN LISTS configs)
      file(STRINGS "${config}" locations REGEX "^ *IMPORTED_LOCATION_[A-Z]+ ")
      foreach (location IN LISTS locations)
        string(REGEX REPLACE "^.*\"\\\${_IMPORT_PREFIX}([^\"]*)\".*$" "\\1" file "${location}")
        if (NOT EXISTS "${_vtk_module_import_prefix}${file}")
          set(missing "${_vtk_module_import_prefix}${file}")
        endif ()
      endforeach ()
    endforeach ()
    if (NOT missing)
      continue ()
    endif ()
    file(STRINGS "${dir}/${export_set}-targets.cmake" expected
      REGEX "^foreach\\(_cmake_expected_target IN ITEMS ")
    string(REGEX REPLACE "^foreach\\(_cmake_expected_target IN ITEMS (.*)\\)$" "\\1" expected
      "${expected}")
    separate_arguments(expected)
    foreach (target IN LISTS expected)
      if (NOT TARGET "${target}")
        add_library("${target}" UNKNOWN IMPORTED)
      endif ()
    endforeach ()
    list(LENGTH expected count)
    message(STATUS "ParaView's ${export_set} targets name missing files (${missing}): "
      "${count} targets defined without a location")
  endforeach ()
endfunction ()
