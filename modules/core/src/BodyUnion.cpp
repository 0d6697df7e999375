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
    u.firstNode.push_back(nodes);
    u.firstElement.push_back(elements);
    u.firstVertex.push_back(vertices);
    nodes += body.mesh->nodeCount();
    elements += body.mesh->elementCount();
    vertices += body.skin->vertexCount();
    triangles += body.skin->triangleCount();
  }
  u.firstNode.push_back(nodes);
  u.firstElement.push_back(elements);
  u.firstVertex.push_back(vertices);

  u.mesh.nodes.resize(nodes, 3);
  u.mesh.elements.resize(elements, 4);
  u.mesh.levels = {LevelRange{0, nodes, 0, elements}};
  u.skin.positions.resize(vertices, 3);
  u.skin.triangles.resize(triangles, 3);
  u.binding = *bodies.front().binding;
  u.binding.level = 0;
  u.binding.resize(vertices);
  u.vertexBody.resize(static_cast<std::size_t>(vertices));
  Index triangle = 0;
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    const BodyParts& body = bodies[b];
    const Index node = u.firstNode[b], element = u.firstElement[b], vertex = u.firstVertex[b];
    const int nodeOffset = static_cast<int>(node), vertexOffset = static_cast<int>(vertex);
    u.mesh.nodes.middleRows(node, body.mesh->nodeCount()) = body.mesh->nodes;
    u.mesh.elements.middleRows(element, body.mesh->elementCount()) =
        body.mesh->elements.array() + nodeOffset;
    const Index count = body.skin->vertexCount();
    u.skin.positions.middleRows(vertex, count) = body.skin->positions;
    u.skin.triangles.middleRows(triangle, body.skin->triangleCount()) =
        body.skin->triangles.array() + vertexOffset;
    triangle += body.skin->triangleCount();
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

}  // namespace tetskin
