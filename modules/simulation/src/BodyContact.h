// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Contact of the skins with each other and with themselves, as a force
// model: the bodies of a run meet skin to skin, and a body folded onto
// itself keeps its surfaces apart. Skins are a thin shell of `thickness`:
// a skin vertex p closer than that to a triangle (closest point q,
// distance d) is pushed out by a penalty spring k (thickness - d) along
// n = (p - q) / d, and the triangle's corners by its opposite, shared by
// q's barycentric weights. A vertex that has gone through the triangle
// (behind it by the pseudo-normal of the feature q lies on: skins are
// closed and wound outward) is pushed back: d counts negative and
// n = (q - p) / |d|. Every point acts on its control nodes
// through the binding's weights (the normal's turn with an offset vertex
// left out, as ObstacleContact does). With a_j the weight of node j in
// p - q (the vertex's weights, less the corners' times q's barycentric
// ones; they sum to zero, so no contact pushes the bodies' centre of mass),
// the spring is k u u^T with u = sum_j a_j e_j (x) n: linearized over the
// step it adds h^2 k u u^T to the system, its diagonal blocks to A and the
// rest as coupling springs (CouplingSprings.h: the nodes of two bodies
// share no element, so the pattern has no place for them), and
// u k (thickness - d - h u.v) to the force. A penalty spring pushes, it
// never pulls: the contacts are an active set (as for one-sided
// constraints). After the solve, one whose spring would end the step
// pulling (the pair parting faster than the shell lets go) leaves the
// step, one out of it whose spring would end it pushing comes in, and the
// step is solved again (updateActiveSet). A contact that ended a step
// pulling starts the next one out of it.
//
// Continuous detection: a vertex that closes on a skin faster than the
// shell per step can pass from outside the shell to behind it in one
// step, where no search within the shell finds it. So after the solve,
// each vertex without a contact whose path over the step (start to solved
// end, the skins moving linearly) crosses a triangle from outside becomes
// a contact, as of the step's start (its gap below zero when it started
// farther than the shell), and joins the active set.
//
// Coulomb friction after the solve, per contact in turn: the tangential
// part of the relative velocity sum_j a_j v_j changes by at most
// mu h f_n / m (m the contact's effective mass, 1 / sum_j a_j^2 / m_j;
// f_n its spring at the step's end): all of it within mu_s's allowance
// (sticking), mu_k's share otherwise (sliding). The impulse on node j is
// a_j times one vector, so it too leaves the momentum as it was. It
// changes the velocities only, not the step's positions.
//
// Which pairs: a vertex and a triangle of another body, or of its own body
// when self-contact is on and the two lie farther apart in the rest shape
// than kNeighbourhood thicknesses (the vertex's own neighbourhood never
// touches it). Candidates come from a bounding-box tree per body over its
// skin's triangles, built at rest and refitted each step. A body's tree
// against another's first (AabbTree::forEachLeafNear) picks the vertices
// that may lie within the shell of that body: in a pile most of a body's
// vertices lie in another body's box, but far from its skin (7,700 of
// 96,000 on three piled bunnies). Each of those searches the trees of the
// bodies whose boxes it lies in, its own only with self-contact, nearest
// boxes first (branch and bound), and takes its closest triangle only.

#include <array>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "ForceModel.h"
#include "NodeConstraints.h"
#include "tetskin/core/SurfaceBinding.h"
#include "tetskin/core/SurfaceMesh.h"
#include "tetskin/deformation/SurfaceDeformer.h"
#include "tetskin/deformation/VertexNormals.h"
#include "tetskin/spatial/AabbTree.h"
#include "tetskin/spatial/TriangleDistance.h"

namespace tetskin {

class BodyContact : public ForceModel {
 public:
  // Pairs of one body lying closer than this many thicknesses at rest are
  // a neighbourhood, not a contact.
  static constexpr double kNeighbourhood = 3;

  // `restSkin` bound by `binding` (ids: the model's node numbers) and
  // placed by `deformer`; `vertexBody` its vertices' bodies (a number per
  // vertex); `mass` (lumped, per dof) and `constraints` (whose held nodes
  // friction leaves alone) outlive the model. `stiffness` is k per vertex
  // (N/m); `settings` say whether a body's skin meets itself and the
  // friction.
  BodyContact(std::unique_ptr<SurfaceDeformer> deformer, const SurfaceMesh& restSkin,
              const SurfaceBinding& binding, std::vector<int> vertexBody,
              const Eigen::VectorXd& mass, const NodeConstraints& constraints,
              const SkinCollisions& settings, double thickness, double stiffness);

  int addForce(const StepState& at, StepSystem& system) override;
  void addMatrix(const StepState& at, StepSystem& system) override;
  void project(Eigen::VectorXd& x, Eigen::VectorXd& v) const override;
  void addForceAt(const Eigen::VectorXd& x, const Eigen::VectorXd& v,
                  Eigen::VectorXd& force) const override;
  bool isContact() const override { return true; }
  // After the step's solve (its velocity change dv from v, the step
  // starting at control positions x), the contacts as an active set: with
  // `crossings`, the vertices whose path crosses a skin become contacts
  // out of the step (addCrossings); those in the step whose spring would
  // end it pulling leave it, and those out of it (let go in an earlier
  // round or at the end of the last step, or just found crossing) whose
  // spring would end it pushing come in. Their share goes out of or into
  // the step's `system` as assembled and constrained (b, A's blocks, the
  // springs' diagonal, the coupling springs), for the same step solved
  // again. Where one of them touches a
  // held node (whose rows the constraints rewrote) it leaves the system as
  // it is and says `reassemble`: the step is assembled again, its next
  // addForce taking the contacts as they are.
  struct ActiveSetChange {
    int crossed = 0;  // contacts added where a vertex's path crossed a skin
    int released = 0, taken = 0;
    bool reassemble = false;
    bool any() const { return released + taken > 0; }
  };
  ActiveSetChange updateActiveSet(const Eigen::VectorXd& x, const Eigen::VectorXd& v,
                                  const Eigen::VectorXd& dv, StepSystem& system,
                                  bool crossings = true);
  // The next addForce takes the contacts as they are (the same step
  // assembled again) instead of searching.
  void keepNextStep() { keepContacts_ = true; }
  // Forgets the last step's contacts and friction (a new start).
  void forgetStep() {
    keepContacts_ = false;
    contacts_.clear();
    frictionForces_.clear();
    letGo_.clear();
  }

  // The springs' stiffness by default (N/m per skin vertex): the bound
  // nodes' inertia in a step, m / h^2, shared out over the skin's vertices
  // (their mass over the vertices), kInertiaFactor times. A spring between
  // two bodies couples their nodes off the diagonal, where block Jacobi
  // does not see it. The obstacles' rule, 100 times the stiffest element
  // (six times this on three level-1 bunnies dropped into the bowl), took
  // CG to 241 iterations per step on average there, this 116 (the bowl
  // alone: 55 to 65). A tenth of this took 72, but three finest-level
  // bunnies piled in the bowl then sank into each other in one run (22,714
  // contacts). It stops a vertex's own inertia within the shell when the
  // shell is as thick as the vertex travels in a step (1/2 k t^2 >= 1/2 m
  // v^2 at t = v h), a body's behind it over a patch of many vertices.
  static double automaticStiffness(const Eigen::VectorXd& mass, const SurfaceBinding& binding,
                                   double timeStep);
  double thickness() const { return thickness_; }
  double stiffness() const { return stiffness_; }

 private:
  static constexpr double kInertiaFactor = 1000;  // automaticStiffness'
  static constexpr int kMaxNodes = 16;            // a vertex's four and three corners' four
  struct Contact {
    int vertex, triangle;
    double gap;              // thickness - d at the step's start (< 0: a crossing's, from afar)
    Eigen::Vector3d normal;  // n
    std::array<CouplingSprings::Entry, kMaxNodes> entries;  // (node, a_j), nodes distinct
    int count = 0;
    double start = 0;    // u.x at the step's start
    bool active = true;  // in the step (updateActiveSet)
    int spring = -1;     // its coupling spring while in the step

    double along(const Eigen::VectorXd& values) const;
  };
  // The contacts at x; refits `trees` (the step's; a query at another
  // state refits copies of its own); and the skin at x into `skin` (for
  // the step's crossings), unless null.
  void findContacts(const Eigen::VectorXd& x, std::vector<Contact>& out,
                    std::vector<AabbTree>& trees, Points3* skin) const;
  // The contact of vertex v with `triangle` (its closest point `closest`)
  // on the skin at `skin` (placed by control positions x); none for a
  // degenerate triangle touched at a point.
  std::optional<Contact> contactWith(const Points3& skin, const Eigen::VectorXd& x, Index v,
                                     int triangle, const ClosestPointOnTriangle& closest) const;
  // The pseudo-normal (not unit) of the feature of `triangle` at
  // `barycentric` on the skin at `skin`.
  Eigen::Vector3d pseudoNormal(const Points3& skin, int triangle,
                               const Eigen::Vector3d& barycentric) const;
  // Whether vertex v may meet triangle t (of its own body: sameBody): not
  // one of its own triangles, nor, on its own body, its neighbourhood.
  bool mayMeet(Index v, int t, bool sameBody) const;
  // Per vertex, whether it stands in a leaf of its body's tree in `trees`
  // that lies within `margin` of another body's tree there
  // (AabbTree::forEachLeafNear), for the pairs of bodies (body, other)
  // that `pair` lets through.
  std::vector<char> verticesNearOtherBodies(
      const std::vector<AabbTree>& trees, double margin,
      const std::function<bool(std::size_t, std::size_t)>& pair) const;
  // Each body's box on the skin at `skin`, grown by the thickness.
  std::vector<Aabb> bodyBoxes(const Points3& skin) const;
  // Contacts, out of the step, for the vertices without one whose path
  // from the step's start to control positions `end` crosses a skin
  // (continuous detection, as of the start's skin); returns how many.
  int addCrossings(const Eigen::VectorXd& x, const Eigen::VectorXd& end);

  // Its share of the step: force and springs' diagonal as addForce puts
  // them, or (intoSystem) b and A's blocks of the assembled step; sign -1
  // takes it out.
  void addShare(const Contact& c, const Eigen::VectorXd& v, double sign, StepSystem& system,
                bool intoSystem) const;
  // Its coupling spring (numbered in c.spring), and with ownBlocks each
  // node's off-diagonal own block to A.
  void addSpring(Contact& c, double h2k, StepSystem& system, bool ownBlocks);

  std::unique_ptr<SurfaceDeformer> skin_;
  Triangles triangles_;
  Points3 restSkin_;
  Eigen::Matrix<int, Eigen::Dynamic, 4, Eigen::RowMajor> controls_;
  Eigen::Matrix<double, Eigen::Dynamic, 4, Eigen::RowMajor> weights_;
  int controlsPerVertex_;
  std::vector<int> body_;
  const Eigen::VectorXd& mass_;
  const NodeConstraints& constraints_;
  std::vector<char> selfContact_;  // per body: whether its skin meets itself
  bool keepContacts_ = false;      // the next addForce: the same step again
  double thickness_, stiffness_, staticFriction_, kineticFriction_;
  std::vector<std::vector<int>> bodyTriangles_;  // per body: its triangles
  std::vector<AabbTree> trees_;  // per body: over bodyTriangles_, refitted each step
  Triangles neighbours_;         // per triangle, across the edge opposite corner k (-1: none)
  VertexTriangleAdjacency vertexTriangles_;  // per vertex, the triangles around it
  // Per body, per triangle of its tree: the vertices it stands for (-1:
  // none), each vertex once.
  std::vector<std::vector<std::array<int, 3>>> ownedVertices_;
  double h_ = 0;
  std::vector<Contact> contacts_;     // of the step being taken, in it or not
  Points3 stepSkin_;                  // the skin at the step's start
  std::vector<AabbTree> sweptTrees_;  // per body: each triangle's box over the step
  // Per skin vertex: its contact ended the last step pulling (project).
  mutable std::vector<char> letGo_;
  // The last step's friction, m_j dv_j / h, on the nodes it acted on.
  mutable std::vector<std::pair<Index, Eigen::Vector3d>> frictionForces_;
};

}  // namespace tetskin
