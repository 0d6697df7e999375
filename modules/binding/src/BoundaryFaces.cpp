// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/binding/BoundaryFaces.h"

#include <algorithm>
#include <array>

namespace tetskin {

BoundaryFaces boundaryFaces(const TetMesh& mesh, int nodeOffset) {
  // The faces of a positive tetrahedron (0,1,2,3), each wound so its normal
  // points away from the opposite corner.
  static constexpr int kFaces[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
  struct Entry {
    std::array<int, 3> key;  // sorted ids: equal for the two sides of an inner face
    int element;
    int face;
  };
  std::vector<Entry> entries;
  entries.reserve(static_cast<std::size_t>(mesh.elementCount()) * 4);
  for (Index e = 0; e < mesh.elementCount(); ++e)
    for (int f = 0; f < 4; ++f) {
      std::array<int, 3> key = {mesh.elements(e, kFaces[f][0]), mesh.elements(e, kFaces[f][1]),
                                mesh.elements(e, kFaces[f][2])};
      std::sort(key.begin(), key.end());
      entries.push_back({key, static_cast<int>(e), f});
    }
  std::sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) {
    return a.key != b.key ? a.key < b.key : a.element < b.element;
  });
  BoundaryFaces out;
  std::vector<std::array<int, 3>> faces;
  for (std::size_t i = 0; i < entries.size();) {
    std::size_t j = i + 1;
    while (j < entries.size() && entries[j].key == entries[i].key) ++j;
    if (j - i == 1) {
      const Entry& e = entries[i];
      faces.push_back({mesh.elements(e.element, kFaces[e.face][0]) + nodeOffset,
                       mesh.elements(e.element, kFaces[e.face][1]) + nodeOffset,
                       mesh.elements(e.element, kFaces[e.face][2]) + nodeOffset});
      out.elements.push_back(e.element);
    }
    i = j;
  }
  out.faces.resize(static_cast<Index>(faces.size()), 3);
  for (std::size_t f = 0; f < faces.size(); ++f)
    for (int k = 0; k < 3; ++k) out.faces(static_cast<Index>(f), k) = faces[f][k];
  return out;
}

SurfaceMesh boundarySurface(const TetMesh& mesh) {
  const Triangles faces = boundaryFaces(mesh).faces;
  std::vector<int> newId(static_cast<std::size_t>(mesh.nodeCount()), -1);
  for (Index f = 0; f < faces.rows(); ++f)
    for (int k = 0; k < 3; ++k) newId[static_cast<std::size_t>(faces(f, k))] = 0;
  int next = 0;
  for (int& id : newId)
    if (id == 0) id = next++;
  SurfaceMesh surface;
  surface.positions.resize(next, 3);
  for (Index v = 0; v < mesh.nodeCount(); ++v)
    if (const int id = newId[static_cast<std::size_t>(v)]; id >= 0)
      surface.positions.row(id) = mesh.nodes.row(v);
  surface.triangles.resize(faces.rows(), 3);
  for (Index f = 0; f < faces.rows(); ++f)
    for (int k = 0; k < 3; ++k)
      surface.triangles(f, k) = newId[static_cast<std::size_t>(faces(f, k))];
  return surface;
}

}  // namespace tetskin
