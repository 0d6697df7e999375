// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/io/TetrahedraFile.h"

#include "tetskin/core/Error.h"
#include "tetskin/io/FileNames.h"
#include "tetskin/io/GmshFormat.h"
#include "tetskin/io/MeditFormat.h"
#include "tetskin/io/TetGenFormat.h"

namespace tetskin {

std::string TetrahedraFile::elementName(Index e) const {
  const std::string number = std::to_string(numbers[static_cast<std::size_t>(e)]);
  return (format == "MEDIT" ? "tetrahedron " : "element ") + number;
}

bool isTetrahedraFile(const std::filesystem::path& path) {
  const std::string e = lowerExtension(path);
  return e == ".msh" || e == ".mesh" || e == ".node" || e == ".ele";
}

TetrahedraFile readTetrahedraFile(const std::filesystem::path& path) {
  const std::string extension = lowerExtension(path);
  TetrahedraFile out;
  if (extension == ".msh") {
    GmshTetrahedra read = readGmshTetrahedra(path);
    out.mesh = std::move(read.mesh);
    out.skippedElements = read.skippedElements;
    out.numbers = std::move(read.elementTags);
    out.format = "Gmsh";
  } else if (extension == ".mesh") {
    MeditMesh read = readMedit(path);
    if (read.tetrahedra.rows() == 0)
      throw Error(path.string(), 0,
                  "has no tetrahedra (a surface mesh? a dataset is made of tetrahedra)");
    out.mesh.nodes = std::move(read.vertices);
    out.mesh.elements = std::move(read.tetrahedra);
    out.skippedElements = read.triangles.rows() + read.skippedRecords;
    out.format = "MEDIT";
    for (Index e = 0; e < out.mesh.elementCount(); ++e) out.numbers.push_back(e + 1);
  } else if (extension == ".node" || extension == ".ele") {
    const NodeElePaths pair = nodeElePair(path);
    int first = 0;
    out.mesh = readTetMesh(pair.node, pair.ele, &first);
    out.format = "TetGen";
    for (Index e = 0; e < out.mesh.elementCount(); ++e) out.numbers.push_back(e + first);
  } else {
    throw Error(path.string(), 0,
                "is not a tetrahedral mesh this reads (Gmsh .msh, MEDIT .mesh, a TetGen "
                ".node/.ele pair)");
  }
  return out;
}

}  // namespace tetskin
