// SPDX-License-Identifier: AGPL-3.0-or-later
// Several bodies as one (uniteBodies) and each body's part of the union
// back (bodyPart): the union numbers the bodies one after another, and a
// body's part is that body as it was given, field for field.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "ExpectError.h"
#include "Shapes.h"
#include "tetskin/core/BodyUnion.h"

namespace tetskin::test {
namespace {

// A box skin whose vertex v is bound to nodes v, v + 1 and v + 2 of `mesh`
// with weights 0.5, 0.3 and 0.2, at distance v / 100, to element v.
struct Body {
  TetMesh mesh;
  SurfaceMesh skin;
  SurfaceBinding binding;
};
Body body(int nx, const Eigen::Vector3d& corner) {
  Body b;
  b.mesh = tetGrid(nx, 1, 1, {0.1 * nx, 0.1, 0.1});
  b.mesh.nodes.rowwise() += corner.transpose();
  b.skin = box(corner, corner + Eigen::Vector3d(0.1 * nx, 0.1, 0.1));
  b.binding.resize(b.skin.vertexCount());
  for (Index v = 0; v < b.skin.vertexCount(); ++v) {
    for (int j = 0; j < 3; ++j) b.binding.controlIds(v, j) = static_cast<int>(v) + j;
    b.binding.weights.row(v) << 0.5, 0.3, 0.2, 0;
    b.binding.distance[v] = static_cast<double>(v) / 100;
    b.binding.faceId[v] = static_cast<int>(v);
    b.binding.minBarycentric[v] = 0.2;
  }
  return b;
}

TEST(BodyUnion, BodiesAreNumberedOneAfterAnotherAndComeBackAsTheyWere) {
  const std::vector<Body> bodies = {body(2, {0, 0, 0}), body(3, {1, 0, 0})};
  std::vector<BodyParts> parts;
  for (const Body& b : bodies) parts.push_back({&b.mesh, &b.skin, &b.binding});
  const BodyUnion u = uniteBodies(parts);
  ASSERT_EQ(u.bodyCount(), 2);
  const BodyRange& second = u.bodies[1];
  EXPECT_EQ(second.firstNode, bodies[0].mesh.nodeCount());
  EXPECT_EQ(second.firstElement, bodies[0].mesh.elementCount());
  EXPECT_EQ(second.firstVertex, 8);
  EXPECT_EQ(second.firstTriangle, 12);
  EXPECT_EQ(u.mesh.levels.size(), 1u);
  EXPECT_EQ(u.mesh.nodes.rows(), second.firstNode + second.nodeCount);
  EXPECT_EQ(u.vertexBody[7], 0);
  EXPECT_EQ(u.vertexBody[8], 1);
  // The second body's ids moved by the first's counts.
  EXPECT_EQ(u.binding.controlIds(8, 0), second.firstNode);
  EXPECT_EQ(u.mesh.elements(second.firstElement, 0),
            bodies[1].mesh.elements(0, 0) + second.firstNode);
  EXPECT_EQ(u.skin.triangles(12, 0), bodies[1].skin.triangles(0, 0) + 8);

  for (int k = 0; k < 2; ++k) {
    const BodyRange& range = u.bodies[static_cast<std::size_t>(k)];
    const Body& given = bodies[static_cast<std::size_t>(k)];
    const TetMesh mesh = bodyPart(extractLevel(u.mesh, 0), range);
    EXPECT_EQ(mesh.nodes, given.mesh.nodes);
    EXPECT_EQ(mesh.elements, given.mesh.elements);
    const SurfaceMesh skin = bodyPart(u.skin, range);
    EXPECT_EQ(skin.positions, given.skin.positions);
    EXPECT_EQ(skin.triangles, given.skin.triangles);
    const SurfaceBinding binding = bodyPart(u.binding, range);
    EXPECT_EQ(binding.controlIds, given.binding.controlIds);
    EXPECT_EQ(binding.weights, given.binding.weights);
    EXPECT_EQ(binding.distance, given.binding.distance);
    EXPECT_EQ(binding.faceId, given.binding.faceId);
  }

  // A frame's fields: per node and per element rows of the body.
  FrameFields fields;
  const Index nodes = u.mesh.nodes.rows(), elements = u.mesh.elements.rows();
  fields.positions = Points3::Random(nodes, 3);
  fields.velocities = Points3::Random(nodes, 3);
  fields.externalForces = Points3::Random(nodes, 3);
  fields.reactionForces = Points3::Random(nodes, 3);
  fields.vonMisesStress = Eigen::VectorXd::Random(elements);
  fields.equivalentStrain = Eigen::VectorXd::Random(elements);
  fields.stress = SymmetricTensors::Random(elements, 6);
  const FrameFields part = bodyPart(fields, second);
  EXPECT_EQ(part.stress, fields.stress.bottomRows(second.elementCount));
  EXPECT_EQ(part.positions, fields.positions.bottomRows(second.nodeCount));
  EXPECT_EQ(part.reactionForces, fields.reactionForces.bottomRows(second.nodeCount));
  EXPECT_EQ(part.vonMisesStress, fields.vonMisesStress.tail(second.elementCount));
  EXPECT_EQ(part.contactForces.rows(), 0);  // none given, none taken
}

TEST(BodyUnion, ABindingThatDoesNotFitItsBodyIsNamed) {
  Body bad = body(2, {0, 0, 0});
  bad.binding.controlIds(3, 1) = 1000;
  const Body good = body(2, {1, 0, 0});
  const std::vector<BodyParts> parts = {{&good.mesh, &good.skin, &good.binding},
                                        {&bad.mesh, &bad.skin, &bad.binding}};
  EXPECT_NE(errorText([&] { uniteBodies(parts); }).find("body 1's binding"), std::string::npos);
}

}  // namespace
}  // namespace tetskin::test
