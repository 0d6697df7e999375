// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The multigrid solver's own coarse levels: nested grids that enclose the
// system's mesh. Level 1 is a grid of cubic cells, each split into six
// tetrahedra along its main diagonal (Kuhn's triangulation, conforming from
// cell to cell); every fine node lies in a cell and takes the 4 barycentric
// weights of its tetrahedron there. Each further level doubles the cell
// size, so its nodes lie on the next one's lattice (at a corner, an edge's,
// a face's or a cell's middle) and coarsen about 8x, as a multigrid wants.
// Weights are never negative (nothing is extrapolated), rows sum to 1, and
// linear fields (rigid motions among them) are reproduced exactly. A level
// keeps only the grid nodes that receive some weight, and a grid node whose
// support holds pieces of the body that are not joined inside it (an ear
// beside the head, two legs in one cell) becomes one coarse node per piece,
// so that the coarse levels keep the body's topology.
//
// Against the dataset's levels (decimated surfaces meshed again, 4.5-4.8x
// apart on the bunny, with extrapolated weights for fine nodes outside
// them) this gives the solver the coarsening of a geometric multigrid; the
// dataset's levels stay what the user built.

#include <vector>

#include "tetskin/simulation/CorotatedFem.h"

namespace tetskin {

struct GridLevel {
  double cellSize = 0;
  // Nodes in lattice units: node i lies at origin + cellSize * lattice.row(i).
  // (Nodes of separate pieces share a lattice point.)
  Eigen::Matrix<int, Eigen::Dynamic, 3, Eigen::RowMajor> lattice;
  Points3 nodes;  // the same in space
  // Finer level's nodes x this level's nodes (the finer level of level 1 is
  // the mesh itself): one row of 1-4 weights per finer node.
  SparseMatrix prolongation;
};

struct GridHierarchyOptions {
  double coarsening = 8;      // about this many times fewer nodes per level
  Index coarsestNodes = 200;  // stop once a level has at most this many
  int maxLevels = 8;          // coarse levels at most
};

struct GridHierarchy {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  std::vector<GridLevel> levels;  // level 1 (the finest grid) first

  // The nodal prolongations, level l+1 to level l, l = 0 the mesh.
  std::vector<SparseMatrix> prolongations() const;
};

// Input: the system's mesh (#N x 3 nodes, #T x 4 tetrahedra: its elements'
// edges give the topology). Output: the grids over it, finest first, each
// with its #Nl x #N(l-1) prolongation. Level 1's cell is sized so that it has about
// nodes/coarsening nodes. A mesh with at most options.coarsestNodes nodes
// gets no level.
GridHierarchy enclosingGrids(const TetMesh& mesh, const GridHierarchyOptions& options = {});

}  // namespace tetskin
