// SPDX-License-Identifier: AGPL-3.0-or-later
#include "ImplicitEuler.h"

namespace tetskin {

ImplicitEuler::ImplicitEuler(double timeStep, const Eigen::VectorXd& mass, bool still)
    : h_(timeStep), mass_(mass), still_(still) {}

int ImplicitEuler::assemble(const ForceModels& models, double t, const Eigen::VectorXd& x,
                            const Eigen::VectorXd& v, const Eigen::VectorXd& external,
                            SparseMatrix& A, Eigen::VectorXd& b) {
  const StepState at{x, v, h_, t, still_};
  system_.diagonal = mass_;
  system_.hasSprings = false;
  system_.force = external;
  system_.coupling.clear();
  system_.A = &A;
  system_.b = &b;
  int contacts = 0;
  for (const auto& model : models) contacts += model->addForce(at, system_);
  for (const auto& model : models) model->addMatrix(at, system_);
  b = h_ * system_.force;
  for (const auto& model : models) model->constrain(at, system_);
  return contacts;
}

CoarseDiscretization ImplicitEuler::coarseDiscretization(const ForceModels& models) const {
  CoarseDiscretization coarse;
  coarse.massScale = 1;
  coarse.terms.stiffnessScale = 0;
  for (const auto& model : models) model->addCoarseTerms(h_, coarse);
  return coarse;
}

void ImplicitEuler::advance(const ForceModels& models, const Eigen::VectorXd& x,
                            const Eigen::VectorXd& v, const Eigen::VectorXd& dv,
                            Eigen::VectorXd& newX, Eigen::VectorXd& newV) const {
  newV = v + dv;
  newX = x + h_ * newV;
  for (const auto& model : models) model->project(newX, newV);
}

}  // namespace tetskin
