// SPDX-License-Identifier: AGPL-3.0-or-later
#include <gtest/gtest.h>
#include <signal.h>
#include <unistd.h>

#include <chrono>

#include "Shapes.h"
#include "tetskin/core/Error.h"
#include "tetskin/meshing/IsolatedJobs.h"

namespace tetskin {
namespace {

using test::unitTetrahedron;

TEST(IsolatedJobs, FailuresOfOneJobDoNotStopTheOthers) {
  const std::vector<MeshJob> jobs = {
      [] { return unitTetrahedron(); },
      []() -> TetMesh { throw Error("refused this input"); },
      []() -> TetMesh {
        ::raise(SIGSEGV);
        return {};
      },
      []() -> TetMesh { throw 3; },  // TetGen's way
      []() -> TetMesh {
        ::sleep(30);
        return {};
      },
      []() -> TetMesh { std::abort(); },
      [] {
        TetMesh big;
        big.nodes = Points3::Random(100000, 3);  // larger than a pipe buffer
        big.elements = Tetrahedra::Zero(50000, 4);
        return big;
      },
  };
  std::vector<std::size_t> order;
  const auto results =
      runIsolated(jobs, 3, 2.0, [&](std::size_t i, const IsolatedResult&) { order.push_back(i); });
  ASSERT_EQ(results.size(), jobs.size());
  EXPECT_EQ(order.size(), jobs.size());
  EXPECT_TRUE(results[0].ok);
  EXPECT_EQ(results[0].mesh.nodes, unitTetrahedron().nodes);
  EXPECT_EQ(results[0].mesh.elements, unitTetrahedron().elements);
  EXPECT_EQ(results[1].error, "refused this input");
  EXPECT_NE(results[2].error.find("crashed (signal 11"), std::string::npos) << results[2].error;
  EXPECT_NE(results[3].error.find("error code 3"), std::string::npos) << results[3].error;
  EXPECT_NE(results[4].error.find("did not finish within 2 s"), std::string::npos)
      << results[4].error;
  EXPECT_NE(results[5].error.find("crashed"), std::string::npos) << results[5].error;
  ASSERT_TRUE(results[6].ok) << results[6].error;
  EXPECT_EQ(results[6].mesh.nodeCount(), 100000);
  EXPECT_EQ(results[6].mesh.elementCount(), 50000);
}

// A mesher that would take more memory than its share fails alone, with
// a word of what to change, before the machine runs out: asking for 90% of
// the machine's memory at once (untouched, so without the limit the kernel
// would grant it) is refused in the child.
TEST(IsolatedJobs, AJobPastItsShareOfMemoryFails) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "no address-space limit under AddressSanitizer";
#endif
  const double memory = static_cast<double>(::sysconf(_SC_PHYS_PAGES)) *
                        static_cast<double>(::sysconf(_SC_PAGE_SIZE));
  const std::vector<MeshJob> jobs = {[memory]() -> TetMesh {
    // (Through a volatile pointer: the compiler may drop a new/delete pair.)
    char* volatile block = new char[static_cast<std::size_t>(0.9 * memory)];
    block[0] = 1;
    delete[] block;
    return unitTetrahedron();
  }};
  const auto results = runIsolated(jobs, 2, 60.0);
  ASSERT_FALSE(results[0].ok);
  EXPECT_NE(results[0].error.find("the mesher ran out of memory ("), std::string::npos)
      << results[0].error;
  EXPECT_NE(results[0].error.find("fewer --jobs give each process more"), std::string::npos);
}

}  // namespace
}  // namespace tetskin

namespace tetskin {
namespace {

TEST(IsolatedJobs, CancellingKillsTheRunningJobsAtOnce) {
  const std::vector<MeshJob> jobs(4, []() -> TetMesh {
    ::sleep(30);
    return {};
  });
  const auto start = std::chrono::steady_clock::now();
  int polls = 0;
  EXPECT_THROW(runIsolated(jobs, 2, 60, {}, [&] { return ++polls > 3; }), Cancelled);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_LT(seconds, 10.0);  // not the jobs' 30 s
}

}  // namespace
}  // namespace tetskin
