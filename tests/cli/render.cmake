# CLI tests of tetskin render (and films) (included by tests/cli/CMakeLists.txt).

tetskin_cli_test(render_needs_display FAIL NO_DISPLAY STDERR "^error: rendering needs an X display"
  NOT_EXIST ${cli_out}/nodisplay.png
  ARGS render ${data}/bunny.json --level 0 -o ${cli_out}/nodisplay.png)
# A DISPLAY with no X server behind it: VTK would abort the process.
tetskin_cli_test(render_dead_display FAIL STATUS 1 DEAD_DISPLAY
  STDERR "^error: rendering needs an X display: run under xvfb-run -a \\(cannot connect to the X display ':4095'\\)\n$"
  NOT_EXIST ${cli_out}/deaddisplay.png
  ARGS render ${data}/bunny.json --level 0 -o ${cli_out}/deaddisplay.png)
tetskin_cli_test(render_unknown_path FAIL STDERR "^error: unknown render path 'fur' \\(known: cpu, gpu-1pass, gpu-2pass, fur-cpu, fur-gpu\\)"
  ARGS render ${data}/bunny.json --path fur -o ${cli_out}/x.png)
tetskin_cli_test(render_bad_fur_lighting FAIL STDERR "^error: unknown fur lighting 'shiny'"
  NOT_EXIST ${cli_out}/badfur.png
  ARGS render ${data}/bunny.json --path fur-cpu --fur-lighting shiny -o ${cli_out}/badfur.png)
tetskin_cli_test(render_bad_fur_shells FAIL STATUS 1
  STDERR "^error: --fur-shells: must lie in \\[1, 256\\], found 0\n$"
  ARGS render ${data}/bunny.json --path fur-gpu --fur-shells 0 -o ${cli_out}/badfur.png)
tetskin_cli_test(render_bad_fur_repeats FAIL STATUS 1
  STDERR "^error: --fur-texture-repeats: must lie in \\(0, 1000., found 0\n$"  # (. for ']': an unpaired bracket splits CMake lists)
  ARGS render ${data}/bunny.json --path fur-gpu --fur-texture-repeats 0 -o ${cli_out}/badfur.png)
# Values of the wrong type name the option (CLI11 alone: "Could not convert: --fur-fins = 2",
# and any whole number read as true).
tetskin_cli_test(render_bad_bool FAIL STATUS 1
  STDERR "^error: --fur-fins: '2' is not true or false \\(see tetskin render --help\\)\n$"
  ARGS render ${data}/bunny.json --path fur-gpu --fur-fins 2 -o ${cli_out}/badfur.png)
tetskin_cli_test(render_bad_shells FAIL STATUS 1
  STDERR "^error: --fur-shells: 'many' is not a whole number \\(see tetskin render --help\\)\n$"
  ARGS render ${data}/bunny.json --path fur-gpu --fur-shells many -o ${cli_out}/badfur.png)
tetskin_cli_test(render_bad_control FAIL STATUS 1
  STDERR "^error: unknown control mesh style 'mesh' \\(known: none, surface, wireframe, shrink\\)\n$"
  ARGS render ${data}/bunny.json --control mesh -o ${cli_out}/badfur.png)
tetskin_cli_test(render_output_not_png FAIL STATUS 1
  STDERR "^error: --output: '[^\n]*image.jpg' does not end in .png or .ogv \\(see tetskin render --help\\)\n$"
  NOT_EXIST ${cli_out}/image.jpg
  ARGS render ${data}/bunny.json --path cpu -o ${cli_out}/image.jpg)
tetskin_cli_test(render_into_a_new_folder FRESH ${cli_out}/new_render
  PNG_SIZE ${cli_out}/new_render/bunny.png 64x48
  ARGS render ${data}/bunny.json --path cpu --size 64x48 -o ${cli_out}/new_render/bunny.png)
set_tests_properties(cli.render_into_a_new_folder PROPERTIES LABELS "cli;rendering"
  RESOURCE_LOCK x_display)
tetskin_cli_test(render_frames_gpu STDOUT "3 frames, path gpu-1pass.*frames/s. per frame: simulation.*renderer: .*wrote"
  NOT_EXIST ${cli_out}/never.png
  ARGS render ${data}/bunny.json --surface ${data}/bunny.obj --path gpu-1pass --level 0 --frames 3
       --size 160x120 --control wireframe -o ${cli_out}/frames.png)
set_tests_properties(cli.render_frames_gpu PROPERTIES LABELS "cli;rendering" RESOURCE_LOCK x_display)
# The scenario options of simulate also shape render's frames, and only those.
tetskin_cli_test(render_scenario_options STDOUT "3 frames, path cpu.*wrote"
  ARGS render ${data}/bunny.json --surface ${data}/bunny.obj --level 0 --frames 3 --size 160x120
       --scenario twist --twist-degrees 45 --base-share 0.2 --fixed-nodes ${tdata}/held_nodes.txt
       -o ${cli_out}/twist45.png)
set_tests_properties(cli.render_scenario_options PROPERTIES LABELS "cli;rendering" RESOURCE_LOCK x_display)
# A binding from bind is drawn as it is: an embed binding by gpu-2pass and by
# gpu-1pass, on the binding's level.
tetskin_cli_test(render_embed_binding REQUIRES embed_binding
  STDOUT "2 frames, path gpu-2pass, [0-9]+ triangles, level 0 .*wrote"
  ARGS render ${data}/bunny.json --surface ${cli_out}/bunny_embed.vtp --path gpu-2pass --frames 2
       --size 160x120 -o ${cli_out}/embed.png)
tetskin_cli_test(render_embed_gpu1pass REQUIRES embed_binding
  STDOUT "2 frames, path gpu-1pass, [0-9]+ triangles, level 0 .*wrote"
  ARGS render ${data}/bunny.json --surface ${cli_out}/bunny_embed.vtp --path gpu-1pass --frames 2
       --size 160x120 -o ${cli_out}/embed1.png)
tetskin_cli_test(render_binding_other_level FAIL STATUS 1 REQUIRES embed_binding
  STDERR "^error: --level 1: [^\n]*bunny_embed.vtp is bound to level 0. leave --level out to use that level\n$"
  ARGS render ${data}/bunny.json --surface ${cli_out}/bunny_embed.vtp --level 1 -o ${cli_out}/embed2.png)
set_tests_properties(cli.render_embed_binding cli.render_embed_gpu1pass PROPERTIES
  LABELS "cli;rendering" RESOURCE_LOCK x_display)
# The material and time step of simulate also shape render's frames: the
# softer body's frames differ from the default one's, the film's rate is 1/dt.
tetskin_cli_test(render_live_material FRESH ${cli_out}/live_soft
  STDOUT "^5 frames, path cpu, [^\n]*level 0 [^\n]*\n  scenario wobble, 0.02 s per frame, material: E 20000 Pa, nu 0.3, density 100 kg/m\\^3, alpha 0.1, beta 0.01\n.*wrote [^\n]*soft.ogv \\(5 frames at 50 frames/s\\)\n$"
  ARGS render ${data}/bunny.json --level 0 --frames 5 --youngs-modulus 2e4 --time-step 0.02 --size 160x120
       -o ${cli_out}/live_soft/soft.ogv)
tetskin_cli_test(render_live_soft_image SETUP live_soft_image
  ARGS render ${data}/bunny.json --level 0 --frames 5 --youngs-modulus 2e4 --size 160x120
       -o ${cli_out}/live_soft.png)
tetskin_cli_test(render_live_default_image SETUP live_default_image
  STDOUT "material: E 200000 Pa, nu 0.3, density 100"
  ARGS render ${data}/bunny.json --level 0 --frames 5 --size 160x120
       -o ${cli_out}/live_default.png)
add_test(NAME cli.render_live_material_shapes_frames COMMAND ${CMAKE_COMMAND} -E compare_files
  ${cli_out}/live_soft.png ${cli_out}/live_default.png)
set_tests_properties(cli.render_live_material_shapes_frames PROPERTIES
  FIXTURES_REQUIRED "live_soft_image;live_default_image" WILL_FAIL TRUE)
set_tests_properties(cli.render_live_material cli.render_live_soft_image
  cli.render_live_default_image cli.render_live_material_shapes_frames PROPERTIES
  LABELS "cli;rendering" RESOURCE_LOCK x_display)
tetskin_cli_test(render_material_without_frames FAIL STATUS 1
  STDERR "^error: --youngs-modulus: applies to simulated frames. give --frames N\n$"
  NOT_EXIST ${cli_out}/still_soft.png
  ARGS render ${data}/bunny.json --youngs-modulus 2e4 -o ${cli_out}/still_soft.png)
tetskin_cli_test(render_time_step_without_frames FAIL STATUS 1
  STDERR "^error: --time-step: applies to simulated frames. give --frames N\n$"
  ARGS render ${data}/bunny.json --time-step 0.01 -o ${cli_out}/still_soft.png)
tetskin_cli_test(render_bad_material FAIL STATUS 1
  STDERR "^error: --poisson-ratio: Poisson's ratio must lie in \\(-1, 0.5\\), got 0.5\n$"
  NOT_EXIST ${cli_out}/bad_material.ogv
  ARGS render ${data}/bunny.json --frames 3 --poisson-ratio 0.5 -o ${cli_out}/bad_material.ogv)
tetskin_cli_test(render_scenario_without_frames FAIL STATUS 1
  STDERR "^error: --twist-degrees: applies to simulated frames. give --frames N\n$"
  NOT_EXIST ${cli_out}/still45.png
  ARGS render ${data}/bunny.json --twist-degrees 45 -o ${cli_out}/still45.png)
tetskin_cli_test(render_scenario_name_without_frames FAIL STATUS 1
  STDERR "^error: --scenario: applies to simulated frames. give --frames N\n$"
  NOT_EXIST ${cli_out}/still_drop.png
  ARGS render ${data}/bunny.json --scenario drop -o ${cli_out}/still_drop.png)
tetskin_cli_test(render_fur_option_without_fur FAIL STATUS 1
  STDERR "^error: --fur-shells: applies to the fur paths \\(fur-cpu, fur-gpu\\), not to gpu-2pass\n$"
  NOT_EXIST ${cli_out}/no_fur.png
  ARGS render ${data}/bunny.json --path gpu-2pass --fur-shells 10 -o ${cli_out}/no_fur.png)
tetskin_cli_test(render_textured STDOUT "2 frames, path gpu-2pass, 7998 triangles.*wrote"
  ARGS render ${data}/bunny.json --surface ${data}/bunny_8k_tex.obj --texture ${data}/bunny_texture.png
       --path gpu-2pass --level 0 --frames 2 --size 160x120 -o ${cli_out}/textured.png)
tetskin_cli_test(render_texture_needs_texcoords FAIL STDERR "^error: [^\n]*bunny_texture.png: cannot be applied: the surface has no texture coordinates"
  NOT_EXIST ${cli_out}/untextured.png
  ARGS render ${data}/bunny.json --surface ${data}/bunny.obj --texture ${data}/bunny_texture.png
       --level 0 -o ${cli_out}/untextured.png)
tetskin_cli_test(render_fur_cpu STDOUT "2 frames, path fur-cpu.*fur: 6 shells drawn.*wrote"
  ARGS render ${data}/bunny.json --surface ${data}/bunny_8k_tex.obj --texture ${data}/bunny_texture.png
       --path fur-cpu --level 0 --frames 2 --size 160x120 --fur-shells 6 --fur-adaptive-shells false
       --fur-fins true --fur-lighting kajiya-kay -o ${cli_out}/fur_cpu.png)
tetskin_cli_test(render_fur_gpu_adaptive STDOUT "2 frames, path fur-gpu.*fur: 4 shells drawn.*wrote"
  ARGS render ${data}/bunny.json --surface ${data}/bunny.obj --path fur-gpu --level 0 --frames 2
       --size 160x120 --fur-shells 32 --fur-min-shells 4 --fur-fins true -o ${cli_out}/fur_gpu.png)
# The fur's switch took its config key's name; the old flag is still read
# (with a warning) and refused beside the new one, before anything is drawn.
tetskin_cli_test(render_old_fur_flag FAIL STATUS 1
  STDERR "^error: --fur-adaptive: is the same option as --fur-adaptive-shells: give one\n$"
  ARGS render ${data}/bunny.json --path fur-cpu --fur-adaptive-shells true --fur-adaptive false
       -o ${cli_out}/old_fur_flag.png)
set_tests_properties(cli.render_textured cli.render_texture_needs_texcoords cli.render_fur_cpu
  cli.render_fur_gpu_adaptive PROPERTIES
  LABELS "cli;rendering" RESOURCE_LOCK x_display)
tetskin_cli_test(render_recorded_run REQUIRES "recorded_run;stale_image" SETUP drawn_run NOT_EXIST ${cli_out}/drawn/f_00004.png
  STDOUT "^drew 4 frames of [^\n]*recorded/run.pvd \\(t 0 .. 0.5 s\\), path cpu, 7998 triangles, level 2, 160x120\n.*wrote [^\n]*drawn/f_00000.png .. [^\n]*drawn/f_00003.png\n$"
  PNG_SIZE ${cli_out}/drawn/f_00003.png 160x120
  ARGS render ${data}/bunny.json --run ${cli_out}/recorded/run.pvd --size 160x120
       -o ${cli_out}/drawn/f.png)
add_test(NAME cli.render_recorded_run_moves COMMAND ${CMAKE_COMMAND} -E compare_files
  ${cli_out}/drawn/f_00000.png ${cli_out}/drawn/f_00003.png)
set_tests_properties(cli.render_recorded_run_moves PROPERTIES FIXTURES_REQUIRED drawn_run
  WILL_FAIL TRUE)
# (A run recorded without a surface is drawn with the dataset's; one with
# its own surface, as the wobble above, with that one: 7998 triangles.)
tetskin_cli_test(render_run_at_rest REQUIRES run_at_rest SETUP drawn_at_rest FRESH ${cli_out}/drawn_at_rest
  STDOUT "^drew 3 frames of [^\n]*at_rest/run.pvd [^\n]*, path cpu, 3674 triangles, level 2, 160x120\n"
  ARGS render ${data}/bunny.json --run ${cli_out}/at_rest/run.pvd --size 160x120
       -o ${cli_out}/drawn_at_rest/f.png)
tetskin_cli_test(render_still_of_the_run SETUP still_of_run
  ARGS render ${data}/bunny.json --size 160x120 -o ${cli_out}/drawn_still.png)
add_test(NAME cli.render_recorded_run_at_rest_as_still COMMAND ${CMAKE_COMMAND} -E compare_files
  ${cli_out}/drawn_at_rest/f_00002.png ${cli_out}/drawn_still.png)
set_tests_properties(cli.render_recorded_run_at_rest_as_still PROPERTIES
  FIXTURES_REQUIRED "drawn_at_rest;still_of_run")
tetskin_cli_test(render_recorded_drop REQUIRES drop_run SETUP drawn_drop FRESH ${cli_out}/drawn_drop
  ARGS render ${data}/bunny.json --run ${cli_out}/drop/run.pvd --size 160x120
       -o ${cli_out}/drawn_drop/f.png)
tetskin_cli_test(render_live_drop SETUP live_drop
  ARGS render ${data}/bunny.json --scenario drop --frames 1 --level 0 --size 160x120
       -o ${cli_out}/live_drop.png)
tetskin_cli_test(render_recorded_run_fur REQUIRES recorded_run FRESH ${cli_out}/drawn_fur
  STDOUT "^drew 4 frames of [^\n]*run.pvd \\(t 0 .. 0.5 s\\), path fur-gpu, 7998 triangles, level 2, 96x72\n"
  PNG_SIZE ${cli_out}/drawn_fur/f_00003.png 96x72
  ARGS render ${data}/bunny.json --run ${cli_out}/recorded/run.pvd --path fur-gpu --size 96x72
       -o ${cli_out}/drawn_fur/f.png)
# A recorded run filmed into one movie (.ogv): as many frames as the run,
# at the rate they were recorded (4 frames over 0.5 s: 6 frames/s); decoded
# with libtheora, its first frame is the first image drawn of the run.
tetskin_cli_test(render_recorded_run_film REQUIRES recorded_run SETUP filmed_run FRESH ${cli_out}/film
  STDOUT "wrote [^\n]*film/wobble.ogv \\(4 frames at 6 frames/s\\)\n$"
  ARGS render ${data}/bunny.json --run ${cli_out}/recorded/run.pvd --size 160x120
       -o ${cli_out}/film/wobble.ogv)
tetskin_cli_test(render_film_without_a_run FAIL STATUS 1
  STDERR "^error: -o [^\n]*still.ogv: a movie is filmed of a run: give --frames N \\(simulated now\\) or --run RUN.pvd \\(recorded\\)\n$"
  NOT_EXIST ${cli_out}/still.ogv
  ARGS render ${data}/bunny.json -o ${cli_out}/still.ogv)
# A simulation filmed as it runs: every frame, at 1/dt frames/s; its first
# frame is the image render --frames 1 draws.
tetskin_cli_test(render_live_film SETUP live_film FRESH ${cli_out}/live_film
  STDOUT "wrote [^\n]*live_film/wobble.ogv \\(3 frames at 60 frames/s\\)\n$"
  ARGS render ${data}/bunny.json --frames 3 --size 160x120 -o ${cli_out}/live_film/wobble.ogv)
tetskin_cli_test(render_live_first_frame SETUP live_first_frame
  ARGS render ${data}/bunny.json --frames 1 --size 160x120 -o ${cli_out}/live_first_frame.png)
# The frames' level is the run's: --level, a binding of another level and
# --frames contradict it.
tetskin_cli_test(render_recorded_run_other_level FAIL STATUS 1 REQUIRES recorded_run
  STDERR "^error: --level 0: the run's frames are of level 2. leave --level out\n$"
  NOT_EXIST ${cli_out}/drawn_other/f_00000.png
  ARGS render ${data}/bunny.json --run ${cli_out}/recorded/run.pvd --level 0
       -o ${cli_out}/drawn_other/f.png)
tetskin_cli_test(render_recorded_run_and_frames FAIL STATUS 1 REQUIRES recorded_run
  STDERR "^error: --frames: simulates a new run. --run draws the recorded one: give one of them\n$"
  ARGS render ${data}/bunny.json --run ${cli_out}/recorded/run.pvd --frames 3
       -o ${cli_out}/drawn_other/f.png)
tetskin_cli_test(render_recorded_run_scenario_option FAIL STATUS 1 REQUIRES recorded_run
  STDERR "^error: --push-acceleration: applies to simulated frames. give --frames N \\(--run draws a recorded run as it was simulated\\)\n$"
  ARGS render ${data}/bunny.json --run ${cli_out}/recorded/run.pvd --push-acceleration 3
       -o ${cli_out}/drawn_other/f.png)
tetskin_cli_test(render_recorded_run_other_binding FAIL STATUS 1 REQUIRES "recorded_run;embed_binding"
  STDERR "^error: [^\n]*bunny_embed.vtp: is bound to level 0, the run's frames are of level 2: bind the surface to level 2 or give the plain surface\n$"
  ARGS render ${data}/bunny.json --run ${cli_out}/recorded/run.pvd --surface ${cli_out}/bunny_embed.vtp
       -o ${cli_out}/drawn_other/f.png)
tetskin_cli_test(render_recorded_run_missing_frame FAIL STATUS 1
  STDERR "^error: [^\n]*missing_frame_run.pvd: names the frame missing_frame_run/control_00000.vtu, which is not there\n$"
  ARGS render ${data}/bunny.json --run ${tdata}/missing_frame_run.pvd -o ${cli_out}/drawn_other/f.png)
# A frame that cannot be read halfway: the images drawn before it, and the
# folder made for them, are removed.
add_test(NAME cli.copy_recorded_run COMMAND ${CMAKE_COMMAND} -E copy_directory
  ${cli_out}/recorded ${cli_out}/recorded_broken)
set_tests_properties(cli.copy_recorded_run PROPERTIES
  FIXTURES_REQUIRED recorded_run FIXTURES_SETUP broken_run_copy)
add_test(NAME cli.break_recorded_frame COMMAND ${CMAKE_COMMAND} -E copy ${tdata}/loads.txt
  ${cli_out}/recorded_broken/run_frames/control_00002.vtu)
set_tests_properties(cli.break_recorded_frame PROPERTIES
  FIXTURES_REQUIRED broken_run_copy FIXTURES_SETUP broken_run)
tetskin_cli_test(render_recorded_run_broken_film FAIL STATUS 1 REQUIRES broken_run
  FRESH ${cli_out}/film_broken NOT_EXIST ${cli_out}/film_broken
  STDERR "^error: [^\n]*recorded_broken/run_frames/control_00002.vtu: is not a VTK XML file"
  ARGS render ${data}/bunny.json --run ${cli_out}/recorded_broken/run.pvd
       -o ${cli_out}/film_broken/deeper/f.ogv)
tetskin_cli_test(render_recorded_run_broken_frame FAIL STATUS 1 REQUIRES broken_run
  FRESH ${cli_out}/drawn_broken NOT_EXIST ${cli_out}/drawn_broken
  STDERR "^error: [^\n]*recorded_broken/run_frames/control_00002.vtu: is not a VTK XML file"
  ARGS render ${data}/bunny.json --run ${cli_out}/recorded_broken/run.pvd
       -o ${cli_out}/drawn_broken/deeper/f.png)
# --print-run: the run --frames would simulate (python.run_parity compares
# it with simulate's); a recorded run (--run) is drawn as it was.
tetskin_cli_test(render_print_run_of_a_recording FAIL STATUS 1
  STDERR "^error: --print-run: prints the run --frames simulates \\(--run draws a recorded one as it was\\)\n$"
  ARGS render ${data}/bunny.json --run ${tdata}/missing_frame_run.pvd --print-run)

# Scenes: render draws a scene's bodies, skins and obstacles, simulated
# (--frames) or recorded (--run). A scene of one body and nothing else is
# drawn as its dataset is, byte for byte; a cube beside it (inside the
# bunny's box, so the framing stays) changes the picture.
tetskin_cli_test(render_scene_alone SETUP scene_alone
  ARGS render ${tdata}/scenes/bunny_alone.json --size 160x120 -o ${cli_out}/scene_alone.png)
tetskin_cli_test(render_scene_as_dataset SETUP scene_as_dataset
  ARGS render ${data}/bunny.json --level 0 --surface ${data}/bunny_8k.obj --size 160x120
       -o ${cli_out}/scene_as_dataset.png)
tetskin_cli_test(render_scene_with_cube SETUP scene_with_cube
  ARGS render ${tdata}/scenes/bunny_and_cube.json --size 160x120 -o ${cli_out}/scene_with_cube.png)
add_test(NAME cli.render_scene_drawn_as_its_dataset COMMAND ${CMAKE_COMMAND} -E compare_files
  ${cli_out}/scene_alone.png ${cli_out}/scene_as_dataset.png)
set_tests_properties(cli.render_scene_drawn_as_its_dataset PROPERTIES
  FIXTURES_REQUIRED "scene_alone;scene_as_dataset")
add_test(NAME cli.render_scene_draws_its_obstacle COMMAND ${CMAKE_COMMAND} -E compare_files
  ${cli_out}/scene_alone.png ${cli_out}/scene_with_cube.png)
set_tests_properties(cli.render_scene_draws_its_obstacle PROPERTIES
  FIXTURES_REQUIRED "scene_alone;scene_with_cube" WILL_FAIL TRUE)
# A run of two bodies, recorded, drawn on its scene: each frame the bodies'
# frames side by side; a run at rest (no steps) is drawn as the scene's
# still, byte for byte; filmed, its first frame is the first image.
tetskin_cli_test(simulate_two_bodies_to_draw SETUP two_bodies_run FRESH ${cli_out}/two_bodies
  ARGS simulate ${tdata}/scenes/two_bunnies.json --steps 6 --every 3 -q -o ${cli_out}/two_bodies/run.pvd)
tetskin_cli_test(render_recorded_two_bodies REQUIRES two_bodies_run SETUP drawn_two_bodies
  FRESH ${cli_out}/drawn_two_bodies
  STDOUT "^drew 3 frames of [^\n]*two_bodies/run.pvd \\(t 0 .. 0.1 s\\), path cpu, 15996 triangles, level 0, 160x120\n"
  ARGS render ${tdata}/scenes/two_bunnies.json --run ${cli_out}/two_bodies/run.pvd --size 160x120
       -o ${cli_out}/drawn_two_bodies/f.png)
tetskin_cli_test(render_filmed_two_bodies REQUIRES two_bodies_run SETUP filmed_two_bodies
  FRESH ${cli_out}/film_two_bodies
  STDOUT "wrote [^\n]*two_bodies.ogv \\(3 frames at 20 frames/s\\)\n$"
  ARGS render ${tdata}/scenes/two_bunnies.json --run ${cli_out}/two_bodies/run.pvd --size 160x120
       -o ${cli_out}/film_two_bodies/two_bodies.ogv)
tetskin_cli_test(render_filmed_two_bodies_decodes REQUIRES "filmed_two_bodies;drawn_two_bodies"
  EXE tetskin_ogv_frames
  STDOUT "^3 frames, 160x120, first and last frames differ\nfirst frame matches the image"
  ARGS ${cli_out}/film_two_bodies/two_bodies.ogv ${cli_out}/drawn_two_bodies/f_00000.png)
tetskin_cli_test(simulate_two_bodies_at_rest SETUP two_bodies_at_rest FRESH ${cli_out}/two_at_rest
  ARGS simulate ${tdata}/scenes/two_bunnies.json --steps 0 -q -o ${cli_out}/two_at_rest/run.pvd)
tetskin_cli_test(render_two_bodies_at_rest REQUIRES two_bodies_at_rest SETUP drawn_two_at_rest
  FRESH ${cli_out}/drawn_two_at_rest
  ARGS render ${tdata}/scenes/two_bunnies.json --run ${cli_out}/two_at_rest/run.pvd --size 160x120
       -o ${cli_out}/drawn_two_at_rest/f.png)
tetskin_cli_test(render_two_bodies_still SETUP two_bodies_still
  ARGS render ${tdata}/scenes/two_bunnies.json --size 160x120 -o ${cli_out}/two_bodies_still.png)
add_test(NAME cli.render_recorded_two_bodies_at_rest_as_still COMMAND ${CMAKE_COMMAND} -E compare_files
  ${cli_out}/drawn_two_at_rest/f_00000.png ${cli_out}/two_bodies_still.png)
set_tests_properties(cli.render_recorded_two_bodies_at_rest_as_still PROPERTIES
  FIXTURES_REQUIRED "drawn_two_at_rest;two_bodies_still")
# The scene's run is its own; its bodies' levels and skins too; a run of
# several bodies is drawn on its scene, not on a dataset.
tetskin_cli_test(render_scene_material_option FAIL STATUS 1
  STDERR "^error: --youngs-modulus: [^\n]*two_bunnies.json is a scene, whose run is its own: set it in the scene\n$"
  ARGS render ${tdata}/scenes/two_bunnies.json --frames 2 --youngs-modulus 1e5 -o ${cli_out}/refused.png)
tetskin_cli_test(render_scene_two_bodies_level FAIL STATUS 1
  STDERR "two_bunnies.json: holds 2 bodies. each takes its level and surface from the scene, not from --level or --surface"
  ARGS render ${tdata}/scenes/two_bunnies.json --level 0 -o ${cli_out}/refused.png)
tetskin_cli_test(render_two_bodies_on_a_dataset FAIL STATUS 1 REQUIRES two_bodies_run
  STDERR "^error: [^\n]*two_bodies/run.pvd: records 2 bodies of [0-9]+ nodes and [0-9]+ tetrahedra in all. level 0 of [^\n]*bunny.json has [0-9]+ and [0-9]+: [^\n]*the scene it was recorded from\n$"
  NOT_EXIST ${cli_out}/refused_f_00000.png
  ARGS render ${data}/bunny.json --surface ${data}/bunny_8k.obj --run ${cli_out}/two_bodies/run.pvd --size 160x120
       -o ${cli_out}/refused_f.png)
set_tests_properties(cli.render_scene_alone cli.render_scene_as_dataset cli.render_scene_with_cube
  cli.render_scene_drawn_as_its_dataset cli.render_scene_draws_its_obstacle
  cli.simulate_two_bodies_to_draw cli.render_recorded_two_bodies cli.render_filmed_two_bodies
  cli.render_filmed_two_bodies_decodes cli.simulate_two_bodies_at_rest cli.render_two_bodies_at_rest
  cli.render_two_bodies_still cli.render_recorded_two_bodies_at_rest_as_still
  cli.render_scene_material_option cli.render_scene_two_bodies_level cli.render_two_bodies_on_a_dataset
  PROPERTIES LABELS "cli;rendering" RESOURCE_LOCK x_display)
