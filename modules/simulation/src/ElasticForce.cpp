// SPDX-License-Identifier: AGPL-3.0-or-later
#include "ElasticForce.h"

namespace tetskin {

ElasticForce::ElasticForce(CorotatedFem& fem, double stiffnessDamping, Tangent tangent)
    : fem_(fem), beta_(stiffnessDamping), tangent_(tangent) {}

void ElasticForce::addMatrix(const StepState& at, StepSystem& system) {
  // One element pass (K_rot only with the full tangent, its compressive
  // modes dropped from the matrix only: CorotatedFem::SystemTerms; damping
  // stays beta K, which leaves a stressed body's rigid rotation undamped).
  const double h = at.h;
  CorotatedFem::SystemTerms terms;
  terms.stiffnessScale = h * beta_ + h * h;
  terms.diagonal = &system.diagonal;
  terms.velocity = &at.v;
  terms.velocityWeight = beta_ + h;
  if (tangent_ == Tangent::Full) {
    terms.rotationScale = h * h;
    terms.rotationVelocityWeight = h;
  }
  fem_.update(at.x, force_, *system.A, terms);
  system.force += force_;
}

double stiffestRestDiagonal(CorotatedFem& fem) {
  Eigen::VectorXd force;
  SparseMatrix stiffness = fem.pattern();
  fem.update(fem.restPositions(), force, stiffness);
  return stiffness.diagonal().maxCoeff();
}

void ElasticForce::addForceAt(const Eigen::VectorXd& x, const Eigen::VectorXd& v,
                              Eigen::VectorXd& force) const {
  force += fem_.dampedElasticForce(x, v, beta_);
}

void ElasticForce::addEnergy(const Eigen::VectorXd& x, Energies& energies) const {
  energies.elastic += fem_.elasticEnergy(x);
}

void ElasticForce::addCoarseTerms(double h, CoarseDiscretization& coarse) const {
  coarse.terms.stiffnessScale += h * beta_ + h * h;
  if (tangent_ == Tangent::Full) coarse.terms.rotationScale += h * h;
}

}  // namespace tetskin
