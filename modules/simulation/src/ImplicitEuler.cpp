// SPDX-License-Identifier: AGPL-3.0-or-later
#include "ImplicitEuler.h"

#include <chrono>

namespace tetskin {

ImplicitEuler::ImplicitEuler(const SimulationOptions& options, const CorotatedFem& fem)
    : h_(options.timeStep),
      material_(options.material),
      gravity_(options.gravity),
      tangent_(options.tangent),
      mass_(fem.lumpedMass()),
      dampedMass_((1 + options.timeStep * options.material.massDamping) * fem.lumpedMass()) {}

double ImplicitEuler::assemble(CorotatedFem& fem, const Eigen::VectorXd& x,
                               const Eigen::VectorXd& v, const Eigen::VectorXd& external,
                               const Eigen::VectorXd* contactDiagonal,
                               const Eigen::VectorXd* contactForce, SparseMatrix& A,
                               Eigen::VectorXd& b) {
  const double h = h_;
  const Eigen::VectorXd* diagonal = &dampedMass_;
  if (contactDiagonal) {
    diagonal_ = dampedMass_ + *contactDiagonal;
    diagonal = &diagonal_;
  }
  // A = (1 + h alpha) M + (h beta + h^2) K + h^2 K_rot (+ contact) and
  // f_el - (beta + h) K v - h K_rot v, in one element pass (K_rot only with
  // the full tangent, its compressive modes dropped from the matrix only:
  // CorotatedFem::SystemTerms; damping stays beta K, which leaves a stressed
  // body's rigid rotation undamped); then b = h (f_el - (beta + h) K v - h K_rot v
  // + M g + f_ext - alpha M v + f_contact).
  const auto start = std::chrono::steady_clock::now();
  CorotatedFem::SystemTerms terms;
  terms.stiffnessScale = h * material_.stiffnessDamping + h * h;
  terms.diagonal = diagonal;
  terms.velocity = &v;
  terms.velocityWeight = material_.stiffnessDamping + h;
  if (tangent_ == Tangent::Full) {
    terms.rotationScale = h * h;
    terms.rotationVelocityWeight = h;
  }
  fem.update(x, force_, A, terms);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  b.resize(force_.size());
  for (Index node = 0; node < force_.size() / 3; ++node)
    b.segment<3>(3 * node) = h * (force_.segment<3>(3 * node) + external.segment<3>(3 * node) +
                                  mass_.segment<3>(3 * node).cwiseProduct(
                                      gravity_ - material_.massDamping * v.segment<3>(3 * node)));
  if (contactForce) b += h * *contactForce;
  return seconds;
}

CoarseDiscretization ImplicitEuler::coarseDiscretization() const {
  CoarseDiscretization coarse;
  coarse.massScale = 1 + h_ * material_.massDamping;
  coarse.terms.stiffnessScale = h_ * material_.stiffnessDamping + h_ * h_;
  if (tangent_ == Tangent::Full) coarse.terms.rotationScale = h_ * h_;
  return coarse;
}

void ImplicitEuler::advance(const Eigen::VectorXd& x, const Eigen::VectorXd& v,
                            const Eigen::VectorXd& dv, Eigen::VectorXd& newX,
                            Eigen::VectorXd& newV) const {
  newV = v + dv;
  newX = x + h_ * newV;
}

}  // namespace tetskin
