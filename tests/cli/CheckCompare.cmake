# cmake -DTETSKIN=exe -DDATASET=bunny.json -DSURFACE=bunny.obj -DOUT=dir -P CheckCompare.cmake:
# compares levels 0 and 1 of the bundled bunny against level 2 over the
# wobble, and checks what a researcher reads off the report: the finer
# level is closer to the reference (median and 99th percentile of the
# distance and of the normal angle), each level's cost per step is given
# (not compared: a test asserts no timings), and the table has a row per
# frame and level.
execute_process(COMMAND ${TETSKIN} compare ${DATASET} ${SURFACE} --levels 0,1 --steps 60 --every 10
                        -o ${OUT}/wobble.pvd -q
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "compare failed (${rc})")
endif()
set(number "[0-9.e+-]+")
foreach(level 0 1)
  if(NOT out MATCHES "\n  ${level} +[0-9]+ +(${number}) +(${number})% / (${number})% / (${number})% +(${number}) / (${number}) / (${number})\n")
    message(FATAL_ERROR "no row for level ${level}")
  endif()
  set(cost${level} ${CMAKE_MATCH_1})
  set(distance_p99_${level} ${CMAKE_MATCH_3})
  set(distance_median_${level} ${CMAKE_MATCH_4})
  set(angle_p99_${level} ${CMAKE_MATCH_6})
  set(angle_median_${level} ${CMAKE_MATCH_7})
endforeach()
if(NOT out MATCHES "\n  2 ref +12713 +(${number}) +.reference.")
  message(FATAL_ERROR "no row for the reference, level 2")
endif()
set(cost2 ${CMAKE_MATCH_1})
foreach(measure distance_p99 distance_median angle_p99 angle_median)
  if(NOT ${measure}_1 LESS ${measure}_0)
    message(FATAL_ERROR "${measure}: level 1 (${${measure}_1}) is not closer than level 0 (${${measure}_0})")
  endif()
endforeach()
foreach(level 0 1 2)
  if(NOT cost${level} GREATER 0)
    message(FATAL_ERROR "level ${level}: ms per step ${cost${level}}")
  endif()
endforeach()
# 7 frames (the start and every 10th step) x 3 levels, and the header.
file(STRINGS ${OUT}/wobble.csv rows)
list(LENGTH rows count)
if(NOT count EQUAL 22)
  message(FATAL_ERROR "wobble.csv: ${count} lines, expected 22")
endif()
list(GET rows 21 last)
if(NOT last MATCHES "^6,1,2,2,${number},0,0,0,0,0,0,0,0,0$")
  message(FATAL_ERROR "wobble.csv: the reference's last row is '${last}'")
endif()
message(STATUS "finer is closer: distance p99 ${distance_p99_0}% -> ${distance_p99_1}%, median ${distance_median_0}% -> ${distance_median_1}%")
