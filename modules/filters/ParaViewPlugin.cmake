# The filters as a ParaView plugin (paraview/): a CMake project of its own,
# since it builds against ParaView's VTK rather than Debian's VTK 9.1, made
# here as an external project where Debian's paraview-dev is installed and
# python3-paraview is unpacked (TETSKIN_PARAVIEW_ROOT). TETSKIN_PARAVIEW_PLUGIN
# is the built plugin's path (for the tests), empty without it.
set(TETSKIN_PARAVIEW_PLUGIN "" CACHE INTERNAL "the built ParaView plugin")
set(config "/usr/lib/${CMAKE_LIBRARY_ARCHITECTURE}/cmake/paraview-5.11/paraview-config.cmake")
if(NOT TETSKIN_BUILD_PARAVIEW_PLUGIN OR NOT TETSKIN_PARAVIEW_ROOT OR TETSKIN_SANITIZE)
  return()
endif()
if(NOT EXISTS "${config}")
  message(STATUS "ParaView plugin: not built (no paraview-dev: ${config} is missing)")
  return()
endif()

include(ExternalProject)
set(binary "${CMAKE_CURRENT_BINARY_DIR}/paraview")
set(plugin "${binary}/lib/paraview-5.11/plugins/TetSkinFilters/TetSkinFilters.so")
ExternalProject_Add(paraview_plugin
  SOURCE_DIR "${CMAKE_CURRENT_SOURCE_DIR}/paraview"
  BINARY_DIR "${binary}"
  CMAKE_GENERATOR "${CMAKE_GENERATOR}"
  CMAKE_ARGS
    -DCMAKE_BUILD_TYPE=${CMAKE_BUILD_TYPE}
    -DCMAKE_CXX_COMPILER=${CMAKE_CXX_COMPILER}
    -DCMAKE_C_COMPILER=${CMAKE_C_COMPILER}
    -DCMAKE_CXX_COMPILER_LAUNCHER=${CMAKE_CXX_COMPILER_LAUNCHER}
    -DCMAKE_C_COMPILER_LAUNCHER=${CMAKE_C_COMPILER_LAUNCHER}
    -DTETSKIN_WERROR=${TETSKIN_WERROR}
    -DTETSKIN_PARAVIEW_ROOT=${TETSKIN_PARAVIEW_ROOT}
  INSTALL_COMMAND ""
  BUILD_ALWAYS ON  # its sources are TetSkin's: let its own build decide what is stale
  BUILD_BYPRODUCTS "${plugin}")
set(TETSKIN_PARAVIEW_PLUGIN "${plugin}" CACHE INTERNAL "the built ParaView plugin")
# Beside ParaView's own plugins, in a package of its own
# (tetskin-paraview-plugin, which depends on paraview; tetskin does not).
install(FILES "${plugin}"
  DESTINATION lib/${CMAKE_LIBRARY_ARCHITECTURE}/paraview-5.11/plugins/TetSkinFilters
  COMPONENT paraview_plugin)
