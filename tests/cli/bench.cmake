# CLI tests of tetskin bench (included by tests/cli/CMakeLists.txt).

tetskin_cli_test(bench_bad_size FAIL STATUS 1
  STDERR "^error: --size: '0x0' is not WIDTHxHEIGHT with both in \\[16, 8192\\] \\(see tetskin bench --help\\)\n$"
  ARGS bench --size 0x0 --frames 1)
