# SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
# SPDX-License-Identifier: BSD-3-Clause
# What every test folder shares: each module's tests (Rendering/<Folder>/Testing, added by
# vtk_module_build) and the programs' (Testing/). Included before vtk_module_build, with
# BUILD_TESTING (Documentation/testing.md, "Adding a test").
# Every test renders headless (no X server) with multisampling off, unless it says so. Images
# that differ from a baseline land in ${npr_test_output_dir} (with a diff image).
set(npr_baseline_dir "${PROJECT_SOURCE_DIR}/Testing/Data/Baseline")
set(npr_data_dir "${PROJECT_SOURCE_DIR}/Testing/Data")
set(npr_test_output_dir "${CMAKE_BINARY_DIR}/Testing/Temporary")
file(MAKE_DIRECTORY "${npr_test_output_dir}")
set(npr_test_environment
  "DISPLAY="
  "NPR_TEST_OUTPUT_DIR=${npr_test_output_dir}"
  "NPR_BACKEND=")
if (NPR_SANITIZE) # the sanitizers' options and suppressions (cmake/vtkNPRSanitize.cmake)
  list(APPEND npr_test_environment ${NPR_SANITIZE_ENVIRONMENT})
endif ()

find_program(NPR_XVFB_RUN xvfb-run)
# Every test's X server: -noreset, because an Xvfb that resets when its last client leaves drops
# a client that connects during the reset (XOpenDisplay fails: "bad X server connection"), which
# happens when one process closes its display as another opens it (pvpython and the pvbatch it
# starts, two MPI ranks, VTK probing OpenGL).
set(npr_xvfb_server_args "-screen 0 1280x1024x24 -noreset")

# A test program on the harness (nprTesting, Testing/Toolkit). In a module's Testing folder it is
# VTK's test executable: linked with the module and its vtk.module's TEST_DEPENDS, whose factory
# overrides (VTK::RenderingOpenGL2) it initialises.
function (npr_add_test_executable name)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "" "SOURCES;LIBRARIES")
  if (DEFINED _vtk_build_test) # the module whose Testing folder vtk_module_build is adding
    vtk_module_test_executable(${name} ${arg_SOURCES})
  else ()
    add_executable(${name} ${arg_SOURCES})
    vtk_module_autoinit(TARGETS ${name} MODULES VTK::RenderingOpenGL2)
  endif ()
  target_link_libraries(${name} PRIVATE ${arg_LIBRARIES} nprTesting
    VTK::FiltersSources VTK::FiltersCore VTK::IOGeometry VTK::IOPLY VTK::IOXML VTK::IOLegacy)
endfunction ()

function (npr_add_test name)
  add_test(NAME ${name} COMMAND ${ARGN})
  set_tests_properties(${name} PROPERTIES ENVIRONMENT "${npr_test_environment}")
endfunction ()

# Which module each test exercises: ctest -L <label> (Documentation/testing.md). Called at the end
# of each folder that registers tests: its tests without a label get the given ones. A module's
# Testing folder gives its module's (_vtk_build_test_labels: the TEST_LABELS of its vtk.module,
# then the module's names); Testing/ gives Programs.
function (npr_label_tests)
  get_property(tests DIRECTORY PROPERTY TESTS)
  foreach (test IN LISTS tests)
    get_property(labels TEST "${test}" PROPERTY LABELS)
    if (NOT labels)
      set_property(TEST "${test}" PROPERTY LABELS ${ARGN})
    endif ()
  endforeach ()
endfunction ()
