# SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
# SPDX-License-Identifier: BSD-3-Clause
# NPR_SANITIZE: builds every target of the project (the modules, their Python modules, the
# programs and the tests) with AddressSanitizer and UndefinedBehaviorSanitizer. VTK, Mesa and
# Python stay as installed (not instrumented); ASan still sees their heap through its malloc.
# Utilities/bootstrap.sh's `sanitize` stage builds this in $NPR_BUILD_DIR/sanitize
# (Documentation/testing.md, "The sanitizer build"). Sets, when ON:
#   NPR_SANITIZE_FLAGS        the compile flags (also given to the consumer test's project)
#   NPR_SANITIZE_LINK_FLAGS   the link flags
#   NPR_ASAN_LIBRARY          the compiler's libasan.so, which a program not built with ASan
#                             (/usr/bin/python3 importing vtknpr) must preload
#   NPR_SANITIZE_ENVIRONMENT  ASAN_OPTIONS, UBSAN_OPTIONS and LSAN_OPTIONS for the tests, and
#                             Mesa's shader disk cache off
#   NPR_SANITIZE_NO_LEAKS     ASAN_OPTIONS for the few tests that cannot be leak-checked (the
#                             reasons: Utilities/sanitizers/lsan.supp); ASan's other checks stay
option(NPR_SANITIZE "Build with AddressSanitizer and UndefinedBehaviorSanitizer" OFF)
if (NOT NPR_SANITIZE)
  return()
endif ()
if (NOT CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
  message(FATAL_ERROR "NPR_SANITIZE needs gcc or clang, not ${CMAKE_CXX_COMPILER_ID}")
endif ()

# Every undefined-behaviour report aborts the program (a test fails), as an ASan report does.
# float-cast-overflow (not part of "undefined" in gcc): a NaN or out-of-range double converted to
# an integer, e.g. a pixel coordinate from a degenerate projection.
set(NPR_SANITIZE_FLAGS
  -fsanitize=address,undefined,float-cast-overflow -fno-omit-frame-pointer
  -fno-sanitize-recover=all)
set(NPR_SANITIZE_LINK_FLAGS -fsanitize=address,undefined,float-cast-overflow)
add_compile_options(${NPR_SANITIZE_FLAGS})
add_link_options(${NPR_SANITIZE_LINK_FLAGS})

execute_process(COMMAND "${CMAKE_CXX_COMPILER}" -print-file-name=libasan.so
  OUTPUT_VARIABLE npr_asan_library OUTPUT_STRIP_TRAILING_WHITESPACE)
get_filename_component(npr_asan_library "${npr_asan_library}" REALPATH)
if (NOT EXISTS "${npr_asan_library}")
  message(FATAL_ERROR "NPR_SANITIZE: ${CMAKE_CXX_COMPILER} has no libasan.so "
    "(Debian: apt-get install libasan8 or libclang-rt-dev)")
endif ()
set(NPR_ASAN_LIBRARY "${npr_asan_library}")

# The suppressions cover other projects' code only (Mesa, VTK, libpng), each entry explained there.
set(npr_sanitizers_dir "${PROJECT_SOURCE_DIR}/Utilities/sanitizers")
set(npr_asan_options "halt_on_error=1:check_initialization_order=1")
set(NPR_SANITIZE_NO_LEAKS "ASAN_OPTIONS=${npr_asan_options}:detect_leaks=0")
# Mesa's shader disk cache off: a process that loaded a shader from it (one another test or an
# earlier stage put there) ends with LeakSanitizer's tracer dying of signal 11 ("LeakSanitizer has
# encountered a fatal error"), every time, for as long as the cache holds it. That failed CI's
# sanitize stage on two baseline tests whose shaders the host stage had cached just before.
# use_tls=0: LeakSanitizer's tracer, walking the threads' dynamic thread-local storage (Mesa's
# llvmpipe threads and its dlopen'ed driver), died of signal 11 in about half the runs of the bunny
# baseline on this machine ("Tracer caught signal 11: addr=0x1100"; CI failed it twice in a row)
# and in none of 14 runs without that walk. Fewer roots can only add reports, never hide a leak:
# the ones it adds, glibc's loader's and dlerror's own, are suppressed in lsan.supp.
set(NPR_SANITIZE_ENVIRONMENT
  "MESA_SHADER_CACHE_DISABLE=true"
  "ASAN_OPTIONS=${npr_asan_options}:detect_leaks=1"
  "LSAN_OPTIONS=suppressions=${npr_sanitizers_dir}/lsan.supp:print_suppressions=0:use_tls=0"
  "UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1:suppressions=${npr_sanitizers_dir}/ubsan.supp")
message(STATUS "vtkNPR: AddressSanitizer and UndefinedBehaviorSanitizer on (${NPR_ASAN_LIBRARY})")
