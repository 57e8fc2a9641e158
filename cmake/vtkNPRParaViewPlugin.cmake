# The ParaView plugin "Render View (NPR)" (Plugin/), built against ParaView's own VTK; the NPR
# module is compiled into it from Rendering/.
set(CMAKE_LIBRARY_OUTPUT_DIRECTORY "${CMAKE_BINARY_DIR}/${CMAKE_INSTALL_LIBDIR}")
set(CMAKE_ARCHIVE_OUTPUT_DIRECTORY "${CMAKE_BINARY_DIR}/${CMAKE_INSTALL_LIBDIR}")
set(CMAKE_RUNTIME_OUTPUT_DIRECTORY "${CMAKE_BINARY_DIR}/${CMAKE_INSTALL_BINDIR}")
set(CMAKE_POSITION_INDEPENDENT_CODE ON)
# Only the components used: a bare find_package(ParaView) also wants Qt, GDAL, FFMPEG... -dev
# packages. Debian's ParaView links VTK::Python -> Python3::Module, which a component-limited
# find_package(ParaView) does not look up itself.
find_package(Python3 REQUIRED COMPONENTS Interpreter Development)
include("${CMAKE_CURRENT_LIST_DIR}/vtkNPRParaViewPythonTargets.cmake") # Debian's ParaView 5.13
npr_predefine_missing_paraview_python_targets()
find_package(ParaView 5.11 REQUIRED COMPONENTS RemotingViews)
find_package(OpenGL REQUIRED COMPONENTS OpenGL EGL)
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
