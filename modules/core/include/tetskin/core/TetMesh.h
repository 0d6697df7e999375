// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Tetrahedral meshes: one level (the control mesh the simulation runs on) and
// the multi-level dataset that holds all levels, coarsest first, in one node
// array and one element array.

#include <string>
#include <vector>

#include "tetskin/core/Geometry.h"
#include "tetskin/core/Types.h"

namespace tetskin {

// Units: TetSkin has none of its own. Positions are in the model's units
// (the dataset's; metres where a material is given in pascals and kg/m^3),
// times in seconds.
struct TetMesh {
  Points3 nodes;        // #N x 3 positions
  Tetrahedra elements;  // #T x 4 node indices into `nodes`, positively oriented

  Index nodeCount() const { return nodes.rows(); }
  Index elementCount() const { return elements.rows(); }
};

// Where one level lies inside the dataset's node and element arrays.
struct LevelRange {
  Index firstNode = 0;
  Index nodeCount = 0;
  Index firstElement = 0;
  Index elementCount = 0;

  bool operator==(const LevelRange&) const = default;
};

// All levels of a dataset. Element rows hold dataset-wide node indices; the
// elements of a level refer only to the nodes of the same level.
struct MultiLevelTetMesh {
  Points3 nodes;                   // #N x 3: every level's nodes, level after level
  Tetrahedra elements;             // #T x 4: every level's elements, dataset-wide node ids
  std::vector<LevelRange> levels;  // 0 = coarsest

  int levelCount() const { return static_cast<int>(levels.size()); }
  int finestLevel() const { return levelCount() - 1; }
};

// Signed volume of element e of `mesh`.
double elementVolume(const TetMesh& mesh, Index e);

// Sum of the elements' signed volumes (the body's volume when every
// element is positively oriented).
double meshVolume(const TetMesh& mesh);

// Throws Error naming `name` and the element or node when a node index is out
// of range, a coordinate is not finite or (if requirePositiveVolume) an
// element's signed volume is not positive.
void validateTetMesh(const TetMesh& mesh, const std::string& name,
                     bool requirePositiveVolume = true);

// Throws Error when the level ranges are not contiguous and ascending, do not
// cover both arrays exactly, or an element refers to a node outside its level.
void validateLevels(const MultiLevelTetMesh& mesh, const std::string& name);

// Nodes no element refers to, ascending.
std::vector<Index> unreferencedNodes(const TetMesh& mesh);

// Removes unreferenced nodes and renumbers the elements; returns how many
// nodes were removed.
Index removeUnreferencedNodes(TetMesh& mesh);

// Swaps two nodes of every element of negative volume (a mesher's or
// another tool's other orientation convention), so all are positive;
// returns how many. Elements of zero volume stay as they are
// (validateTetMesh names them).
Index orientElementsPositively(TetMesh& mesh);

// Level k with level-local node indices.
TetMesh extractLevel(const MultiLevelTetMesh& mesh, int level);

// Appends `level` as the new finest level (its indices are level-local).
void appendLevel(MultiLevelTetMesh& mesh, const TetMesh& level);

}  // namespace tetskin
