# CPack: `cpack -G DEB` in the build folder makes the Debian package tetskin
# (the executables, the bundled data, a desktop entry) and, where the ParaView
# plugin was built, tetskin-paraview-plugin (the filters for ParaView 5.11).
install(DIRECTORY ${PROJECT_SOURCE_DIR}/data/ DESTINATION share/tetskin/data
  PATTERN "tools" EXCLUDE)
install(FILES ${PROJECT_SOURCE_DIR}/packaging/tetskin.desktop DESTINATION share/applications)
install(FILES ${PROJECT_SOURCE_DIR}/packaging/tetskin.svg
  DESTINATION share/icons/hicolor/scalable/apps)
install(FILES ${PROJECT_SOURCE_DIR}/LICENSE ${PROJECT_SOURCE_DIR}/README.md
  DESTINATION share/doc/tetskin)
# The user's pages and the README's picture, where the README's links find them.
install(DIRECTORY ${PROJECT_SOURCE_DIR}/doc/user ${PROJECT_SOURCE_DIR}/doc/images
  DESTINATION share/doc/tetskin/doc)

set(CPACK_PACKAGE_NAME tetskin)
set(CPACK_PACKAGE_VENDOR "TetSkin developers")
set(CPACK_PACKAGE_CONTACT "TetSkin developers <tetskin@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
  "Real-time deformable bodies: tetrahedral control mesh, bound high-resolution surface, fur")
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_RESOURCE_FILE_LICENSE ${PROJECT_SOURCE_DIR}/LICENSE)
set(CPACK_GENERATOR DEB)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
# dpkg-shlibdeps derives the runtime library dependencies (VTK, Qt, TetGen, TBB).
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
if(TETSKIN_WITH_NETGEN)
  get_filename_component(nglib_dir ${NGLIB_LIBRARY} DIRECTORY)
  set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS_PRIVATE_DIRS ${nglib_dir})
endif()
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
# One package per install component.
set(CPACK_DEB_COMPONENT_INSTALL ON)
set(CPACK_DEBIAN_TETSKIN_PACKAGE_NAME tetskin)
# The Python module (app/python) imports NumPy; tetskin.vtk needs VTK's Python.
if(TETSKIN_BUILD_PYTHON AND NOT TETSKIN_SANITIZE)
  set(CPACK_DEBIAN_TETSKIN_PACKAGE_DEPENDS "python3 (>= 3.11), python3 (<< 3.12), python3-numpy")
  set(CPACK_DEBIAN_TETSKIN_PACKAGE_RECOMMENDS "python3-vtk9")
endif()
# Only these: the Python filters' VTK module installs a static library of its
# own (component python_vtk_build_only), which is no package's.
set(CPACK_COMPONENTS_ALL tetskin)
if(TETSKIN_PARAVIEW_PLUGIN)
  list(APPEND CPACK_COMPONENTS_ALL paraview_plugin)
endif()
set(CPACK_DEBIAN_PARAVIEW_PLUGIN_PACKAGE_NAME tetskin-paraview-plugin)
set(CPACK_DEBIAN_PARAVIEW_PLUGIN_PACKAGE_SECTION science)
set(CPACK_COMPONENT_PARAVIEW_PLUGIN_DESCRIPTION
  "TetSkin's Bind Surface and Deform Surface filters as a ParaView 5.11 plugin")
include(CPack)
