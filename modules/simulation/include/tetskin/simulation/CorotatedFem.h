// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Corotated linear elasticity on linear tetrahedra (Georgii & Westermann;
// doc/dev/numerics.md): per element a rest stiffness K_e = V B^T C B, a rotation R
// from the polar decomposition of the deformation gradient, the elastic force
// f_e = -R K_e (R^T x_e - X_e) and the stiffness R K_e R^T. Everything that
// depends only on the rest shape (shape gradients, lumped mass, the sparsity
// pattern and where each element's blocks go in it) is computed once.
//
// The material is isotropic, so nothing 12x12 is stored or multiplied: with
// shape gradients g_k and r_k = R g_k, block (i, j) of R K_e R^T is
// V (lambda r_i r_j^T + mu r_j r_i^T + mu (g_i . g_j) I), and K_e z sums to
// V sigma g_i per node with sigma the linear stress of sym(R^T F) - I. Both
// are a few dozen flops per block, against two 3x3 products for R K_ij R^T.
// Assembly runs in parallel over chunks of spatially close elements (Morton
// order), coloured once in the constructor so that the chunks of a colour
// share no node. Within a chunk, four elements at a time go through one
// vector kernel (rotation, strain, stress, forces and blocks in the lanes of
// four-double vectors; AVX2 where the CPU has it, SimdKernel.h), and their
// results are added into the matrix a block row of the four at a time.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <Eigen/SparseCore>
#include <array>
#include <span>
#include <vector>

#include "tetskin/core/ElasticMaterial.h"
#include "tetskin/core/FrameFields.h"
#include "tetskin/core/TetMesh.h"
#include "tetskin/simulation/SimdKernel.h"

namespace tetskin {

// The element pass's storage, in the layout of its vector kernel (lane l of
// group g is stored element 4 g + l). Internal to CorotatedFem; declared
// here because it holds them.
namespace corotated {
struct alignas(32) ElementGroup {  // what the rest shape fixes
  double gradients[4][3][4];       // [node k][axis][lane]: shape-function gradient g_k
  double volume[4];
  double gradientDots[10][4];  // V g_i . g_j for the pairs i <= j, in row order
  double lambda[4], mu[4];     // the element's Lame parameters (Pa)
  int nodes[4][4];             // [node k][lane]
};
struct alignas(32) RotationEstimates {  // the last rotations, as unit quaternions
  double w[4], x[4], y[4], z[4];
};
struct ElementScatter {           // where an element's blocks go
  int id;                         // in the mesh (elements are stored in Morton order)
  std::array<int, 16> slots;      // value index of entry (3 n_i, 3 n_j) per (i, j)
  std::array<int, 4> rowLengths;  // of node i's rows: row 3 n_i + a starts a lengths on
};
}  // namespace corotated

// Row-major so rows can be processed in parallel (SpMV, Dirichlet rows).
using SparseMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor, int>;

// Elements of another material than the mesh's: elements [firstElement,
// firstElement + elementCount) of the mesh (a body of several a run steps
// as one). Their Young's modulus, Poisson's ratio and density count; the
// damping is the run's, one for all its elements.
struct MaterialRegion {
  Index firstElement = 0, elementCount = 0;
  ElasticMaterial material;
};

class CorotatedFem {
 public:
  // Inputs: the rest mesh (#N x 3 nodes in m, #T x 4 positively oriented
  // tetrahedra) and its material (Pa, kg/m^3), `regions` of other
  // materials over it (later regions over earlier ones). Throws Error for a
  // material out of its ranges or a region beyond the elements.
  CorotatedFem(const TetMesh& rest, const ElasticMaterial& material,
               std::span<const MaterialRegion> regions = {});

  Index nodeCount() const { return restPositions_.size() / 3; }
  Index dofCount() const { return restPositions_.size(); }
  Index elementCount() const { return static_cast<Index>(scatter_.size()); }
  const Eigen::VectorXd& restPositions() const { return restPositions_; }  // xyz per node
  const Eigen::VectorXd& lumpedMass() const { return mass_; }              // per dof
  // The mesh's material (an element in a region has the region's
  // elasticity and density).
  const ElasticMaterial& material() const { return material_; }
  // The pattern of the assembled stiffness (values zero), for callers that
  // build systems of the same shape.
  const SparseMatrix& pattern() const { return pattern_; }

  // What update() assembles besides the elastic force: an implicit step
  // needs A = s K + q K_rot + D (D diagonal, e.g. the damped mass) and the
  // force f_el - w K v - u K_rot v, all in the same element pass (no
  // separate products, no second pass over the matrix).
  //
  // K = sum_e R K_e R^T is the stiffness warping of Müller et al. (2002):
  // the tangent of the corotated force with R held fixed. K_rot is the rest
  // of the tangent, from the rotations' dependence on the positions (the
  // derivative of the polar decomposition, McAdams et al. 2011). It stiffens
  // rotations under tension: without it, the implicit step of a stretched
  // body under large time steps overshoots them and blows up. Under
  // compression it is negative; in the matrix those modes are dropped per
  // element (the projection of Teran et al. 2005), so q K_rot is positive
  // semidefinite and the system positive definite for any step. The force's
  // u K_rot v keeps them: it is the exact linearization of the force along
  // v, which nothing requires to be definite. At the rest shape K_rot is
  // zero.
  struct SystemTerms {
    double stiffnessScale = 1;                  // s
    const Eigen::VectorXd* diagonal = nullptr;  // D per dof; none = 0
    const Eigen::VectorXd* velocity = nullptr;  // v per dof; none = 0
    double velocityWeight = 0;                  // w
    double rotationScale = 0;                   // q (0 and u = 0: K_rot is not computed)
    double rotationVelocityWeight = 0;          // u
  };

  // Inputs:  x          3n positions (m), x, y, z per node
  // Outputs: force      3n elastic forces (N)
  //          stiffness  3n x 3n, R K R^T (N/m), in pattern()'s shape (values
  //                     overwritten)
  // and the elements' rotations kept. Elements are processed in parallel.
  void update(const Eigen::VectorXd& x, Eigen::VectorXd& force, SparseMatrix& stiffness) {
    update(x, force, stiffness, SystemTerms{});
  }
  // The same with the terms above: `force` = f_el(x) - w K v - u K_rot v
  // (every mode) and `matrix` = s K + q K_rot + D (compressive modes
  // dropped) at x.
  void update(const Eigen::VectorXd& x, Eigen::VectorXd& force, SparseMatrix& matrix,
              const SystemTerms& terms);
  // Which version of the element pass's kernel update() runs (the same
  // results to rounding).
  void setKernel(SimdKernel kernel) { kernel_ = kernel; }

  // Elastic energy sum 1/2 z^T K_e z, z = R^T x_e - X_e, R from x.
  double elasticEnergy(const Eigen::VectorXd& x) const;

  // Per element at positions x: the stress R sigma(e) R^T (Pa; xx, yy, zz,
  // xy, yz, xz), the rotated-frame stress turned into the world's axes: the
  // Cauchy stress of the corotated material, whose strains are small; its
  // von Mises stress; and the equivalent (von Mises) strain of the
  // rotated-frame strain e = sym(R^T F) - I, sqrt(2/3 dev(e) : dev(e))
  // (dimensionless: 0.01 is 1% in a uniaxial stretch of an incompressible
  // body).
  struct ElementMeasures {
    Eigen::VectorXd vonMisesStress, equivalentStrain;
    SymmetricTensors stress;
  };
  ElementMeasures elementMeasures(const Eigen::VectorXd& x) const;

  // The elastic force with its stiffness damping at positions x and
  // velocities v (3n each): f_el(x) - beta K v, K = R K_e R^T at x (the
  // force update() assembles with velocityWeight beta, without the matrix,
  // and without touching the warm starts of the rotations: a query between
  // steps, such as the supports' reactions, leaves the next step as it was).
  Eigen::VectorXd dampedElasticForce(const Eigen::VectorXd& x, const Eigen::VectorXd& v,
                                     double beta) const;

  // The rotation of the polar decomposition F = R S, a proper rotation also
  // for inverted elements (SVD with the sign fix of Irving, Teran & Fedkiw):
  // the rotation that maximizes trace(R^T F).
  static Eigen::Matrix3d rotation(const Eigen::Matrix3d& F);
  // The same rotation by quaternion steps in the manner of Müller et al. 2016
  // ("A robust method to extract the rotational part of deformations"), with
  // Newton steps on trace(R^T F) from `estimate` (updated in place): one or
  // two steps when warm-started from the last time step; falls back to the
  // SVD if it does not converge.
  static Eigen::Matrix3d rotation(const Eigen::Matrix3d& F, Eigen::Quaterniond& estimate);

  // Rest stiffness of element e (12 x 12, node-major xyz).
  Eigen::Matrix<double, 12, 12> elementStiffness(Index e) const;
  // The rotation of element e (mesh numbering) at the last update().
  const Eigen::Matrix3d& elementRotation(Index e) const {
    return rotations_[static_cast<std::size_t>(storedAt_[static_cast<std::size_t>(e)])];
  }

 private:
  // Stored element e's rest-shape constants and the deformation gradient
  // F = sum_k x_k g_k^T (the gradients sum to zero, so no origin is needed).
  int node(std::size_t e, int k) const { return groups_[e / 4].nodes[k][e % 4]; }
  double volume(std::size_t e) const { return groups_[e / 4].volume[e % 4]; }
  Eigen::Vector3d gradient(std::size_t e, int k) const;
  Eigen::Matrix3d deformationGradient(std::size_t e, const Eigen::VectorXd& x) const;
  double lambda(std::size_t e) const { return groups_[e / 4].lambda[e % 4]; }
  double mu(std::size_t e) const { return groups_[e / 4].mu[e % 4]; }
  // The element's strain in its rotated frame, sym(R^T F) - I, and stored
  // element e's linear (Hooke) stress of a strain.
  static Eigen::Matrix3d rotatedFrameStrain(const Eigen::Matrix3d& R, const Eigen::Matrix3d& F);
  Eigen::Matrix3d linearStress(std::size_t e, const Eigen::Matrix3d& strain) const;
  ElasticMaterial material_;
  // Per stored element (Morton order of the centroids; groups padded to
  // four with copies of the last element).
  std::vector<corotated::ElementGroup> groups_;
  std::vector<corotated::ElementScatter> scatter_;
  std::vector<int> storedAt_;  // per mesh element: its stored index
  Eigen::VectorXd restPositions_;
  Eigen::VectorXd mass_;
  SparseMatrix pattern_;
  std::vector<int> diagonalSlots_;                       // per node: value index of entry (3v, 3v)
  std::vector<Eigen::Matrix3d> rotations_;               // per stored element
  std::vector<corotated::RotationEstimates> estimates_;  // warm starts, per group
  SimdKernel kernel_ = SimdKernel::Fastest;
  // Chunks of consecutive stored elements (their first index), grouped so
  // that no two chunks of a group share a node: each group is assembled in
  // parallel without locks or atomics.
  std::vector<std::vector<int>> colors_;
};

}  // namespace tetskin
