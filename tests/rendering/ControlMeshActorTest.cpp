// SPDX-License-Identifier: AGPL-3.0-or-later
#include <gtest/gtest.h>
#include <vtkActor.h>
#include <vtkAlgorithm.h>
#include <vtkDataSet.h>
#include <vtkMapper.h>
#include <vtkMatrix4x4.h>
#include <vtkProperty.h>

#include <cmath>

#include "Shapes.h"
#include "tetskin/core/Error.h"
#include "tetskin/rendering/ControlMeshActor.h"
#include "tetskin/rendering/FloorActor.h"
#include "tetskin/rendering/ObstacleActor.h"

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

// The floor lies in its plane under the body, three times the body's
// widest side across, whatever the up axis.
TEST(FloorActor, LiesInItsPlaneUnderTheBody) {
  BoundingBox body;
  body.extend(Eigen::Vector3d(1, 2, 3));
  body.extend(Eigen::Vector3d(3, 6, 4));  // 2 x 4 x 1
  const FloorActor yUp(FloorPlane{UpAxis::Y, 1.5}, body);
  double b[6];
  yUp.actor()->GetMapper()->GetInputAlgorithm()->Update();
  yUp.actor()->GetMapper()->GetInput()->GetBounds(b);
  // Centred on (2, 3.5) in x and z, 1.5 * 2 either side.
  EXPECT_DOUBLE_EQ(b[0], -1);
  EXPECT_DOUBLE_EQ(b[1], 5);
  EXPECT_DOUBLE_EQ(b[2], 1.5);
  EXPECT_DOUBLE_EQ(b[3], 1.5);
  EXPECT_DOUBLE_EQ(b[4], 0.5);
  EXPECT_DOUBLE_EQ(b[5], 6.5);
  EXPECT_EQ(yUp.bounds().min, Eigen::Vector3d(-1, 1.5, 0.5));
  EXPECT_EQ(yUp.bounds().max, Eigen::Vector3d(5, 1.5, 6.5));
  const FloorActor zUp(FloorPlane{UpAxis::Z, -2}, body);
  // Widest horizontal side 4 (y): centred on (2, 4), 6 either side.
  EXPECT_EQ(zUp.bounds().min, Eigen::Vector3d(-4, -2, -2));
  EXPECT_EQ(zUp.bounds().max, Eigen::Vector3d(8, 10, -2));
}

TEST(FloorActor, RefusesAnEmptyBodyAndANonFiniteHeight) {
  EXPECT_THROW(FloorActor(FloorPlane{}, BoundingBox{}), Error);
  BoundingBox body;
  body.extend(Eigen::Vector3d(0, 0, 0));
  body.extend(Eigen::Vector3d(1, 1, 1));
  EXPECT_THROW(FloorActor(FloorPlane{UpAxis::Y, std::nan("")}, body), Error);
}

// The obstacle's own surface is drawn as it is, posed by the actor's
// matrix: a box of side 2 turned a quarter about z, doubled and moved
// lies where the map puts its corners, translucent.
TEST(ObstacleActor, IsPosedByItsMatrixAndTranslucent) {
  ObstacleActor obstacle(test::box({0, 0, 0}, {2, 1, 1}));
  Eigen::Affine3d pose = Eigen::Affine3d::Identity();
  pose.translate(Eigen::Vector3d(10, 0, 0))
      .rotate(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()))
      .scale(2);
  obstacle.setPose(pose);
  vtkMatrix4x4* m = obstacle.actor()->GetUserMatrix();
  ASSERT_NE(m, nullptr);
  EXPECT_DOUBLE_EQ(m->GetElement(0, 3), 10);
  EXPECT_NEAR(m->GetElement(1, 0), 2, 1e-12);  // x goes to 2 y
  double b[6];
  obstacle.actor()->GetBounds(b);  // the actor's: with its matrix
  EXPECT_NEAR(b[0], 8, 1e-9);      // y in [0, 1] -> x in [8, 10]
  EXPECT_NEAR(b[1], 10, 1e-9);
  EXPECT_NEAR(b[2], 0, 1e-9);  // x in [0, 2] -> y in [0, 4]
  EXPECT_NEAR(b[3], 4, 1e-9);
  EXPECT_NEAR(obstacle.bounds().min.x(), 8, 1e-9);
  EXPECT_NEAR(obstacle.bounds().max.y(), 4, 1e-9);
  EXPECT_NEAR(obstacle.bounds().max.z(), 2, 1e-9);
  EXPECT_DOUBLE_EQ(obstacle.actor()->GetProperty()->GetOpacity(), ObstacleActor::kOpacity);
  EXPECT_LT(ObstacleActor::kOpacity, 1);
  EXPECT_THROW(ObstacleActor(SurfaceMesh{}), Error);
}

}  // namespace
}  // namespace tetskin
