// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Nodes of a level named in a text file, by their numbers from 0 (the point
// ids ParaView shows for a level's .vtu), `#` starting a comment:
// - a node list, e.g. the nodes `tetskin simulate --fixed-nodes` holds
//   still: numbers separated by spaces or line breaks; a number given twice
//   counts once;
// - node forces (`--loads`): one node per line, `NODE FX FY FZ`; the forces
//   of a node given twice add up;
// - a face set (`--load-faces`): one face per line, its three nodes
//   `A B C` in any order.

#include <array>
#include <filesystem>
#include <vector>

#include "tetskin/core/Types.h"

namespace tetskin {

// Throws Error naming the file and line for a token that is not a whole
// number or names no node of a mesh with `nodeCount` nodes, and for a file
// without any number. Returns the numbers sorted, each once.
std::vector<int> readNodeList(const std::filesystem::path& path, Index nodeCount);

// Throws Error naming the file and line for a line that is not a node and
// three finite numbers, a node a mesh with `nodeCount` nodes lacks, and for a
// file without any line. Returns the force on every node (nodeCount rows).
Points3 readNodeForces(const std::filesystem::path& path, Index nodeCount);

// A face of a face set and the line that names it.
struct FaceSetLine {
  std::array<int, 3> nodes;
  long line = 0;
};
// Throws Error naming the file and line for a line that is not three node
// numbers of a mesh with `nodeCount` nodes, and for a file without any
// line. Returns the faces in the file's order.
std::vector<FaceSetLine> readFaceSet(const std::filesystem::path& path, Index nodeCount);

}  // namespace tetskin
