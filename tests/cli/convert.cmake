# CLI tests of tetskin convert (included by tests/cli/CMakeLists.txt).

tetskin_cli_test(convert_obj_to_vtp STDOUT "wrote .*1839 vertices, 3674 triangles"
  ARGS convert ${data}/bunny.obj ${cli_out}/bunny.vtp)
tetskin_cli_test(convert_bad_leaves_nothing FAIL STDERR "^error: [^\n]*bad_index.obj:5:"
  NOT_EXIST ${cli_out}/bad.vtp ARGS convert ${tdata}/bad_index.obj ${cli_out}/bad.vtp)
# Every command makes the folders its output lacks (before, only build and
# simulate did; bind, deform, convert and render refused "... does not
# exist"), and only once it writes: bad input leaves no folder behind.
tetskin_cli_test(convert_into_new_folders FRESH ${cli_out}/new_convert
  STDOUT "wrote [^\n]*new_convert/a/b.ply .1839 vertices"
  ARGS convert ${data}/bunny.obj ${cli_out}/new_convert/a/b.ply)
tetskin_cli_test(convert_bad_input_makes_no_folder FAIL STATUS 1 FRESH ${cli_out}/new_bad
  STDERR "^error: [^\n]*bad_index.obj:5: vertex index 4 is out of range"
  NOT_EXIST ${cli_out}/new_bad
  ARGS convert ${tdata}/bad_index.obj ${cli_out}/new_bad/x.ply)
tetskin_cli_test(convert_slivers_to_vtu REQUIRES sliver_cylinder SETUP sliver_vtu
  ARGS convert ${cli_out}/sliver_cylinder.json ${cli_out}/sliver_cylinder.vtu)
tetskin_cli_test(convert_slivers_to_dataset REQUIRES sliver_vtu
  STDERR "^warning: level 0 \\([^\n]*sliver_cylinder.vtu\\) has slivers \\(smallest dihedral angle 0[.][0-9]+ deg, [^\n]*\\), which slow the solvers\n$"
  ARGS convert ${cli_out}/sliver_cylinder.vtu ${cli_out}/sliver_imported.json)
# Tetrahedral meshes made elsewhere, one per level, make a dataset: the
# Gmsh-like cube (lower cells, an unused point, the other orientation) and
# the bunny's levels 0 and 2 round trip (simulated by multigrid over them).
tetskin_cli_test(convert_mesh_to_dataset SETUP imported_cube
  STDOUT "\n0 +6 +8 +45.00 +0.866  [^\n]*gmsh_like_cube.vtu .13 lower cells left out. .1 unused points dropped. .6 inverted elements turned.\nwrote [^\n]*imported_cube.json"
  ARGS convert ${tdata}/gmsh_like_cube.vtu ${cli_out}/imported_cube.json)
tetskin_cli_test(convert_level0_for_import SETUP level0_vtu
  ARGS convert ${data}/bunny.json ${cli_out}/import_level0.vtu --level 0)
tetskin_cli_test(convert_meshes_to_dataset REQUIRES level_vtu level0_vtu SETUP imported_bunny
  STDOUT "\n0 +598 +224 [^\n]*import_level0.vtu\n1 +12713 +3270 [^\n]*level2.vtu\nwrote "
  ARGS convert ${cli_out}/level2.vtu ${cli_out}/import_level0.vtu ${cli_out}/imported_bunny.json)
tetskin_cli_test(convert_meshes_of_other_objects FAIL STATUS 1 REQUIRES level_vtu
  STDERR "^error: [^\n]*gmsh_like_cube.vtu: is not a level of detail of [^\n]*level2.vtu: their bounding boxes share"
  NOT_EXIST ${cli_out}/mixed_import.json
  ARGS convert ${tdata}/gmsh_like_cube.vtu ${cli_out}/level2.vtu ${cli_out}/mixed_import.json)
tetskin_cli_test(convert_several_to_a_surface FAIL STATUS 1 REQUIRES level_vtu
  STDERR "^error: [^\n]*x.obj: several inputs convert only to a dataset"
  ARGS convert ${tdata}/gmsh_like_cube.vtu ${cli_out}/level2.vtu ${cli_out}/x.obj)
tetskin_cli_test(convert_flat_tetrahedron FAIL STATUS 1
  STDERR "^error: [^\n]*flat_tetrahedron.vtu: cell 2, a tetrahedron, has volume 0 .degenerate.\n$"
  NOT_EXIST ${cli_out}/flat_import.json
  ARGS convert ${tdata}/flat_tetrahedron.vtu ${cli_out}/flat_import.json)
tetskin_cli_test(convert_surface_to_dataset FAIL STATUS 1
  STDERR "^error: [^\n]*bunny.obj: is not tetrahedra \\(.vtu, Gmsh .msh, MEDIT .mesh, or a TetGen .node/.ele pair\\): a dataset is made of one tetrahedral mesh per level\n$"
  ARGS convert ${data}/bunny.obj ${cli_out}/from_surface.json)
# Gmsh volume meshes (.msh, as Gmsh 4.8 wrote them: tests/data/gmsh) and
# TetGen .node/.ele pairs make datasets too, mixed with .vtu as it comes.
tetskin_cli_test(convert_gmsh_to_dataset SETUP gmsh_dataset
  STDOUT "\n0 +679 +205 [^\n]*sphere_coarse_v41.msh .320 lower cells left out.\n1 +898 +258 [^\n]*sphere_fine_v22.msh .380 lower cells left out.\nwrote "
  ARGS convert ${tdata}/gmsh/sphere_fine_v22.msh ${tdata}/gmsh/sphere_coarse_v41.msh
       ${cli_out}/gmsh_sphere.json)
# A Gmsh mesh alone to .vtu for ParaView, and to its boundary: the 320
# triangles Gmsh wrote for the sphere's surface.
tetskin_cli_test(convert_gmsh_to_vtu SETUP gmsh_vtu
  STDOUT "wrote [^\n]*gmsh_sphere.vtu \\(level 0: 205 nodes, 679 tetrahedra\\)\n$"
  ARGS convert ${tdata}/gmsh/sphere_coarse_v41.msh ${cli_out}/gmsh_sphere.vtu)
tetskin_cli_test(convert_gmsh_to_surface SETUP gmsh_surface
  STDOUT "wrote [^\n]*gmsh_sphere.obj \\(the boundary of level 0: 162 vertices, 320 triangles\\)\n$"
  ARGS convert ${tdata}/gmsh/sphere_coarse_v41.msh ${cli_out}/gmsh_sphere.obj)
tetskin_cli_test(convert_gmsh_to_png FAIL STATUS 1
  STDERR "^error: [^\n]*sphere.png: a dataset converts to .vtu"
  ARGS convert ${tdata}/gmsh/sphere_coarse_v41.msh ${cli_out}/sphere.png)
# MEDIT .mesh: a level out (nodes, boundary triangles, tetrahedra) and back
# in, as a one-level dataset, into a dataset, and described by info.
tetskin_cli_test(convert_level_to_medit SETUP medit_level
  STDOUT "wrote [^\n]*level0.mesh \\(level 0: 224 nodes, 422 boundary triangles, 598 tetrahedra\\)\n$"
  ARGS convert ${data}/bunny.json --level 0 ${cli_out}/level0.mesh)
tetskin_cli_test(convert_medit_to_dataset REQUIRES medit_level
  STDOUT "\n0 +598 +224 [^\n]*level0.mesh .422 lower cells left out.\nwrote "
  ARGS convert ${cli_out}/level0.mesh ${cli_out}/medit_dataset.json)
tetskin_cli_test(convert_medit_truncated FAIL STATUS 1
  STDERR "^error: [^\n]*truncated.mesh:[0-9]+: Tetrahedra count 598 is more than the rest of the file can hold \\(truncated or corrupt file\\?\\)\n$"
  NOT_EXIST ${cli_out}/truncated_medit.json
  ARGS convert ${tdata}/truncated.mesh ${cli_out}/truncated_medit.json)
tetskin_cli_test(convert_gmsh_hexahedron FAIL STATUS 1
  STDERR "^error: [^\n]*hexahedron.msh:17: element 1 is a hexahedron: a dataset is made of tetrahedra \\(mesh with tetrahedra only\\)\n$"
  NOT_EXIST ${cli_out}/gmsh_hex.json
  ARGS convert ${tdata}/gmsh/hexahedron.msh ${cli_out}/gmsh_hex.json)
tetskin_cli_test(convert_tetgen_pair_to_dataset REQUIRES one_level_pair
  STDOUT "\n0 +[1-9][0-9]* +[1-9][0-9]* [^\n]*tetgen_pair/cube.ele\nwrote [^\n]*cube_imported.json"
  ARGS convert ${cli_out}/tetgen_pair/cube.ele ${cli_out}/cube_imported.json)
tetskin_cli_test(convert_level_vtu SETUP level_vtu STDOUT "wrote .*level 2: 3270 nodes, 12713 tetrahedra"
  ARGS convert ${data}/bunny.json ${cli_out}/level2.vtu --level 2)
# The output's ending in any letter case, as everywhere.
tetskin_cli_test(convert_level_upper_case_ending STDOUT "wrote [^\n]*level0.VTU \\(level 0: "
  ARGS convert ${data}/bunny.json ${cli_out}/level0.VTU --level 0)
# Tetrahedra (a level from convert, a run's frame) and a dataset's level
# convert to the surface of their boundary: closed, with the level's
# volume; other outputs, and inputs convert does not take, are named.
tetskin_cli_test(convert_level_to_boundary SETUP level0_boundary
  STDOUT "wrote [^\n]*level0_boundary.obj \\(the boundary of level 0: 213 vertices, 422 triangles\\)\n$"
  ARGS convert ${data}/bunny.json --level 0 ${cli_out}/level0_boundary.obj)
tetskin_cli_test(convert_tetrahedra_to_boundary REQUIRES level_vtu
  STDOUT "wrote [^\n]*level2_boundary.stl \\(the boundary of 12713 tetrahedra: [0-9]+ vertices, [0-9]+ triangles\\)\n$"
  ARGS convert ${cli_out}/level2.vtu ${cli_out}/level2_boundary.stl)
tetskin_cli_test(convert_frame_to_boundary REQUIRES first_run
  STDOUT "wrote [^\n]*frame_boundary.vtp \\(the boundary of 598 tetrahedra: 213 vertices, 422 triangles\\)\n$"
  ARGS convert ${cli_out}/first_run_frames/control_00003.vtu ${cli_out}/frame_boundary.vtp)
tetskin_cli_test(convert_tetrahedra_to_vtu FAIL STATUS 1 REQUIRES level_vtu
  STDERR "^error: [^\n]*level2_copy.vtu: tetrahedra \\(.vtu\\) convert to a surface \\(.obj .ply .stl .vtp: their boundary\\)\n$"
  NOT_EXIST ${cli_out}/level2_copy.vtu
  ARGS convert ${cli_out}/level2.vtu ${cli_out}/level2_copy.vtu)
tetskin_cli_test(convert_series_is_not_taken FAIL STATUS 1 REQUIRES first_run
  STDERR "^error: [^\n]*first_run.pvd: is neither a surface \\(.obj .ply .stl .vtp\\), a dataset \\(.json, or a .node/.ele pair, a Gmsh .msh, a MEDIT .mesh\\) nor tetrahedra \\(.vtu\\): convert takes those\n$"
  NOT_EXIST ${cli_out}/series.obj
  ARGS convert ${cli_out}/first_run.pvd ${cli_out}/series.obj)
tetskin_cli_test(convert_surface_with_level FAIL STATUS 1
  STDERR "^error: --level: applies to a dataset's conversion, not to a surface's\n$"
  NOT_EXIST ${cli_out}/level_surface.vtp
  ARGS convert ${data}/bunny.obj ${cli_out}/level_surface.vtp --level 1)
