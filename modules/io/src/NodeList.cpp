// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/io/NodeList.h"

#include <algorithm>
#include <string>

#include "TextLines.h"
#include "tetskin/core/Error.h"

namespace tetskin {

namespace {

int nodeNumber(const detail::TextLines& lines, std::string_view token, Index nodeCount) {
  const long long node = lines.toInteger(token, "node number");
  if (node < 0 || node >= nodeCount)
    lines.fail("node " + std::to_string(node) + " does not exist (the level has " +
               std::to_string(nodeCount) + " nodes, numbered from 0)");
  return static_cast<int>(node);
}

}  // namespace

std::vector<int> readNodeList(const std::filesystem::path& path, Index nodeCount) {
  const std::string content = detail::readWholeFile(path);
  detail::TextLines lines(content, path.string());
  std::vector<int> nodes;
  while (lines.next())
    for (std::string_view token : lines.tokens())
      nodes.push_back(nodeNumber(lines, token, nodeCount));
  if (nodes.empty()) throw Error(path.string(), 0, "no node numbers in the file");
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  return nodes;
}

Points3 readNodeForces(const std::filesystem::path& path, Index nodeCount) {
  const std::string content = detail::readWholeFile(path);
  detail::TextLines lines(content, path.string());
  Points3 forces = Points3::Zero(nodeCount, 3);
  bool any = false;
  while (lines.next()) {
    lines.expectTokens(4, 4, "node force (NODE FX FY FZ)");
    const int node = nodeNumber(lines, lines[0], nodeCount);
    for (int axis = 0; axis < 3; ++axis)
      forces(node, axis) += lines.toDouble(lines[1 + static_cast<std::size_t>(axis)], "force");
    any = true;
  }
  if (!any) throw Error(path.string(), 0, "no node forces in the file (lines NODE FX FY FZ)");
  if (!forces.allFinite())
    throw Error(path.string(), 0, "the forces given for one node add up beyond any number");
  return forces;
}

std::vector<FaceSetLine> readFaceSet(const std::filesystem::path& path, Index nodeCount) {
  const std::string content = detail::readWholeFile(path);
  detail::TextLines lines(content, path.string());
  std::vector<FaceSetLine> faces;
  while (lines.next()) {
    lines.expectTokens(3, 3, "face (three node numbers)");
    FaceSetLine face;
    for (std::size_t k = 0; k < 3; ++k) face.nodes[k] = nodeNumber(lines, lines[k], nodeCount);
    face.line = lines.lineNumber();
    faces.push_back(face);
  }
  if (faces.empty()) throw Error(path.string(), 0, "no faces in the file (lines A B C)");
  return faces;
}

}  // namespace tetskin
