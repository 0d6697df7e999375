// SPDX-License-Identifier: AGPL-3.0-or-later
// One libFuzzer target: the reader TETSKIN_FUZZ_TARGET names, checked as
// FuzzChecks.cpp checks it.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

#include "FuzzChecks.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const tetskin::fuzz::Check check = [] {
    const tetskin::fuzz::Check found = tetskin::fuzz::checkOf(TETSKIN_FUZZ_TARGET);
    if (!found) {
      std::fprintf(stderr, "no fuzz check named %s\n", TETSKIN_FUZZ_TARGET);
      std::abort();
    }
    return found;
  }();
  check(data, size);
  return 0;
}
