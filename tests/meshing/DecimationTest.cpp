// SPDX-License-Identifier: AGPL-3.0-or-later
#include <gtest/gtest.h>

#include <string>

#include "tetskin/io/ObjFormat.h"
#include "tetskin/meshing/Decimation.h"
#include "tetskin/meshing/SurfaceRepair.h"

namespace tetskin {
namespace {

// A model far from the origin (a site's coordinates) decimates as it does
// at the origin: closed, with the same volume. Decimated in place, the
// quadrics' plane offsets swamped the bunny's size and tore it open.
TEST(Decimation, AModelFarFromTheOriginDecimatesAsAtTheOrigin) {
  const SurfaceMesh bunny = readObj(std::string(TETSKIN_SOURCE_DIR) + "/data/bunny_8k.obj");
  SurfaceMesh far = bunny;
  const Eigen::RowVector3d offset(1e6, -2e6, 5e5);
  far.positions.rowwise() += offset;
  for (const Index target : {3999, 1998, 998}) {
    const SurfaceMesh near = decimateSurface(bunny, target);
    const SurfaceMesh moved = decimateSurface(far, target);
    EXPECT_TRUE(boundaryLoops(near).empty()) << target;
    EXPECT_TRUE(boundaryLoops(moved).empty()) << target;
    EXPECT_NEAR(static_cast<double>(moved.triangleCount()),
                static_cast<double>(near.triangleCount()), 0.02 * static_cast<double>(target));
    EXPECT_NEAR(enclosedVolume(moved), enclosedVolume(near), 0.01 * enclosedVolume(near)) << target;
    EXPECT_LT(
        (boundingBox(moved).center() - boundingBox(near).center() - offset.transpose()).norm(),
        0.01 * boundingBox(near).diagonal());
  }
}

}  // namespace
}  // namespace tetskin
