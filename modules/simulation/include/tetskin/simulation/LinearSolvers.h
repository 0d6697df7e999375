// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Solvers for the symmetric positive definite systems of the implicit step:
// preconditioned conjugate gradients (block-Jacobi), and the same CG with a
// multigrid V-cycle over the dataset's coarser levels as preconditioner.
// Both start from the x passed in (the stepper passes the projected guess of
// ProjectedInitialGuess.h).

#include <chrono>
#include <memory>
#include <vector>

#include "tetskin/core/OptionSchema.h"
#include "tetskin/simulation/CorotatedFem.h"
#include "tetskin/simulation/CouplingSprings.h"
#include "tetskin/simulation/NodeBlockMatrix.h"

namespace tetskin {

struct SolveStats {
  int iterations = 0;
  double relativeResidual = 0;     // |b - A x| / |b|
  bool stoppedAtDeadline = false;  // short of the tolerance: out of time
};

// The systems here have the node-block layout of CorotatedFem::pattern():
// each node pair either has a full 3x3 block (zeros included) or none, so the
// three rows of a node share one column list. hasNodeBlocks() checks that;
// the solvers below require it (conjugateGradient checks the row lengths on
// every call, the multigrid the whole layout when it first sees a pattern).
bool hasNodeBlocks(const SparseMatrix& A);

// y = A x for A in the node-block layout, nodes in parallel.
void multiply(const SparseMatrix& A, const Eigen::VectorXd& x, Eigen::VectorXd& y);

// y = P x for a nodal P (one weight per node pair) applied to xyz vectors:
// y_i = sum_j P_ij x_j per coordinate.
void multiplyNodal(const SparseMatrix& P, const Eigen::VectorXd& x, Eigen::VectorXd& y);

// Preconditioner interface: z = M^-1 r.
class Preconditioner {
 public:
  virtual ~Preconditioner() = default;
  // Called once per system (the matrix changes every step).
  virtual void setup(const SparseMatrix& A) = 0;
  virtual void apply(const Eigen::VectorXd& r, Eigen::VectorXd& z) const = 0;
  // A preconditioner that acts node by node (node v's three entries of z
  // from node v's of r alone) says so and applies itself to a range of
  // nodes: CG then runs it inside its own pass over the vectors, without a
  // pass (and a hand-off between threads) of its own.
  virtual bool actsPerNode() const { return false; }
  // z = M^-1 r on the dofs of nodes [first, last) (only where actsPerNode()).
  virtual void applyToNodes(Index first, Index last, const double* r, double* z) const;
  // The system's springs outside A (null: none), before setup(A): a
  // preconditioner may use them; the default leaves them to CG's products.
  virtual void setCoupling(const CouplingSprings*) {}
};

// Inverse of each node's 3x3 diagonal block (A in the node-block layout).
class BlockJacobi : public Preconditioner {
 public:
  void setup(const SparseMatrix& A) override;
  void apply(const Eigen::VectorXd& r, Eigen::VectorXd& z) const override;
  bool actsPerNode() const override { return true; }
  void applyToNodes(Index first, Index last, const double* r, double* z) const override;
  const Eigen::Matrix3d& inverse(Index node) const {
    return inverse_[static_cast<std::size_t>(node)];
  }

 private:
  std::vector<Eigen::Matrix3d> inverse_;
};

// Block Jacobi, and over the nodes coupling springs touch one symmetric
// block Gauss-Seidel sweep of A's diagonal blocks and the springs' blocks
// between those nodes (forward, then backward: symmetric positive
// definite, as CG needs). A spring between two bodies' nodes is as stiff
// off the diagonal as on it, which block Jacobi does not see; the sweep
// does, at the cost of one pass over the springs' entries each way. The
// blocks between nodes are never formed: a spring's share of node j's row
// is s a_j n (sum of a_i n.z_i over its nodes swept so far). Without
// springs it is block Jacobi, node by node.
class SpringGaussSeidel : public Preconditioner {
 public:
  void setCoupling(const CouplingSprings* coupling) override { coupling_ = coupling; }
  void setup(const SparseMatrix& A) override;
  void apply(const Eigen::VectorXd& r, Eigen::VectorXd& z) const override;
  bool actsPerNode() const override { return order_.empty(); }
  void applyToNodes(Index first, Index last, const double* r, double* z) const override {
    jacobi_.applyToNodes(first, last, r, z);
  }

 private:
  struct Incidence {
    std::size_t spring;
    double weight;
  };
  BlockJacobi jacobi_;
  const CouplingSprings* coupling_ = nullptr;
  std::vector<Index> order_;         // the nodes springs touch, in sweep order
  std::vector<std::size_t> starts_;  // order_[i]'s incidences: starts_[i] .. starts_[i+1]-1
  std::vector<Incidence> incidences_;
  mutable std::vector<double> along_;             // per spring, the sweep's sum of a_i n.z_i so far
  mutable std::vector<Eigen::Vector3d> forward_;  // per swept node, the forward sweep's value
};

// How the V-cycle smooths each level but the coarsest (MultigridPreconditioner):
// - GaussSeidel: one block Gauss-Seidel sweep, forward before the coarse
//   correction and backward after it. Strong per sweep, but each node waits
//   for its neighbours' new values: the sweep runs colour by colour (a
//   barrier each) and took about 2.3 float products at 109k elements.
// - Chebyshev: the Chebyshev polynomial of a given degree (setSmoother) in
//   D^-1 A (D the 3x3 diagonal blocks) over [0.15, 1.1] times its largest
//   eigenvalue (Adams et al. 2003), the same polynomial before and after.
//   Each degree is one pass of a float product fused with the vector
//   updates, node by node, with no order between nodes: parallel without
//   colours, and the same bits on any number of threads. The eigenvalue
//   comes from power steps on each new matrix of a level, started from the
//   last estimate's eigenvector.
enum class MultigridSmoother { GaussSeidel, Chebyshev };
template <>
struct EnumSchema<MultigridSmoother> {
  static constexpr const char* what = "multigrid smoother";
  static constexpr EnumValue<MultigridSmoother> values[] = {
      {MultigridSmoother::GaussSeidel, "gauss-seidel", "block Gauss-Seidel over coloured chunks"},
      {MultigridSmoother::Chebyshev, "chebyshev", "a Chebyshev polynomial in D^-1 A"}};
};

// Multigrid V-cycle on non-nested levels: `nodalProlongations[l]` maps the
// nodes of level l+1 (coarser) to those of level l (level 0 is the system's
// own). The coarse operators are either Galerkin products P^T A P, rebuilt in
// setup(A) by precomputed streams (GalerkinStream.h), or given by the caller
// (setup(A, coarse): e.g. the coarse meshes' own discretization, as sparse as
// the fine one). Smoothing as MultigridSmoother says, symmetric either way
// (the cycle is a symmetric preconditioner): Chebyshev, or block (3x3 per
// node) Gauss-Seidel over coloured chunks of neighbouring nodes (chunks of
// a colour relax in parallel), forward before and exactly backward after
// (the first forward sweep, from zero, and the residual after it read each
// block once between them); an exact Cholesky solve on the coarsest level.
// Fixed nodes (Dirichlet) receive no coarse correction. The sweeps and residuals
// run on copies of the level matrices in 3x3 blocks
// (NodeBlockMatrix.h), in single precision by default (half the memory
// traffic, and a block column is one 4-wide SSE operation).
class MultigridPreconditioner : public Preconditioner {
 public:
  explicit MultigridPreconditioner(std::vector<SparseMatrix> nodalProlongations,
                                   int smoothingSweeps = 1);
  ~MultigridPreconditioner() override;
  // 1 per fixed node of the finest level.
  void setFixedNodes(const std::vector<char>& fixedNodes) {
    setFixedNodesPerLevel(std::vector<std::vector<char>>{fixedNodes});
  }
  // The same per level (level 0 first; missing or empty levels: none fixed).
  // A fixed coarse node is one the caller's coarse operator holds still
  // (identity row): it neither gives nor takes corrections.
  void setFixedNodesPerLevel(const std::vector<std::vector<char>>& fixedPerLevel);
  // Rebuild the coarse operators (and the coarsest factorization) on every
  // `setups`-th setup only, counted from the first after construction or
  // new fixed nodes; the finest level is always the current system. 1 (the
  // default) rebuilds every time.
  void setCoarseReuse(int setups);
  // Whether the next setup takes new coarse operators (see setCoarseReuse):
  // a caller with coarse operators of its own rebuilds them then.
  bool coarseDue() const { return setupsSinceCoarse_ == 0; }
  // The next setup takes new coarse operators, and the reuse count starts
  // over from it (e.g. after steps solved without this preconditioner).
  void renewCoarse() { setupsSinceCoarse_ = 0; }
  // Run the cycle in single precision (the default) or double. The cycle
  // only preconditions: CG's iterates, products and residuals stay double,
  // so the solve reaches its tolerance either way.
  void setSinglePrecision(bool single);
  // The smoother (the default: Chebyshev of degree 2); `degree` is the
  // Chebyshev polynomial's (at least 1), ignored by Gauss-Seidel, whose
  // sweeps the constructor's `smoothingSweeps` counts.
  void setSmoother(MultigridSmoother smoother, int degree = 2);
  // Galerkin coarse operators.
  void setup(const SparseMatrix& A) override;
  // Coarse operators from the caller: coarse[l] is level l+1's, in the
  // node-block layout, with the same pattern on every call. Their values are
  // taken (and the coarsest factorized) when coarseDue() held before the
  // call; otherwise the last ones stay. Both A and `coarse` must outlive
  // apply().
  void setup(const SparseMatrix& A, const std::vector<SparseMatrix>& coarse);
  void apply(const Eigen::VectorXd& r, Eigen::VectorXd& z) const override;
  int levelCount() const { return static_cast<int>(nodal_.size()) + 1; }
  // Level 0 is the system of the last setup().
  const SparseMatrix& coarseOperator(int level) const {
    return this->level(static_cast<std::size_t>(level));
  }

 private:
  const SparseMatrix& level(std::size_t l) const { return *levels_[l]; }
  // Sweep orders, the layout check and the cycle's buffers when the sweep
  // orders are gone (a new pattern or precision: then every level counts as
  // changed); the cycle's data of level 0 and of the levels from
  // `firstChanged` on; the coarsest factorization if it changed.
  void prepareLevels(std::size_t firstChanged);
  struct Impl;
  std::vector<SparseMatrix> prolongations_;  // nodal, as given
  std::vector<SparseMatrix> nodal_;          // with fixed rows and columns removed
  std::vector<SparseMatrix> restrictions_;   // nodal_ transposed
  std::vector<SparseMatrix> galerkin_;       // Galerkin operators of levels 1.. (setup(A))
  std::vector<const SparseMatrix*> levels_;  // the operator of each level
  int sweeps_;
  MultigridSmoother smoother_ = MultigridSmoother::Chebyshev;
  int degree_ = 2;
  int reuse_ = 1;
  int setupsSinceCoarse_ = 0;  // 0: the next setup takes new coarse operators
  // coarseDue(), and counts this setup.
  bool takeCoarseTurn();
  bool single_ = true;
  std::shared_ptr<Impl> impl_;
};

// Inputs:  A  n x n SPD, node-block layout (n = 3 #N); b  n
//          x  n, the starting iterate
// Outputs: x  n, the solution to |b - A x| <= tolerance |b|; the
//          iterations and relative residual reached.
// Preconditioned CG to `tolerance` (relative residual) or `maxIterations`,
// with the Polak-Ribiere beta so that a preconditioner that is symmetric
// only up to rounding (a float V-cycle) does not stall it. An iteration is
// two passes over the nodes in parallel (the product with the new search
// direction's update fused in, then the vector updates with a per-node
// preconditioner fused in); their dot products are summed over fixed
// chunks of nodes in chunk order, so a solve gives the same bits on any
// number of threads.
// Its products use A's block copy (NodeBlockMatrix.h): a caller that
// solves with the same A repeatedly, or keeps the copy's storage from step
// to step, passes that copy instead.
// With a `deadline`, the solve also stops before an iteration that would
// start after it (stoppedAtDeadline; x is the last iterate): how the
// automatic solver cuts a trial off (SolverChoice.h).
// With `coupling`, the system is A + C, C the springs outside A's pattern
// (CouplingSprings.h): every product adds theirs.
SolveStats conjugateGradient(
    const NodeBlockMatrix& A, const Eigen::VectorXd& b, Eigen::VectorXd& x,
    const Preconditioner& preconditioner, double tolerance, int maxIterations,
    std::chrono::steady_clock::time_point deadline = std::chrono::steady_clock::time_point::max(),
    const CouplingSprings* coupling = nullptr);
SolveStats conjugateGradient(const SparseMatrix& A, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                             const Preconditioner& preconditioner, double tolerance,
                             int maxIterations);

}  // namespace tetskin
