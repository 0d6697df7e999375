# CLI tests of tetskin build: model generation (included by tests/cli/CMakeLists.txt).

tetskin_cli_test(build_bunny STDOUT "level +elements.*\n0 .*\n1 .*wrote .*bunny_cli.json"
  ARGS build ${data}/bunny.obj --levels 2 --min-elements 5000 --max-elements 20000
       --qualities 2.0,1.6 -o ${cli_out}/bunny_cli)
# A selection far off its targets says so, and what to change.
tetskin_cli_test(build_off_target
  STDERR "warning: level 0 has 22431 elements, 37x its target of 600\nwarning: levels 0 and 1 are the same candidate \\(22431 elements\\)\n(.*\n)?hint: the only candidate has 22431 elements. choose --min-elements and --max-elements near it, or add coarser levels of detail \\(--decimate, or --lod-series\\)\n"
  ARGS build ${data}/bunny.obj --levels 2 --qualities 2.0 -o ${cli_out}/off_target)
tetskin_cli_test(build_bad_input FAIL STDERR "^error: [^\n]*bad_index.obj:5: vertex index 4"
  NOT_EXIST ${cli_out}/bad_build.json ARGS build ${tdata}/bad_index.obj -o ${cli_out}/bad_build)
# Bad input leaves nothing behind, not even the output's folder.
tetskin_cli_test(build_bad_input_makes_no_folder FAIL STATUS 1
  STDERR "^error: [^\n]*bad_index.obj:5: vertex index 4"
  NOT_EXIST ${cli_out}/never_made ARGS build ${tdata}/bad_index.obj -o ${cli_out}/never_made/ds)
# An output folder that cannot be made is found before the meshing.
tetskin_cli_test(build_output_under_a_file FAIL STATUS 1
  STDERR "^error: [^\n]*triangle.obj/ds.json: cannot be written: [^\n]*triangle.obj is not a folder\n$"
  ARGS build ${data}/bunny.obj -o ${tdata}/triangle.obj/ds -q)
tetskin_cli_test(build_same_input_twice FAIL STATUS 1
  STDERR "^error: [^\n]*bunny.obj: is the same surface as the input [^\n]*bunny.obj. each input is a level of detail of its own\n$"
  NOT_EXIST ${cli_out}/twice
  ARGS build ${data}/bunny.obj ${data}/../data/bunny.obj -o ${cli_out}/twice/ds -q)
# Overlapping parts: the collapse closes them at a change of shape, which
# build names (and still writes the dataset).
tetskin_cli_test(build_overlapping_parts_warns
  STDERR "\nwarning: [^\n]*overlapping_cubes.obj: collapsing [0-9]+ intersecting pair\\(s\\) of triangles changed the enclosed volume by -[0-9.]+% \\(2 to [0-9.]+\\). the collapse closes small defects, not overlapping parts"
  ARGS build ${tdata}/overlapping_cubes.obj --levels 1 --min-elements 20 --max-elements 20
       -o ${cli_out}/overlapping)
tetskin_cli_test(build_other_object_refused FAIL
  STDERR "\nerror: [^\n]*cube_0.obj: is not a level of detail of [^\n]*bunny.obj: their bounding boxes share 0.1% of the volume they span together"
  NOT_EXIST ${cli_out}/mixed.json
  ARGS build ${data}/bunny.obj ${tdata}/cube_0.obj -o ${cli_out}/mixed)
tetskin_cli_test(build_unrepairable FAIL STDERR "^error: [^\n]*open_tetra.obj: cannot be repaired: the surface has 1 hole[^\n]* \\(--wrap auto wraps such inputs in a closed surface\\)\n$"
  NOT_EXIST ${cli_out}/open.json ARGS build ${tdata}/open_tetra.obj -o ${cli_out}/open -q --wrap never)
# Broken scans (tests/data/tools/make_broken_surfaces.py): --wrap auto (the
# default) wraps what repair cannot close, says so, and reports what the
# wrap cost; the input with its holes stays the surface, bound to the
# wrapped levels; an input without area is refused, nothing written.
tetskin_cli_test(build_wraps_a_holed_scan SETUP holed_dataset
  STDERR "\nwrapping [^\n]*bunny_holed.obj .alpha [0-9.]+, offset [0-9.]+. 3 hole.s. closed first.: [^\n]*cannot be repaired: the surface has 3 hole.s.[^\n]*\nwrapped [^\n]*bunny_holed.obj: [0-9]+ triangles in [0-9.]+ s. alpha 4% and offset 0.2% of the diagonal"
  STDOUT "\nlevel 1 was meshed from a wrap: alpha 4% and offset 0.2% of the diagonal [0-9.]+. input -> wrap: max [0-9.e-]+ .[0-9.e-]+%., mean [^\n]*. wrap -> input: max "
  ARGS build ${tdata}/bunny_holed.obj --decimate --levels 2 --min-elements 500
       --max-elements 3000 --wrap-alpha 0.04 -o ${cli_out}/holed)
tetskin_cli_test(build_wrap_never_refuses_a_holed_scan FAIL STATUS 1
  STDERR "^error: [^\n]*bunny_holed.obj: cannot be repaired: the surface has 3 hole.s. [^\n]*--wrap auto wraps such inputs"
  NOT_EXIST ${cli_out}/holed_never.json
  ARGS build ${tdata}/bunny_holed.obj --wrap never -o ${cli_out}/holed_never -q)
tetskin_cli_test(build_open_sheet_becomes_a_shell
  STDERR "\nwarning: [^\n]*open_sheet.obj is an open sheet, not a closed surface: it became a shell body about [0-9.e-]+ thick .twice the wrap's offset. --wrap-offset sets it.\n"
  ARGS build ${tdata}/open_sheet.obj --levels 1 --min-elements 1000 --max-elements 1000
       --wrap-alpha 0.05 --wrap-offset 0.01 -o ${cli_out}/sheet)
tetskin_cli_test(build_no_area FAIL STATUS 1
  STDERR "\nerror: [^\n]*no_area.obj: cannot be repaired: every triangle has zero area .its corners on one line or welded together., so the surface encloses nothing\n$"
  NOT_EXIST ${cli_out}/no_area.json
  ARGS build ${tdata}/no_area.obj -o ${cli_out}/no_area)
tetskin_cli_test(build_wrap_alpha_out_of_range FAIL STATUS 1
  STDERR "^error: --wrap-alpha: 2 is not in .0, 1. \\(see tetskin build --help\\)\n$"
  ARGS build ${tdata}/bunny_holed.obj --wrap-alpha 2 -o ${cli_out}/bad_alpha -q)
tetskin_cli_test(build_wrap_bad_mode FAIL STATUS 1 STDERR "^error: --wrap: [^\n]*sometimes"
  ARGS build ${tdata}/bunny_holed.obj --wrap sometimes -o ${cli_out}/bad_wrap -q)
tetskin_cli_test(build_bad_quality FAIL STATUS 1
  STDERR "^error: --qualities: 0.9 is not > 1 \\(see tetskin build --help\\)\n$"
  ARGS build ${data}/bunny.obj --qualities 2,0.9 -o ${cli_out}/q)
tetskin_cli_test(build_needs_input FAIL STDERR "no input" ARGS build -o ${cli_out}/none)
# Slivers: TetGen meshes a decimated cylinder with them; build, info and
# convert each say so for the level.
tetskin_cli_test(build_slivers SETUP sliver_cylinder
  STDERR "\nwarning: level 0 has slivers \\(smallest dihedral angle 0[.][0-9]+ deg, largest radius-edge ratio [0-9.]+\\), which slow the solvers. --mesher netgen remeshes the surface\n"
  ARGS build ${tdata}/decimated_cylinder.obj -o ${cli_out}/sliver_cylinder --levels 1
       --min-elements 4000 --max-elements 4000)
# A cantilever from a surface, end to end: Netgen meshes the decimated
# cylinder (4 m long along x, radius 0.5), --fixed-box holds its x = 0 end
# (88 nodes within 1% of the length) and sag's gravity pulls down across it
# (E 2e6 Pa, density 100).
# After 4 s of damped sag the tip has come down 0.2499 m: Euler-Bernoulli's
# q L^4 / (8 E I) is 0.2511, Timoshenko's (with shear) 0.2626; the test
# takes 0.24 to 0.26. The held end carries the beam's weight: 310.231 kg
# times 9.81 is 3043.37 N (3043.67 after the 4 s; the test takes 3043 to
# 3044.99 up, along y).
tetskin_cli_test(build_cantilever SETUP cantilever
  ARGS build ${tdata}/decimated_cylinder.obj -o ${cli_out}/cantilever --mesher netgen --levels 2
       --min-elements 1000 --max-elements 10000 --size-to-targets -q)
tetskin_cli_test(build_lod_series STDOUT "level +elements.*\n0 .*wrote .*lod.json"
  ARGS build --lod-series ${tdata}/cube --inputs 2 --levels 1 --min-elements 5 --max-elements 50
       -o ${cli_out}/lod -q)
# A box gives a few elements at every quality: the hint names sizing, and
# sizing gives levels under volume bounds, which info shows.
tetskin_cli_test(build_box_hints_sizing
  STDERR "hint: the 5 candidates all have 6 elements. choose --min-elements and --max-elements near that[^\n]*. --size-to-targets meshes under size bounds aimed at the targets\n"
  ARGS build ${tdata}/cube_0.obj --levels 2 --min-elements 200 --max-elements 2000
       -o ${cli_out}/box_plain)
tetskin_cli_test(build_box_sized SETUP sized_box
  STDOUT "level +elements.*\n0 +[0-9]+ +[0-9]+  tetgen +q[0-9.]+ a[0-9.e-]+ .*\n1 +[0-9]+ +[0-9]+  tetgen +q[0-9.]+ a[0-9.e-]+ .*\n[0-9]+ candidates meshed"
  ARGS build ${tdata}/cube_0.obj --levels 2 --min-elements 200 --max-elements 2000
       --size-to-targets -o ${cli_out}/box_sized -q)
# A hollow cube: repair names the cavity, and every level leaves it empty
# (the wall's volume, 27 - 1).
tetskin_cli_test(build_hollow SETUP hollow_box
  STDERR "repaired [^\n]*hollow_cube.obj: input_vertices=16 input_triangles=24 cavities=1 output_vertices=16"
  ARGS build ${tdata}/hollow_cube.obj --levels 2 --min-elements 200 --max-elements 2000
       --size-to-targets -o ${cli_out}/hollow_box)
# A cube meshed face by face, every edge a seam of T-junctions: repair
# splits them and the cube is meshed whole (before, its open edges ate it).
tetskin_cli_test(build_t_junctions SETUP t_junction_box
  STDERR "repaired [^\n]*t_junction_cube.obj: input_vertices=58 input_triangles=86 t_junctions_split=26 output_vertices=58 output_triangles=112"
  ARGS build ${tdata}/t_junction_cube.obj --levels 2 --min-elements 200 --max-elements 2000
       --size-to-targets -o ${cli_out}/t_junction_box)
tetskin_cli_test(build_polygon_faces SETUP polygon_prism
  STDERR "repaired [^\n]*l_prism.obj: input_vertices=12 input_triangles=20 output_vertices=12"
  ARGS build ${tdata}/l_prism.obj --levels 2 --min-elements 200 --max-elements 2000
       --size-to-targets -o ${cli_out}/l_prism)
# A thin plate: TetGen's quality bound refines it to its thickness whatever
# the surface; the hint names Netgen, not decimation.
tetskin_cli_test(build_thin_plate_hints_netgen
  STDERR "hint: the only candidate has 12[0-9]+ elements. choose --min-elements and --max-elements near it. the fewest are [0-9]+x the input's 12 triangles, so the shape, not its surface, sets them .thin parts refine under TetGen's quality bound.: --mesher netgen meshes thin shapes coarser\n"
  ARGS build ${tdata}/thin_plate.obj -o ${cli_out}/thin_plate)
# The up axis: build records it, info shows it, simulate's scenarios,
# floor and default gravity follow it (--up overrides the config's).
tetskin_cli_test(build_up_z SETUP up_z_box
  ARGS build ${tdata}/cube_0.obj --up z --levels 1 --min-elements 200 --max-elements 200
       --size-to-targets -o ${cli_out}/up_z_box -q)
tetskin_cli_test(build_one_level_pair SETUP one_level_pair
  ARGS build ${tdata}/cube_0.obj --levels 1 --qualities 1.4 -o ${cli_out}/tetgen_pair/cube -q)
tetskin_cli_test(build_lod_series_missing FAIL STDERR "^error: [^\n]*cube_2.obj: cannot open"
  ARGS build --lod-series ${tdata}/cube --inputs 3 -o ${cli_out}/lod3 -q)
# Faithful levels (#68): fins no level of 12000 elements can follow are
# refused with the level, its distance, the bound and the ways out, and
# nothing is written; --accept-unfaithful writes the level, its config
# records that it lies beyond its bound, and info warns.
tetskin_cli_test(build_refuses_an_unfaithful_level FAIL STATUS 1
  STDERR "^error: level 2 .target 12000 elements. has no faithful candidate near its target: the nearest, [^\n]*nonmanifold_fins.obj [^\n]* lies off the input by [0-9.]+% of the diagonal at worst .at most [0-9.]+% for its element size [0-9.]+%.. the nearest faithful candidate has [0-9]+ elements. Ways out: [^\n]*--accept-unfaithful to write it anyway\n.nothing was written. the bound is 0.5 of the element size on average and 2 at worst.\n$"
  NOT_EXIST ${cli_out}/fins_refused.json
  ARGS build ${tdata}/nonmanifold_fins.obj --decimate -q -o ${cli_out}/fins_refused)
tetskin_cli_test(build_accept_unfaithful SETUP unfaithful_dataset
  STDOUT "wrote [^\n]*fins_accepted.json"
  ARGS build ${tdata}/nonmanifold_fins.obj --decimate -q --accept-unfaithful
       -o ${cli_out}/fins_accepted)
tetskin_cli_test(info_warns_of_an_unfaithful_level REQUIRES unfaithful_dataset
  STDOUT "\n  level 2 against the input: input -> level: [^\n]* .beyond its bound: accepted by the user.\n[^\n]*\n?  warning: level 2 lies off its input beyond its fidelity bound .written with --accept-unfaithful.\n"
  ARGS info ${cli_out}/fins_accepted.json)
