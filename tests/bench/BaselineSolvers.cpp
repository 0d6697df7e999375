// SPDX-License-Identifier: AGPL-3.0-or-later
#include "BaselineSolvers.h"

#include <HYPRE.h>
#include <HYPRE_parcsr_ls.h>
#include <mpi.h>

#include <Eigen/CholmodSupport>
#include <stdexcept>
#include <vector>

namespace tetskin::bench {
namespace {

using ColumnMajor = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

// The stepper's systems are symmetric: a row-major matrix's arrays read as
// column-major are the same matrix.
ColumnMajor asColumnMajor(const SparseMatrix& A) {
  return Eigen::Map<const ColumnMajor>(A.rows(), A.cols(), A.nonZeros(), A.outerIndexPtr(),
                                       A.innerIndexPtr(), A.valuePtr());
}

class CholmodFactor : public Preconditioner {
 public:
  explicit CholmodFactor(int refactorEvery) : every_(refactorEvery) {}
  void setup(const SparseMatrix& A) override {
    if (steps_++ % every_ != 0) return;
    const ColumnMajor upper = asColumnMajor(A);
    if (!analyzed_) {
      llt_.analyzePattern(upper);
      analyzed_ = true;
    }
    llt_.factorize(upper);
    if (llt_.info() != Eigen::Success) throw std::runtime_error("CHOLMOD: factorization failed");
  }
  void apply(const Eigen::VectorXd& r, Eigen::VectorXd& z) const override { z = llt_.solve(r); }

 private:
  int every_;
  long steps_ = 0;
  bool analyzed_ = false;
  Eigen::CholmodSupernodalLLT<ColumnMajor, Eigen::Upper> llt_;
};

void check(HYPRE_Int error, const char* call) {
  if (error != 0) throw std::runtime_error(std::string("hypre: ") + call + " failed");
}

class BoomerAmg : public Preconditioner {
 public:
  explicit BoomerAmg(int setupEvery) : every_(setupEvery) {}
  ~BoomerAmg() override {
    if (amg_) HYPRE_BoomerAMGDestroy(amg_);
    if (matrix_) HYPRE_IJMatrixDestroy(matrix_);
    if (b_) HYPRE_IJVectorDestroy(b_);
    if (x_) HYPRE_IJVectorDestroy(x_);
  }

  void setup(const SparseMatrix& A) override {
    const HYPRE_BigInt n = static_cast<HYPRE_BigInt>(A.rows());
    if (!matrix_) {
      check(HYPRE_IJMatrixCreate(MPI_COMM_WORLD, 0, n - 1, 0, n - 1, &matrix_), "matrix");
      check(HYPRE_IJMatrixSetObjectType(matrix_, HYPRE_PARCSR), "matrix type");
      std::vector<HYPRE_Int> sizes(static_cast<std::size_t>(n));
      rows_.resize(static_cast<std::size_t>(n));
      for (HYPRE_BigInt i = 0; i < n; ++i) {
        sizes[static_cast<std::size_t>(i)] = A.outerIndexPtr()[i + 1] - A.outerIndexPtr()[i];
        rows_[static_cast<std::size_t>(i)] = i;
      }
      rowSizes_ = sizes;
      check(HYPRE_IJMatrixSetRowSizes(matrix_, sizes.data()), "row sizes");
      columns_.assign(A.innerIndexPtr(), A.innerIndexPtr() + A.nonZeros());
      for (HYPRE_IJVector* v : {&b_, &x_}) {
        check(HYPRE_IJVectorCreate(MPI_COMM_WORLD, 0, n - 1, v), "vector");
        check(HYPRE_IJVectorSetObjectType(*v, HYPRE_PARCSR), "vector type");
        check(HYPRE_IJVectorInitialize(*v), "vector init");
        check(HYPRE_IJVectorAssemble(*v), "vector assemble");
      }
    }
    // The fine level's values every step (the hierarchy keeps pointing at
    // this matrix), the hierarchy every `every_` steps.
    check(HYPRE_IJMatrixInitialize(matrix_), "matrix init");
    check(HYPRE_IJMatrixSetValues(matrix_, static_cast<HYPRE_Int>(n), rowSizes_.data(),
                                  rows_.data(), columns_.data(), A.valuePtr()),
          "matrix values");
    check(HYPRE_IJMatrixAssemble(matrix_), "matrix assemble");
    HYPRE_IJMatrixGetObject(matrix_, reinterpret_cast<void**>(&parcsr_));
    HYPRE_IJVectorGetObject(b_, reinterpret_cast<void**>(&parB_));
    HYPRE_IJVectorGetObject(x_, reinterpret_cast<void**>(&parX_));
    if (steps_++ % every_ != 0) return;
    if (amg_) HYPRE_BoomerAMGDestroy(amg_);
    HYPRE_BoomerAMGCreate(&amg_);
    HYPRE_BoomerAMGSetPrintLevel(amg_, 0);
    HYPRE_BoomerAMGSetMaxIter(amg_, 1);  // one V-cycle per application
    HYPRE_BoomerAMGSetTol(amg_, 0.0);
    HYPRE_BoomerAMGSetNumFunctions(amg_, 3);       // x, y, z per node
    HYPRE_BoomerAMGSetNodal(amg_, 4);              // nodal coarsening (row-sum norm of the blocks)
    HYPRE_BoomerAMGSetStrongThreshold(amg_, 0.5);  // hypre's advice for 3D
    HYPRE_BoomerAMGSetCoarsenType(amg_, 10);       // HMIS
    HYPRE_BoomerAMGSetInterpType(amg_, 6);         // extended+i
    HYPRE_BoomerAMGSetPMaxElmts(amg_, 4);
    HYPRE_BoomerAMGSetRelaxType(amg_, 8);  // l1 symmetric Gauss-Seidel: a symmetric cycle
    HYPRE_BoomerAMGSetNumSweeps(amg_, 1);
    check(HYPRE_BoomerAMGSetup(amg_, parcsr_, parB_, parX_), "BoomerAMG setup");
  }

  void apply(const Eigen::VectorXd& r, Eigen::VectorXd& z) const override {
    const HYPRE_Int n = static_cast<HYPRE_Int>(r.size());
    z.setZero(r.size());
    HYPRE_IJVectorSetValues(b_, n, rows_.data(), r.data());
    HYPRE_IJVectorSetValues(x_, n, rows_.data(), z.data());
    HYPRE_BoomerAMGSolve(amg_, parcsr_, parB_, parX_);
    HYPRE_IJVectorGetValues(x_, n, rows_.data(), z.data());
  }

 private:
  int every_;
  long steps_ = 0;
  HYPRE_IJMatrix matrix_ = nullptr;
  HYPRE_IJVector b_ = nullptr, x_ = nullptr;
  HYPRE_ParCSRMatrix parcsr_ = nullptr;
  HYPRE_ParVector parB_ = nullptr, parX_ = nullptr;
  HYPRE_Solver amg_ = nullptr;
  std::vector<HYPRE_BigInt> rows_, columns_;
  std::vector<HYPRE_Int> rowSizes_;
};

}  // namespace

std::unique_ptr<Preconditioner> cholmodFactor(int refactorEvery) {
  return std::make_unique<CholmodFactor>(refactorEvery);
}

std::unique_ptr<Preconditioner> boomerAmg(int setupEvery) {
  return std::make_unique<BoomerAmg>(setupEvery);
}

void startMpi(int& argc, char**& argv) {
  MPI_Init(&argc, &argv);
}
void finishMpi() {
  MPI_Finalize();
}

}  // namespace tetskin::bench
