// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/simulation/CorotatedFem.h"

#include <tbb/parallel_for.h>

#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>

#include "tetskin/core/Error.h"

namespace tetskin {
namespace {

// Greedy colouring: an element takes the first colour none of its nodes uses yet.
std::vector<std::vector<int>> colourElements(const TetMesh& mesh) {
  std::vector<std::vector<int>> colours;
  std::vector<std::vector<char>> nodeUses;  // per colour: node already taken
  for (Index e = 0; e < mesh.elementCount(); ++e) {
    std::size_t c = 0;
    for (;; ++c) {
      if (c == colours.size()) {
        colours.emplace_back();
        nodeUses.emplace_back(static_cast<std::size_t>(mesh.nodeCount()), 0);
      }
      bool free = true;
      for (int k = 0; k < 4; ++k)
        free = free && !nodeUses[c][static_cast<std::size_t>(mesh.elements(e, k))];
      if (free) break;
    }
    colours[c].push_back(static_cast<int>(e));
    for (int k = 0; k < 4; ++k) nodeUses[c][static_cast<std::size_t>(mesh.elements(e, k))] = 1;
  }
  return colours;
}

}  // namespace

Eigen::Matrix3d CorotatedFem::rotation(const Eigen::Matrix3d& F) {
  Eigen::JacobiSVD<Eigen::Matrix3d> svd(F, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d U = svd.matrixU();
  Eigen::Matrix3d V = svd.matrixV();
  // A reflection means an inverted element (or a reflected basis): flip the
  // axis of the smallest singular value so R is a proper rotation that pushes
  // the element back out.
  if (U.determinant() < 0) U.col(2) *= -1;
  if (V.determinant() < 0) V.col(2) *= -1;
  return U * V.transpose();
}

Eigen::Matrix3d CorotatedFem::rotation(const Eigen::Matrix3d& F, Eigen::Quaterniond& q) {
  const double scale = F.norm();
  if (!(scale > 0) || !std::isfinite(scale)) return rotation(F);
  const Eigen::Matrix3d A = F / scale;  // the tolerances below are relative
  for (int iteration = 0; iteration < 30; ++iteration) {
    const Eigen::Matrix3d R = q.toRotationMatrix();
    // Maximize trace(R^T A) over R exp([w]x): with S = R^T A the gradient is
    // s = axial(S - S^T) and the Hessian H = trace(S) I - sym(S), so Newton's
    // step is H w = s (quadratic convergence; Müller et al. divide by trace(S)
    // alone, which converges linearly). Far from the maximum, where H is not
    // positive definite, their gradient step.
    const Eigen::Matrix3d S = R.transpose() * A;
    const Eigen::Vector3d gradient(S(2, 1) - S(1, 2), S(0, 2) - S(2, 0), S(1, 0) - S(0, 1));
    const Eigen::Matrix3d symmetric = 0.5 * (S + S.transpose());
    const Eigen::Matrix3d hessian = symmetric.trace() * Eigen::Matrix3d::Identity() - symmetric;
    const Eigen::LLT<Eigen::Matrix3d> llt(hessian);
    Eigen::Vector3d step = llt.info() == Eigen::Success && hessian.diagonal().minCoeff() > 1e-3
                               ? Eigen::Vector3d(llt.solve(gradient))
                               : Eigen::Vector3d(gradient / (std::abs(symmetric.trace()) + 1e-9));
    const double angle = step.norm();
    if (angle < 1e-14) return R;
    if (angle > 1.0) step /= angle;  // trust region: at most a radian per step
    q = q * Eigen::Quaterniond(Eigen::AngleAxisd(step.norm(), step.normalized()));
    q.normalize();
  }
  // Not converged (a near-degenerate F): the SVD decides.
  const Eigen::Matrix3d R = rotation(F);
  q = Eigen::Quaterniond(R);
  return R;
}

CorotatedFem::CorotatedFem(const TetMesh& rest, const ElasticMaterial& material)
    : material_(material) {
  validateMaterial(material);
  validateTetMesh(rest, "simulation mesh", /*requirePositiveVolume=*/true);
  const Index n = rest.nodeCount();
  restPositions_.resize(3 * n);
  for (Index v = 0; v < n; ++v) restPositions_.segment<3>(3 * v) = rest.nodes.row(v).transpose();
  mass_.setZero(3 * n);
  const double lambda = material.lameLambda(), mu = material.lameMu();
  elements_.resize(static_cast<std::size_t>(rest.elementCount()));
  std::vector<Eigen::Triplet<double, int>> triplets;
  triplets.reserve(static_cast<std::size_t>(rest.elementCount()) * 144);
  for (Index e = 0; e < rest.elementCount(); ++e) {
    Element& el = elements_[static_cast<std::size_t>(e)];
    for (int k = 0; k < 4; ++k) el.nodes[k] = rest.elements(e, k);
    const Eigen::Vector3d x0 = rest.nodes.row(el.nodes[0]);
    Eigen::Matrix3d Dm;
    for (int k = 0; k < 3; ++k) Dm.col(k) = rest.nodes.row(el.nodes[k + 1]).transpose() - x0;
    el.restInverse = Dm.inverse();
    el.volume = Dm.determinant() / 6.0;
    // grad N_k = row k-1 of Dm^-1 for k = 1..3; grad N_0 = -(sum of the others).
    el.gradients[0].setZero();
    for (int k = 1; k < 4; ++k) {
      el.gradients[k] = el.restInverse.row(k - 1).transpose();
      el.gradients[0] -= el.gradients[k];
    }
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) {
        const Eigen::Vector3d& gi = el.gradients[i];
        const Eigen::Vector3d& gj = el.gradients[j];
        el.stiffness[i * 4 + j] =
            el.volume * (lambda * gi * gj.transpose() + mu * gj * gi.transpose() +
                         mu * gi.dot(gj) * Eigen::Matrix3d::Identity());
        for (int a = 0; a < 3; ++a)
          for (int b = 0; b < 3; ++b)
            triplets.emplace_back(3 * el.nodes[i] + a, 3 * el.nodes[j] + b, 0.0);
      }
    for (int k = 0; k < 4; ++k)
      mass_.segment<3>(3 * el.nodes[k]).array() += material.density * el.volume / 4.0;
  }
  pattern_.resize(3 * n, 3 * n);
  pattern_.setFromTriplets(triplets.begin(), triplets.end());
  pattern_.makeCompressed();
  // Where entry (3 n_i + a, 3 n_j) lives in the value array (the 3 entries
  // b = 0..2 follow it: columns of one node are adjacent in a sorted row).
  const int* outer = pattern_.outerIndexPtr();
  const int* inner = pattern_.innerIndexPtr();
  for (Element& el : elements_)
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j)
        for (int a = 0; a < 3; ++a) {
          const int row = 3 * el.nodes[i] + a, col = 3 * el.nodes[j];
          const int* begin = inner + outer[row];
          const int* end = inner + outer[row + 1];
          el.slots[(i * 4 + j) * 3 + a] =
              static_cast<int>(std::lower_bound(begin, end, col) - inner);
        }
  rotations_.assign(elements_.size(), Eigen::Matrix3d::Identity());
  estimates_.assign(elements_.size(), Eigen::Quaterniond::Identity());
  colors_ = colourElements(rest);
}

Eigen::Matrix3d CorotatedFem::deformationGradient(const Element& el, const Eigen::VectorXd& x) {
  const Eigen::Vector3d x0 = x.segment<3>(3 * el.nodes[0]);
  Eigen::Matrix3d Ds;
  for (int k = 0; k < 3; ++k) Ds.col(k) = x.segment<3>(3 * el.nodes[k + 1]) - x0;
  return Ds * el.restInverse;
}

Eigen::Matrix3d CorotatedFem::elementRotation(const Element& el, const Eigen::VectorXd& x) {
  return rotation(deformationGradient(el, x));
}

Eigen::Matrix<double, 12, 12> CorotatedFem::elementStiffness(Index e) const {
  Eigen::Matrix<double, 12, 12> K;
  const Element& el = elements_[static_cast<std::size_t>(e)];
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) K.block<3, 3>(3 * i, 3 * j) = el.stiffness[i * 4 + j];
  return K;
}

void CorotatedFem::update(const Eigen::VectorXd& x, Eigen::VectorXd& force,
                          SparseMatrix& stiffness) {
  if (x.size() != dofCount()) throw Error("state size does not match the mesh");
  if (force.size() != dofCount()) force.resize(dofCount());
  force.setZero();
  if (stiffness.nonZeros() != pattern_.nonZeros()) stiffness = pattern_;
  double* values = stiffness.valuePtr();
  std::fill(values, values + stiffness.nonZeros(), 0.0);
  for (const std::vector<int>& colour : colors_) {
    tbb::parallel_for(
        tbb::blocked_range<std::size_t>(0, colour.size(), 64), [&](const auto& range) {
          for (std::size_t c = range.begin(); c != range.end(); ++c) {
            const int e = colour[c];
            const Element& el = elements_[static_cast<std::size_t>(e)];
            const Eigen::Matrix3d R =
                rotation(deformationGradient(el, x), estimates_[static_cast<std::size_t>(e)]);
            rotations_[static_cast<std::size_t>(e)] = R;
            // z = R^T x - X per node: the displacement in the element's rotated
            // frame.
            std::array<Eigen::Vector3d, 4> z;
            for (int k = 0; k < 4; ++k)
              z[k] = R.transpose() * x.segment<3>(3 * el.nodes[k]) -
                     restPositions_.segment<3>(3 * el.nodes[k]);
            for (int i = 0; i < 4; ++i) {
              Eigen::Vector3d fi = Eigen::Vector3d::Zero();
              for (int j = 0; j < 4; ++j) fi += el.stiffness[i * 4 + j] * z[j];
              force.segment<3>(3 * el.nodes[i]) -= R * fi;
              // K_e is symmetric: block (j, i) is block (i, j) transposed.
              for (int j = i; j < 4; ++j) {
                const Eigen::Matrix3d rotated = R * el.stiffness[i * 4 + j] * R.transpose();
                for (int a = 0; a < 3; ++a) {
                  double* slot = values + el.slots[(i * 4 + j) * 3 + a];
                  for (int b = 0; b < 3; ++b) slot[b] += rotated(a, b);
                }
                if (j == i) continue;
                for (int a = 0; a < 3; ++a) {
                  double* slot = values + el.slots[(j * 4 + i) * 3 + a];
                  for (int b = 0; b < 3; ++b) slot[b] += rotated(b, a);
                }
              }
            }
          }
        });
  }
}

double CorotatedFem::elasticEnergy(const Eigen::VectorXd& x) const {
  double energy = 0;
  for (std::size_t e = 0; e < elements_.size(); ++e) {
    const Element& el = elements_[e];
    const Eigen::Matrix3d R = elementRotation(el, x);
    std::array<Eigen::Vector3d, 4> z;
    for (int k = 0; k < 4; ++k)
      z[k] = R.transpose() * x.segment<3>(3 * el.nodes[k]) -
             restPositions_.segment<3>(3 * el.nodes[k]);
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) energy += 0.5 * z[i].dot(el.stiffness[i * 4 + j] * z[j]);
  }
  return energy;
}

Eigen::VectorXd CorotatedFem::vonMisesStress(const Eigen::VectorXd& x) const {
  Eigen::VectorXd stress(elementCount());
  const double lambda = material_.lameLambda(), mu = material_.lameMu();
  for (std::size_t e = 0; e < elements_.size(); ++e) {
    const Element& el = elements_[e];
    const Eigen::Matrix3d R = elementRotation(el, x);
    Eigen::Matrix3d gradient = Eigen::Matrix3d::Zero();  // grad of z (rotated-frame displacement)
    for (int k = 0; k < 4; ++k)
      gradient += (R.transpose() * x.segment<3>(3 * el.nodes[k]) -
                   restPositions_.segment<3>(3 * el.nodes[k])) *
                  el.gradients[k].transpose();
    const Eigen::Matrix3d strain = 0.5 * (gradient + gradient.transpose());
    const Eigen::Matrix3d sigma =
        lambda * strain.trace() * Eigen::Matrix3d::Identity() + 2 * mu * strain;
    const Eigen::Matrix3d deviator = sigma - sigma.trace() / 3.0 * Eigen::Matrix3d::Identity();
    stress[static_cast<Index>(e)] = std::sqrt(1.5 * deviator.cwiseProduct(deviator).sum());
  }
  return stress;
}

}  // namespace tetskin
