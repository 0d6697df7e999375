# CLI tests of tetskin simulate (included by tests/cli/CMakeLists.txt).

# A usage error is bad input like a malformed file: one line naming the option, status 1.
tetskin_cli_test(bad_option_value FAIL STATUS 1
  STDERR "^error: [^\n]*--steps[^\n]*abc[^\n]*\\(see tetskin simulate --help\\)\n$"
  NOT_EXIST ${cli_out}/badsteps.pvd
  ARGS simulate ${data}/bunny.json --steps abc -o ${cli_out}/badsteps.pvd)
tetskin_cli_test(option_given_twice FAIL STATUS 1
  STDERR "^error: --steps: given 2 times. give it once \\(see tetskin simulate --help\\)\n$"
  NOT_EXIST ${cli_out}/twice.pvd
  ARGS simulate ${data}/bunny.json --steps 3 --steps 4 -o ${cli_out}/twice.pvd)
tetskin_cli_test(list_option_short FAIL STATUS 1
  STDERR "^error: --gravity: takes 3 values, got 2 \\(see tetskin simulate --help\\)\n$"
  NOT_EXIST ${cli_out}/short.pvd
  ARGS simulate ${data}/bunny.json --gravity 0,-9 -o ${cli_out}/short.pvd)
# Beyond an int: the whole range is named, though --help shows only the minimum.
tetskin_cli_test(too_large_option_value FAIL STATUS 1
  STDERR "^error: --steps: 3000000000 is not in \\[0, 2147483647\\] \\(see tetskin simulate --help\\)\n$"
  NOT_EXIST ${cli_out}/badsteps.pvd
  ARGS simulate ${data}/bunny.json --steps 3000000000 -o ${cli_out}/badsteps.pvd)
tetskin_cli_test(nan_time_step FAIL STATUS 1
  STDERR "^error: --time-step: 'nan' is not a finite number \\(see tetskin simulate --help\\)\n$"
  ARGS simulate ${data}/bunny.json --time-step nan -o ${cli_out}/badsteps.pvd)
tetskin_cli_test(unknown_option FAIL STATUS 1
  STDERR "^error: [^\n]*--stepz[^\n]*\\(see tetskin simulate --help\\)\n$"
  ARGS simulate ${data}/bunny.json --stepz 3 -o ${cli_out}/badsteps.pvd)
tetskin_cli_test(simulate_zero_area_triangle
  STDERR "^warning: [^\n]*zero_area_triangle.obj: 1 triangle of zero area [^\n]*.first: vertex 3.\n$"
  ARGS simulate ${data}/bunny.json --level 0 --surface ${tdata}/zero_area_triangle.obj --steps 1 -q -o ${cli_out}/zero_area_run.pvd)
tetskin_cli_test(simulate_bad_young FAIL STATUS 1
  STDERR "^error: --youngs-modulus: '2e5Pa' is not a finite number \\(see tetskin simulate --help\\)\n$"
  NOT_EXIST ${cli_out}/bad_young.pvd
  ARGS simulate ${data}/bunny.json --youngs-modulus 2e5Pa -o ${cli_out}/bad_young.pvd)
tetskin_cli_test(simulate_bad_damping FAIL STATUS 1
  STDERR "^error: --stiffness-damping: Rayleigh stiffness damping \\(beta\\) must be finite and >= 0, got -0.01\n$"
  NOT_EXIST ${cli_out}/bad_damping.pvd
  ARGS simulate ${data}/bunny.json --stiffness-damping -0.01 -o ${cli_out}/bad_damping.pvd)
# Scenario options: held nodes join the scenario's (none here: --base-share 0),
# gravity and a floor as given.
tetskin_cli_test(simulate_held_nodes
  STDOUT "scenario sag.*\n  3 of 224 nodes fixed, gravity 0,0,-9.81 m/s\\^2, floor at y = -2\n"
  ARGS simulate ${data}/bunny.json --level 0 --scenario sag --base-share 0 --fixed-nodes ${tdata}/held_nodes.txt
       --gravity 0,0,-9.81 --floor-height -2 --steps 3 -o ${cli_out}/held.pvd -q)
# A run started from another run's last frame.
tetskin_cli_test(simulate_first_run SETUP first_run
  ARGS simulate ${data}/bunny.json --level 0 --scenario sag --steps 3 -o ${cli_out}/first_run.pvd -q)
tetskin_cli_test(simulate_initial REQUIRES first_run
  STDOUT "\n  started from [^\n]*first_run_frames/control_00003.vtu\n"
  ARGS simulate ${data}/bunny.json --level 0 --scenario wobble
       --initial ${cli_out}/first_run_frames/control_00003.vtu --steps 2 -o ${cli_out}/second_run.pvd -q)
tetskin_cli_test(simulate_initial_other_level FAIL STATUS 1 REQUIRES first_run
  STDERR "^error: [^\n]*control_00003.vtu: has 224 points and 598 tetrahedra. level 1 of [^\n]*bunny.json has 837 and 2926\n$"
  NOT_EXIST ${cli_out}/other_level.pvd
  ARGS simulate ${data}/bunny.json --level 1 --initial ${cli_out}/first_run_frames/control_00003.vtu
       -o ${cli_out}/other_level.pvd)
tetskin_cli_test(simulate_initial_own_frames FAIL STATUS 1 REQUIRES first_run
  STDERR "^error: [^\n]*control_00003.vtu: is among the frames this run writes \\(-o [^\n]*first_run.pvd\\): write the new run to another name\n$"
  ARGS simulate ${data}/bunny.json --level 0 --initial ${cli_out}/first_run_frames/control_00003.vtu
       -o ${cli_out}/first_run.pvd)
tetskin_cli_test(simulate_loads
  STDOUT "scenario sag.*\n  35 of 224 nodes fixed, 2 loaded \\(total force 0,-3,0 N for 0.02 s\\), gravity 0,-9.81,0 m/s\\^2\n"
  ARGS simulate ${data}/bunny.json --level 0 --scenario sag --loads ${tdata}/loads.txt
       --load-seconds 0.02 --steps 3 -o ${cli_out}/loads.pvd -q)
tetskin_cli_test(simulate_loads_seconds_alone FAIL STATUS 1
  STDERR "^error: --load-seconds: applies with --loads or a surface load \\(--pressure, --traction\\), and none is given\n$"
  NOT_EXIST ${cli_out}/alone.pvd
  ARGS simulate ${data}/bunny.json --load-seconds 1 -o ${cli_out}/alone.pvd)
tetskin_cli_test(simulate_load_curve
  STDOUT "2 loaded \\(total force 0,-3,0 N, scaled by a load curve of 4 points from 0 to 0.06 s, factors 0 to 1\\), gravity"
  ARGS simulate ${data}/bunny.json --level 0 --scenario sag --loads ${tdata}/loads.txt
       --load-curve ${tdata}/load_curve.txt --steps 3 -o ${cli_out}/load_curve.pvd -q)
tetskin_cli_test(simulate_repeated_load_curve
  STDOUT "scaled by a load curve of 4 points from 0 to 0.05 s, factors 0 to 1, repeated every 0.05 s\\), gravity"
  ARGS simulate ${data}/bunny.json --level 0 --scenario sag --loads ${tdata}/loads.txt
       --load-curve ${tdata}/pulse_load_curve.txt --steps 3 -o ${cli_out}/pulses.pvd -q)
tetskin_cli_test(simulate_load_curve_alone FAIL STATUS 1
  STDERR "^error: --load-curve: applies with --loads or a surface load \\(--pressure, --traction\\), and none is given\n$"
  NOT_EXIST ${cli_out}/curve_alone.pvd
  ARGS simulate ${data}/bunny.json --load-curve ${tdata}/load_curve.txt -o ${cli_out}/curve_alone.pvd)
tetskin_cli_test(simulate_bad_load_curve FAIL STATUS 1
  STDERR "^error: [^\n]*bad_load_curve.txt:4: the times must increase, but 0.25 s follows 0.5 s\n$"
  NOT_EXIST ${cli_out}/bad_curve.pvd
  ARGS simulate ${data}/bunny.json --level 0 --loads ${tdata}/loads.txt
       --load-curve ${tdata}/bad_load_curve.txt -o ${cli_out}/bad_curve.pvd)
tetskin_cli_test(simulate_bad_loads FAIL STATUS 1
  STDERR "^error: [^\n]*bad_loads.txt:3: node force \\(NODE FX FY FZ\\): expected 4 values, found 3\n$"
  NOT_EXIST ${cli_out}/bad_loads.pvd
  ARGS simulate ${data}/bunny.json --level 0 --loads ${tdata}/bad_loads.txt -o ${cli_out}/bad_loads.pvd)
tetskin_cli_test(simulate_pressure SETUP pressed_run
  STDOUT "  surface load 0: pressure 1000 Pa, traction 0,0,0 Pa on 212 faces of 81.7459 m\\^2 \\(total force at rest -1985.1,-29566,-5388.18 N\\)\n.*  the surface loads' potential: -[0-9.]+ J\n"
  ARGS simulate ${data}/bunny.json --level 0 --scenario sag --pressure 1000
       --load-box -100,4,-100,100,100,100 --steps 3 -o ${cli_out}/pressure.pvd)
tetskin_cli_test(simulate_traction_on_a_face_set
  STDOUT "  surface load 0: pressure 0 Pa, traction 0,-100,0 Pa on 2 faces of 1.45634 m\\^2 \\(total force at rest 0,-145.634,0 N\\)\n"
  ARGS simulate ${data}/bunny.json --level 0 --scenario sag --traction 0,-100,0
       --load-faces ${tdata}/bunny_base.faces --steps 2 -o ${cli_out}/traction.pvd)
tetskin_cli_test(simulate_pressure_without_faces FAIL STATUS 1
  STDERR "^error: --pressure and --traction need the faces they act on: --load-box or --load-faces\n$"
  NOT_EXIST ${cli_out}/no_faces.pvd
  ARGS simulate ${data}/bunny.json --level 0 --pressure 5 -o ${cli_out}/no_faces.pvd)
tetskin_cli_test(simulate_load_box_without_a_load FAIL STATUS 1
  STDERR "^error: --load-box: selects the faces of --pressure or --traction, and neither is given\n$"
  NOT_EXIST ${cli_out}/box_alone.pvd
  ARGS simulate ${data}/bunny.json --level 0 --load-box 0,0,0,1,1,1 -o ${cli_out}/box_alone.pvd)
tetskin_cli_test(simulate_bad_face_set FAIL STATUS 1
  STDERR "^error: [^\n]*bad_faces.faces:3: nodes 0, 1, 2 are not a face of the boundary\n$"
  NOT_EXIST ${cli_out}/bad_faces.pvd
  ARGS simulate ${data}/bunny.json --level 0 --traction 0,-100,0
       --load-faces ${tdata}/bad_faces.faces -o ${cli_out}/bad_faces.pvd)
tetskin_cli_test(simulate_floor_through_the_body
  STDERR "^warning: 126 of 224 nodes start below the floor at y = 5. contact pushes them up at once\n$"
  ARGS simulate ${data}/bunny.json --level 0 --scenario sag --floor-height 5 --steps 2 -o ${cli_out}/floor5.pvd -q)
tetskin_cli_test(simulate_bad_held_nodes FAIL STATUS 1
  STDERR "^error: [^\n]*bad_held_nodes.txt:3: node 224 does not exist \\(the level has 224 nodes, numbered from 0\\)\n$"
  NOT_EXIST ${cli_out}/bad_held.pvd
  ARGS simulate ${data}/bunny.json --level 0 --fixed-nodes ${tdata}/bad_held_nodes.txt -o ${cli_out}/bad_held.pvd)
tetskin_cli_test(simulate_option_of_another_scenario FAIL STATUS 1
  STDERR "^error: --push-acceleration: applies to the wobble scenario, not to drop\n$"
  NOT_EXIST ${cli_out}/other.pvd
  ARGS simulate ${data}/bunny.json --scenario drop --push-acceleration 3 -o ${cli_out}/other.pvd)
tetskin_cli_test(simulate_bad_base FAIL STATUS 1
  STDERR "^error: --base-share: 1 is not in .0, 1\\) \\(see tetskin simulate --help\\)\n$"
  ARGS simulate ${data}/bunny.json --base-share 1 -o ${cli_out}/bad_base.pvd)

# Solves cut off at the iteration limit are warned of (the run goes on).
tetskin_cli_test(simulate_iteration_limit
  STDERR "^warning: 2 steps stopped at the iteration limit .2000. with the relative residual above the tolerance 1e-06 .at most [0-9.e+-]+, in step [12].. --solver multigrid needs far fewer iterations on stiff bodies\n$"
  STDOUT "wrote [^\n]*iteration_limit.pvd .3 frames.\n$"
  ARGS simulate ${data}/bunny.json --level 1 --youngs-modulus 1e13 --poisson-ratio 0.499 --solver cg --steps 2 -o ${cli_out}/iteration_limit.pvd)

# A run that blows up stops with the step and a node, exit 1, and leaves a
# .pvd of the frames before it that reads back.
tetskin_cli_test(simulate_blows_up FAIL STATUS 1 SETUP blown_up_run
  STDERR "^error: the simulation diverged in step 2 \\(t = 0.0333333 s\\): node [0-9]+ would get a position component of [^\n]* m, beyond 1e.30 m. smaller loads or time steps, or a stiffer material, may keep it stable. [^\n]*blown_up.pvd keeps the 2 frame.s. written before it\n$"
  ARGS simulate ${data}/bunny.json --level 0 --push-acceleration 1e300 --steps 5 -o ${cli_out}/blown_up.pvd -q)
tetskin_cli_test(simulate_output_under_a_file FAIL STATUS 1
  STDERR "^error: [^\n]*triangle.obj/run_frames: Not a directory\n$"
  ARGS simulate ${data}/bunny.json --steps 1 -o ${tdata}/triangle.obj/run.pvd -q)
tetskin_cli_test(simulate_cantilever REQUIRES cantilever SETUP cantilever_run
  STDOUT "\n  body: [^\n]*, mass 310.231 kg\n  88 of 2471 nodes fixed, gravity 0,-9.81,0 m/s\\^2\n.*\n  supports: reaction [-0-9.e]+,304[34][.][0-9]+,[-0-9.e]+ N in all at the end, on the 88 fixed nodes\n"
  ARGS simulate ${cli_out}/cantilever.json --scenario sag --base-share 0 --fixed-box -1,-1,-1,0.04,1,1
       --youngs-modulus 2e6 --mass-damping 2 --steps 240 --every 240 -o ${cli_out}/cantilever_run.pvd)
# --fixed-box joins --fixed-nodes (the box holds 20 nodes, two of the
# file's 3 among them: 21 in all); a box without nodes, or turned inside
# out, is an error.
tetskin_cli_test(simulate_fixed_box_and_nodes
  STDOUT "\n  21 of 224 nodes fixed, "
  ARGS simulate ${data}/bunny.json --level 0 --scenario sag --base-share 0 --fixed-nodes ${tdata}/held_nodes.txt
       --fixed-box -10,-1,-10,10,0.2,10 --steps 1 -o ${cli_out}/fixed_box.pvd -q)
tetskin_cli_test(simulate_fixed_box_empty FAIL STATUS 1
  STDERR "^error: --fixed-box: no node of the level lies in 20,0,0 .. 30,1,1 \\(the level spans -4.89157,0.0129493,-3.82186 .. 5.05561,9.49403,3.88938\\)\n$"
  NOT_EXIST ${cli_out}/fixed_box_empty.pvd
  ARGS simulate ${data}/bunny.json --level 0 --fixed-box 20,0,0,30,1,1 -o ${cli_out}/fixed_box_empty.pvd)
tetskin_cli_test(simulate_fixed_box_inside_out FAIL STATUS 1
  STDERR "^error: --fixed-box: its minimum 1,0,0 exceeds its maximum 0,1,1 along an axis\n$"
  ARGS simulate ${data}/bunny.json --level 0 --fixed-box 1,0,0,0,1,1 -o ${cli_out}/fixed_box_out.pvd)
# Before the automatic solver's first sample (step 2), multigrid solves
# alone; a run of no steps reports no speed, and writes its start.
tetskin_cli_test(simulate_auto_too_few_steps
  STDOUT "  auto: multigrid solved 2 of 2 steps, cg the rest. 0 sample steps of the other solver \\(0 cut off at their budget\\), 0 changes. preferred at the end: multigrid\n"
  ARGS simulate ${data}/bunny.json --level 0 --steps 2 -q -o ${cli_out}/two_steps.pvd)
tetskin_cli_test(simulate_no_steps
  STDOUT "^simulated 0 steps [^\n]*\n  material: [^\n]*\n  body: [^\n]*\n  [^\n]*gravity [^\n]*\n  final energy: kinetic 0, [^\n]*\n  supports: reaction [^\n]* N in all at the end, on the 35 fixed nodes\nwrote [^\n]*no_steps.pvd \\(1 frame\\)\n$"
  ARGS simulate ${data}/bunny.json --level 0 --steps 0 -q -o ${cli_out}/no_steps.pvd)
# The series' ending in any letter case: not RUN.PVD.pvd.
tetskin_cli_test(simulate_upper_case_ending STDOUT "wrote [^\n]*upper_case.PVD \\(1 frame\\)\n$"
  NOT_EXIST ${cli_out}/upper_case.PVD.pvd
  ARGS simulate ${data}/bunny.json --level 0 --steps 0 -q -o ${cli_out}/upper_case.PVD)
# Every writer names the dataset from the written file's folder: given
# relative to the working folder (the source tree here), it is found again
# from the frames' folder and from deform's output.
tetskin_cli_test(simulate_relative_dataset_name SETUP relative_run
  STDOUT "wrote .*relative_run.pvd \\(2 frames\\)"
  ARGS simulate data/bunny.json --level 0 --surface tests/data/triangle.obj --steps 1
       -o ${cli_out}/relative_run.pvd -q)

tetskin_cli_test(simulate_twist_cg SETUP twist_run STDOUT "simulated 5 steps .* level 0 .*scenario twist, solver cg.*wrote .*twist.pvd \\(6 frames\\)"
  ARGS simulate ${data}/bunny.json --level 0 --scenario twist --solver cg --steps 5
       -o ${cli_out}/twist.pvd -q)
# --every K writes the start, every K-th step and the last step (5 of 5
# steps: frames at steps 0, 2, 4, 5).
tetskin_cli_test(simulate_every_keeps_the_last_step SETUP every_run
  STDOUT "wrote [^\n]*every.pvd \\(4 frames\\)\n"
  ARGS simulate ${data}/bunny.json --level 0 --steps 5 --every 2 -q -o ${cli_out}/every.pvd)
tetskin_cli_test(simulate_drop_multigrid STDOUT "scenario drop, solver multigrid.*\\(3 frames\\)"
  ARGS simulate ${data}/bunny.json --level 1 --scenario drop --solver multigrid --steps 4 --every 2
       -o ${cli_out}/drop.pvd -q)
# The default solver starts with multigrid and samples CG at steps 2 and
# 4 within a budget, and two steps after a win (SolverChoice.h).
tetskin_cli_test(simulate_auto
  STDOUT "scenario wobble, solver auto, galerkin on grid.*auto: multigrid solved ([0-9]|1[0-2]) of 12 steps, cg the rest. [1-5] sample steps of the other solver \\([0-5] cut off at their budget\\), [0-3] changes. preferred at the end: (cg|multigrid)"
  ARGS simulate ${data}/bunny.json --level 1 --steps 12 --every 12 -o ${cli_out}/auto.pvd -q)
# A nearly incompressible body: both solvers need hundreds of iterations
# (CG up to the limit); which is faster depends on the machine, and the
# run completes with one of them (SolverChoiceTest: a solver that stops
# short of the tolerance loses whatever its time).
tetskin_cli_test(simulate_auto_incompressible
  STDOUT "auto: multigrid solved ([0-9]|1[0-2]) of 12 steps, cg the rest. [2-5] sample steps of the other solver \\([0-5] cut off at their budget\\), [0-3] changes. preferred at the end: (cg|multigrid)"
  ARGS simulate ${data}/bunny.json --level 1 --poisson-ratio 0.4999 --steps 12 --every 12
       -o ${cli_out}/auto_incompressible.pvd -q)
# --log: every step in a table (the start too), for plots of energy,
# iterations and step times; a run that blows up keeps its steps so far.
tetskin_cli_test(simulate_step_log SETUP step_log
  STDOUT "wrote [^\n]*step_log/steps.csv \\(6 steps and the start\\)\n$"
  ARGS simulate ${data}/bunny.json --level 0 --steps 6 --log ${cli_out}/step_log/steps.csv
       -o ${cli_out}/step_log/run.pvd -q)
add_test(NAME cli.simulate_step_log_table COMMAND ${CMAKE_COMMAND}
  -DLOG=${cli_out}/step_log/steps.csv -DSTEPS=6 -P ${CMAKE_CURRENT_SOURCE_DIR}/CheckStepLog.cmake)
set_tests_properties(cli.simulate_step_log_table PROPERTIES LABELS cli FIXTURES_REQUIRED step_log)
# Energies are measured from the rest shape: a drop's log, and a run
# continued from its frame after step 2, which starts with that step's
# energies (gravitational included).
tetskin_cli_test(simulate_drop_step_log SETUP drop_step_log
  ARGS simulate ${data}/bunny.json --level 0 --scenario drop --steps 4 --every 2
       --log ${cli_out}/drop_log/steps.csv -o ${cli_out}/drop_log/run.pvd -q)
tetskin_cli_test(simulate_continued_step_log REQUIRES drop_step_log SETUP continued_step_log
  ARGS simulate ${data}/bunny.json --level 0 --scenario drop --steps 2
       --initial ${cli_out}/drop_log/run_frames/control_00001.vtu
       --log ${cli_out}/drop_log/continued.csv -o ${cli_out}/drop_continued.pvd -q)
add_test(NAME cli.simulate_continued_step_log_energies COMMAND ${CMAKE_COMMAND}
  -DFIRST=${cli_out}/drop_log/steps.csv -DSTEP=2 -DCONTINUED=${cli_out}/drop_log/continued.csv
  -P ${CMAKE_CURRENT_SOURCE_DIR}/CheckContinuedStepLog.cmake)
set_tests_properties(cli.simulate_continued_step_log_energies PROPERTIES LABELS cli
  FIXTURES_REQUIRED "drop_step_log;continued_step_log")
tetskin_cli_test(simulate_step_log_blown_up FAIL STATUS 1
  STDERR "blown_up.pvd keeps the 2 frame.s. written before it, [^\n]*blown_up.csv the 1 step.s.\n$"
  ARGS simulate ${data}/bunny.json --level 0 --push-acceleration 1e300 --steps 5 --solver cg
       --log ${cli_out}/blown_up.csv -o ${cli_out}/blown_up.pvd -q)
add_test(NAME cli.simulate_step_log_blown_up_table COMMAND ${CMAKE_COMMAND}
  -DLOG=${cli_out}/blown_up.csv -DSTEPS=1 -P ${CMAKE_CURRENT_SOURCE_DIR}/CheckStepLog.cmake)
set_tests_properties(cli.simulate_step_log_blown_up_table PROPERTIES LABELS cli
  DEPENDS cli.simulate_step_log_blown_up)
tetskin_cli_test(simulate_step_log_not_csv FAIL STATUS 1
  STDERR "^error: --log: '[^\n]*steps.txt' does not end in .csv"
  ARGS simulate ${data}/bunny.json --log ${cli_out}/steps.txt -o ${cli_out}/x.pvd)
tetskin_cli_test(simulate_step_log_in_a_file FAIL STATUS 1
  STDERR "^error: [^\n]*bunny.obj/steps.csv: cannot be written: [^\n]*bunny.obj is not a folder\n$"
  NOT_EXIST ${cli_out}/log_run.pvd
  ARGS simulate ${data}/bunny.json --log ${data}/bunny.obj/steps.csv -o ${cli_out}/log_run.pvd)
tetskin_cli_test(simulate_bad_material FAIL STDERR "^error: --poisson-ratio: Poisson's ratio must lie in \\(-1, 0.5\\), got 0.5\n$"
  NOT_EXIST ${cli_out}/bad_material.pvd
  ARGS simulate ${data}/bunny.json --poisson-ratio 0.5 -o ${cli_out}/bad_material.pvd)
# The material comes from the dataset config's elasticity section; options override it key by key.
tetskin_cli_test(simulate_config_material
  STDOUT "\n  material: E 2e\\+06 Pa, nu 0.3, density 50 kg/m\\^3, alpha 0.1, beta 0.01\n"
  ARGS simulate ${tdata}/stiff_bunny.json --level 0 --steps 2 -o ${cli_out}/stiff.pvd -q)
tetskin_cli_test(simulate_option_over_config_material
  STDOUT "\n  material: E 300000 Pa, nu 0.3, density 50 kg/m\\^3, alpha 0, beta 0.01\n"
  ARGS simulate ${tdata}/stiff_bunny.json --level 0 --youngs-modulus 3e5 --mass-damping 0 --steps 2
       -o ${cli_out}/stiff_override.pvd -q)
tetskin_cli_test(simulate_coarse_reuse STDOUT "simulated 4 steps .*solver multigrid"
  ARGS simulate ${data}/bunny.json --level 1 --solver multigrid --steps 4 --every 4 --coarse-reuse 3
       -o ${cli_out}/reuse.pvd -q)
tetskin_cli_test(simulate_rediscretized STDOUT "simulated 4 steps .*solver multigrid, rediscretized on dataset"
  ARGS simulate ${data}/bunny.json --solver multigrid --steps 4 --every 4 --coarse-operators rediscretized
       --coarse-levels dataset --coarse-reuse 2 -o ${cli_out}/rediscretized.pvd -q)
tetskin_cli_test(simulate_rediscretized_needs_dataset_levels FAIL STATUS 1
  STDERR "rediscretized coarse operators need the dataset's coarse levels"
  NOT_EXIST ${cli_out}/rediscretized_grid.pvd
  ARGS simulate ${data}/bunny.json --solver multigrid --coarse-operators rediscretized --steps 2
       -o ${cli_out}/rediscretized_grid.pvd -q)
tetskin_cli_test(simulate_dataset_levels STDOUT "simulated 4 steps .*solver multigrid, galerkin on dataset"
  ARGS simulate ${data}/bunny.json --solver multigrid --steps 4 --every 4 --coarse-levels dataset
       -o ${cli_out}/dataset_levels.pvd -q)
tetskin_cli_test(simulate_coarse_option_with_cg FAIL STATUS 1
  STDERR "^error: --coarse-reuse: applies to the multigrid solver \\(--solver multigrid or auto\\), not to cg\n$"
  NOT_EXIST ${cli_out}/cg_reuse.pvd
  ARGS simulate ${data}/bunny.json --solver cg --coarse-reuse 2 -o ${cli_out}/cg_reuse.pvd)
tetskin_cli_test(simulate_bad_coarse_operators FAIL STDERR "coarse-operators: nested not in"
  NOT_EXIST ${cli_out}/nested.pvd
  ARGS simulate ${data}/bunny.json --coarse-operators nested -o ${cli_out}/nested.pvd)
tetskin_cli_test(simulate_full_tangent_by_default STDOUT "simulated 2 steps .*solver cg, full tangent\n"
  ARGS simulate ${data}/bunny.json --level 0 --solver cg --steps 2 -o ${cli_out}/full_tangent.pvd -q)
tetskin_cli_test(simulate_warped_tangent STDOUT "simulated 2 steps .*solver cg, warped tangent\n"
  ARGS simulate ${data}/bunny.json --level 0 --solver cg --tangent warped --steps 2
       -o ${cli_out}/warped.pvd -q)
tetskin_cli_test(simulate_bad_tangent FAIL STATUS 1 STDERR "tangent: exact not in"
  NOT_EXIST ${cli_out}/exact.pvd
  ARGS simulate ${data}/bunny.json --tangent exact -o ${cli_out}/exact.pvd)
tetskin_cli_test(simulate_plain_warm_start STDOUT "simulated 4 steps .*scenario wobble, solver multigrid"
  ARGS simulate ${data}/bunny.json --level 1 --solver multigrid --steps 4 --every 4 --guess-solutions 0
       -o ${cli_out}/plain.pvd -q)
tetskin_cli_test(simulate_bad_guess_solutions FAIL STATUS 1
  STDERR "^error: --guess-solutions: 17 is not in \\[0, 16\\] \\(see tetskin simulate --help\\)\n$"
  NOT_EXIST ${cli_out}/guess17.pvd
  ARGS simulate ${data}/bunny.json --guess-solutions 17 -o ${cli_out}/guess17.pvd)
# A broken mesh: the element named, nothing written.
tetskin_cli_test(simulate_inverted_element FAIL STATUS 1
  STDERR "^error: [^\n]*inverted_tet.node: level 0: element 0 has non-positive volume -0.166667 \\(inverted or degenerate\\)\n$"
  NOT_EXIST ${cli_out}/inverted.pvd
  ARGS simulate ${tdata}/inverted_tet.node -o ${cli_out}/inverted.pvd)
tetskin_cli_test(simulate_bad_scenario FAIL STDERR "scenario: spin not in"
  ARGS simulate ${data}/bunny.json --scenario spin -o ${cli_out}/x.pvd)
tetskin_cli_test(simulate_embed_binding REQUIRES embed_binding SETUP embed_run
  STDOUT "simulated 2 steps of [^\n]* on level 0 .*wrote .*embed_run.pvd \\(3 frames\\)"
  ARGS simulate ${data}/bunny.json --surface ${cli_out}/bunny_embed.vtp --steps 2
       -o ${cli_out}/embed_run.pvd -q)
# Options that would change nothing in the run asked for are errors, not ignored.
tetskin_cli_test(simulate_from_a_surface_frame REQUIRES embed_run
  STDOUT "simulated 2 steps of [^\n]* on level 0 .*wrote .*from_frame.pvd \\(3 frames\\)"
  ARGS simulate ${data}/bunny.json --surface ${cli_out}/embed_run_frames/surface_00002.vtp
       --steps 2 -o ${cli_out}/from_frame.pvd -q)
tetskin_cli_test(simulate_up_z REQUIRES up_z_box
  STDOUT "scenario drop.*\n  body: 1 x 1 x 1 m .z up., mass 100 kg\n.*, gravity 0,0,-9.81 m/s\\^2, floor at z = 0\n"
  ARGS simulate ${cli_out}/up_z_box.json --scenario drop --steps 2 -o ${cli_out}/up_z_run.pvd -q)
tetskin_cli_test(simulate_up_overrides_the_config
  STDOUT "gravity -9.81,0,0 m/s\\^2\n"
  ARGS simulate ${data}/bunny.json --level 0 --up x --steps 1 -o ${cli_out}/up_x_run.pvd -q)
tetskin_cli_test(simulate_up_unknown FAIL STATUS 1
  STDERR "^error: --up: w not in {x,y,z} .see tetskin simulate --help.\n$"
  ARGS simulate ${data}/bunny.json --up w -o ${cli_out}/up_w_run.pvd)
tetskin_cli_test(simulate_imported_dataset REQUIRES imported_bunny
  STDOUT "simulated 2 steps [^\n]* on level 1 .12713 tetrahedra.[^\n]*solver multigrid"
  ARGS simulate ${cli_out}/imported_bunny.json --solver multigrid --steps 2
       -o ${cli_out}/imported_run.pvd -q)
tetskin_cli_test(simulate_gmsh_dataset REQUIRES gmsh_dataset
  STDOUT "simulated 3 steps [^\n]* on level 1 .898 tetrahedra.[^\n]*solver multigrid"
  ARGS simulate ${cli_out}/gmsh_sphere.json --scenario drop --solver multigrid --steps 3
       -o ${cli_out}/gmsh_run.pvd -q)
# ... and is a dataset of one level wherever one is taken.
tetskin_cli_test(simulate_gmsh_mesh
  STDOUT "simulated 2 steps [^\n]* on level 0 .679 tetrahedra."
  ARGS simulate ${tdata}/gmsh/sphere_coarse_v41.msh --scenario drop --steps 2
       -o ${cli_out}/gmsh_mesh_run.pvd -q)
tetskin_cli_test(simulate_gmsh_binary_mesh
  STDOUT "simulated 2 steps [^\n]* on level 0 .679 tetrahedra."
  ARGS simulate ${tdata}/gmsh/sphere_coarse_v41_binary.msh --scenario drop --steps 2
       -o ${cli_out}/gmsh_binary_run.pvd -q)
tetskin_cli_test(simulate_medit_mesh REQUIRES medit_level
  STDOUT "simulated 2 steps [^\n]* on level 0 .598 tetrahedra."
  ARGS simulate ${cli_out}/level0.mesh --scenario drop --steps 2 -o ${cli_out}/medit_run.pvd -q)
# A name with '&' is legal on disk and must be escaped in the .pvd's XML.
tetskin_cli_test(simulate_name_with_ampersand SETUP ampersand_run STDOUT "wrote .*a&b.pvd \\(3 frames\\)"
  ARGS simulate ${data}/bunny.json --level 0 --steps 2 -o ${cli_out}/a&b.pvd -q)

# A recorded run drawn frame by frame (render --run): the control frames
# (part 0) only, the surface's (part 1) left out; frame 0 is the rest state,
# drawn as the still image; a later frame shows the body moved.
tetskin_cli_test(simulate_run_to_draw SETUP recorded_run STDOUT "wrote [^\n]*recorded/run.pvd \\(4 frames\\)\n$"
  ARGS simulate ${data}/bunny.json --steps 30 --every 10 --surface ${data}/bunny_8k.obj
       -o ${cli_out}/recorded/run.pvd)
# (The folder holds a stale image of an earlier, longer drawing, which goes.)
add_test(NAME cli.stale_drawn_image COMMAND ${CMAKE_COMMAND} -E copy ${data}/bunny_texture.png
  ${cli_out}/drawn/f_00004.png)
set_tests_properties(cli.stale_drawn_image PROPERTIES FIXTURES_SETUP stale_image)
# A run that stays at rest (no gravity, no push) is drawn as the still
# image, byte for byte, frame after frame: the frames' positions reach the
# picture exactly.
tetskin_cli_test(simulate_run_at_rest SETUP run_at_rest
  ARGS simulate ${data}/bunny.json --scenario sag --gravity 0,0,0 --steps 2
       -o ${cli_out}/at_rest/run.pvd)
# A drop starts above the rest shape: the camera frames the whole motion, a
# recorded one and a simulated one, so no frame leaves the picture (the
# ears were cut off at the top).
tetskin_cli_test(simulate_drop_to_draw SETUP drop_run
  ARGS simulate ${data}/bunny.json --scenario drop --level 0 --steps 60 --every 20
       -o ${cli_out}/drop/run.pvd)
# The schema's range (simulation_option::kTolerance), checked on the
# command line before any work.
tetskin_cli_test(simulate_tolerance_out_of_range FAIL STATUS 1
  STDERR "^error: --tolerance: 1 is not in \\(0, 1\\) \\(see tetskin simulate --help\\)\n$"
  NOT_EXIST ${cli_out}/tolerance1.pvd
  ARGS simulate ${data}/bunny.json --tolerance 1 -o ${cli_out}/tolerance1.pvd)

# Soak (issue #53): a long simulate with periodic frames needs no more memory
# than one a tenth as long (simulate_soak.py; TETSKIN_SOAK_STEPS sets the
# length, the default a short form). Label long: not in the sanitized suite.
add_test(NAME cli.simulate_soak
  COMMAND python3 ${CMAKE_CURRENT_SOURCE_DIR}/simulate_soak.py $<TARGET_FILE:tetskin> ${cli_out}/soak)
set_tests_properties(cli.simulate_soak PROPERTIES LABELS long TIMEOUT 3600)

# The surface's frames in pieces (issue #54): a .pvtp per frame, 2 pieces,
# the control frames whole; --pieces without a surface is refused.
tetskin_cli_test(simulate_surface_in_pieces SETUP pieces_run FRESH ${cli_out}/pieces_run
  STDOUT "wrote [^\n]*pieces_run/run.pvd \\(3 frames\\)"
  ARGS simulate ${data}/bunny.json --steps 2 --surface ${data}/bunny_8k.obj --pieces 2
       -o ${cli_out}/pieces_run/run.pvd -q)
tetskin_cli_test(info_simulated_surface_in_pieces REQUIRES pieces_run
  STDOUT "run.pvd: time series, 3 time steps[^\n]*\n  part 0 +3 files, run_frames/control_00000.vtu .. run_frames/control_00002.vtu, all present\n  part 1 +3 files, run_frames/surface_00000.pvtp .. run_frames/surface_00002.pvtp, all present\n"
  ARGS info ${cli_out}/pieces_run/run.pvd)
tetskin_cli_test(simulate_pieces_without_surface FAIL STATUS 1
  NOT_EXIST ${cli_out}/pieces_nothing.pvd
  STDERR "^error: --pieces 3 splits the surface's frames: give the surface \\(--surface\\)\n$"
  ARGS simulate ${data}/bunny.json --steps 1 --pieces 3 -o ${cli_out}/pieces_nothing.pvd)
# --print-run: the run the options describe, as JSON, and nothing run or
# written (the front ends' parity test, python.run_parity, compares it with
# render's, the GUI's and Python's); without it, -o is required.
tetskin_cli_test(simulate_print_run
  STDOUT "\"solver\": \"auto\".*\"scenario\": \"drop\"\n}\n$"
  NOT_EXIST ${cli_out}/print_run.pvd
  ARGS simulate ${data}/bunny.json --scenario drop --print-run)
tetskin_cli_test(simulate_without_output FAIL STATUS 1
  STDERR "^error: --output is required \\(or --print-run\\)\n$"
  ARGS simulate ${data}/bunny.json --steps 1)
# One name per option: the flag is the key in kebab case; the old flag is
# still read, with a warning, and refused beside the new one.
tetskin_cli_test(simulate_old_flag_warns
  STDERR "^warning: --alpha: is deprecated, use --mass-damping \\(the same option\\)\n$"
  STDOUT "\"mass_damping\": 0.25"
  ARGS simulate ${data}/bunny.json --alpha 0.25 --print-run)
tetskin_cli_test(simulate_old_and_new_flag FAIL STATUS 1
  STDERR "^error: --alpha: is the same option as --mass-damping: give one\n$"
  ARGS simulate ${data}/bunny.json --mass-damping 0.3 --alpha 0.25 --print-run)
# --static: the bunny under gravity, its base held (sag), solved for its
# equilibrium and written as the run's only frame; --initial equilibrium
# starts a run there. --static takes no --steps.
tetskin_cli_test(simulate_static
  STDOUT "static equilibrium: [0-9]+ Newton iterations .[0-9]+ linear., largest force left [^ ]+ N .largest load [^ ]+ N.\n.*wrote [^\n]*static.pvd .1 frames?."
  ARGS simulate ${data}/bunny.json --level 0 --scenario sag --static -o ${cli_out}/static.pvd -q)
tetskin_cli_test(simulate_initial_equilibrium
  STDOUT "static equilibrium: [0-9]+ Newton iterations.*wrote [^\n]*from_static.pvd .4 frames."
  ARGS simulate ${data}/bunny.json --level 0 --scenario sag --initial equilibrium --steps 3 -o ${cli_out}/from_static.pvd -q)
tetskin_cli_test(simulate_static_with_steps FAIL STATUS 1
  STDERR "^error: --static writes the equilibrium alone: it takes no --steps\n$"
  NOT_EXIST ${cli_out}/static_steps.pvd
  ARGS simulate ${data}/bunny.json --static --steps 3 -o ${cli_out}/static_steps.pvd)
tetskin_cli_test(simulate_static_free_body FAIL STATUS 1
  STDERR "^error: there is no static equilibrium: the body is free .no held node, floor or obstacle. under a net load of [^ ]+ N. hold nodes or add a floor\n$"
  NOT_EXIST ${cli_out}/static_free.pvd
  ARGS simulate ${data}/bunny.json --level 0 --scenario sag --base-share 0 --static -o ${cli_out}/static_free.pvd)
# A recorded run read at points: one row per frame and point, the
# displacement 0 at the start, the stress with six components.
tetskin_cli_test(probe_a_run REQUIRES pressed_run
  STDOUT "^time,point,x,y,z,element,displacement_x,displacement_y,displacement_z,stress_xx,stress_yy,stress_zz,stress_xy,stress_yz,stress_xz,von_mises\n0,0,0,5,0,[0-9]+,0,0,0,[^\n]*\n0,1,1,2,0.5,[0-9]+,0,0,0,[^\n]*\n0.016666666666666666,0,0,5,0,[0-9]+,-?[0-9.e-]+,-0.00[0-9]+,[^\n]*\n([^\n]*\n)([^\n]*\n)([^\n]*\n)([^\n]*\n)([^\n]*\n)$"
  ARGS probe ${cli_out}/pressure.pvd --points ${tdata}/probe_points.txt)
tetskin_cli_test(probe_to_a_table REQUIRES pressed_run
  STDOUT "^wrote [^\n]*probe.csv \\(4 frames x 2 points\\)\n$"
  ARGS probe ${cli_out}/pressure.pvd --points ${tdata}/probe_points.txt -o ${cli_out}/probe.csv)
tetskin_cli_test(probe_outside_the_body FAIL STATUS 1 REQUIRES pressed_run
  STDERR "^error: [^\n]*probe_outside.txt:2: the point 0,50,0 lies outside the run's control mesh \\(40.5[0-9]* from its nearest element\\)\n$"
  NOT_EXIST ${cli_out}/outside.csv
  ARGS probe ${cli_out}/pressure.pvd --points ${tdata}/probe_outside.txt -o ${cli_out}/outside.csv)
