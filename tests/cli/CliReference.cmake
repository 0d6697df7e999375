# doc/user/cli-reference.md from the --help of tetskin, its subcommands and
# tetskin-gui: with UPDATE=ON it writes the page, otherwise it fails when the
# page differs from what --help prints now (an option added, renamed or
# re-documented without the page).
#   cmake -DTETSKIN=build/app/cli/tetskin -DTETSKIN_GUI=build/app/gui/tetskin-gui
#         -DPAGE=doc/user/cli-reference.md -DSOURCE_DIR=$PWD [-DUPDATE=ON]
#         -P tests/cli/CliReference.cmake
foreach(var TETSKIN TETSKIN_GUI PAGE SOURCE_DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "CliReference.cmake needs -D${var}=...")
  endif()
endforeach()

function(help_of out)
  execute_process(COMMAND ${ARGN} --help OUTPUT_VARIABLE text RESULT_VARIABLE status
                  ERROR_VARIABLE errors)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${ARGN} --help failed (${status}): ${errors}")
  endif()
  # The program's path as the user types it, not the build tree's.
  string(REPLACE "${TETSKIN_GUI}" "tetskin-gui" text "${text}")
  string(REPLACE "${TETSKIN}" "tetskin" text "${text}")
  # Defaults under the source tree (bench --data) as the README's commands
  # run them, from its root: the page is the same on every machine.
  string(REPLACE "${SOURCE_DIR}/" "" text "${text}")
  string(STRIP "${text}" text)
  set(${out} "${text}" PARENT_SCOPE)
endfunction()

set(page "# Command-line reference\n\n")
string(APPEND page "Every option of `tetskin` and `tetskin-gui`, as their `--help` prints it.\n")
string(APPEND page "Generated: do not edit. `cli.reference` fails when this page and `--help`\n")
string(APPEND page "differ; after changing an option, rewrite it from the build tree with\n\n")
string(APPEND page "```sh\ncmake -DTETSKIN=build/app/cli/tetskin -DTETSKIN_GUI=build/app/gui/tetskin-gui \\\n")
string(APPEND page "      -DPAGE=doc/user/cli-reference.md -DSOURCE_DIR=$PWD -DUPDATE=ON \\\n")
string(APPEND page "      -P tests/cli/CliReference.cmake\n```\n\n")
string(APPEND page "Conventions every command shares (levels, errors, outputs): [command-line.md](command-line.md).\n")
help_of(text ${TETSKIN})
string(APPEND page "\n## tetskin\n\n```text\n${text}\n```\n")
foreach(sub build bind deform simulate compare render bench probe info convert)
  help_of(text ${TETSKIN} ${sub})
  string(APPEND page "\n## tetskin ${sub}\n\n```text\n${text}\n```\n")
endforeach()
set(ENV{QT_QPA_PLATFORM} offscreen)  # (--help needs no display)
help_of(text ${TETSKIN_GUI})
string(APPEND page "\n## tetskin-gui\n\n```text\n${text}\n```\n")

if(UPDATE)
  file(WRITE ${PAGE} "${page}")
  message(STATUS "wrote ${PAGE}")
  return()
endif()
if(NOT EXISTS ${PAGE})
  message(FATAL_ERROR "${PAGE} is missing; write it with -DUPDATE=ON")
endif()
file(READ ${PAGE} committed)
if(NOT committed STREQUAL page)
  file(WRITE ${PAGE}.new "${page}")
  execute_process(COMMAND diff -u ${PAGE} ${PAGE}.new OUTPUT_VARIABLE difference)
  file(REMOVE ${PAGE}.new)
  message(FATAL_ERROR "${PAGE} differs from --help (rewrite it with -DUPDATE=ON):\n${difference}")
endif()
