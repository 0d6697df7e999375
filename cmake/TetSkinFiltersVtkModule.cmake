# tetskin_add_filters_vtk_module(NAME): the filters of modules/filters
# (vtkTetSkinBindSurface, vtkTetSkinDeformSurface), their own sources and
# headers, as the static VTK module NAME for VTK's wrapping: ParaView's
# client-server wrapping for the plugin (modules/filters/paraview, against
# ParaView's VTK) and VTK's Python wrapping for tetskin.vtk (app/python/vtk,
# against Debian's). Call it where NAME's vtk.module is built.
function(tetskin_add_filters_vtk_module name)
  set(filters "${CMAKE_CURRENT_FUNCTION_LIST_DIR}/../modules/filters")
  set(CMAKE_POSITION_INDEPENDENT_CODE ON)  # (linked into a shared library)
  vtk_module_add_module(${name} FORCE_STATIC
    SOURCES "${filters}/src/vtkTetSkinBindSurface.cpp" "${filters}/src/vtkTetSkinDeformSurface.cpp"
    HEADERS "${filters}/include/tetskin/filters/vtkTetSkinBindSurface.h"
            "${filters}/include/tetskin/filters/vtkTetSkinDeformSurface.h")
  # The generated wrappers include the headers by their bare names.
  vtk_module_include(${name} PUBLIC "${filters}/include" "${filters}/include/tetskin/filters")
  vtk_module_link(${name} PRIVATE TetSkin::binding TetSkin::deformation TetSkin::vtkio
    TetSkin::flags)
endfunction()
