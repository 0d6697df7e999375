# CLI tests of tetskin-gui from the command line (included by tests/cli/CMakeLists.txt).

if(TETSKIN_BUILD_GUI)
  # --size is the image's: the view's size, whatever the docks beside it take.
  tetskin_cli_test(gui_screenshot EXE tetskin-gui STDOUT "wrote .*gui_shot.png"
    PNG_SIZE ${cli_out}/gui_shot.png 320x240
    ARGS ${data}/bunny.json ${data}/bunny.obj --path gpu-2pass --size 320x240
         --screenshot ${cli_out}/gui_shot.png)
  tetskin_cli_test(gui_screenshot_window EXE tetskin-gui STDOUT "wrote .*gui_window.png"
    PNG_SIZE ${cli_out}/gui_window.png 1000x700
    ARGS ${data}/bunny.json --size 1000x700 --window --screenshot ${cli_out}/gui_window.png)
  tetskin_cli_test(gui_bad_choice FAIL STATUS 1 EXE tetskin-gui
    STDERR "(^|\n)error: --control: 'bogus' is not one of none, surface, wireframe, shrink\n$"
    NOT_EXIST ${cli_out}/gui_choice.png
    ARGS ${data}/bunny.json --control bogus --screenshot ${cli_out}/gui_choice.png)
  tetskin_cli_test(gui_screenshot_not_png FAIL STATUS 1 EXE tetskin-gui
    STDERR "(^|\n)error: [^\n]*gui_shot.jpg: a screenshot is a PNG image: the name must end in .png\n$"
    NOT_EXIST ${cli_out}/gui_shot.jpg
    ARGS ${data}/bunny.json --screenshot ${cli_out}/gui_shot.jpg)
  tetskin_cli_test(gui_bad_size FAIL STATUS 1 EXE tetskin-gui
    STDERR "(^|\n)error: --size: '320x240x' is not WIDTHxHEIGHT with both in .16, 8192.\n$"
    ARGS --size 320x240x --screenshot ${cli_out}/gui_size.png)
  tetskin_cli_test(gui_bad_file FAIL EXE tetskin-gui STDERR "(^|\n)error: [^\n]*bad_index.obj:5: vertex index"
    NOT_EXIST ${cli_out}/gui_bad.png
    ARGS ${data}/bunny.json ${tdata}/bad_index.obj --screenshot ${cli_out}/gui_bad.png)
  # A comparison from the command line: level 0 against the finest.
  tetskin_cli_test(gui_compare_screenshot EXE tetskin-gui STDOUT "wrote .*gui_compare.png"
    PNG_SIZE ${cli_out}/gui_compare.png 320x240
    ARGS ${data}/bunny.json ${data}/bunny.obj --compare 0 --steps 6 --size 320x240
         --screenshot ${cli_out}/gui_compare.png)
  tetskin_cli_test(gui_compare_bad_level FAIL STATUS 1 EXE tetskin-gui
    STDERR "(^|\n)error: --compare: [^\n]*level 7[^\n]*\n$"
    NOT_EXIST ${cli_out}/gui_compare_bad.png
    ARGS ${data}/bunny.json ${data}/bunny.obj --compare 7 --screenshot ${cli_out}/gui_compare_bad.png)
  # A scenario as the Simulation dock sets it: a drop lands on its floor,
  # which fills the bottom of the view; the wobble's view has no floor.
  # (--no-overlay: the frame statistics' text would reach the edges.)
  tetskin_cli_test(gui_drop_screenshot SETUP gui_drop EXE tetskin-gui STDOUT "wrote .*gui_drop.png"
    ARGS ${data}/bunny.json --scenario drop --steps 30 --size 320x240 --no-overlay
         --screenshot ${cli_out}/gui_drop.png)
  tetskin_cli_test(gui_drop_floor FAIL STATUS 1 REQUIRES gui_drop EXE tetskin_image_border
    STDOUT "gui_drop.png: drawn at the bottom edge" ARGS ${cli_out}/gui_drop.png)
  tetskin_cli_test(gui_wobble_screenshot SETUP gui_wobble EXE tetskin-gui
    ARGS ${data}/bunny.json --scenario wobble --steps 30 --size 320x240 --no-overlay
         --screenshot ${cli_out}/gui_wobble.png)
  tetskin_cli_test(gui_wobble_without_floor REQUIRES gui_wobble EXE tetskin_image_border
    STDOUT "gui_wobble.png: the border is background\n$" ARGS ${cli_out}/gui_wobble.png)
  # The prescribed nodes marked (the GUI test checks the marks themselves).
  tetskin_cli_test(gui_prescribed_screenshot EXE tetskin-gui STDOUT "wrote .*gui_prescribed.png"
    PNG_SIZE ${cli_out}/gui_prescribed.png 320x240
    ARGS ${data}/bunny.json --scenario twist --steps 2 --prescribed --size 320x240 --no-overlay
         --screenshot ${cli_out}/gui_prescribed.png)
  tetskin_cli_test(gui_bad_scenario FAIL STATUS 1 EXE tetskin-gui
    STDERR "(^|\n)error: --scenario: 'spin' is not one of wobble, drop, twist, sag, free\n$"
    NOT_EXIST ${cli_out}/gui_spin.png
    ARGS ${data}/bunny.json --scenario spin --screenshot ${cli_out}/gui_spin.png)
  set_tests_properties(cli.gui_drop_screenshot cli.gui_drop_floor cli.gui_wobble_screenshot
    cli.gui_wobble_without_floor cli.gui_prescribed_screenshot cli.gui_bad_scenario PROPERTIES
    LABELS "cli;rendering;gui" RESOURCE_LOCK x_display)
  # Steps asked for on a level the simulation refuses: an error, no screenshot.
  tetskin_cli_test(gui_steps_without_simulation FAIL STATUS 1 EXE tetskin-gui
    STDERR "(^|\n)error: [^\n]*inverted_tet.node: level 0: element 0 has non-positive volume"
    NOT_EXIST ${cli_out}/gui_no_steps.png
    ARGS ${tdata}/inverted_tet.node --steps 2 --screenshot ${cli_out}/gui_no_steps.png)
  tetskin_cli_test(gui_needs_display FAIL NO_DISPLAY EXE tetskin-gui
    STDERR "^error: tetskin-gui needs an X display" ARGS --screenshot ${cli_out}/x.png)
  # (Qt's xcb platform would abort the process.)
  tetskin_cli_test(gui_dead_display FAIL STATUS 1 DEAD_DISPLAY EXE tetskin-gui
    STDERR "^error: tetskin-gui needs an X display \\(cannot connect to the X display ':4095'"
    NOT_EXIST ${cli_out}/gui_dead.png ARGS ${data}/bunny.json --screenshot ${cli_out}/gui_dead.png)
  # Help, the version and usage errors need no display.
  tetskin_cli_test(gui_help NO_DISPLAY EXE tetskin-gui
    STDOUT "^Usage: [^\n]*tetskin-gui \\[options\\] \\[DATASET\\] \\[SURFACE\\]\n.*--screenshot <FILE>"
    ARGS --help)
  tetskin_cli_test(gui_version NO_DISPLAY EXE tetskin-gui STDOUT "^tetskin-gui ${PROJECT_VERSION}\n$"
    ARGS --version)
  tetskin_cli_test(gui_unknown_option FAIL STATUS 1 NO_DISPLAY EXE tetskin-gui
    STDERR "^error: Unknown option 'bogus'. \\(see tetskin-gui --help\\)\n$" ARGS --bogus)
  tetskin_cli_test(gui_bad_size_without_display FAIL STATUS 1 NO_DISPLAY EXE tetskin-gui
    STDERR "^error: --size: '0x0' is not WIDTHxHEIGHT" ARGS --size 0x0 --screenshot ${cli_out}/x.png)
  # A platform without OpenGL (Qt's offscreen one has none without X):
  # named, not an empty or black screenshot.
  tetskin_cli_test(gui_without_opengl FAIL STATUS 1 NO_DISPLAY EXE tetskin-gui
    STDERR "(^|\n)error: the view cannot create an OpenGL context on this display"
    NOT_EXIST ${cli_out}/gui_no_gl.png
    ARGS -platform offscreen ${data}/bunny.json --screenshot ${cli_out}/gui_no_gl.png)
  set_tests_properties(cli.gui_screenshot cli.gui_screenshot_window cli.gui_bad_choice
    cli.gui_screenshot_not_png cli.gui_bad_size cli.gui_bad_file cli.gui_steps_without_simulation PROPERTIES
    LABELS "cli;rendering;gui" RESOURCE_LOCK x_display)
endif()
