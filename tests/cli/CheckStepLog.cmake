# cmake -DLOG=steps.csv -DSTEPS=N -P CheckStepLog.cmake: the table simulate
# --log wrote has its header, the start and N steps, 17 fields each, the
# steps numbered in order with a solver and iterations; at the start (at
# rest, before any step) the held base carries the weight of its nodes:
# reaction_y positive.
file(STRINGS "${LOG}" lines)
list(LENGTH lines count)
math(EXPR expected "${STEPS} + 2")
if(NOT count EQUAL expected)
  message(FATAL_ERROR "${LOG}: ${count} lines, expected ${expected}")
endif()
list(GET lines 0 header)
if(NOT header STREQUAL "step,time_s,solver,iterations,relative_residual,contacts,assembly_ms,setup_ms,solve_ms,step_ms,kinetic_J,elastic_J,gravitational_J,load_J,total_J,reaction_x_N,reaction_y_N,reaction_z_N")
  message(FATAL_ERROR "${LOG}: header '${header}'")
endif()
list(GET lines 1 start)
if(NOT start MATCHES "^0,0,,,,,,,,,0,[^,]+,0,0,[^,]+,[^,]+,[1-9][^,]*,[^,]+$")
  message(FATAL_ERROR "${LOG}: start row '${start}'")
endif()
foreach(step RANGE 1 ${STEPS})
  math(EXPR index "${step} + 1")
  list(GET lines ${index} row)
  string(REPLACE "," ";" fields "${row}")
  list(LENGTH fields n)
  if(NOT n EQUAL 18 OR NOT row MATCHES "^${step},[0-9.e+-]+,(cg|multigrid),[1-9][0-9]*,")
    message(FATAL_ERROR "${LOG}: row ${step} '${row}'")
  endif()
endforeach()
message(STATUS "${LOG}: the start and ${STEPS} steps")
