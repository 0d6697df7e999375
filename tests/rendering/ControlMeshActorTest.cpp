// SPDX-License-Identifier: AGPL-3.0-or-later
#include <gtest/gtest.h>
#include <vtkActor.h>
#include <vtkDataSet.h>
#include <vtkMapper.h>

#include "Shapes.h"
#include "tetskin/core/Error.h"
#include "tetskin/rendering/ControlMeshActor.h"

namespace tetskin {
namespace {

TEST(ControlMeshActor, DrawsThePositionsItIsGiven) {
  const TetMesh rest = test::unitTetrahedron();
  ControlMeshActor control(rest, ControlMeshStyle::Surface);
  // A block of a larger matrix, as the GUI passes its level's rows.
  Points3 all = Points3::Zero(rest.nodeCount() + 2, 3);
  all.middleRows(1, rest.nodeCount()) = rest.nodes.rowwise() + Eigen::RowVector3d(5, 0, -2);
  control.update(all.middleRows(1, rest.nodeCount()));
  double bounds[6];
  control.actor()->GetMapper()->GetInput()->GetBounds(bounds);
  const Eigen::Vector3d lo = rest.nodes.colwise().minCoeff(), hi = rest.nodes.colwise().maxCoeff();
  EXPECT_DOUBLE_EQ(bounds[0], lo.x() + 5);
  EXPECT_DOUBLE_EQ(bounds[1], hi.x() + 5);
  EXPECT_DOUBLE_EQ(bounds[4], lo.z() - 2);
  EXPECT_DOUBLE_EQ(bounds[5], hi.z() - 2);
}

TEST(ControlMeshActor, RefusesPositionsOfAnotherNodeCount) {
  const TetMesh rest = test::unitTetrahedron();
  ControlMeshActor control(rest, ControlMeshStyle::Wireframe);
  const Points3 tooMany = Points3::Zero(rest.nodeCount() + 1, 3);
  try {
    control.update(tooMany);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "control mesh positions: 5 rows for 4 nodes");
  }
}

}  // namespace
}  // namespace tetskin
