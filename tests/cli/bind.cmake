# CLI tests of tetskin bind (included by tests/cli/CMakeLists.txt).

tetskin_cli_test(bind_zero_area_triangle
  STDERR "^warning: [^\n]*zero_area_triangle.obj: 1 triangle of zero area \\(first: triangle 1\\). 1 vertex without a normal, in no triangle of positive area \\(first: vertex 3\\)\n$"
  STDOUT "bound 4 vertices to level 2.*wrote [^\n]*zero_area.vtp"
  ARGS bind ${data}/bunny.json ${tdata}/zero_area_triangle.obj -o ${cli_out}/zero_area.vtp)
tetskin_cli_test(bind_far_surface_warns SETUP far_binding
  STDERR "^warning: [^\n]*far_tetrahedron.obj: a tenth of the vertices lie more than [0-9]+% of level 2's diagonal from its boundary: is the surface the dataset's object, placed and scaled as it is\\?\n$"
  STDOUT "bound 4 vertices to level 2.*wrote [^\n]*far.vtp"
  ARGS bind ${data}/bunny.json ${tdata}/far_tetrahedron.obj -o ${cli_out}/far.vtp)
# Outputs of a fixed format must carry its extension, checked before any work.
tetskin_cli_test(bind_output_not_vtp FAIL STATUS 1
  STDERR "^error: --output: '[^\n]*binding.obj' does not end in .vtp \\(see tetskin bind --help\\)\n$"
  NOT_EXIST ${cli_out}/binding.obj
  ARGS bind ${data}/bunny.json ${data}/bunny.obj -o ${cli_out}/binding.obj)
tetskin_cli_test(bind_into_a_new_folder FRESH ${cli_out}/new_bind
  STDOUT "wrote [^\n]*new_bind/bunny.vtp\n"
  ARGS bind ${data}/bunny.json ${data}/bunny.obj -o ${cli_out}/new_bind/bunny.vtp)
tetskin_cli_test(bind_holed_scan_to_wrapped_level REQUIRES holed_dataset
  STDOUT "bound 1616 vertices to level 1 [^\n]*\n[^\n]*\n.*  wrapped level:      [^\n]*bunny_holed.obj[^\n]* was alpha-wrapped for it: alpha 4% and offset 0.2% of the diagonal [^\n]*. vertices in the input's holes and gaps bind to their closest boundary triangle\n"
  ARGS bind ${cli_out}/holed.json ${tdata}/bunny_holed.obj -o ${cli_out}/holed_bound.vtp)

tetskin_cli_test(bind_bunny SETUP binding
  STDOUT "bound 1839 vertices to level 2 \\(method closest, offset normal\\).*all weights >= 0: .*wrote"
  ARGS bind ${data}/bunny.json ${data}/bunny.obj -o ${cli_out}/bunny_binding.vtp)
tetskin_cli_test(bind_embed_level0 SETUP embed_binding STDOUT "to level 0 \\(method embed\\)\n"
  ARGS bind ${data}/bunny.json ${data}/bunny.obj --level 0 --method embed
       -o ${cli_out}/bunny_embed.vtp)
# Either offset deforms an embedded vertex alike (binding_tests' accuracy
# table): asking for one with embed is refused, not silently ignored.
tetskin_cli_test(bind_embed_with_offset FAIL STATUS 1
  STDERR "^error: --offset: applies to the closest and seed methods, not to embed \\(an embedded vertex is its tetrahedron's barycentric combination, with no offset\\)\n$"
  NOT_EXIST ${cli_out}/embed_offset.vtp
  ARGS bind ${data}/bunny.json ${data}/bunny.obj --method embed --offset normal
       -o ${cli_out}/embed_offset.vtp)
tetskin_cli_test(bind_bad_level FAIL STDERR "^error: level 5 does not exist"
  NOT_EXIST ${cli_out}/bad_level.vtp
  ARGS bind ${data}/bunny.json ${data}/bunny.obj --level 5 -o ${cli_out}/bad_level.vtp)
tetskin_cli_test(bind_bad_negative_level FAIL STATUS 1
  STDERR "^error: level -4 does not exist: the dataset has levels 0..2 \\(or -3..-1 counted from the finest\\)\n$"
  NOT_EXIST ${cli_out}/bad_level.vtp
  ARGS bind ${data}/bunny.json ${data}/bunny_8k.obj --level -4 -o ${cli_out}/bad_level.vtp)
tetskin_cli_test(bind_level_from_the_finest STDOUT "bound 4001 vertices to level 0 "
  ARGS bind ${data}/bunny.json ${data}/bunny_8k.obj --level -3 -o ${cli_out}/level_from_finest.vtp)
tetskin_cli_test(bind_arguments_swapped FAIL STATUS 1
  STDERR "^error: [^\n]*bunny.obj: is not a dataset \\(expected its .json config, a .node/.ele pair, a Gmsh .msh or a MEDIT .mesh\\)\n$"
  NOT_EXIST ${cli_out}/swapped.vtp
  ARGS bind ${data}/bunny.obj ${data}/bunny.json -o ${cli_out}/swapped.vtp)
tetskin_cli_test(bind_bad_method FAIL STDERR "method: nearest not in" ARGS bind ${data}/bunny.json
  ${data}/bunny.obj --method nearest -o ${cli_out}/x.vtp)
tetskin_cli_test(bind_medit_mesh REQUIRES medit_level STDOUT "bound 4001 vertices to level 0 "
  ARGS bind ${cli_out}/level0.mesh ${data}/bunny_8k.obj -o ${cli_out}/medit_bound.vtp)
# A recorded run's control frames applied to a binding (deform --positions
# RUN.pvd): the surface series simulate --surface wrote beside them, file
# for file.
tetskin_cli_test(bind_for_recorded_run SETUP run_binding
  ARGS bind ${data}/bunny.json ${data}/bunny_8k.obj -o ${cli_out}/run_binding.vtp)

# --compress (issue #56): the .vtp's data in zlib, lz4 (the default, as
# bind_bunny wrote it) or none; another name is refused before any work.
tetskin_cli_test(bind_compressed_with_zlib SETUP zlib_binding
  ARGS bind ${data}/bunny.json ${data}/bunny.obj --compress zlib -o ${cli_out}/bunny_zlib.vtp)
add_test(NAME cli.bind_compression_in_the_file COMMAND ${CMAKE_COMMAND}
  -DFILES=${cli_out}/bunny_zlib.vtp|${cli_out}/bunny_binding.vtp
  -DTEXTS=vtkZLibDataCompressor|vtkLZ4DataCompressor
  -P ${CMAKE_CURRENT_SOURCE_DIR}/CheckFileHeads.cmake)
set_tests_properties(cli.bind_compression_in_the_file PROPERTIES LABELS cli
  FIXTURES_REQUIRED "zlib_binding;binding")
tetskin_cli_test(bind_unknown_compression FAIL STATUS 1 NOT_EXIST ${cli_out}/bunny_gzip.vtp
  STDERR "^error: --compress: gzip not in {none,zlib,lz4} .see tetskin bind --help.\n$"
  ARGS bind ${data}/bunny.json ${data}/bunny.obj --compress gzip -o ${cli_out}/bunny_gzip.vtp)
