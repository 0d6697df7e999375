# CLI tests of scenes: tetskin simulate SCENE.json (included by
# tests/cli/CMakeLists.txt).

# The bundled scene, briefly, on its coarsest level: the skin meets the bowl.
tetskin_cli_test(simulate_scene
  STDOUT "scenario free.*\n  1 obstacle met by the skin. at the end [0-9]+ contacts"
  ARGS simulate ${data}/scenes/bunny-in-bowl.json --level 0 --steps 90 -q -o ${cli_out}/scene_run.pvd)
# A body's skin meeting itself: the run says so, with its shell's thickness.
tetskin_cli_test(simulate_scene_self_contact
  STDOUT "\n  the floor met by the skin[^\n]*\n  the skin meets itself: a shell 0.05 thick, springs of [0-9.e+]+ N.m. at the end [0-9]+ contacts in all\n"
  ARGS simulate ${tdata}/scenes/self_contact.json --steps 20 -q -o ${cli_out}/self_contact.pvd)
# Two bodies, the second dropped onto the first: each body's part and
# material, and their skins meeting.
tetskin_cli_test(simulate_scene_two_bodies
  STDOUT "\n  body /bodies/0: 598 tetrahedra, [0-9]+ skin vertices, material E 200000 Pa[^\n]*\n  body /bodies/1: 598 tetrahedra, [0-9]+ skin vertices, material E 400000 Pa.*\n  the 2 bodies. skins meet each other: a shell [0-9.e-]+ thick, springs of [0-9.e+]+ N.m. at the end [0-9]+ contacts in all\n"
  ARGS simulate ${tdata}/scenes/two_bunnies.json --steps 20 -q -o ${cli_out}/two_bunnies.pvd)
# More than one body: the level and the surface are each body's own.
tetskin_cli_test(simulate_scene_two_bodies_level FAIL STATUS 1
  STDERR "two_bunnies.json: holds 2 bodies. each takes its level and surface from the scene, not from --level or --surface"
  ARGS simulate ${tdata}/scenes/two_bunnies.json --level 1 -o ${cli_out}/two_bunnies_level.pvd)
# The command line's options over the scene's values; the rest the scene's.
tetskin_cli_test(simulate_scene_overrides
  STDOUT "\"dataset\": \"[^,]*bunny.json\".*\"level\": 0,.*\"contact_points\": \"skin\".*\"friction\": 0.3,.*\"obstacles\": .*\"kinetic_friction\": 0.4,.*\"time_step\": 0.01.*\"scenario\": \"free\""
  ARGS simulate ${data}/scenes/bunny-in-bowl.json --level 0 --time-step 0.01 --friction 0.3 --print-run)
# Bad scenes: the scene file and the field named, nothing written.
tetskin_cli_test(simulate_scene_bad_key FAIL STATUS 1
  STDERR "^error: [^\n]*bad_key.json: /bodies/0/colour: is not a known field\n$"
  NOT_EXIST ${cli_out}/bad_scene.pvd
  ARGS simulate ${tdata}/scenes/bad_key.json -o ${cli_out}/bad_scene.pvd)
tetskin_cli_test(simulate_scene_missing_obstacle FAIL STATUS 1
  STDERR "^error: [^\n]*missing_obstacle.json: /obstacles/0/surface: [^\n]*no_such_bowl.obj: no such file\n$"
  NOT_EXIST ${cli_out}/bad_scene.pvd
  ARGS simulate ${tdata}/scenes/missing_obstacle.json -o ${cli_out}/bad_scene.pvd)
tetskin_cli_test(simulate_scene_open_obstacle FAIL STATUS 1
  STDERR "^error: [^\n]*open_obstacle.json: /obstacles/0/surface: [^\n]*open_sheet.obj[^\n]*edge[^\n]*\n$"
  NOT_EXIST ${cli_out}/bad_scene.pvd
  ARGS simulate ${tdata}/scenes/open_obstacle.json -o ${cli_out}/bad_scene.pvd)
# A scene of one body is the same run as that body without a scene: the
# bunny on a floor, from the scene and from the command line, writes the
# same frames byte for byte (cg alone: the automatic choice times its
# solvers).
tetskin_cli_test(simulate_scene_of_one_body SETUP one_body_scene FRESH ${cli_out}/one_body_scene
  ARGS simulate ${tdata}/scenes/bunny_on_floor.json --solver cg --steps 10 --every 10 -q
       -o ${cli_out}/one_body_scene/run.pvd)
tetskin_cli_test(simulate_one_body_without_scene SETUP one_body_plain FRESH ${cli_out}/one_body_plain
  ARGS simulate ${data}/bunny.json --level 0 --surface ${data}/bunny_8k.obj --scenario free
       --floor-height 0.5 --friction 0.4 --solver cg --steps 10 --every 10 -q
       -o ${cli_out}/one_body_plain/run.pvd)
foreach(frame control_00001.vtu surface_00001.vtp)
  add_test(NAME cli.scene_of_one_body_is_the_plain_run_${frame} COMMAND ${CMAKE_COMMAND} -E compare_files
    ${cli_out}/one_body_scene/run_frames/${frame} ${cli_out}/one_body_plain/run_frames/${frame})
  set_tests_properties(cli.scene_of_one_body_is_the_plain_run_${frame} PROPERTIES LABELS cli
    FIXTURES_REQUIRED "one_body_scene;one_body_plain")
endforeach()
