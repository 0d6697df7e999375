# CLI tests of tetskin info (included by tests/cli/CMakeLists.txt).

# (No warning after the bounds: every vertex of the bunny has a normal.)
tetskin_cli_test(info_bunny STDOUT "vertices +1839.*triangles +3674.*diagonal [0-9.]+\n$" ARGS info ${data}/bunny.obj)
tetskin_cli_test(info_zero_area_triangle
  STDOUT "diagonal [0-9.]+\n  warning: 1 triangle of zero area \\(first: triangle 1\\). 1 vertex without a normal, in no triangle of positive area \\(first: vertex 3\\)\n$"
  ARGS info ${tdata}/zero_area_triangle.obj)
# Whether a surface is closed, as build needs it, and what it encloses.
tetskin_cli_test(info_hollow_surface
  STDOUT "area +60\n  closed +yes: 2 parts, 1 bounding a cavity. volume 26\n  bounds"
  ARGS info ${tdata}/hollow_cube.obj)
tetskin_cli_test(info_open_surface STDOUT "\n  closed +no: 1 chain of open edges "
  ARGS info ${tdata}/open_tetra.obj)
tetskin_cli_test(info_t_junction_surface
  STDOUT "\n  closed +yes once build splits 26 T-junctions: 1 part. volume 1\n"
  ARGS info ${tdata}/t_junction_cube.obj)
# A triangle soup is closed once welded, as build welds it (before, info
# counted 4 chains of open edges).
tetskin_cli_test(info_triangle_soup
  STDOUT "\n  closed +yes once build welds 8 duplicate vertices: 1 part. volume 0.166667\n"
  ARGS info ${tdata}/soup_tetra.obj)
# Degenerate and duplicate triangles, which build removes, do not open it.
tetskin_cli_test(info_degenerate_and_duplicate_triangles
  STDOUT "\n  closed +yes once build removes 1 degenerate triangle and 1 duplicate triangle: 1 part. volume 0.166667\n"
  ARGS info ${tdata}/tetra_degenerate_duplicate.obj)
# Non-convex polygon faces are clipped, not fanned over their notch.
tetskin_cli_test(info_polygon_faces
  STDOUT "\n  triangles +20\n.*\n  area +14\n  closed +yes: 1 part. volume 3\n"
  ARGS info ${tdata}/l_prism.obj)
tetskin_cli_test(info_overlapping_surface
  STDOUT "\n  closed +yes: 2 parts, triangles intersecting .build collapses them.. volume 2 counting overlaps twice\n"
  ARGS info ${tdata}/overlapping_cubes.obj)
tetskin_cli_test(info_bad_obj FAIL
  STDERR "^error: [^\n]*bad_index.obj:5: vertex index 4 is out of range"
  ARGS info ${tdata}/bad_index.obj)
tetskin_cli_test(simulate_blown_up_frames_read_back REQUIRES blown_up_run
  STDOUT "blown_up.pvd: time series, 2 time steps, t 0 .. 0.0166667\n  part 0     2 files, [^\n]*, all present\n  level      0 \\(of the control-mesh frames\\)\n  prescribed 35 nodes \\(held still or driven\\)\n[^\n]*control_00001.vtu: tetrahedral mesh\n  nodes      224\n"
  ARGS info ${cli_out}/blown_up.pvd ${cli_out}/blown_up_frames/control_00001.vtu)
tetskin_cli_test(info_wrapped_dataset REQUIRES holed_dataset
  STDOUT "  1 +[0-9]+ +[0-9]+ [^\n]*bunny_holed.obj[^\n]* tetgen q[0-9.]+ .wrapped.\n  level 0 wrap: alpha 4% and offset 0.2% of the diagonal [^\n]*\n  level 0 against the input: input -> level: mean [0-9.e-]+ .[0-9.e-]+% of the diagonal., max [^\n]*. element size [0-9.e-]+\n  level 1 wrap: alpha "
  ARGS info ${cli_out}/holed.json)
tetskin_cli_test(info_slivers REQUIRES sliver_cylinder
  STDOUT "  0 +[0-9]+ +[0-9]+ +[0-9.]+ +[0-9.e-]+ +0[.][0-9]+  [^\n]*decimated_cylinder.obj tetgen q[0-9.]+\n  level 0 against the input: input -> level: mean 0 .0% of the diagonal., max 0 .0%.[^\n]*\n  warning: level 0 has slivers \\(smallest dihedral angle 0[.][0-9]+ deg, [^\n]*\\), which slow the solvers\n$"
  ARGS info ${cli_out}/sliver_cylinder.json)
tetskin_cli_test(info_cantilever_deflection REQUIRES cantilever_run
  STDOUT "\n  point data Displacement \\(3 components\\): length 0 [.][.] 0[.]2[45][0-9]*\n.*\n  forces     external 0,0,0 N, reaction [-0-9.e]+,304[34][.][0-9]+,[-0-9.e]+ N in all\n$"
  ARGS info ${cli_out}/cantilever_run_frames/control_00001.vtu)
tetskin_cli_test(info_sample_dataset STDOUT "3 level\\(s\\).*\n.*\n.*level.*\n  0 +[0-9]+ +598 .*\n  2 +[0-9]+ +12713"
  ARGS info ${data}/bunny.json)
tetskin_cli_test(info_binding REQUIRES binding
  STDOUT "bunny_binding.vtp: binding\n  vertices +1839\n.*  dataset +${data}/bunny.json\nbound 1839 vertices to level 2 \\(method closest, offset normal\\)\n  all weights >= 0: [^\n]*\n  .distance. / diag: [^\n]*\n  most negative weight: [^\n]*\n  farthest: [^\n]*\n$"
  ARGS info ${cli_out}/bunny_binding.vtp)
# info looks the binding's dataset up (named from the binding's folder) and
# says what bind said of the fit, or that the dataset is not there.
tetskin_cli_test(info_far_binding REQUIRES far_binding
  STDOUT "  dataset +${data}/bunny.json\n.*\n  warning: a tenth of the vertices lie more than [0-9]+% of level 2's diagonal from its boundary: [^\n]*\n$"
  ARGS info ${cli_out}/far.vtp)
tetskin_cli_test(info_binding_without_its_dataset
  STDOUT "  dataset +${tdata}/no_such_folder/bunny.json\n.*\n  warning: its dataset ${tdata}/no_such_folder/bunny.json is not there \\(moved without the binding\\?\\)\n$"
  ARGS info ${tdata}/binding_of_a_missing_dataset.vtp)
tetskin_cli_test(info_deformed_surface REQUIRES deformed
  STDOUT "bunny_deformed.vtp: binding, deformed \\(its rest shape: points - Displacement\\)\n.*bound 1839 vertices to level 2"
  ARGS info ${cli_out}/bunny_deformed.vtp)
tetskin_cli_test(info_frame_names_its_dataset REQUIRES relative_run
  STDOUT "surface_00001.vtp: binding, deformed [^\n]*\n.*  dataset +${data}/bunny.json\nbound 3 vertices to level 0 [^\n]*\n  all[^\n]*\n  [^\n]*\n  [^\n]*\n  farthest[^\n]*\n$"
  ARGS info ${cli_out}/relative_run_frames/surface_00001.vtp)
tetskin_cli_test(info_deformed_names_its_dataset REQUIRES relative_deformed
  STDOUT "  dataset +${data}/bunny.json\nbound 3 vertices"
  ARGS info ${cli_out}/relative_deformed.vtp)
tetskin_cli_test(info_every_run REQUIRES every_run
  STDOUT "every.pvd: time series, 4 time steps, t 0 .. 0.0833333\n"
  ARGS info ${cli_out}/every.pvd)
tetskin_cli_test(info_inverted_element
  STDOUT "level 0 has 1 inverted or degenerate element\\(s\\) \\(first: element 0\\)"
  ARGS info ${tdata}/inverted_tet.node)
tetskin_cli_test(info_sized_box REQUIRES sized_box
  STDOUT "  0 +[0-9]+ +[0-9]+ +1 +[0-9.e-]+  [^\n]*cube_0.obj tetgen q[0-9.]+ a[0-9.e-]+\n  1 "
  ARGS info ${cli_out}/box_sized.json)
tetskin_cli_test(info_hollow_box REQUIRES hollow_box
  STDOUT "  0 +[0-9]+ +[0-9]+ +26 +[0-9.e-]+  [^\n]*\n  1 +[0-9]+ +[0-9]+ +26 +[0-9.e-]+  "
  ARGS info ${cli_out}/hollow_box.json)
tetskin_cli_test(info_t_junction_box REQUIRES t_junction_box
  STDOUT "  0 +[0-9]+ +[0-9]+ +1 +[0-9.e-]+  [^\n]*\n  1 +[0-9]+ +[0-9]+ +1 +[0-9.e-]+  "
  ARGS info ${cli_out}/t_junction_box.json)
tetskin_cli_test(info_polygon_prism REQUIRES polygon_prism
  STDOUT "  0 +[0-9]+ +[0-9]+ +3 +[0-9.e-]+  [^\n]*\n  1 +[0-9]+ +[0-9]+ +3 +[0-9.e-]+  "
  ARGS info ${cli_out}/l_prism.json)
tetskin_cli_test(info_up_z REQUIRES up_z_box STDOUT "\n  up +z\n  elasticity "
  ARGS info ${cli_out}/up_z_box.json)
tetskin_cli_test(info_imported_cube REQUIRES imported_cube
  STDOUT "  0 +8 +6 +1 +0.166667  [^\n]*gmsh_like_cube.vtu imported\n"
  ARGS info ${cli_out}/imported_cube.json)
tetskin_cli_test(info_gmsh_vtu REQUIRES gmsh_vtu
  STDOUT "tetrahedral mesh\n  nodes      205\n  elements   679\n  volume     4.04217 "
  ARGS info ${cli_out}/gmsh_sphere.vtu)
tetskin_cli_test(info_gmsh_surface REQUIRES gmsh_surface
  STDOUT "  closed     yes: 1 part. volume 4.04217\n"
  ARGS info ${cli_out}/gmsh_sphere.obj)
tetskin_cli_test(info_gmsh
  STDOUT "sphere_coarse_v41.msh: Gmsh mesh\n  nodes      205\n  elements   679 tetrahedra \\(320 elements of lower dimension left out\\)\n  volume     4.04217 "
  ARGS info ${tdata}/gmsh/sphere_coarse_v41.msh)
# Binary Gmsh files (as Gmsh 4.8 wrote them: the same sphere) wherever the
# ASCII ones go.
tetskin_cli_test(info_gmsh_binary
  STDOUT "sphere_coarse_v22_binary.msh: Gmsh mesh\n  nodes      205\n  elements   679 tetrahedra \\(320 elements of lower dimension left out\\)\n  volume     4.04217 "
  ARGS info ${tdata}/gmsh/sphere_coarse_v22_binary.msh)
tetskin_cli_test(info_medit REQUIRES medit_level
  STDOUT "level0.mesh: MEDIT mesh\n  nodes      224\n  elements   598 tetrahedra \\(422 elements of lower dimension left out\\)\n  volume     181.532 "
  ARGS info ${cli_out}/level0.mesh)
tetskin_cli_test(info_level_boundary REQUIRES level0_boundary
  STDOUT "\n  closed +yes: 1 part. volume 181.532\n"
  ARGS info ${cli_out}/level0_boundary.obj)
tetskin_cli_test(info_level_vtu REQUIRES level_vtu
  STDOUT "level2.vtu: tetrahedral mesh\n  nodes +3270\n  elements +12713\n  volume .*cell data  Level \\(1 component\\): range 2 .. 2\n$"
  ARGS info ${cli_out}/level2.vtu)
tetskin_cli_test(info_simulated_frame REQUIRES twist_run
  STDOUT "control_00005.vtu: tetrahedral mesh\n  nodes +224\n  elements +598\n.*point data Displacement \\(3 components\\): length [-0-9.e]+ .. [-0-9.e]+\n +Velocity .*\n +Prescribed \\(1 component\\): range 0 .. 1\n  cell data  VonMisesStress \\(1 component\\): range"
  ARGS info ${cli_out}/twist_frames/control_00005.vtu)
tetskin_cli_test(info_series REQUIRES twist_run
  STDOUT "twist.pvd: time series, 6 time steps, t 0 .. 0.0833333\n  part 0 +6 files, twist_frames/control_00000.vtu .. twist_frames/control_00005.vtu, all present\n  level +0 \\(of the control-mesh frames\\)\n  prescribed 62 nodes \\(held still or driven\\)\n$"
  ARGS info ${cli_out}/twist.pvd)
tetskin_cli_test(info_series_with_ampersand REQUIRES ampersand_run
  STDOUT "a&b.pvd: time series, 3 time steps.*a&b_frames/control_00002.vtu, all present"
  ARGS info ${cli_out}/a&b.pvd)
tetskin_cli_test(info_unknown_kind FAIL STATUS 1
  STDERR "^error: [^\n]*bunny_texture.png: info reads surfaces \\(.obj .ply .stl .vtp .pvtp\\), tetrahedral meshes \\(.vtu, Gmsh .msh, MEDIT .mesh\\), time series \\(.pvd\\) and datasets \\(.json .node .ele\\), not '.png' files\n$"
  ARGS info ${data}/bunny_texture.png)
tetskin_cli_test(info_drop_run_floor REQUIRES drop_run
  STDOUT "  level      0 \\(of the control-mesh frames\\)\n  floor      y = 0.0129493\n$"
  ARGS info ${cli_out}/drop/run.pvd)
