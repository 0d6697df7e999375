# CLI tests of tetskin compare (included by tests/cli/CMakeLists.txt).

# The bunny's levels over its wobble: the finer level is the closer one.
# (Label long: it simulates the 12.7k level, 141 s in the sanitized Debug
# build, which LevelComparisonTest's small blocks cover there.)
add_test(NAME cli.compare_levels_of_the_bunny
  COMMAND ${CMAKE_COMMAND} -DTETSKIN=$<TARGET_FILE:tetskin> -DDATASET=${data}/bunny.json
          -DSURFACE=${data}/bunny.obj -DOUT=${cli_out}/compare -P ${CMAKE_CURRENT_SOURCE_DIR}/CheckCompare.cmake)
set_tests_properties(cli.compare_levels_of_the_bunny PROPERTIES LABELS long
  PASS_REGULAR_EXPRESSION "finer is closer")

# Two runs of one level recorded alike (cg alone: the automatic choice
# times its solvers) compared: no error anywhere.
tetskin_cli_test(compare_run_a SETUP compare_runs
  ARGS simulate ${data}/bunny.json --level 0 --solver cg --steps 6 --every 2 -o ${cli_out}/compare_a.pvd -q)
tetskin_cli_test(compare_run_b SETUP compare_runs
  ARGS simulate ${data}/bunny.json --level 0 --solver cg --steps 6 --every 2 -o ${cli_out}/compare_b.pvd -q)
tetskin_cli_test(compare_recorded_runs REQUIRES compare_runs
  STDOUT "^compared 2 recorded runs of [^\n]*bunny.json over 4 frames, reference [^\n]*compare_a.pvd .level 0.\n[^\n]*\n[^\n]*\n  0 ref +598 +- +.reference. *\n  0 +598 +- +0% / 0% / 0% +0 / 0 / 0\n"
  ARGS compare ${data}/bunny.json ${data}/bunny.obj --runs ${cli_out}/compare_a.pvd ${cli_out}/compare_b.pvd
       -o ${cli_out}/compare_ab.pvd -q)

# Bad input: named, nothing written.
tetskin_cli_test(compare_one_level FAIL STATUS 1
  STDERR "^error: --levels: level 2 alone: name another level to compare with the reference .3 levels in the dataset.\n$"
  NOT_EXIST ${cli_out}/one_level.pvd
  ARGS compare ${data}/bunny.json ${data}/bunny.obj --levels -1 -o ${cli_out}/one_level.pvd)
tetskin_cli_test(compare_level_twice FAIL STATUS 1
  STDERR "^error: --levels: level 0 is given twice\n$"
  ARGS compare ${data}/bunny.json ${data}/bunny.obj --levels 0,-3 -o ${cli_out}/twice.pvd)
tetskin_cli_test(compare_node_list FAIL STATUS 1
  STDERR "^error: --fixed-nodes: names nodes of one level, and compare runs several: hold nodes by --fixed-box[^\n]*\n$"
  ARGS compare ${data}/bunny.json ${data}/bunny.obj --fixed-nodes ${tdata}/held_nodes.txt -o ${cli_out}/held.pvd)
tetskin_cli_test(compare_face_set FAIL STATUS 1
  STDERR "^error: --load-faces: names faces of one level, and compare runs several: select them by --load-box[^\n]*\n$"
  ARGS compare ${data}/bunny.json ${data}/bunny.obj --traction 0,-1,0 --load-faces ${tdata}/bunny_base.faces -o ${cli_out}/faces.pvd)
tetskin_cli_test(compare_runs_and_steps FAIL STATUS 1 REQUIRES compare_runs
  STDERR "^error: --steps: compares simulated levels. --runs compares recorded runs .the first the reference. frame by frame\n$"
  ARGS compare ${data}/bunny.json ${data}/bunny.obj --runs ${cli_out}/compare_a.pvd ${cli_out}/compare_b.pvd
       --steps 3 -o ${cli_out}/runs_steps.pvd)
tetskin_cli_test(compare_no_steps FAIL STATUS 1
  STDERR "^error: --steps: 0 steps leave the levels at rest, with nothing to compare: give 1 or more\n$"
  NOT_EXIST ${cli_out}/compare_no_steps.pvd
  ARGS compare ${data}/bunny.json ${data}/bunny.obj --steps 0 -o ${cli_out}/compare_no_steps.pvd)
tetskin_cli_test(compare_not_a_pvd FAIL STATUS 1
  STDERR "^error: [^\n]*out.vtp[^\n]*\n$"
  ARGS compare ${data}/bunny.json ${data}/bunny.obj -o ${cli_out}/out.vtp)

# A scene's levels: every body on each level, the errors also per body
# (each against its own skin's diagonal), the table a row per body.
tetskin_cli_test(compare_scene_two_bodies
  STDOUT "^compared 2 levels of [^\n]*two_bunnies.json over 10 steps of 0.0166667 s, scenario free, reference level 1 .every body on the level.\n  skins of 2 bodies: 8002 vertices, diagonal [0-9.]+. errors over every vertex of 3 frames\n[^\n]*\n  0 +1196 +[0-9.e+-]+ +[0-9.e+-]+% / [^\n]*\n    body 0 +[0-9.e+-]+% / [^\n]*\n    body 1 +[0-9.e+-]+% / [^\n]*\n  1 ref +5852 [^\n]*.reference.[^\n]*\n  .distances as % of the diagonal, a body's of its own"
  ARGS compare ${tdata}/scenes/two_bunnies.json --levels 0 --reference 1 --steps 10 --every 5
       -o ${cli_out}/compare_scene.pvd -q)
tetskin_cli_test(compare_scene_with_a_surface FAIL STATUS 1
  STDERR "^error: [^\n]*bunny.obj: [^\n]*two_bunnies.json is a scene, whose skins are its bodies' surfaces: give no SURFACE\n$"
  NOT_EXIST ${cli_out}/compare_refused.pvd
  ARGS compare ${tdata}/scenes/two_bunnies.json ${data}/bunny.obj -o ${cli_out}/compare_refused.pvd)
tetskin_cli_test(compare_scene_runs FAIL STATUS 1 REQUIRES compare_runs
  STDERR "^error: --runs: compares recorded runs of one dataset. a scene's levels are compared by simulating them .--levels.\n$"
  ARGS compare ${tdata}/scenes/two_bunnies.json --runs ${cli_out}/compare_a.pvd ${cli_out}/compare_b.pvd
       -o ${cli_out}/compare_refused.pvd)
tetskin_cli_test(compare_without_a_surface FAIL STATUS 1
  STDERR "^error: SURFACE: the surface compared is required .a scene's skins are its own.\n$"
  ARGS compare ${data}/bunny.json -o ${cli_out}/compare_refused.pvd)
