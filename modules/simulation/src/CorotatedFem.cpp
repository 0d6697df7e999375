// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/simulation/CorotatedFem.h"

#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>

#include "CorotatedElementPass.h"
#include "CorotatedLanes.h"
#include "tetskin/core/Error.h"
#include "tetskin/core/Parallel.h"

namespace tetskin {
namespace {

// Elements are stored in Morton order of their centroids and processed in
// chunks of this many consecutive (so spatially close) elements: a chunk's
// blocks land in few rows of the matrix, which stay in cache while it runs.
// A whole number of the vector kernel's groups of four.
constexpr std::size_t kChunk = 64;
static_assert(kChunk % 4 == 0);

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
template <typename NodeOf>
std::vector<std::vector<int>> colourChunks(std::size_t elementCount, NodeOf node, Index nodeCount) {
  std::vector<std::vector<int>> colours;
  std::vector<std::vector<char>> nodeUses;  // per colour: node already taken
  for (std::size_t first = 0; first < elementCount; first += kChunk) {
    const std::size_t last = std::min(elementCount, first + kChunk);
    std::size_t c = 0;
    for (;; ++c) {
      if (c == colours.size()) {
        colours.emplace_back();
        nodeUses.emplace_back(static_cast<std::size_t>(nodeCount), 0);
      }
      bool free = true;
      for (std::size_t e = first; free && e < last; ++e)
        for (int k = 0; k < 4; ++k)
          free = free && !nodeUses[c][static_cast<std::size_t>(node(e, k))];
      if (free) break;
    }
    colours[c].push_back(static_cast<int>(first));
    for (std::size_t e = first; e < last; ++e)
      for (int k = 0; k < 4; ++k) nodeUses[c][static_cast<std::size_t>(node(e, k))] = 1;
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

namespace {

// A row-major 3x3 of the lane arithmetic (CorotatedLanes.h) as Eigen's.
Eigen::Matrix3d fromRowMajor(const double m[9]) {
  return Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(m);
}

}  // namespace

Eigen::Matrix3d CorotatedFem::rotation(const Eigen::Matrix3d& F, Eigen::Quaterniond& q) {
  const double scale = F.norm();
  if (!(scale > 0) || !std::isfinite(scale)) return rotation(F);
  double A[9];  // F / |F|: the tolerances are relative
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) A[3 * i + j] = F(i, j) / scale;
  lanes::Quaternion<double> p{q.w(), q.x(), q.y(), q.z()};
  for (int iteration = 0; iteration < 30; ++iteration) {
    double R[9], step[3];
    const bool newton = lanes::rotationStep(p, A, R, step);
    const double angle = std::sqrt(step[0] * step[0] + step[1] * step[1] + step[2] * step[2]);
    if (angle < lanes::kConverged) {
      q = Eigen::Quaterniond(p.w, p.x, p.y, p.z);
      return fromRowMajor(R);
    }
    if (angle < lanes::kSmallStep) {
      p = lanes::smallRotationStep(p, step);
    } else {
      // The exact exponential, at most a radian per step (trust region).
      const Eigen::Vector3d axis = Eigen::Vector3d(step[0], step[1], step[2]) / angle;
      Eigen::Quaterniond next = Eigen::Quaterniond(p.w, p.x, p.y, p.z) *
                                Eigen::Quaterniond(Eigen::AngleAxisd(std::min(angle, 1.0), axis));
      next.normalize();
      p = {next.w(), next.x(), next.y(), next.z()};
    }
    if (newton && angle < lanes::kFinalStep) {
      q = Eigen::Quaterniond(p.w, p.x, p.y, p.z);
      lanes::rotationMatrix(p, R);
      return fromRowMajor(R);
    }
  }
  // Not converged (a near-degenerate F): the SVD decides.
  const Eigen::Matrix3d R = rotation(F);
  q = Eigen::Quaterniond(R);
  return R;
}

CorotatedFem::CorotatedFem(const TetMesh& rest, const ElasticMaterial& material,
                           std::span<const MaterialRegion> regions)
    : material_(material) {
  validateMaterial(material);
  validateTetMesh(rest, "simulation mesh", /*requirePositiveVolume=*/true);
  const Index n = rest.nodeCount();
  const auto count = static_cast<std::size_t>(rest.elementCount());
  // Each element's material: the mesh's, or the last region's it lies in.
  std::vector<const ElasticMaterial*> materialOf(count, &material);
  for (std::size_t r = 0; r < regions.size(); ++r) {
    const MaterialRegion& region = regions[r];
    if (region.firstElement < 0 || region.elementCount < 0 ||
        region.firstElement + region.elementCount > rest.elementCount())
      throw Error("material region " + std::to_string(r) + " (elements " +
                  std::to_string(region.firstElement) + " to " +
                  std::to_string(region.firstElement + region.elementCount - 1) +
                  ") lies beyond the mesh's " + std::to_string(rest.elementCount()) + " elements");
    validateMaterial(region.material);
    for (Index e = region.firstElement; e < region.firstElement + region.elementCount; ++e)
      materialOf[static_cast<std::size_t>(e)] = &region.material;
  }
  restPositions_.resize(3 * n);
  for (Index v = 0; v < n; ++v) restPositions_.segment<3>(3 * v) = rest.nodes.row(v).transpose();
  mass_.setZero(3 * n);
  groups_.assign((count + 3) / 4, corotated::ElementGroup{});
  scatter_.resize(count);
  storedAt_.resize(count);
  std::vector<Eigen::Triplet<double, int>> triplets;
  triplets.reserve(count * 144);
  const std::vector<int> order = mortonOrder(rest);
  // The last group's spare lanes repeat the last element (computed, never
  // added in).
  for (std::size_t stored = 0; stored < 4 * groups_.size(); ++stored) {
    const int e = order[std::min(stored, count - 1)];
    corotated::ElementGroup& group = groups_[stored / 4];
    const std::size_t lane = stored % 4;
    for (int k = 0; k < 4; ++k) group.nodes[k][lane] = rest.elements(e, k);
    const Eigen::Vector3d x0 = rest.nodes.row(rest.elements(e, 0));
    Eigen::Matrix3d Dm;
    for (int k = 0; k < 3; ++k)
      Dm.col(k) = rest.nodes.row(rest.elements(e, k + 1)).transpose() - x0;
    const Eigen::Matrix3d restInverse = Dm.inverse();
    const double volume = Dm.determinant() / 6.0;
    // grad N_k = row k-1 of Dm^-1 for k = 1..3; grad N_0 = -(sum of the others).
    std::array<Eigen::Vector3d, 4> gradients;
    gradients[0].setZero();
    for (int k = 1; k < 4; ++k) {
      gradients[k] = restInverse.row(k - 1).transpose();
      gradients[0] -= gradients[k];
    }
    for (int k = 0; k < 4; ++k)
      for (int a = 0; a < 3; ++a) group.gradients[k][a][lane] = gradients[k][a];
    group.volume[lane] = volume;
    const ElasticMaterial& own = *materialOf[static_cast<std::size_t>(e)];
    group.lambda[lane] = own.lameLambda();
    group.mu[lane] = own.lameMu();
    for (int i = 0, pair = 0; i < 4; ++i)
      for (int j = i; j < 4; ++j, ++pair)
        group.gradientDots[pair][lane] = volume * gradients[i].dot(gradients[j]);
    if (stored >= count) continue;
    storedAt_[static_cast<std::size_t>(e)] = static_cast<int>(stored);
    scatter_[stored].id = e;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j)
        for (int a = 0; a < 3; ++a)
          for (int b = 0; b < 3; ++b)
            triplets.emplace_back(3 * rest.elements(e, i) + a, 3 * rest.elements(e, j) + b, 0.0);
    for (int k = 0; k < 4; ++k)
      mass_.segment<3>(3 * rest.elements(e, k)).array() += own.density * volume / 4.0;
  }
  pattern_.resize(3 * n, 3 * n);
  pattern_.setFromTriplets(triplets.begin(), triplets.end());
  pattern_.makeCompressed();
  // Where entry (3 n_i, 3 n_j) lives in the value array: the 3 entries of
  // that block row follow it (columns of one node are adjacent in a sorted
  // row), and the node's next row starts one row length further.
  const int* outer = pattern_.outerIndexPtr();
  const int* inner = pattern_.innerIndexPtr();
  for (std::size_t e = 0; e < count; ++e)
    for (int i = 0; i < 4; ++i) {
      const int row = 3 * node(e, i);
      scatter_[e].rowLengths[i] = outer[row + 1] - outer[row];
      for (int j = 0; j < 4; ++j) {
        const int* begin = inner + outer[row];
        const int* end = inner + outer[row + 1];
        scatter_[e].slots[i * 4 + j] =
            static_cast<int>(std::lower_bound(begin, end, 3 * node(e, j)) - inner);
      }
    }
  diagonalSlots_.assign(static_cast<std::size_t>(n), -1);  // -1: in no element
  for (std::size_t e = 0; e < count; ++e)
    for (int k = 0; k < 4; ++k)
      diagonalSlots_[static_cast<std::size_t>(node(e, k))] = scatter_[e].slots[k * 4 + k];
  rotations_.assign(count, Eigen::Matrix3d::Identity());
  corotated::RotationEstimates identity{};
  std::fill(std::begin(identity.w), std::end(identity.w), 1.0);
  estimates_.assign(groups_.size(), identity);
  colors_ = colourChunks(
      count, [&](std::size_t e, int k) { return node(e, k); }, n);
}

Eigen::Vector3d CorotatedFem::gradient(std::size_t e, int k) const {
  const corotated::ElementGroup& group = groups_[e / 4];
  return {group.gradients[k][0][e % 4], group.gradients[k][1][e % 4], group.gradients[k][2][e % 4]};
}

Eigen::Matrix3d CorotatedFem::deformationGradient(std::size_t e, const Eigen::VectorXd& x) const {
  Eigen::Matrix3d F = Eigen::Matrix3d::Zero();
  for (int k = 0; k < 4; ++k)
    F.noalias() += x.segment<3>(3 * node(e, k)) * gradient(e, k).transpose();
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

Eigen::Matrix3d CorotatedFem::linearStress(std::size_t e, const Eigen::Matrix3d& strain) const {
  Eigen::Matrix3d stress = 2 * mu(e) * strain;
  stress.diagonal().array() += lambda(e) * strain.trace();
  return stress;
}

Eigen::Matrix<double, 12, 12> CorotatedFem::elementStiffness(Index e) const {
  const auto stored = static_cast<std::size_t>(storedAt_[static_cast<std::size_t>(e)]);
  const double lambda = this->lambda(stored), mu = this->mu(stored);
  Eigen::Matrix<double, 12, 12> K;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      const Eigen::Vector3d gi = gradient(stored, i);
      const Eigen::Vector3d gj = gradient(stored, j);
      K.block<3, 3>(3 * i, 3 * j) =
          volume(stored) * (lambda * gi * gj.transpose() + mu * gj * gi.transpose() +
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
  parallelFor<Index>(0, nodeCount(), 512, [&](const auto& nodes) {
    for (Index v = nodes.begin(); v != nodes.end(); ++v) {
      std::fill(values + outer[3 * v], values + outer[3 * v + 3], 0.0);
      force.segment<3>(3 * v).setZero();
      if (!terms.diagonal || diagonalSlots_[static_cast<std::size_t>(v)] < 0) continue;
      const int slot = diagonalSlots_[static_cast<std::size_t>(v)];
      const int length = outer[3 * v + 1] - outer[3 * v];
      for (int a = 0; a < 3; ++a) values[slot + a * length + a] = (*terms.diagonal)[3 * v + a];
    }
  });
  corotated::PassArgs args;
  args.groups = groups_.data();
  args.estimates = estimates_.data();
  args.scatter = scatter_.data();
  args.elementCount = scatter_.size();
  args.x = x.data();
  args.velocity = terms.velocity ? terms.velocity->data() : nullptr;
  args.velocityWeight = terms.velocityWeight;
  args.stiffnessScale = terms.stiffnessScale;
  args.rotationScale = terms.rotationScale;
  args.rotationVelocityWeight = terms.rotationVelocityWeight;
  args.force = force.data();
  args.values = values;
  args.rotations = rotations_.data()->data();
  const corotated::GroupsKernel kernel = corotated::groupsKernel(kernel_);
  for (const std::vector<int>& colour : colors_) {
    parallelFor<std::size_t>(0, colour.size(), 1, [&](const auto& chunks) {
      for (std::size_t c = chunks.begin(); c != chunks.end(); ++c) {
        const auto first = static_cast<std::size_t>(colour[c]);
        const std::size_t last = std::min(scatter_.size(), first + kChunk);
        kernel(args, first / 4, (last + 3) / 4);
      }
    });
  }
}

double CorotatedFem::elasticEnergy(const Eigen::VectorXd& x) const {
  // 1/2 z^T K_e z = V/2 sigma : strain. In parallel (a polar decomposition
  // per element: 7.7 ms at 12.7k elements on one core, which simulate
  // --log and the GUI's energy plot pay every sample), summed in a fixed
  // order: the same state gives the same energy, bit for bit.
  return parallelDeterministicReduce<std::size_t>(
      0, scatter_.size(), 1024, 0.0,
      [&](const IndexRange<std::size_t>& elements, double energy) {
        for (std::size_t e = elements.begin(); e < elements.end(); ++e) {
          const Eigen::Matrix3d F = deformationGradient(e, x);
          const Eigen::Matrix3d strain = rotatedFrameStrain(rotation(F), F);
          energy += 0.5 * volume(e) * linearStress(e, strain).cwiseProduct(strain).sum();
        }
        return energy;
      },
      std::plus<>());
}

CorotatedFem::ElementMeasures CorotatedFem::elementMeasures(const Eigen::VectorXd& x) const {
  ElementMeasures m;
  m.vonMisesStress.resize(elementCount());
  m.equivalentStrain.resize(elementCount());
  m.stress.resize(elementCount(), 6);
  const auto deviatorNorm = [](const Eigen::Matrix3d& t) {
    return (t - t.trace() / 3.0 * Eigen::Matrix3d::Identity()).norm();
  };
  parallelFor<std::size_t>(0, scatter_.size(), 1024, [&](const auto& range) {
    for (std::size_t e = range.begin(); e < range.end(); ++e) {
      const Eigen::Matrix3d F = deformationGradient(e, x);
      const Eigen::Matrix3d R = rotation(F);
      const Eigen::Matrix3d strain = rotatedFrameStrain(R, F);
      const Eigen::Matrix3d rotated = linearStress(e, strain);
      const Eigen::Matrix3d world = R * rotated * R.transpose();
      const int id = scatter_[e].id;
      m.stress.row(id) << world(0, 0), world(1, 1), world(2, 2), world(0, 1), world(1, 2),
          world(0, 2);
      m.vonMisesStress[id] = std::sqrt(1.5) * deviatorNorm(rotated);
      m.equivalentStrain[id] = std::sqrt(2.0 / 3.0) * deviatorNorm(strain);
    }
  });
  return m;
}

Eigen::VectorXd CorotatedFem::dampedElasticForce(const Eigen::VectorXd& x, const Eigen::VectorXd& v,
                                                 double beta) const {
  // Per node k of an element, with F = sum_k x_k g_k^T and its rate
  // Fdot = sum_k v_k g_k^T: -V R (sigma(sym(R^T F) - I) + beta sigma(sym(R^T Fdot))) g_k,
  // the gradient of the energy V/2 sigma : strain with R held fixed, and
  // K_e R^T v rotated back. Elements in parallel, scattered in order: the
  // same state gives the same forces, bit for bit.
  std::vector<Eigen::Matrix<double, 3, 4>> perElement(scatter_.size());
  parallelFor<std::size_t>(0, scatter_.size(), 512, [&](const auto& range) {
    for (std::size_t e = range.begin(); e < range.end(); ++e) {
      const Eigen::Matrix3d F = deformationGradient(e, x);
      const Eigen::Matrix3d R = rotation(F);
      Eigen::Matrix3d rate = Eigen::Matrix3d::Zero();
      for (int k = 0; k < 4; ++k)
        rate.noalias() += v.segment<3>(3 * node(e, k)) * gradient(e, k).transpose();
      const Eigen::Matrix3d rotatedRate = R.transpose() * rate;
      const Eigen::Matrix3d stress =
          linearStress(e, rotatedFrameStrain(R, F)) +
          beta * linearStress(e, 0.5 * (rotatedRate + rotatedRate.transpose()));
      const Eigen::Matrix3d P = -volume(e) * R * stress;
      for (int k = 0; k < 4; ++k) perElement[e].col(k) = P * gradient(e, k);
    }
  });
  Eigen::VectorXd force = Eigen::VectorXd::Zero(dofCount());
  for (std::size_t e = 0; e < scatter_.size(); ++e)
    for (int k = 0; k < 4; ++k) force.segment<3>(3 * node(e, k)) += perElement[e].col(k);
  return force;
}

}  // namespace tetskin
