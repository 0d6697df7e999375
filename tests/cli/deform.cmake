# CLI tests of tetskin deform (included by tests/cli/CMakeLists.txt).

tetskin_cli_test(deform_rest_state REQUIRES binding SETUP deformed STDOUT "wrote .*1839 vertices deformed"
  ARGS deform ${data}/bunny.json ${cli_out}/bunny_binding.vtp --positions ${data}/bunny.node
       -o ${cli_out}/bunny_deformed.vtp)
# A deformed surface is still its binding (rest = points - Displacement):
# deformed again, it starts from its rest shape.
tetskin_cli_test(deform_its_output_again REQUIRES deformed STDOUT "wrote .*1839 vertices deformed"
  ARGS deform ${data}/bunny.json ${cli_out}/bunny_deformed.vtp --positions ${data}/bunny.node
       -o ${cli_out}/deformed_twice.vtp)
tetskin_cli_test(deform_relative_dataset_name REQUIRES relative_run SETUP relative_deformed
  STDOUT "wrote [^\n]*relative_deformed.vtp"
  ARGS deform data/bunny.json ${cli_out}/relative_run_frames/surface_00001.vtp
       --positions ${cli_out}/relative_run_frames/control_00001.vtu -o ${cli_out}/relative_deformed.vtp)
tetskin_cli_test(deform_wrong_count FAIL REQUIRES binding
  STDERR "^error: [^\n]*bad_index.obj: positions must be a .node"
  NOT_EXIST ${cli_out}/deformed_bad.vtp
  ARGS deform ${data}/bunny.json ${cli_out}/bunny_binding.vtp --positions ${tdata}/bad_index.obj
       -o ${cli_out}/deformed_bad.vtp)
# An output that is one of the inputs is refused (here it would replace the binding).
tetskin_cli_test(deform_onto_its_binding FAIL STATUS 1 REQUIRES binding
  STDERR "^error: [^\n]*bunny_binding.vtp: is also an input of this command. write to another file\n$"
  ARGS deform ${data}/bunny.json ${cli_out}/bunny_binding.vtp --positions ${data}/bunny.node
       -o ${cli_out}/bunny_binding.vtp)
tetskin_cli_test(deform_level_count_mismatch FAIL REQUIRES binding
  STDERR "^error: [^\n]*unit.node: has 4 positions. expected all 4331 dataset nodes or the 3270 nodes of level 2"
  ARGS deform ${data}/bunny.json ${cli_out}/bunny_binding.vtp --positions ${tdata}/unit.node
       -o ${cli_out}/deformed_bad2.vtp)
tetskin_cli_test(deform_from_vtu REQUIRES "binding;level_vtu" STDOUT "wrote .*1839 vertices deformed"
  ARGS deform ${data}/bunny.json ${cli_out}/bunny_binding.vtp --positions ${cli_out}/level2.vtu
       -o ${cli_out}/deformed_vtu.vtp)
tetskin_cli_test(deform_recorded_run REQUIRES "recorded_run;run_binding" SETUP deformed_run
  FRESH ${cli_out}/deformed_run
  STDOUT "^wrote [^\n]*deformed_run/surf.pvd \\(4 frames of 4001 vertices deformed by [^\n]*recorded/run.pvd, t 0 .. 0.5 s\\)\n$"
  ARGS deform ${data}/bunny.json ${cli_out}/run_binding.vtp --positions ${cli_out}/recorded/run.pvd
       -o ${cli_out}/deformed_run/surf.pvd)
add_test(NAME cli.deform_recorded_run_as_simulated COMMAND ${CMAKE_COMMAND} -E compare_files
  ${cli_out}/deformed_run/surf_frames/surface_00003.vtp
  ${cli_out}/recorded/run_frames/surface_00003.vtp)
set_tests_properties(cli.deform_recorded_run_as_simulated PROPERTIES LABELS cli
  FIXTURES_REQUIRED deformed_run)
tetskin_cli_test(deform_recorded_run_other_level FAIL STATUS 1 REQUIRES "recorded_run;embed_binding"
  FRESH ${cli_out}/deformed_other NOT_EXIST ${cli_out}/deformed_other
  STDERR "^error: [^\n]*control_00000.vtu: has 3270 points and 12713 tetrahedra. level 0 of [^\n]*bunny.json \\(the level [^\n]*bunny_embed.vtp is bound to\\) has [0-9]+ and [0-9]+\n$"
  ARGS deform ${data}/bunny.json ${cli_out}/bunny_embed.vtp --positions ${cli_out}/recorded/run.pvd
       -o ${cli_out}/deformed_other/surf.pvd)
tetskin_cli_test(deform_recorded_run_to_one_file FAIL STATUS 1 REQUIRES "recorded_run;run_binding"
  STDERR "^error: -o [^\n]*surf.vtp: the surface of a recorded run \\(--positions RUN.pvd\\) is a series: name a .pvd\n$"
  ARGS deform ${data}/bunny.json ${cli_out}/run_binding.vtp --positions ${cli_out}/recorded/run.pvd
       -o ${cli_out}/deformed_other/surf.vtp)
tetskin_cli_test(deform_one_frame_to_a_series FAIL STATUS 1 REQUIRES "recorded_run;run_binding"
  STDERR "^error: -o [^\n]*surf.pvd: a deformed surface is a .vtp, or a .pvtp in pieces \\(a .pvd series is written for a recorded run, --positions RUN.pvd\\)\n$"
  ARGS deform ${data}/bunny.json ${cli_out}/run_binding.vtp
       --positions ${cli_out}/recorded/run_frames/control_00001.vtu -o ${cli_out}/deformed_other/surf.pvd)
# A series written where the run's own frames lie would clear them first:
# refused, the frames kept (on a copy of the run, other.pvd naming its frames).
add_test(NAME cli.copy_run_to_overwrite COMMAND ${CMAKE_COMMAND} -E copy_directory
  ${cli_out}/recorded ${cli_out}/recorded_guarded)
set_tests_properties(cli.copy_run_to_overwrite PROPERTIES LABELS cli
  FIXTURES_REQUIRED recorded_run FIXTURES_SETUP guarded_run_copy)
add_test(NAME cli.rename_run_to_overwrite COMMAND ${CMAKE_COMMAND} -E rename
  ${cli_out}/recorded_guarded/run.pvd ${cli_out}/recorded_guarded/other.pvd)
set_tests_properties(cli.rename_run_to_overwrite PROPERTIES LABELS cli
  FIXTURES_REQUIRED guarded_run_copy FIXTURES_SETUP guarded_run)
tetskin_cli_test(deform_recorded_run_over_its_frames FAIL STATUS 1 REQUIRES "guarded_run;run_binding"
  STDERR "^error: [^\n]*recorded_guarded/run_frames/control_00000.vtu: is in the folder the series -o [^\n]*recorded_guarded/run.pvd writes its frames to: write it to another name\n$"
  ARGS deform ${data}/bunny.json ${cli_out}/run_binding.vtp
       --positions ${cli_out}/recorded_guarded/other.pvd -o ${cli_out}/recorded_guarded/run.pvd)
add_test(NAME cli.deform_recorded_run_over_its_frames_kept COMMAND ${CMAKE_COMMAND} -E compare_files
  ${cli_out}/recorded_guarded/run_frames/control_00003.vtu
  ${cli_out}/recorded/run_frames/control_00003.vtu)
set_tests_properties(cli.deform_recorded_run_over_its_frames_kept PROPERTIES LABELS cli
  DEPENDS cli.deform_recorded_run_over_its_frames FIXTURES_REQUIRED guarded_run)

# In pieces (issue #54): a recorded run's surface as a .pvtp per frame, in 3
# compact pieces; read back whole (info, and deform reading a frame as its
# binding), it is the run written whole: deformed again to the same frame,
# a frame read from its pieces and the same frame written whole give the
# same file, byte for byte.
tetskin_cli_test(deform_recorded_run_in_pieces REQUIRES "recorded_run;run_binding"
  SETUP deformed_pieces FRESH ${cli_out}/deformed_pieces
  STDOUT "^wrote [^\n]*deformed_pieces/surf.pvd \\(4 frames of 4001 vertices deformed by [^\n]*recorded/run.pvd, t 0 .. 0.5 s\\)\n$"
  ARGS deform ${data}/bunny.json ${cli_out}/run_binding.vtp --positions ${cli_out}/recorded/run.pvd
       --pieces 3 -o ${cli_out}/deformed_pieces/surf.pvd)
tetskin_cli_test(info_run_in_pieces REQUIRES deformed_pieces
  STDOUT "surf.pvd: time series, 4 time steps, t 0 .. 0.5\n  part 1 +4 files, surf_frames/surface_00000.pvtp .. surf_frames/surface_00003.pvtp, all present\n$"
  ARGS info ${cli_out}/deformed_pieces/surf.pvd)
tetskin_cli_test(info_surface_in_pieces REQUIRES deformed_pieces
  STDOUT "surface_00003.pvtp: binding, deformed[^\n]*\n  vertices   4001\n  triangles  7998\n.*  pieces +3 \\(surface_00003_piece0.vtp .. surface_00003_piece2.vtp\\), read whole\n$"
  ARGS info ${cli_out}/deformed_pieces/surf_frames/surface_00003.pvtp)
tetskin_cli_test(deform_frame_read_from_pieces REQUIRES deformed_pieces SETUP from_pieces
  ARGS deform ${data}/bunny.json ${cli_out}/deformed_pieces/surf_frames/surface_00003.pvtp
       --positions ${cli_out}/recorded/run_frames/control_00003.vtu
       -o ${cli_out}/deformed_pieces/again_from_pieces.vtp)
tetskin_cli_test(deform_frame_read_whole REQUIRES deformed_run SETUP from_whole
  ARGS deform ${data}/bunny.json ${cli_out}/deformed_run/surf_frames/surface_00003.vtp
       --positions ${cli_out}/recorded/run_frames/control_00003.vtu
       -o ${cli_out}/deformed_run/again_whole.vtp)
add_test(NAME cli.deform_pieces_read_back_whole COMMAND ${CMAKE_COMMAND} -E compare_files
  ${cli_out}/deformed_pieces/again_from_pieces.vtp ${cli_out}/deformed_run/again_whole.vtp)
set_tests_properties(cli.deform_pieces_read_back_whole PROPERTIES LABELS cli
  FIXTURES_REQUIRED "from_pieces;from_whole")
# One state in pieces: a .pvtp; more than one piece to a .vtp is refused.
tetskin_cli_test(deform_one_frame_in_pieces REQUIRES "recorded_run;run_binding"
  STDOUT "wrote [^\n]*deformed_pieces/one.pvtp \\(4001 vertices deformed"
  ARGS deform ${data}/bunny.json ${cli_out}/run_binding.vtp
       --positions ${cli_out}/recorded/run_frames/control_00001.vtu --pieces 2
       -o ${cli_out}/deformed_pieces/one.pvtp)
tetskin_cli_test(deform_pieces_to_a_vtp FAIL STATUS 1 REQUIRES "recorded_run;run_binding"
  NOT_EXIST ${cli_out}/deformed_pieces_bad.vtp
  STDERR "^error: -o [^\n]*deformed_pieces_bad.vtp: a surface in 2 pieces is written as a .pvtp\n$"
  ARGS deform ${data}/bunny.json ${cli_out}/run_binding.vtp
       --positions ${cli_out}/recorded/run_frames/control_00001.vtu --pieces 2
       -o ${cli_out}/deformed_pieces_bad.vtp)
