# cmake -DFIRST=a.csv -DSTEP=K -DCONTINUED=b.csv -P CheckContinuedStepLog.cmake:
# a run continued with --initial from the frame after step K of another run
# starts (its step 0) with the energies that run logged for step K:
# kinetic, elastic, gravitational (from the rest shape, whatever the
# run's start), the surface loads' potential and total, fields 11 to 15,
# the same to the digit.
cmake_policy(SET CMP0007 NEW)  # (empty list items count: the start row's empty fields)
function(energies_of file index out)
  file(STRINGS "${file}" lines)
  math(EXPR line "${index} + 1")
  list(GET lines ${line} row)
  string(REPLACE "," ";" fields "${row}")
  list(LENGTH fields count)
  if(NOT count EQUAL 18)
    message(FATAL_ERROR "${file}: step ${index}: not 18 fields in '${row}'")
  endif()
  list(SUBLIST fields 10 5 energies)
  string(REPLACE ";" "," energies "${energies}")
  set(${out} "${energies}" PARENT_SCOPE)
endfunction()
energies_of("${FIRST}" ${STEP} first)
energies_of("${CONTINUED}" 0 continued)
if(NOT first STREQUAL continued)
  message(FATAL_ERROR "${CONTINUED} starts with energies ${continued}; "
                      "${FIRST} logged ${first} for step ${STEP}")
endif()
# The drop starts lifted above its rest shape: gravitational energy to lose.
energies_of("${FIRST}" 0 start)
if(NOT start MATCHES "^0,[^,]+,[1-9][0-9.]*(e\\+[0-9]+)?,0,[1-9]")
  message(FATAL_ERROR "${FIRST}: a drop's start has energies ${start}")
endif()
message(STATUS "${CONTINUED} starts with ${FIRST}'s step ${STEP}: ${first}")
