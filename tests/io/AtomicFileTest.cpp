// SPDX-License-Identifier: AGPL-3.0-or-later
#include <gtest/gtest.h>

#include <fstream>

#include "ExpectError.h"
#include "TestFiles.h"
#include "tetskin/core/Error.h"
#include "tetskin/io/AtomicFile.h"
#include "tetskin/io/ObjFormat.h"

namespace tetskin {
namespace {

TEST(AtomicFile, CommitReplacesTheTarget) {
  test::ScratchDir dir;
  dir.write("out.txt", "old");
  writeTextAtomically(dir / "out.txt", [](std::ostream& out) { out << "new"; });
  EXPECT_EQ(test::readText(dir / "out.txt"), "new");
  EXPECT_EQ(dir.listing(), "out.txt\n");
}

TEST(AtomicFile, FailureInTheMiddleKeepsTheOldFileAndLeavesNoTemporary) {
  test::ScratchDir dir;
  dir.write("out.txt", "old");
  EXPECT_THROW(writeTextAtomically(dir / "out.txt",
                                   [](std::ostream& out) {
                                     out << "half of it";
                                     throw Error("disk on fire");
                                   }),
               Error);
  EXPECT_EQ(test::readText(dir / "out.txt"), "old");
  EXPECT_EQ(dir.listing(), "out.txt\n");
}

TEST(AtomicFile, FailedWriteLeavesNoNewFile) {
  test::ScratchDir dir;
  EXPECT_THROW(writeFileAtomically(dir / "x.vtp",
                                   [](const std::filesystem::path& tmp) {
                                     std::ofstream(tmp) << "partial";
                                     throw Error("writer failed");
                                   }),
               Error);
  EXPECT_EQ(dir.listing(), "");
}

// Both writers make the folders the target lacks (before, a missing folder
// was an error for every writer but build's and simulate's, which made it),
// and check the target's location first: the streams' and VTK's own
// messages would name the temporary file, or (VTK's PNG writer) a full disk.
TEST(AtomicFile, MissingFoldersAreMadeAndAFileForOneIsAClearError) {
  test::ScratchDir dir;
  dir.write("file.txt", "not a folder");
  const std::filesystem::path missing = dir / "missing" / "deeper" / "out.txt";
  writeTextAtomically(missing, [](std::ostream& out) { out << "text"; });
  EXPECT_TRUE(std::filesystem::is_regular_file(missing));
  const std::filesystem::path vtk = dir / "made" / "out.vtp";
  writeFileAtomically(vtk, [](const std::filesystem::path& tmp) { std::ofstream(tmp) << "x"; });
  EXPECT_TRUE(std::filesystem::is_regular_file(vtk));
  const std::filesystem::path underFile = dir / "file.txt" / "out.vtp";
  EXPECT_EQ(test::errorText([&] {
              writeFileAtomically(underFile, [](const std::filesystem::path&) {
                ADD_FAILURE() << "the writer ran";
              });
            }),
            underFile.string() + ": cannot be written: " + (dir / "file.txt").string() +
                " is not a folder");
  EXPECT_EQ(dir.listing(), "file.txt\nmade\nmissing\n");
}

TEST(AtomicFile, AFailedWriteRemovesTheFoldersItMade) {
  test::ScratchDir dir;
  std::filesystem::create_directory(dir / "kept");
  EXPECT_THROW(writeTextAtomically(dir / "kept" / "new" / "deeper" / "out.txt",
                                   [](std::ostream&) { throw Error("the writer failed"); }),
               Error);
  EXPECT_THROW(writeFileAtomically(dir / "other" / "out.vtp",
                                   [](const std::filesystem::path&) {}),  // writes no file
               Error);
  EXPECT_EQ(dir.listing(), "kept\n");  // (made before: it stays)
  EXPECT_TRUE(std::filesystem::is_empty(dir / "kept"));
}

TEST(AtomicFile, WriterRejectingInvalidMeshWritesNothing) {
  test::ScratchDir dir;
  SurfaceMesh m;
  m.positions = Points3::Zero(3, 3);
  m.triangles.resize(1, 3);
  m.triangles << 0, 1, 7;
  EXPECT_THROW(writeObj(dir / "m.obj", m), Error);
  EXPECT_EQ(dir.listing(), "");
}

// A location is writable when the nearest existing folder on its path is a
// writable folder (the rest would be made); checking it makes nothing.
TEST(AtomicFile, WritableLocationIsCheckedWithoutMakingFolders) {
  test::ScratchDir dir;
  dir.write("file.txt", "not a folder");
  EXPECT_NO_THROW(requireWritableLocation(dir / "out.json"));
  EXPECT_NO_THROW(requireWritableLocation(dir / "new" / "deeper" / "out.json"));
  try {
    requireWritableLocation(dir / "file.txt" / "sub" / "out.json");
    ADD_FAILURE() << "no error under a file";
  } catch (const Error& e) {
    EXPECT_EQ(e.message(),
              "cannot be written: " + (dir / "file.txt").string() + " is not a folder");
  }
  EXPECT_EQ(dir.listing(), "file.txt\n");
}

}  // namespace
}  // namespace tetskin
