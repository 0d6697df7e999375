// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/core/BodyUnion.h"

#include <string>

#include "tetskin/core/Error.h"

namespace tetskin {

BodyUnion uniteBodies(std::span<const BodyParts> bodies) {
  if (bodies.empty()) throw Error("a union of bodies needs at least one body");
  BodyUnion u;
  Index nodes = 0, elements = 0, vertices = 0, triangles = 0;
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    const BodyParts& body = bodies[b];
    if (!body.mesh || !body.skin || !body.binding)
      throw Error("body " + std::to_string(b) + " lacks its mesh, skin or binding");
    if (body.binding->method != bodies.front().binding->method)
      throw Error("body " + std::to_string(b) +
                  "'s skin is bound by another method than body 0's: one binding holds one");
    validateBinding(*body.binding, body.skin->vertexCount(), body.mesh->nodeCount(),
                    "body " + std::to_string(b) + "'s binding");
    BodyRange& range = u.bodies.emplace_back();
    range.firstNode = nodes;
    range.nodeCount = body.mesh->nodeCount();
    range.firstElement = elements;
    range.elementCount = body.mesh->elementCount();
    range.firstVertex = vertices;
    range.vertexCount = body.skin->vertexCount();
    range.firstTriangle = triangles;
    range.triangleCount = body.skin->triangleCount();
    nodes += range.nodeCount;
    elements += range.elementCount;
    vertices += range.vertexCount;
    triangles += range.triangleCount;
  }

  u.mesh.nodes.resize(nodes, 3);
  u.mesh.elements.resize(elements, 4);
  u.mesh.levels = {LevelRange{0, nodes, 0, elements}};
  u.skin.positions.resize(vertices, 3);
  u.skin.triangles.resize(triangles, 3);
  u.binding = *bodies.front().binding;
  u.binding.level = 0;
  u.binding.resize(vertices);
  u.vertexBody.resize(static_cast<std::size_t>(vertices));
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    const BodyParts& body = bodies[b];
    const BodyRange& range = u.bodies[b];
    const Index element = range.firstElement, vertex = range.firstVertex;
    const int nodeOffset = static_cast<int>(range.firstNode),
              vertexOffset = static_cast<int>(vertex);
    placeBodyPart(*body.mesh, range, u.mesh.nodes, u.mesh.elements);
    const Index count = body.skin->vertexCount();
    u.skin.positions.middleRows(vertex, count) = body.skin->positions;
    u.skin.triangles.middleRows(range.firstTriangle, range.triangleCount) =
        body.skin->triangles.array() + vertexOffset;
    const SurfaceBinding& from = *body.binding;
    for (Index v = 0; v < count; ++v) {
      for (int j = 0; j < 4; ++j) {
        const int id = from.controlIds(v, j);
        u.binding.controlIds(vertex + v, j) = id < 0 ? id : id + nodeOffset;
      }
      u.binding.weights.row(vertex + v) = from.weights.row(v);
      u.binding.distance[vertex + v] = from.distance[v];
      u.binding.faceId[vertex + v] = from.faceId[v] + static_cast<int>(element);
      u.binding.minBarycentric[vertex + v] = from.minBarycentric[v];
      u.vertexBody[static_cast<std::size_t>(vertex + v)] = static_cast<int>(b);
    }
  }
  return u;
}

void placeBodyPart(const TetMesh& part, const BodyRange& body, Points3& nodes,
                   Tetrahedra& elements) {
  nodes.middleRows(body.firstNode, body.nodeCount) = part.nodes;
  elements.middleRows(body.firstElement, body.elementCount) =
      part.elements.array() + static_cast<int>(body.firstNode);
}

TetMesh bodyPart(const TetMesh& united, const BodyRange& body) {
  TetMesh part;
  part.nodes = united.nodes.middleRows(body.firstNode, body.nodeCount);
  part.elements = united.elements.middleRows(body.firstElement, body.elementCount).array() -
                  static_cast<int>(body.firstNode);
  return part;
}

SurfaceMesh bodyPart(const SurfaceMesh& united, const BodyRange& body) {
  SurfaceMesh part;
  part.positions = united.positions.middleRows(body.firstVertex, body.vertexCount);
  if (united.normals.rows() == united.positions.rows())
    part.normals = united.normals.middleRows(body.firstVertex, body.vertexCount);
  part.triangles = united.triangles.middleRows(body.firstTriangle, body.triangleCount).array() -
                   static_cast<int>(body.firstVertex);
  return part;
}

SurfaceBinding bodyPart(const SurfaceBinding& united, const BodyRange& body) {
  SurfaceBinding part = united;
  part.resize(body.vertexCount);
  for (Index v = 0; v < body.vertexCount; ++v) {
    const Index from = body.firstVertex + v;
    for (int j = 0; j < united.controlIds.cols(); ++j) {
      const int id = united.controlIds(from, j);
      part.controlIds(v, j) = id < 0 ? id : id - static_cast<int>(body.firstNode);
    }
    part.weights.row(v) = united.weights.row(from);
    part.distance[v] = united.distance[from];
    part.faceId[v] = united.faceId[from] - static_cast<int>(body.firstElement);
    part.minBarycentric[v] = united.minBarycentric[from];
  }
  return part;
}

FrameFields bodyPart(const FrameFields& united, const BodyRange& body) {
  const auto nodeRows = [&](const Points3& rows) -> Points3 {
    if (rows.rows() == 0) return rows;
    return rows.middleRows(body.firstNode, body.nodeCount);
  };
  const auto elementRows = [&](const Eigen::VectorXd& rows) -> Eigen::VectorXd {
    if (rows.size() == 0) return rows;
    return rows.segment(body.firstElement, body.elementCount);
  };
  FrameFields part;
  part.positions = nodeRows(united.positions);
  part.velocities = nodeRows(united.velocities);
  part.externalForces = nodeRows(united.externalForces);
  part.reactionForces = nodeRows(united.reactionForces);
  part.contactForces = nodeRows(united.contactForces);
  part.vonMisesStress = elementRows(united.vonMisesStress);
  part.equivalentStrain = elementRows(united.equivalentStrain);
  if (united.stress.rows() > 0)
    part.stress = united.stress.middleRows(body.firstElement, body.elementCount);
  return part;
}

}  // namespace tetskin
