# CLI tests of tetskin itself: help, version, usage errors and conventions every subcommand shares (included by tests/cli/CMakeLists.txt).

tetskin_cli_test(help STDOUT "build.*bind.*deform.*simulate.*render.*bench.*info.*convert" ARGS --help)
tetskin_cli_test(version STDOUT "^tetskin ${PROJECT_VERSION}\n$" ARGS --version)
tetskin_cli_test(no_subcommand FAIL STATUS 1 STDERR "^error: [^\n]*subcommand[^\n]*\\(see tetskin --help\\)\n$" ARGS)
tetskin_cli_test(render_recorded_drop_in_the_picture REQUIRES drawn_drop EXE tetskin_image_border
  STDOUT "f_00000.png: the top edge is background\n$" ARGS ${cli_out}/drawn_drop/f_00000.png top)
tetskin_cli_test(render_live_drop_in_the_picture REQUIRES live_drop EXE tetskin_image_border
  STDOUT "live_drop.png: the top edge is background\n$" ARGS ${cli_out}/live_drop.png top)
# The floor a drop lands on is drawn, live and recorded (the run's frames
# record it; info shows it): it fills the picture's bottom edge, which a
# run without a floor leaves background.
tetskin_cli_test(render_live_drop_floor FAIL STATUS 1 REQUIRES live_drop EXE tetskin_image_border
  STDOUT "live_drop.png: drawn at the bottom edge" ARGS ${cli_out}/live_drop.png)
tetskin_cli_test(render_recorded_drop_floor FAIL STATUS 1 REQUIRES drawn_drop EXE tetskin_image_border
  STDOUT "f_00002.png: drawn at the bottom edge" ARGS ${cli_out}/drawn_drop/f_00002.png)
tetskin_cli_test(render_recorded_run_without_floor REQUIRES drawn_run EXE tetskin_image_border
  STDOUT "f_00003.png: the border is background\n$" ARGS ${cli_out}/drawn/f_00003.png)
tetskin_cli_test(render_recorded_run_film_decodes REQUIRES "filmed_run;drawn_run" EXE tetskin_ogv_frames
  STDOUT "^4 frames, 160x120, first and last frames differ\nfirst frame matches the image"
  ARGS ${cli_out}/film/wobble.ogv ${cli_out}/drawn/f_00000.png)
tetskin_cli_test(render_live_film_decodes REQUIRES "live_film;live_first_frame" EXE tetskin_ogv_frames
  STDOUT "^3 frames, 160x120, first and last frames differ\nfirst frame matches the image"
  ARGS ${cli_out}/live_film/wobble.ogv ${cli_out}/live_first_frame.png)

# doc/user/cli-reference.md is what --help prints (CliReference.cmake).
if(TARGET tetskin-gui)
  add_test(NAME cli.reference
    COMMAND ${CMAKE_COMMAND} -DTETSKIN=$<TARGET_FILE:tetskin> -DTETSKIN_GUI=$<TARGET_FILE:tetskin-gui>
            -DPAGE=${PROJECT_SOURCE_DIR}/doc/user/cli-reference.md -DSOURCE_DIR=${PROJECT_SOURCE_DIR}
            -P ${CMAKE_CURRENT_SOURCE_DIR}/CliReference.cmake)
  set_tests_properties(cli.reference PROPERTIES LABELS cli)
endif()

# The command line starts without the GUI's, Python's and MPI's libraries
# (nor Netgen's, which brings the last two): by the loader's account, for
# --help and for info on a small file. Building with Netgen loads its module
# (the check sees a library loaded later, by dlopen).
set(heavy_libraries "libQt5|libpython|libmpi|libopen-pal|libnglib|libtetskin_netgen|libTK")
add_test(NAME cli.help_loads_no_gui_python_mpi COMMAND ${CMAKE_COMMAND} -DTETSKIN=$<TARGET_FILE:tetskin>
  -DARGS=--help "-DFORBIDDEN=${heavy_libraries}" -P ${CMAKE_CURRENT_SOURCE_DIR}/CheckLoadedLibraries.cmake)
add_test(NAME cli.info_loads_no_gui_python_mpi COMMAND ${CMAKE_COMMAND} -DTETSKIN=$<TARGET_FILE:tetskin>
  "-DARGS=info|${data}/bunny.obj" "-DFORBIDDEN=${heavy_libraries}"
  -P ${CMAKE_CURRENT_SOURCE_DIR}/CheckLoadedLibraries.cmake)
set_tests_properties(cli.help_loads_no_gui_python_mpi cli.info_loads_no_gui_python_mpi
  PROPERTIES LABELS cli)
if(TETSKIN_WITH_NETGEN)
  add_test(NAME cli.netgen_build_loads_its_module COMMAND ${CMAKE_COMMAND} -DTETSKIN=$<TARGET_FILE:tetskin>
    "-DARGS=build|${tdata}/cube_0.obj|-o|${cli_out}/netgen_cube|--mesher|netgen|--levels|1|--min-elements|10|--max-elements|200|-q"
    -DFORBIDDEN=libQt5 "-DREQUIRED=libtetskin_netgen[.]so|libnglib"
    -P ${CMAKE_CURRENT_SOURCE_DIR}/CheckLoadedLibraries.cmake)
  set_tests_properties(cli.netgen_build_loads_its_module PROPERTIES LABELS cli)
endif()
