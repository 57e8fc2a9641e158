# SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
# SPDX-License-Identifier: BSD-3-Clause
# cmake -DPROGRAM=path -P CheckLinks.cmake: PROGRAM's shared libraries (DT_NEEDED) include
# vtkNPRPasses and no other vtkNPR library.
execute_process(COMMAND readelf -d "${PROGRAM}" OUTPUT_VARIABLE dynamic RESULT_VARIABLE result)
if (NOT result EQUAL 0)
  message(FATAL_ERROR "readelf -d ${PROGRAM} failed")
endif ()
if (NOT dynamic MATCHES "libvtkNPRPasses")
  message(FATAL_ERROR "${PROGRAM} does not link libvtkNPRPasses:\n${dynamic}")
endif ()
foreach (library IN ITEMS vtkNPRLines vtkNPRIO vtkNPRHeadless)
  if (dynamic MATCHES "lib${library}")
    message(FATAL_ERROR "${PROGRAM} links lib${library}, though it uses only the passes")
  endif ()
endforeach ()
message(STATUS "${PROGRAM} links libvtkNPRPasses and no other vtkNPR library")
