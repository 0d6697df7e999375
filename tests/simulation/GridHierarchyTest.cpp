// SPDX-License-Identifier: AGPL-3.0-or-later
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <limits>

#include "SampleData.h"
#include "tetskin/core/Error.h"
#include "tetskin/io/Dataset.h"
#include "tetskin/simulation/GridHierarchy.h"

namespace tetskin {
namespace {

using test::sampleDataset;

// The sample dataset's finest level: the mesh the solver coarsens.
const TetMesh& fineMesh() {
  static const TetMesh mesh =
      extractLevel(sampleDataset().mesh, sampleDataset().mesh.finestLevel());
  return mesh;
}

TEST(GridHierarchy, CoarsensAboutEightTimesPerLevelDownToTheCoarsest) {
  const Points3& nodes = fineMesh().nodes;
  GridHierarchyOptions options;
  options.coarsestNodes = 40;  // (3270 mesh nodes: three levels)
  const GridHierarchy grids = enclosingGrids(fineMesh(), options);
  ASSERT_GE(grids.levels.size(), 2u) << nodes.rows() << " mesh nodes";
  Index finer = nodes.rows();
  for (std::size_t l = 0; l < grids.levels.size(); ++l) {
    const GridLevel& level = grids.levels[l];
    const double ratio = static_cast<double>(finer) / static_cast<double>(level.nodes.rows());
    std::printf("grid level %zu: %lld nodes, cell %.4g, %.2fx coarser\n", l + 1,
                static_cast<long long>(level.nodes.rows()), level.cellSize, ratio);
    // Level 1 is sized to 8x; the doubled ones lose some to the surface.
    EXPECT_GT(ratio, l == 0 ? 7.0 : 3.0) << "level " << l + 1;
    EXPECT_LT(ratio, l == 0 ? 9.0 : 8.5) << "level " << l + 1;
    EXPECT_EQ(level.prolongation.rows(), finer);
    EXPECT_EQ(level.prolongation.cols(), level.nodes.rows());
    if (l > 0) {
      EXPECT_DOUBLE_EQ(level.cellSize, 2 * grids.levels[l - 1].cellSize);
    }
    finer = level.nodes.rows();
  }
  EXPECT_LE(finer, options.coarsestNodes);
  EXPECT_GT(grids.levels[grids.levels.size() - 2].nodes.rows(), options.coarsestNodes);
}

// Each level encloses the finer one: every finer node lies in a cell of
// the grid (weights in [0, 1], at most 4, summing to 1: no extrapolation),
// and linear fields, rigid motions among them, are reproduced exactly.
TEST(GridHierarchy, TransfersReproduceLinearFieldsWithoutExtrapolating) {
  const GridHierarchy grids = enclosingGrids(fineMesh());
  Points3 finerNodes = fineMesh().nodes;
  const Eigen::Matrix3d A{{0.3, -1.2, 0.7}, {2.0, 0.1, -0.4}, {-0.6, 0.9, 1.5}};
  const Eigen::RowVector3d offset(2.0, -1.0, 0.5);
  for (const GridLevel& level : grids.levels) {
    const SparseMatrix& P = level.prolongation;
    for (int row = 0; row < P.outerSize(); ++row) {
      double sum = 0;
      int count = 0;
      for (SparseMatrix::InnerIterator it(P, row); it; ++it) {
        EXPECT_GT(it.value(), 0.0);
        EXPECT_LE(it.value(), 1.0);
        sum += it.value();
        ++count;
      }
      EXPECT_LE(count, 4);
      EXPECT_NEAR(sum, 1.0, 1e-12);
    }
    // The grid's own nodes lie on its lattice.
    const Points3 fromLattice =
        (level.lattice.cast<double>() * level.cellSize).rowwise() + grids.origin.transpose();
    EXPECT_LT((fromLattice - level.nodes).cwiseAbs().maxCoeff(), 1e-12);
    // u = A x + b, given at the coarse nodes, is u at the finer ones.
    const Points3 coarseField = (level.nodes * A.transpose()).rowwise() + offset;
    const Points3 expected = (finerNodes * A.transpose()).rowwise() + offset;
    const double scale = expected.cwiseAbs().maxCoeff();
    EXPECT_LT((Points3(P * coarseField) - expected).cwiseAbs().maxCoeff(), 1e-12 * scale);
    // Every coarse node takes some weight (no empty columns).
    const Eigen::VectorXd columnSums =
        SparseMatrix(P.transpose()) * Eigen::VectorXd::Ones(P.rows());
    EXPECT_GT(columnSums.minCoeff(), 0.0);
    finerNodes = level.nodes;
  }
}

TEST(GridHierarchy, SmallMeshesGetNoLevelAndBadNodesAnError) {
  TetMesh few;
  few.nodes = fineMesh().nodes.topRows(50);
  EXPECT_TRUE(enclosingGrids(few).levels.empty());
  TetMesh broken = fineMesh();
  broken.nodes(7, 1) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(enclosingGrids(broken), Error);
  GridHierarchyOptions options;
  options.coarsening = 1;
  EXPECT_THROW(enclosingGrids(fineMesh(), options), Error);
}

// Two copies of the body side by side, closer than a cell: cells along the
// gap hold nodes of both, but no coarse node on any level takes weight
// from both (each piece gets its own), so the coarse levels can move the
// two apart as the fine one can.
TEST(GridHierarchy, PiecesThatShareACellGetCoarseNodesOfTheirOwn) {
  const TetMesh& one = fineMesh();
  const double cell = enclosingGrids(one).levels.at(0).cellSize;
  const double width = one.nodes.col(0).maxCoeff() - one.nodes.col(0).minCoeff();
  TetMesh two;
  two.nodes.resize(2 * one.nodeCount(), 3);
  two.nodes << one.nodes, one.nodes.rowwise() + Eigen::RowVector3d(width + 0.2 * cell, 0, 0);
  two.elements.resize(2 * one.elementCount(), 4);
  two.elements << one.elements, one.elements.array() + static_cast<int>(one.nodeCount());
  const GridHierarchy grids = enclosingGrids(two);
  ASSERT_GE(grids.levels.size(), 2u);
  // Which copy each node belongs to, carried down the levels.
  std::vector<int> copy(static_cast<std::size_t>(two.nodeCount()));
  for (Index v = 0; v < two.nodeCount(); ++v)
    copy[static_cast<std::size_t>(v)] = v >= one.nodeCount();
  for (std::size_t l = 0; l < grids.levels.size(); ++l) {
    const SparseMatrix& P = grids.levels[l].prolongation;
    std::vector<int> coarseCopy(static_cast<std::size_t>(P.cols()), -1);
    int mixed = 0;
    for (int row = 0; row < P.outerSize(); ++row)
      for (SparseMatrix::InnerIterator it(P, row); it; ++it) {
        int& c = coarseCopy[static_cast<std::size_t>(it.col())];
        if (c >= 0 && c != copy[static_cast<std::size_t>(row)]) ++mixed;
        c = copy[static_cast<std::size_t>(row)];
      }
    EXPECT_EQ(mixed, 0) << "level " << l + 1;
    copy = coarseCopy;
  }
  // Some lattice points along the gap serve both copies (as two nodes).
  const GridLevel& first = grids.levels[0];
  std::vector<std::array<int, 3>> points;
  for (Index n = 0; n < first.lattice.rows(); ++n)
    points.push_back({first.lattice(n, 0), first.lattice(n, 1), first.lattice(n, 2)});
  std::sort(points.begin(), points.end());
  EXPECT_NE(std::adjacent_find(points.begin(), points.end()), points.end());
}

}  // namespace
}  // namespace tetskin
