// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Contact of the body's nodes with obstacles (Obstacle.h) as a force model:
// implicit penalty springs along the contact normal and Coulomb friction.
//
// A node at depth d >= 0 inside an obstacle (normal n, the obstacle's
// surface moving with velocity v_o there) gets the force k d n, linearized
// with the obstacle's motion over the step: the block h^2 k n n^T on its
// diagonal (the step stays symmetric positive definite, so every solver
// keeps working) and k (d + h n.v_o) n - h k n n^T v in the force. After the
// solve, friction acts on the velocity relative to the obstacle: the normal
// force at the step's end, f_n, allows a tangential velocity change of
// mu h f_n / m; a tangential velocity within mu_s's allowance stops
// (sticking), a larger one loses mu_k's (sliding), and the position follows
// (x = x0 + h v). Nodes farther than the search radius from an obstacle are
// not looked at: the radius bounds the depth a contact can be found at.

#include <vector>

#include "ForceModel.h"
#include "tetskin/simulation/Obstacle.h"

namespace tetskin {

class ObstacleContact : public ForceModel {
 public:
  // `obstacles` checked (obstacleProblem); a stiffness of 0 becomes
  // `automaticStiffness`. `mass` (lumped, per dof) outlives the model;
  // `searchRadius` (model units) > 0.
  ObstacleContact(std::vector<Obstacle> obstacles, const Eigen::VectorXd& mass,
                  double automaticStiffness, double searchRadius);

  int addForce(const StepState& at, StepSystem& system) override;
  void addMatrix(const StepState& at, StepSystem& system) override;
  void project(Eigen::VectorXd& x, Eigen::VectorXd& v) const override;
  void addForceAt(const Eigen::VectorXd& x, const Eigen::VectorXd& v,
                  Eigen::VectorXd& force) const override;
  bool isContact() const override { return true; }

 private:
  struct Contact {
    Index node;
    int obstacle;
    double depth;              // at the step's start
    Eigen::Vector3d normal;    // outward, unit
    Eigen::Vector3d velocity;  // of the obstacle's surface there, over the step
    Eigen::Vector3d start;     // the node's position at the step's start
  };

  std::vector<Obstacle> obstacles_;
  std::vector<double> stiffness_;  // per obstacle
  const Eigen::VectorXd& mass_;
  double radius_;
  double h_ = 0, t_ = 0;           // of the step being taken
  std::vector<Contact> contacts_;  // of the step being taken
};

}  // namespace tetskin
