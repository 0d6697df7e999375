// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// What every reader must do with any input (issue #53): accept it or throw
// tetskin::Error, never crash; and what it accepts must hold up: indices in
// range, coordinates finite, and a round trip through our writer reads back
// equal. One check per reader, on raw bytes: the libFuzzer targets
// (fuzz_*.cpp, built with TETSKIN_FUZZ) call them on every input they try,
// and the regression suite (FuzzCorpusTest.cpp, in every build) on every
// file of the committed corpus, crashes found once included. A violated
// invariant aborts (as a crash does), naming what broke on stderr.

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace tetskin::fuzz {

using Check = void (*)(const std::uint8_t* data, std::size_t size);

struct Target {
  const char* name;  // fuzz_<name>, corpus/<name>/, <name>.dict
  Check check;
};

// Every reader's check, by name.
const std::vector<Target>& targets();
Check checkOf(const std::string& name);

}  // namespace tetskin::fuzz
