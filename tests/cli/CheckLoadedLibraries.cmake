# Runs TETSKIN with ARGS (separated by '|') and checks, by the dynamic
# loader's own account (LD_DEBUG=files), which shared libraries the process
# loaded: none matching FORBIDDEN, and one matching each of REQUIRED (a
# regex list separated by '|' as well; optional). The command must succeed.
#   cmake -DTETSKIN=... -DARGS=--help -DFORBIDDEN=libpython -P CheckLoadedLibraries.cmake
string(REPLACE "|" ";" args "${ARGS}")
execute_process(COMMAND ${CMAKE_COMMAND} -E env LD_DEBUG=files ${TETSKIN} ${args}
  RESULT_VARIABLE status OUTPUT_QUIET ERROR_VARIABLE log)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "tetskin ${ARGS} failed (${status})")
endif()
string(REGEX MATCHALL "file=[^ ;\n]+" loads "${log}")
list(REMOVE_DUPLICATES loads)
list(LENGTH loads count)
if(count LESS 5)
  message(FATAL_ERROR "the loader reported ${count} libraries: LD_DEBUG gave no account")
endif()
foreach(load IN LISTS loads)
  if(load MATCHES "${FORBIDDEN}")
    message(FATAL_ERROR "tetskin ${ARGS} loaded ${load} (matches ${FORBIDDEN})")
  endif()
endforeach()
string(REPLACE "|" ";" required "${REQUIRED}")
foreach(pattern IN LISTS required)
  string(REGEX MATCH "${pattern}" found "${loads}")
  if(NOT found)
    message(FATAL_ERROR "tetskin ${ARGS} loaded nothing matching ${pattern}")
  endif()
endforeach()
message(STATUS "tetskin ${ARGS}: ${count} libraries loaded")
