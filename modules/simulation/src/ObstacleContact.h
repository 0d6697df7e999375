// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Contact of the body with obstacles (Obstacle.h), the floor among them, as a force model:
// implicit penalty springs along the contact normal and Coulomb friction,
// at contact points: the control nodes, the bound skin's vertices, or
// both (ContactPoints). A skin vertex p = sum_j w_j x_j (+ its offset)
// acts on its control nodes j through the binding's weights.
//
// A point at depth d >= 0 inside an obstacle (normal n, the obstacle's
// surface moving with velocity v_o there) is a spring k d that acts on its
// nodes along g_j = w_j n; for a skin point, n at node j is the node's
// mean skin contact normal (over all skin contacts at it, by |w_j|), so
// that friction, which stops a node's motion across that normal, moves
// none of its points along their push. (With each point's own normal, a
// bunny at rest in a bowl was held by contact forces 7% above its weight:
// the nodes' friction moved the points along their normals.) (For a skin vertex offset along its
// control face's normal, the depth's exact gradient has a further term, the face normal's turn; it
// is left out on purpose: with it, friction that stops a node's tangential motion moves offset
// points along the normal, and a skin resting on a slab with friction settled on contact forces
// of 1.8 times its weight; without it, on its weight within 1e-4.)
// Linearized with the obstacle's motion over the step it adds the blocks
// h^2 k g_j g_l^T between its nodes j, l (one element's: the pattern holds
// them; the step stays symmetric positive definite, so every solver keeps
// working) and g_j k (d + h n.v_o - h sum_l g_l.v_l) to node j's force.
// After the solve, friction acts per node: each contact's normal force at
// the step's end, f_n, is shared out over its point's nodes by the
// weights, and a node's gathered normal force N_j allows a change of its
// tangential velocity (relative to the surfaces it touches) of
// mu h |N_j| / m_j; a tangential velocity within mu_s's allowance stops
// (sticking), a larger one loses mu_k's (sliding), and the positions
// follow (x = x0 + h v). Gathering per node matters for skin points: each
// one spending its own stopping impulse on shared nodes overshot, and the
// skin chattered in and out of contact. Points farther than the search
// radius from an obstacle are not looked at: the radius bounds the depth
// a contact is found at.

#include <array>
#include <memory>
#include <optional>
#include <vector>

#include "ForceModel.h"
#include "tetskin/deformation/SurfaceDeformer.h"
#include "tetskin/simulation/Obstacle.h"
#include "tetskin/simulation/Simulation.h"

namespace tetskin {

class ObstacleContact : public ForceModel {
 public:
  // `obstacles` checked by the caller (obstacleProblem, in Simulation's
  // option check); a stiffness of 0 becomes
  // `automaticStiffness` (unused when none has 0). `mass` (lumped, per dof) outlives the model;
  // `searchRadius` (model units) > 0. The control nodes are the contact
  // points until setSkin.
  ObstacleContact(std::vector<Obstacle> obstacles, const Eigen::VectorXd& mass,
                  double automaticStiffness, double searchRadius);

  // About a hundred times the stiffest element diagonal of `fem` at its
  // rest positions: penetration stays small without ruining the
  // conditioning of the system.
  static double automaticStiffness(CorotatedFem& fem);

  // The bound skin: `deformer` places it from the nodes' positions (its
  // binding's ids are the model's node numbers). Its vertices become the
  // contact points for `points` skin, or join the nodes for both; for cage
  // the nodes stay the contact points and the skin is only reported on
  // (skinContact).
  void setSkin(std::unique_ptr<SurfaceDeformer> deformer, const SurfaceBinding& binding,
               ContactPoints points);
  bool hasSkin() const { return skin_ != nullptr; }
  // Obstacle k's placement from the next step on (Simulation::
  // setObstaclePlacement has checked it).
  void setPlacement(std::size_t k, const ObstaclePose& placement) {
    obstacles_[k].placement = placement;
    clearance_.clear();  // (measured against the old placement)
  }

  // Per skin vertex at positions x and time t: how deep it lies in the
  // obstacle it is deepest in (positive inside; -radius beyond the search
  // radius of all) and its contact spring's force k d n (zero when the
  // skin is not among the contact points).
  void skinContact(const Eigen::VectorXd& x, double t, Eigen::VectorXd& penetration,
                   Points3& force) const;

  int addForce(const StepState& at, StepSystem& system) override;
  void addMatrix(const StepState& at, StepSystem& system) override;
  void project(Eigen::VectorXd& x, Eigen::VectorXd& v) const override;
  void addForceAt(const Eigen::VectorXd& x, const Eigen::VectorXd& v,
                  Eigen::VectorXd& force) const override;
  bool isContact() const override { return true; }
  // Forgets the last step's contacts and friction (a new start: a static
  // solve's outcome has none).
  void forgetStep() {
    contacts_.clear();
    frictionForces_.clear();
  }

 private:
  // A point moving as sum w_j x_j of up to four nodes; its spring is
  // `share` of the obstacle's stiffness.
  struct Point {
    std::array<Index, 4> nodes{};
    std::array<double, 4> weights{};
    int count = 1;
    double share = 1;
    Eigen::Vector3d combine(const Eigen::VectorXd& values) const {
      Eigen::Vector3d sum = Eigen::Vector3d::Zero();
      for (int j = 0; j < count; ++j) sum += weights[j] * values.segment<3>(3 * nodes[j]);
      return sum;
    }
  };
  struct Contact {
    int point;
    int obstacle;
    double depth;                             // at the step's start
    Eigen::Vector3d normal;                   // outward, unit
    Eigen::Vector3d velocity;                 // of the obstacle's surface there, over the step
    std::array<Eigen::Vector3d, 4> gradient;  // g_j
    double start;                             // sum g_j.x_j at the step's start
    double stiffness;                         // k times the point's share

    double along(const Point& p, const Eigen::VectorXd& values) const {
      double sum = 0;
      for (int j = 0; j < p.count; ++j)
        sum += gradient[static_cast<std::size_t>(j)].dot(
            values.segment<3>(3 * p.nodes[static_cast<std::size_t>(j)]));
      return sum;
    }
  };

  // What one search for contacts works in: the points' positions, the
  // skin's, each point's closest obstacle point, the nodes' mean normals.
  // The step's search has its own (members); a search at another state
  // (addForceAt, which a front end may call while a step runs) a local one.
  struct Search {
    Points3 positions, skinPositions;
    std::vector<std::optional<SurfacePoint>> hits;  // per point, of one obstacle
    std::vector<Eigen::Vector3d> nodeNormals;       // the mean skin contact normal per node
  };
  // A static obstacle's clearance per point: the point lay at least
  // `distance` outside it when it was at `at`. Since the distance to a
  // surface changes no faster than the point moves, a point that has moved
  // less than its clearance since is still outside, and is not looked up
  // again (most of a skin at rest in a bowl). Only the step's search keeps
  // it; it changes which points are looked up, never a contact.
  struct Clearance {
    Eigen::VectorXd distance;  // 0: look up (inside, touching, or not yet measured)
    Points3 at;
  };

  // The contact points' positions at x.
  const Points3& pointPositions(const Eigen::VectorXd& x, Search& search) const;
  // The contacts at x (time t, over a step of h); `clearance` (the step's
  // search) skips points that cannot touch a static obstacle.
  void findContacts(const Eigen::VectorXd& x, double t, double h, std::vector<Contact>& out,
                    Search& search, std::vector<Clearance>* clearance) const;

  std::vector<Obstacle> obstacles_;
  std::vector<double> stiffness_;  // per obstacle
  const Eigen::VectorXd& mass_;
  double radius_;
  std::vector<Point> points_;
  Index firstSkinPoint_;  // points from here on are the skin's vertices
  bool skinCollides_ = false;
  std::unique_ptr<SurfaceDeformer> skin_;
  Search search_;                     // the step's
  std::vector<Clearance> clearance_;  // per obstacle, of the step's search
  double h_ = 0, t_ = 0;              // of the step being taken
  std::vector<Contact> contacts_;     // of the step being taken
  // A node's share of its contacts' normal forces (sum w_j f_n n) and
  // what they weigh by it: the surfaces' velocity and the coefficients.
  struct NodeFriction {
    Eigen::Vector3d normalForce = Eigen::Vector3d::Zero();
    Eigen::Vector3d surfaceVelocity = Eigen::Vector3d::Zero();
    double staticFriction = 0, kineticFriction = 0, total = 0;
  };
  mutable std::vector<NodeFriction> friction_;  // per node, zero between steps
  // The last step's friction, m_j dv_j / h, on the nodes it acted on.
  mutable std::vector<std::pair<Index, Eigen::Vector3d>> frictionForces_;
};

}  // namespace tetskin
