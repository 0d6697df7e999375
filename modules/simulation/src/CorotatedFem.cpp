// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/simulation/CorotatedFem.h"

#include <tbb/parallel_for.h>

#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "tetskin/core/Error.h"

namespace tetskin {
namespace {

// Elements are stored in Morton order of their centroids and processed in
// chunks of this many consecutive (so spatially close) elements: a chunk's
// blocks land in few rows of the matrix, which stay in cache while it runs.
constexpr std::size_t kChunk = 64;

// Morton order of the element centroids (10 bits per axis).
std::vector<int> mortonOrder(const TetMesh& mesh) {
  const Eigen::RowVector3d low = mesh.nodes.colwise().minCoeff();
  const Eigen::RowVector3d extent =
      (mesh.nodes.colwise().maxCoeff() - low).cwiseMax(Eigen::RowVector3d::Constant(1e-300));
  auto spread = [](std::uint64_t v) {  // bit k of v to bit 3k
    std::uint64_t r = 0;
    for (int k = 0; k < 10; ++k) r |= ((v >> k) & 1u) << (3 * k);
    return r;
  };
  std::vector<std::pair<std::uint64_t, int>> keys(static_cast<std::size_t>(mesh.elementCount()));
  for (Index e = 0; e < mesh.elementCount(); ++e) {
    Eigen::RowVector3d centroid = Eigen::RowVector3d::Zero();
    for (int k = 0; k < 4; ++k) centroid += 0.25 * mesh.nodes.row(mesh.elements(e, k));
    std::uint64_t key = 0;
    for (int a = 0; a < 3; ++a) {
      const double t = std::clamp((centroid[a] - low[a]) / extent[a], 0.0, 1.0);
      key |= spread(static_cast<std::uint64_t>(t * 1023.0)) << a;
    }
    keys[static_cast<std::size_t>(e)] = {key, static_cast<int>(e)};
  }
  std::sort(keys.begin(), keys.end());
  std::vector<int> order;
  order.reserve(keys.size());
  for (const auto& key : keys) order.push_back(key.second);
  return order;
}

// Greedy colouring of the chunks: a chunk takes the first colour none of its
// nodes uses yet, so the chunks of a colour share no node and are assembled
// in parallel without locks or atomics. Returns the chunks' first elements.
template <typename Elements>
std::vector<std::vector<int>> colourChunks(const Elements& elements, Index nodeCount) {
  std::vector<std::vector<int>> colours;
  std::vector<std::vector<char>> nodeUses;  // per colour: node already taken
  for (std::size_t first = 0; first < elements.size(); first += kChunk) {
    const std::size_t last = std::min(elements.size(), first + kChunk);
    std::size_t c = 0;
    for (;; ++c) {
      if (c == colours.size()) {
        colours.emplace_back();
        nodeUses.emplace_back(static_cast<std::size_t>(nodeCount), 0);
      }
      bool free = true;
      for (std::size_t e = first; free && e < last; ++e)
        for (int k = 0; k < 4; ++k)
          free = free && !nodeUses[c][static_cast<std::size_t>(elements[e].nodes[k])];
      if (free) break;
    }
    colours[c].push_back(static_cast<int>(first));
    for (std::size_t e = first; e < last; ++e)
      for (int k = 0; k < 4; ++k) nodeUses[c][static_cast<std::size_t>(elements[e].nodes[k])] = 1;
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
    // H is symmetric: its inverse from cofactors; positive definite when
    // the leading minors are (Sylvester).
    const double c00 = hessian(1, 1) * hessian(2, 2) - hessian(1, 2) * hessian(1, 2);
    const double c01 = hessian(0, 2) * hessian(1, 2) - hessian(0, 1) * hessian(2, 2);
    const double c02 = hessian(0, 1) * hessian(1, 2) - hessian(0, 2) * hessian(1, 1);
    const double c11 = hessian(0, 0) * hessian(2, 2) - hessian(0, 2) * hessian(0, 2);
    const double c12 = hessian(0, 1) * hessian(0, 2) - hessian(0, 0) * hessian(1, 2);
    const double c22 = hessian(0, 0) * hessian(1, 1) - hessian(0, 1) * hessian(0, 1);
    const double det = hessian(0, 0) * c00 + hessian(0, 1) * c01 + hessian(0, 2) * c02;
    const bool newton =
        hessian(0, 0) > 0 && c22 > 0 && det > 0 && hessian.diagonal().minCoeff() > 1e-3;
    Eigen::Vector3d step =
        newton ? Eigen::Vector3d(
                     Eigen::Vector3d(c00 * gradient.x() + c01 * gradient.y() + c02 * gradient.z(),
                                     c01 * gradient.x() + c11 * gradient.y() + c12 * gradient.z(),
                                     c02 * gradient.x() + c12 * gradient.y() + c22 * gradient.z()) /
                     det)
               : Eigen::Vector3d(gradient / (std::abs(symmetric.trace()) + 1e-9));
    const double angle = step.norm();
    if (angle < 1e-14) return R;
    if (angle > 1.0) step /= angle;  // trust region: at most a radian per step
    // Small steps: exp(w/2) to second order, renormalized (the error is of
    // the order of angle^3, below the next Newton step's reach).
    q = q * (angle < 1e-2 ? Eigen::Quaterniond(1, 0.5 * step.x(), 0.5 * step.y(), 0.5 * step.z())
                          : Eigen::Quaterniond(Eigen::AngleAxisd(step.norm(), step.normalized())));
    q.normalize();
    // Newton converges quadratically: after a step this small the error is
    // of the order of angle^2 (1e-12), so no confirming iteration.
    if (newton && angle < 1e-6) return q.toRotationMatrix();
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
  elements_.resize(static_cast<std::size_t>(rest.elementCount()));
  storedAt_.resize(elements_.size());
  std::vector<Eigen::Triplet<double, int>> triplets;
  triplets.reserve(static_cast<std::size_t>(rest.elementCount()) * 144);
  const std::vector<int> order = mortonOrder(rest);
  for (std::size_t stored = 0; stored < order.size(); ++stored) {
    const int e = order[stored];
    storedAt_[static_cast<std::size_t>(e)] = static_cast<int>(stored);
    Element& el = elements_[stored];
    el.id = e;
    for (int k = 0; k < 4; ++k) el.nodes[k] = rest.elements(e, k);
    const Eigen::Vector3d x0 = rest.nodes.row(el.nodes[0]);
    Eigen::Matrix3d Dm;
    for (int k = 0; k < 3; ++k) Dm.col(k) = rest.nodes.row(el.nodes[k + 1]).transpose() - x0;
    const Eigen::Matrix3d restInverse = Dm.inverse();
    el.volume = Dm.determinant() / 6.0;
    // grad N_k = row k-1 of Dm^-1 for k = 1..3; grad N_0 = -(sum of the others).
    el.gradients[0].setZero();
    for (int k = 1; k < 4; ++k) {
      el.gradients[k] = restInverse.row(k - 1).transpose();
      el.gradients[0] -= el.gradients[k];
    }
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j)
        for (int a = 0; a < 3; ++a)
          for (int b = 0; b < 3; ++b)
            triplets.emplace_back(3 * el.nodes[i] + a, 3 * el.nodes[j] + b, 0.0);
    for (int k = 0; k < 4; ++k)
      mass_.segment<3>(3 * el.nodes[k]).array() += material.density * el.volume / 4.0;
  }
  pattern_.resize(3 * n, 3 * n);
  pattern_.setFromTriplets(triplets.begin(), triplets.end());
  pattern_.makeCompressed();
  // Where entry (3 n_i, 3 n_j) lives in the value array: the 3 entries of
  // that block row follow it (columns of one node are adjacent in a sorted
  // row), and the node's next row starts one row length further.
  const int* outer = pattern_.outerIndexPtr();
  const int* inner = pattern_.innerIndexPtr();
  for (Element& el : elements_)
    for (int i = 0; i < 4; ++i) {
      const int row = 3 * el.nodes[i];
      el.rowLengths[i] = outer[row + 1] - outer[row];
      for (int j = 0; j < 4; ++j) {
        const int* begin = inner + outer[row];
        const int* end = inner + outer[row + 1];
        el.slots[i * 4 + j] =
            static_cast<int>(std::lower_bound(begin, end, 3 * el.nodes[j]) - inner);
      }
    }
  diagonalSlots_.assign(static_cast<std::size_t>(n), -1);  // -1: in no element
  for (const Element& el : elements_)
    for (int k = 0; k < 4; ++k)
      diagonalSlots_[static_cast<std::size_t>(el.nodes[k])] = el.slots[k * 4 + k];
  rotations_.assign(elements_.size(), Eigen::Matrix3d::Identity());
  estimates_.assign(elements_.size(), Eigen::Quaterniond::Identity());
  colors_ = colourChunks(elements_, n);
}

Eigen::Matrix3d CorotatedFem::deformationGradient(const Element& el, const Eigen::VectorXd& x) {
  // F = sum_k x_k g_k^T (the gradients sum to zero, so no origin is needed).
  Eigen::Matrix3d F = Eigen::Matrix3d::Zero();
  for (int k = 0; k < 4; ++k)
    F.noalias() += x.segment<3>(3 * el.nodes[k]) * el.gradients[k].transpose();
  return F;
}

Eigen::Matrix3d CorotatedFem::rotatedFrameStrain(const Eigen::Matrix3d& R,
                                                 const Eigen::Matrix3d& F) {
  // The displacement gradient in the rotated frame, sum_k z_k g_k^T with
  // z_k = R^T x_k - X_k, is R^T F - I because sum_k X_k g_k^T = I.
  const Eigen::Matrix3d G = R.transpose() * F;
  Eigen::Matrix3d strain = 0.5 * (G + G.transpose());
  strain.diagonal().array() -= 1.0;
  return strain;
}

Eigen::Matrix3d CorotatedFem::linearStress(const Eigen::Matrix3d& strain) const {
  Eigen::Matrix3d stress = 2 * material_.lameMu() * strain;
  stress.diagonal().array() += material_.lameLambda() * strain.trace();
  return stress;
}

Eigen::Matrix<double, 12, 12> CorotatedFem::elementStiffness(Index e) const {
  const Element& el = elements_[static_cast<std::size_t>(storedAt_[static_cast<std::size_t>(e)])];
  const double lambda = material_.lameLambda(), mu = material_.lameMu();
  Eigen::Matrix<double, 12, 12> K;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      const Eigen::Vector3d& gi = el.gradients[i];
      const Eigen::Vector3d& gj = el.gradients[j];
      K.block<3, 3>(3 * i, 3 * j) =
          el.volume * (lambda * gi * gj.transpose() + mu * gj * gi.transpose() +
                       mu * gi.dot(gj) * Eigen::Matrix3d::Identity());
    }
  return K;
}

void CorotatedFem::update(const Eigen::VectorXd& x, Eigen::VectorXd& force, SparseMatrix& matrix,
                          const SystemTerms& terms) {
  if (x.size() != dofCount()) throw Error("state size does not match the mesh");
  if ((terms.diagonal && terms.diagonal->size() != dofCount()) ||
      (terms.velocity && terms.velocity->size() != dofCount()))
    throw Error("system terms do not match the mesh");
  if (force.size() != dofCount()) force.resize(dofCount());
  if (matrix.nonZeros() != pattern_.nonZeros()) matrix = pattern_;
  double* values = matrix.valuePtr();
  const int* outer = matrix.outerIndexPtr();
  // Clear each node's three rows and force, then put D on the diagonal.
  tbb::parallel_for(tbb::blocked_range<Index>(0, nodeCount(), 512), [&](const auto& nodes) {
    for (Index v = nodes.begin(); v != nodes.end(); ++v) {
      std::fill(values + outer[3 * v], values + outer[3 * v + 3], 0.0);
      force.segment<3>(3 * v).setZero();
      if (!terms.diagonal || diagonalSlots_[static_cast<std::size_t>(v)] < 0) continue;
      const int slot = diagonalSlots_[static_cast<std::size_t>(v)];
      const int length = outer[3 * v + 1] - outer[3 * v];
      for (int a = 0; a < 3; ++a) values[slot + a * length + a] = (*terms.diagonal)[3 * v + a];
    }
  });
  const double lambda = terms.stiffnessScale * material_.lameLambda();
  const double mu = terms.stiffnessScale * material_.lameMu();
  for (const std::vector<int>& colour : colors_) {
    tbb::parallel_for(
        tbb::blocked_range<std::size_t>(0, colour.size(), 1), [&](const auto& chunks) {
          for (std::size_t c = chunks.begin(); c != chunks.end(); ++c) {
            const auto first = static_cast<std::size_t>(colour[c]);
            const std::size_t last = std::min(elements_.size(), first + kChunk);
            for (std::size_t e = first; e < last; ++e) {
              const Element& el = elements_[e];
              const Eigen::Matrix3d F = deformationGradient(el, x);
              const Eigen::Matrix3d R = rotation(F, estimates_[e]);
              rotations_[e] = R;
              // f_i = -V R sigma g_i, sigma the stress of the rotated-frame
              // strain plus w times the rotated-frame velocity gradient's
              // (K_e applied to R^T v_e, by linearity).
              Eigen::Matrix3d strain = rotatedFrameStrain(R, F);
              if (terms.velocity) {
                const Eigen::Matrix3d G = R.transpose() * deformationGradient(el, *terms.velocity);
                strain += (0.5 * terms.velocityWeight) * (G + G.transpose());
              }
              const Eigen::Matrix3d rotatedStress = el.volume * (R * linearStress(strain));
              std::array<Eigen::Vector3d, 4> r;  // rotated gradients
              for (int k = 0; k < 4; ++k) {
                force.segment<3>(3 * el.nodes[k]).noalias() -= rotatedStress * el.gradients[k];
                r[k] = R * el.gradients[k];
              }
              for (int i = 0; i < 4; ++i)
                for (int j = i; j < 4; ++j) {
                  // Block (i, j); block (j, i) is its transpose.
                  const double isotropic = el.volume * mu * el.gradients[i].dot(el.gradients[j]);
                  const Eigen::Vector3d li = (el.volume * lambda) * r[i];
                  const Eigen::Vector3d mj = (el.volume * mu) * r[j];
                  double* upper = values + el.slots[i * 4 + j];
                  double* lower = values + el.slots[j * 4 + i];
                  for (int a = 0; a < 3; ++a)
                    for (int b = 0; b < 3; ++b) {
                      const double entry =
                          li[a] * r[j][b] + mj[a] * r[i][b] + (a == b ? isotropic : 0.0);
                      upper[a * el.rowLengths[i] + b] += entry;
                      if (j != i) lower[b * el.rowLengths[j] + a] += entry;
                    }
                }
            }
          }
        });
  }
}

double CorotatedFem::elasticEnergy(const Eigen::VectorXd& x) const {
  // 1/2 z^T K_e z = V/2 sigma : strain.
  double energy = 0;
  for (const Element& el : elements_) {
    const Eigen::Matrix3d F = deformationGradient(el, x);
    const Eigen::Matrix3d strain = rotatedFrameStrain(rotation(F), F);
    energy += 0.5 * el.volume * linearStress(strain).cwiseProduct(strain).sum();
  }
  return energy;
}

Eigen::VectorXd CorotatedFem::vonMisesStress(const Eigen::VectorXd& x) const {
  Eigen::VectorXd stress(elementCount());
  for (std::size_t e = 0; e < elements_.size(); ++e) {
    const Eigen::Matrix3d F = deformationGradient(elements_[e], x);
    const Eigen::Matrix3d sigma = linearStress(rotatedFrameStrain(rotation(F), F));
    const Eigen::Matrix3d deviator = sigma - sigma.trace() / 3.0 * Eigen::Matrix3d::Identity();
    stress[elements_[e].id] = std::sqrt(1.5 * deviator.squaredNorm());
  }
  return stress;
}

}  // namespace tetskin
