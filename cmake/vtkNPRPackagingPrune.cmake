# SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
# SPDX-License-Identifier: BSD-3-Clause
# Run by CPack (CPACK_PRE_BUILD_SCRIPTS) on the staged files of the plugin's package: ParaView's
# plugin build also installs the static archives of the plugin's modules and of their
# client-server wrappings, which NPRView.so already contains; a package has no use for them.
file(GLOB_RECURSE npr_archives "${CPACK_TEMPORARY_INSTALL_DIRECTORY}/*.a")
if (npr_archives)
  file(REMOVE ${npr_archives})
endif ()
