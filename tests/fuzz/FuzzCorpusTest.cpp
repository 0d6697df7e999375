// SPDX-License-Identifier: AGPL-3.0-or-later
// Every file of the fuzzers' committed corpus (seeds, and the inputs that
// once crashed a reader: regressions/) through its reader's check, in every
// build: what a fuzzer found stays fixed, with or without clang.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "FuzzChecks.h"

namespace tetskin::fuzz {
namespace {

const std::filesystem::path kFuzzDir = std::filesystem::path(TETSKIN_SOURCE_DIR) / "tests/fuzz";

std::vector<std::filesystem::path> filesOf(const std::string& target) {
  std::vector<std::filesystem::path> files;
  for (const char* folder : {"corpus", "regressions"}) {
    const std::filesystem::path dir = kFuzzDir / folder / target;
    if (!std::filesystem::is_directory(dir)) continue;
    for (const auto& entry : std::filesystem::directory_iterator(dir))
      if (entry.is_regular_file()) files.push_back(entry.path());
  }
  return files;
}

class FuzzCorpus : public ::testing::TestWithParam<Target> {};

TEST_P(FuzzCorpus, EveryFileIsReadOrRefusedAndHoldsUp) {
  const std::vector<std::filesystem::path> files = filesOf(GetParam().name);
  ASSERT_GE(files.size(), 2u) << "the corpus of " << GetParam().name << " has no seeds";
  for (const std::filesystem::path& file : files) {
    std::ifstream in(file, std::ios::binary);
    const std::vector<char> bytes((std::istreambuf_iterator<char>(in)),
                                  std::istreambuf_iterator<char>());
    SCOPED_TRACE(file.string());
    // (A broken invariant aborts: the test fails naming it on stderr.)
    GetParam().check(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
  }
}

INSTANTIATE_TEST_SUITE_P(Readers, FuzzCorpus, ::testing::ValuesIn(targets()),
                         [](const ::testing::TestParamInfo<Target>& param) {
                           return std::string(param.param.name);
                         });

}  // namespace
}  // namespace tetskin::fuzz
