# Compiler warnings and sanitizers shared by every TetSkin target, through one
# interface library so a target opts in by linking TetSkin::flags.
add_library(tetskin_flags INTERFACE)
add_library(TetSkin::flags ALIAS tetskin_flags)
target_compile_options(tetskin_flags INTERFACE -Wall -Wextra -Wpedantic -Wshadow -Wconversion
  -Wno-sign-conversion)
if(TETSKIN_WERROR)
  target_compile_options(tetskin_flags INTERFACE -Werror)
endif()
if(TETSKIN_SANITIZE)
  target_compile_options(tetskin_flags INTERFACE -fsanitize=address,undefined
    -fno-omit-frame-pointer -fno-sanitize-recover=undefined)
  target_link_options(tetskin_flags INTERFACE -fsanitize=address,undefined)
endif()
# The fuzzers' build (tests/fuzz): every module instrumented for libFuzzer's
# coverage and checked by ASan and UBSan; the targets link libFuzzer itself.
if(TETSKIN_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "TETSKIN_FUZZ needs clang's libFuzzer: configure with CC=clang CXX=clang++")
  endif()
  target_compile_options(tetskin_flags INTERFACE -fsanitize=fuzzer-no-link,address,undefined
    -fno-omit-frame-pointer -fno-sanitize-recover=undefined)
  target_link_options(tetskin_flags INTERFACE -fsanitize=address,undefined)
endif()
# The race check (issue #53): every module under ThreadSanitizer. Its
# parallel loops then run on std::threads instead of TBB, which TSan cannot
# see into (tetskin/core/Parallel.h).
if(TETSKIN_TSAN)
  if(TETSKIN_SANITIZE OR TETSKIN_FUZZ)
    message(FATAL_ERROR "TETSKIN_TSAN cannot be combined with ASan (TETSKIN_SANITIZE, TETSKIN_FUZZ)")
  endif()
  target_compile_options(tetskin_flags INTERFACE -fsanitize=thread -fno-omit-frame-pointer)
  target_link_options(tetskin_flags INTERFACE -fsanitize=thread)
endif()
