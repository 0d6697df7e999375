// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/session/SurfaceLoadSelection.h"

#include <algorithm>
#include <map>

#include "tetskin/binding/BoundaryFaces.h"
#include "tetskin/core/Error.h"
#include "tetskin/io/NodeList.h"

namespace tetskin {
namespace {

using FaceKey = std::array<int, 3>;

FaceKey keyOf(std::array<int, 3> nodes) {
  std::sort(nodes.begin(), nodes.end());
  return nodes;
}

}  // namespace

SurfaceLoad selectSurfaceLoad(const SurfaceLoadRequest& request, const TetMesh& level) {
  const auto fail = [&](const std::string& what) { throw Error(request.name + ": " + what); };
  const int selections = (request.box ? 1 : 0) + (request.faceFile.empty() ? 0 : 1) +
                         (request.faceNodes.rows() > 0 ? 1 : 0);
  if (selections != 1)
    fail(selections == 0 ? "no faces are selected (give a box or a face set)"
                         : "give its faces by a box or by a face set, not both");
  SurfaceLoad load;
  load.pressure = request.pressure;
  load.traction = request.traction;
  const Index first = request.firstNode;
  const Index count = request.nodeCount < 0 ? level.nodeCount() - first : request.nodeCount;
  const auto ofBody = [&](int node) { return node >= first && node < first + count; };

  // The body's boundary faces, wound outward.
  const BoundaryFaces boundary = boundaryFaces(level);
  std::vector<Index> faces;
  for (Index f = 0; f < boundary.faces.rows(); ++f)
    if (ofBody(boundary.faces(f, 0)) && ofBody(boundary.faces(f, 1)) &&
        ofBody(boundary.faces(f, 2)))
      faces.push_back(f);

  std::vector<Index> chosen;
  if (request.box) {
    const BoundingBox& box = *request.box;
    if (box.empty()) fail("its box's minimum exceeds its maximum along an axis");
    std::vector<char> in(static_cast<std::size_t>(level.nodeCount()), 0);
    for (int node : pointsInBox(level.nodes, box)) in[static_cast<std::size_t>(node)] = 1;
    const auto inside = [&](int node) { return in[static_cast<std::size_t>(node)] != 0; };
    for (Index f : faces)
      if (inside(boundary.faces(f, 0)) && inside(boundary.faces(f, 1)) &&
          inside(boundary.faces(f, 2)))
        chosen.push_back(f);
    if (chosen.empty()) {
      const BoundingBox extent = boundingBox(level.nodes.middleRows(first, count));
      fail("no face of the boundary lies in " + commaSeparated(box.min) + " .. " +
           commaSeparated(box.max) + " (the body spans " + commaSeparated(extent.min) + " .. " +
           commaSeparated(extent.max) + ")");
    }
  } else {
    std::map<FaceKey, Index> byNodes;
    for (Index f : faces)
      byNodes[keyOf({boundary.faces(f, 0), boundary.faces(f, 1), boundary.faces(f, 2)})] = f;
    std::map<Index, std::string> taken;  // face -> where it was named
    // `where` names the face's line or row (`file`, `line`: a file's line,
    // for the Error to carry).
    const auto add = [&](std::array<int, 3> nodes, const std::string& file, long line,
                         const std::string& where) {
      const auto refuse = [&](const std::string& what) {
        if (!file.empty()) throw Error(file, line, what);
        throw Error(request.name + ": " + where + ": " + what);
      };
      for (int& node : nodes) node += static_cast<int>(first);
      const auto found = byNodes.find(keyOf(nodes));
      if (found == byNodes.end())
        refuse("nodes " + std::to_string(nodes[0] - first) + ", " +
               std::to_string(nodes[1] - first) + ", " + std::to_string(nodes[2] - first) +
               " are not a face of the boundary");
      if (const auto [at, fresh] = taken.emplace(found->second, where); !fresh)
        refuse("names the face of " + at->second + " again");
      chosen.push_back(found->second);
    };
    if (!request.faceFile.empty()) {
      const std::string file = request.faceFile.string();
      for (const FaceSetLine& face : readFaceSet(request.faceFile, count))
        add(face.nodes, file, face.line, "line " + std::to_string(face.line));
    } else {
      for (Index r = 0; r < request.faceNodes.rows(); ++r) {
        const std::string where = request.name + ": row " + std::to_string(r);
        std::array<int, 3> nodes{};
        for (std::size_t k = 0; k < 3; ++k) {
          nodes[k] = request.faceNodes(r, static_cast<Index>(k));
          if (nodes[k] < 0 || nodes[k] >= count)
            throw Error(where + ": node " + std::to_string(nodes[k]) +
                        " does not exist (the body has " + std::to_string(count) + " nodes)");
        }
        add(nodes, "", 0, "row " + std::to_string(r));
      }
    }
  }
  load.faces.resize(static_cast<Index>(chosen.size()), 3);
  for (std::size_t k = 0; k < chosen.size(); ++k)
    load.faces.row(static_cast<Index>(k)) = boundary.faces.row(chosen[k]);
  if (const auto problem = surfaceLoadProblem(load, level.nodeCount())) fail(*problem);
  return load;
}

}  // namespace tetskin
