# tetskin_add_module(NAME SOURCES ... [PUBLIC_DEPS ...] [PRIVATE_DEPS ...])
# One static library per concern under modules/NAME, public headers under
# modules/NAME/include/tetskin/NAME, exported as TetSkin::NAME.
function(tetskin_add_module name)
  cmake_parse_arguments(ARG "" "" "SOURCES;PUBLIC_DEPS;PRIVATE_DEPS" ${ARGN})
  add_library(tetskin_${name} STATIC ${ARG_SOURCES})
  add_library(TetSkin::${name} ALIAS tetskin_${name})
  target_include_directories(tetskin_${name} PUBLIC ${CMAKE_CURRENT_SOURCE_DIR}/include)
  target_link_libraries(tetskin_${name} PUBLIC ${ARG_PUBLIC_DEPS} PRIVATE ${ARG_PRIVATE_DEPS}
    TetSkin::flags)
  set_target_properties(tetskin_${name} PROPERTIES POSITION_INDEPENDENT_CODE ON)
endfunction()

# tetskin_add_test(NAME SOURCES ... DEPS ... LABEL label [RESOURCE_LOCK name]
#                  [TIMEOUT seconds]): one GoogleTest executable, its tests
# registered one by one with CTest under one label: gtest_discover_tests
# hands a list-valued property on as separate words, which then pair up
# wrongly (LABELS "gui;rendering" RESOURCE_LOCK x lost the lock).
function(tetskin_add_test name)
  cmake_parse_arguments(ARG "" "LABEL;RESOURCE_LOCK;TIMEOUT" "SOURCES;DEPS" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE ${ARG_DEPS} GTest::gtest_main TetSkin::flags)
  target_compile_definitions(${name} PRIVATE
    TETSKIN_SOURCE_DIR="${PROJECT_SOURCE_DIR}"
    TETSKIN_TEST_DATA_DIR="${PROJECT_SOURCE_DIR}/tests/data")
  set(properties LABELS ${ARG_LABEL})
  if(ARG_RESOURCE_LOCK)
    list(APPEND properties RESOURCE_LOCK ${ARG_RESOURCE_LOCK})
  endif()
  if(ARG_TIMEOUT)
    list(APPEND properties TIMEOUT ${ARG_TIMEOUT})
  endif()
  gtest_discover_tests(${name} DISCOVERY_TIMEOUT 60 PROPERTIES ${properties})
endfunction()
