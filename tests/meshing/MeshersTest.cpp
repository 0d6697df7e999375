// SPDX-License-Identifier: AGPL-3.0-or-later
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "Shapes.h"
#include "tetskin/core/Error.h"
#include "tetskin/meshing/IsolatedJobs.h"
#include "tetskin/meshing/Meshers.h"

namespace tetskin {
namespace {

TEST(Meshers, TetGenFillsTheBoxWithPositiveTetrahedra) {
  const SurfaceMesh box = test::box({0, 0, 0}, {2, 1, 1});
  const TetMesh coarse = tetrahedralizeWithTetGen(box, 2.0);
  const TetMesh fine = tetrahedralizeWithTetGen(box, 1.2);
  for (const TetMesh* m : {&coarse, &fine}) {
    EXPECT_NO_THROW(validateTetMesh(*m, "tetgen", /*requirePositiveVolume=*/true));
    EXPECT_TRUE(unreferencedNodes(*m).empty());
    EXPECT_NEAR(meshVolume(*m), 2.0, 1e-9);
  }
  EXPECT_GT(fine.elementCount(), coarse.elementCount());
}

// A hollow box (the inner wall wound into the cavity): TetGen and Netgen
// fill the wall and leave the cavity empty.
TEST(Meshers, ACavityStaysEmpty) {
  SurfaceMesh inner = test::box({-1, -1, -1}, {1, 1, 1});
  inner.triangles.col(1).swap(inner.triangles.col(2));
  const SurfaceMesh hollow = test::merge(test::box({-2, -2, -2}, {2, 2, 2}), inner);
  const TetMesh tetgen = tetrahedralizeWithTetGen(hollow, 1.6);
  EXPECT_NO_THROW(validateTetMesh(tetgen, "tetgen", /*requirePositiveVolume=*/true));
  EXPECT_NEAR(meshVolume(tetgen), 64.0 - 8.0, 1e-9);
  if (!netgenAvailable()) GTEST_SKIP() << "built without Netgen";
  const TetMesh netgen = tetrahedralizeWithNetgen(hollow, NetgenFineness::Moderate);
  EXPECT_NO_THROW(validateTetMesh(netgen, "netgen", /*requirePositiveVolume=*/true));
  EXPECT_NEAR(meshVolume(netgen), 64.0 - 8.0, 1e-6);
}

TEST(Meshers, TetGenRejectsSelfIntersectingInput) {
  const SurfaceMesh twoBoxes =
      test::merge(test::box({0, 0, 0}, {1, 1, 1}), test::box({0.5, 0.3, 0.2}, {1.5, 1.3, 1.2}));
  // TetGen may throw or, on some inputs, crash: always run it isolated.
  const auto results =
      runIsolated({[&] { return tetrahedralizeWithTetGen(twoBoxes, 2.0); }}, 1, 60);
  EXPECT_FALSE(results[0].ok);
  EXPECT_FALSE(results[0].error.empty());
}

TEST(Meshers, TetGenQualityMustExceedOne) {
  EXPECT_THROW(tetrahedralizeWithTetGen(test::box({0, 0, 0}, {1, 1, 1}), 1.0), Error);
}

// -a bounds every element's volume; the box needs 6 elements without it.
TEST(Meshers, TetGenVolumeBoundBoundsEveryElement) {
  const SurfaceMesh box = test::box({0, 0, 0}, {2, 1, 1});
  const TetMesh unbounded = tetrahedralizeWithTetGen(box, 2.0);
  const double bound = 0.01;
  const TetMesh bounded = tetrahedralizeWithTetGen(box, 2.0, bound);
  EXPECT_NO_THROW(validateTetMesh(bounded, "tetgen", /*requirePositiveVolume=*/true));
  EXPECT_NEAR(meshVolume(bounded), 2.0, 1e-9);
  double largest = 0;
  for (Index e = 0; e < bounded.elementCount(); ++e)
    largest = std::max(largest, elementVolume(bounded, e));
  EXPECT_LE(largest, bound * (1 + 1e-9));
  EXPECT_GE(bounded.elementCount(), 200);  // 2 / 0.01 at the very least
  EXPECT_GT(bounded.elementCount(), unbounded.elementCount());
  EXPECT_THROW(tetrahedralizeWithTetGen(box, 2.0, -1.0), Error);
  EXPECT_THROW(tetrahedralizeWithTetGen(box, 2.0, std::nan("")), Error);
}

// The presets run from coarse to fine; an edge bound (maxh) replaces the
// preset's both ways: a smaller edge gives more elements than the preset
// does, a larger one fewer.
TEST(Meshers, NetgenPresetsAndEdgeBoundsGiveValidMeshes) {
  if (!netgenAvailable()) GTEST_SKIP() << "built without Netgen";
  const SurfaceMesh box = test::box({0, 0, 0}, {2, 1, 1});
  // Netgen prints to stdout; run it the way the tool does.
  const auto results =
      runIsolated({[&] { return tetrahedralizeWithNetgen(box, NetgenFineness::VeryCoarse); },
                   [&] { return tetrahedralizeWithNetgen(box, NetgenFineness::VeryFine); },
                   [&] { return tetrahedralizeWithNetgen(box, NetgenFineness::Moderate); },
                   [&] { return tetrahedralizeWithNetgen(box, NetgenFineness::Moderate, 0.1); },
                   [&] { return tetrahedralizeWithNetgen(box, NetgenFineness::Moderate, 1.0); }},
                  2, 120);
  for (const IsolatedResult& r : results) {
    ASSERT_TRUE(r.ok) << r.error;
    EXPECT_NO_THROW(validateTetMesh(r.mesh, "netgen", true));
    EXPECT_NEAR(meshVolume(r.mesh), 2.0, 1e-6);
  }
  EXPECT_GE(results[1].mesh.elementCount(), results[0].mesh.elementCount());
  EXPECT_GT(results[3].mesh.elementCount(), results[2].mesh.elementCount());
  EXPECT_LT(results[4].mesh.elementCount(), results[2].mesh.elementCount());
  EXPECT_THROW(tetrahedralizeWithNetgen(box, NetgenFineness::Moderate, -0.1), Error);
}

}  // namespace
}  // namespace tetskin
