// SPDX-License-Identifier: AGPL-3.0-or-later
// Real-world OBJ files written by other tools (Debian's assimp-testmodels):
// each one either reads into a valid surface or gives a tetskin::Error that
// names the file; nothing else (no crash, no other exception).
#include <gtest/gtest.h>

#include <filesystem>

#include "tetskin/core/Error.h"
#include "tetskin/io/ObjFormat.h"

namespace tetskin {
namespace {

constexpr const char* kCorpus = "/usr/share/assimp/models";

TEST(ObjCorpus, EveryFileReadsOrGivesAClearError) {
  if (!std::filesystem::is_directory(kCorpus))
    GTEST_SKIP() << "install Debian's assimp-testmodels for the OBJ corpus";
  int read = 0, rejected = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(kCorpus)) {
    if (entry.path().extension() != ".obj") continue;
    SCOPED_TRACE(entry.path().string());
    try {
      const SurfaceMesh m = readObj(entry.path());
      EXPECT_NO_THROW(validateSurface(m, entry.path().string()));
      EXPECT_GT(m.triangleCount(), 0);
      ++read;
    } catch (const Error& e) {
      EXPECT_EQ(std::string(e.what()).rfind(entry.path().string() + ":", 0), 0u) << e.what();
      ++rejected;
    }
  }
  std::printf("OBJ corpus: %d read, %d rejected with an error\n", read, rejected);
  EXPECT_GE(read, 15);     // the corpus is mostly valid
  EXPECT_GE(rejected, 3);  // .../invalid/ holds broken files
}

}  // namespace
}  // namespace tetskin
