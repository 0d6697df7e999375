// SPDX-License-Identifier: AGPL-3.0-or-later
#include "BodyContact.h"

#include <algorithm>
#include <cmath>

#include "tetskin/core/Parallel.h"
#include "tetskin/spatial/TriangleDistance.h"

namespace tetskin {
namespace {

Aabb triangleBox(const Points3& positions, const Triangles& triangles, Index t) {
  Aabb box;
  for (int k = 0; k < 3; ++k) box.extend(positions.row(triangles(t, k)).transpose().eval());
  return box;
}

// The boxes of `chosen` triangles, in that order.
std::vector<Aabb> triangleBoxes(const Points3& positions, const Triangles& triangles,
                                const std::vector<int>& chosen) {
  std::vector<Aabb> boxes(chosen.size());
  for (std::size_t i = 0; i < chosen.size(); ++i)
    boxes[i] = triangleBox(positions, triangles, chosen[i]);
  return boxes;
}

// Per body (numbers from 0 to the largest in `vertexBody`): whether its
// skin meets itself, as `settings` say.
std::vector<char> selfContactOfBodies(const std::vector<int>& vertexBody,
                                      const SkinCollisions& settings) {
  const int largest =
      vertexBody.empty() ? 0 : *std::max_element(vertexBody.begin(), vertexBody.end());
  std::vector<char> self(static_cast<std::size_t>(largest) + 1, settings.self ? 1 : 0);
  for (int body : settings.selfBodies)
    if (body >= 0 && body <= largest) self[static_cast<std::size_t>(body)] = 1;
  return self;
}

}  // namespace

double BodyContact::automaticStiffness(const Eigen::VectorXd& mass, const SurfaceBinding& binding,
                                       double timeStep) {
  std::vector<char> bound(static_cast<std::size_t>(mass.size() / 3), 0);
  double boundMass = 0;
  for (Index v = 0; v < binding.vertexCount(); ++v)
    for (int j = 0; j < binding.controlsPerVertex(); ++j) {
      const auto node = static_cast<std::size_t>(binding.controlIds(v, j));
      if (bound[node]) continue;
      bound[node] = 1;
      boundMass += mass[3 * static_cast<Index>(node)];
    }
  return kInertiaFactor * boundMass /
         (timeStep * timeStep * static_cast<double>(std::max<Index>(1, binding.vertexCount())));
}

double BodyContact::Contact::along(const Eigen::VectorXd& values) const {
  double sum = 0;
  for (int j = 0; j < count; ++j) {
    const CouplingSprings::Entry& e = entries[static_cast<std::size_t>(j)];
    sum += e.weight * normal.dot(values.segment<3>(3 * e.node));
  }
  return sum;
}

BodyContact::BodyContact(std::unique_ptr<SurfaceDeformer> deformer, const SurfaceMesh& restSkin,
                         const SurfaceBinding& binding, std::vector<int> vertexBody,
                         const Eigen::VectorXd& mass, const NodeConstraints& constraints,
                         const SkinCollisions& settings, double thickness, double stiffness)
    : skin_(std::move(deformer)),
      triangles_(restSkin.triangles),
      restSkin_(restSkin.positions),
      controls_(binding.controlIds),
      weights_(binding.weights),
      controlsPerVertex_(binding.controlsPerVertex()),
      body_(std::move(vertexBody)),
      mass_(mass),
      constraints_(constraints),
      selfContact_(selfContactOfBodies(body_, settings)),
      thickness_(thickness),
      stiffness_(stiffness),
      staticFriction_(settings.staticFriction),
      kineticFriction_(settings.kineticFriction) {
  bodyTriangles_.resize(selfContact_.size());
  for (Index t = 0; t < triangles_.rows(); ++t)
    bodyTriangles_[static_cast<std::size_t>(body_[static_cast<std::size_t>(triangles_(t, 0))])]
        .push_back(static_cast<int>(t));
  for (const std::vector<int>& chosen : bodyTriangles_)
    trees_.emplace_back(triangleBoxes(restSkin_, triangles_, chosen));
}

void BodyContact::findContacts(const Eigen::VectorXd& x, std::vector<Contact>& out,
                               std::vector<AabbTree>& trees) const {
  out.clear();
  const Eigen::Map<const Points3> control(x.data(), x.size() / 3, 3);
  Points3 skin;
  skin_->deformPositions(control, skin);
  parallelFor<std::size_t>(0, trees.size(), 1, [&](const IndexRange<std::size_t>& range) {
    for (std::size_t b = range.begin(); b != range.end(); ++b)
      trees[b].refit(triangleBoxes(skin, triangles_, bodyTriangles_[b]));
  });
  // Per vertex its closest triangle within the thickness, in parallel,
  // each in its own slot: the contacts come out in vertex order on any
  // number of threads.
  struct Hit {
    int triangle = -1;
    ClosestPointOnTriangle closest;
  };
  std::vector<Hit> hits(static_cast<std::size_t>(skin.rows()));
  const double reach2 = thickness_ * thickness_;
  const double neighbourhood2 = kNeighbourhood * kNeighbourhood * reach2;
  // Each body's skin's box, grown by the thickness: a vertex of a body that
  // does not meet itself and lies in no other body's box has nothing to
  // meet (bodies apart cost a box test per vertex, not a tree search).
  std::vector<Aabb> bodyBoxes(selfContact_.size());
  for (Index v = 0; v < skin.rows(); ++v)
    bodyBoxes[static_cast<std::size_t>(body_[static_cast<std::size_t>(v)])].extend(
        skin.row(v).transpose().eval());
  for (Aabb& box : bodyBoxes) box = box.inflated(thickness_);
  parallelFor<Index>(0, skin.rows(), 256, [&](const IndexRange<Index>& range) {
    for (Index v = range.begin(); v != range.end(); ++v) {
      const Eigen::Vector3d p = skin.row(v).transpose();
      const int body = body_[static_cast<std::size_t>(v)];
      const Aabb query{p.array() - thickness_, p.array() + thickness_};
      Hit& hit = hits[static_cast<std::size_t>(v)];
      double best = reach2;
      for (std::size_t other = 0; other < trees.size(); ++other) {
        const bool sameBody = static_cast<int>(other) == body;
        if (sameBody ? !selfContact_[other] : !bodyBoxes[other].contains(p)) continue;
        const std::vector<int>& chosen = bodyTriangles_[other];
        trees[other].forEachOverlap(query, [&](int i) {
          const int t = chosen[static_cast<std::size_t>(i)];
          const int a = triangles_(t, 0), b = triangles_(t, 1), c = triangles_(t, 2);
          if (a == v || b == v || c == v) return;
          const ClosestPointOnTriangle closest = closestPointOnTriangle(
              p, skin.row(a).transpose(), skin.row(b).transpose(), skin.row(c).transpose());
          if (closest.squaredDistance >= best) return;
          if (sameBody &&
              closestPointOnTriangle(restSkin_.row(v).transpose(), restSkin_.row(a).transpose(),
                                     restSkin_.row(b).transpose(), restSkin_.row(c).transpose())
                      .squaredDistance < neighbourhood2)
            return;  // its own neighbourhood
          best = closest.squaredDistance;
          hit.triangle = t;
          hit.closest = closest;
        });
      }
    }
  });
  for (Index v = 0; v < skin.rows(); ++v) {
    const Hit& hit = hits[static_cast<std::size_t>(v)];
    if (hit.triangle < 0) continue;
    const double d = std::sqrt(hit.closest.squaredDistance);
    Contact c;
    c.vertex = static_cast<int>(v);
    c.triangle = hit.triangle;
    const Eigen::Vector3d a = skin.row(triangles_(hit.triangle, 0)).transpose();
    const Eigen::Vector3d b = skin.row(triangles_(hit.triangle, 1)).transpose();
    const Eigen::Vector3d e = skin.row(triangles_(hit.triangle, 2)).transpose();
    const Eigen::Vector3d face = (b - a).cross(e - a).normalized();  // outward
    const Eigen::Vector3d away = skin.row(v).transpose() - hit.closest.point;
    // Outside the triangle's skin the vertex is pushed away from it, inside
    // (it went through) back out: the distance is signed by the face's
    // side, so that a vertex that has passed a triangle is not pushed on.
    // Behind means clearly behind, within 60 degrees of the face's inward
    // normal: beside an edge or a corner, p - q lies in the face's plane,
    // and its sign there is rounding's. (A vertex on the triangle itself
    // is pushed along the face's normal.)
    const double side = away.dot(face) < -0.5 * d ? -1.0 : 1.0;
    c.normal = d > 1e-12 * thickness_ ? Eigen::Vector3d(side * away / d) : face;
    c.gap = thickness_ - side * d;
    if (!c.normal.allFinite()) continue;  // a degenerate triangle touched at a point
    // The nodes of p - q with their weights, each node once.
    const auto addNode = [&](Index node, double weight) {
      for (int j = 0; j < c.count; ++j)
        if (c.entries[static_cast<std::size_t>(j)].node == node) {
          c.entries[static_cast<std::size_t>(j)].weight += weight;
          return;
        }
      c.entries[static_cast<std::size_t>(c.count++)] = {node, weight};
    };
    for (int j = 0; j < controlsPerVertex_; ++j) addNode(controls_(v, j), weights_(v, j));
    for (int k = 0; k < 3; ++k) {
      const int corner = triangles_(hit.triangle, k);
      for (int j = 0; j < controlsPerVertex_; ++j)
        addNode(controls_(corner, j), -hit.closest.barycentric[k] * weights_(corner, j));
    }
    c.start = c.along(x);
    out.push_back(c);
  }
}

int BodyContact::addForce(const StepState& at, StepSystem& system) {
  h_ = at.h;
  // (After releasePulling, the same step again with the contacts kept.)
  if (!keepContacts_) findContacts(at.x, contacts_, trees_);
  keepContacts_ = false;
  const double h = at.h, k = stiffness_;
  for (const Contact& c : contacts_) {
    const double spring = k * (c.gap - h * c.along(at.v));
    for (int j = 0; j < c.count; ++j) {
      const CouplingSprings::Entry& e = c.entries[static_cast<std::size_t>(j)];
      const Eigen::Vector3d g = e.weight * c.normal;
      system.force.segment<3>(3 * e.node) += spring * g;
      for (int a = 0; a < 3; ++a) system.addSpring(3 * e.node + a, h * h * k * g[a] * g[a]);
    }
  }
  return static_cast<int>(contacts_.size());
}

int BodyContact::releasePulling(const Eigen::VectorXd& v, const Eigen::VectorXd& dv,
                                StepSystem& system) {
  const Eigen::VectorXd end = v + dv;
  std::vector<char> kept(contacts_.size(), 1);
  int released = 0;
  bool held = false;
  for (std::size_t k = 0; k < contacts_.size(); ++k) {
    const Contact& c = contacts_[k];
    if (c.gap - h_ * c.along(end) >= 0) continue;
    kept[k] = 0;
    ++released;
    for (int j = 0; j < c.count; ++j)
      held = held || constraints_.isFixed(c.entries[static_cast<std::size_t>(j)].node);
  }
  if (released == 0) return 0;
  if (!held) {
    // Its force (b = h f) and its blocks out, as addForce and addMatrix
    // put them in (the nodes free: their rows are as assembled). (The
    // step's `diagonal` was spent on A when it was assembled.)
    const double h = h_, k = stiffness_, h2k = h * h * k;
    Eigen::VectorXd& b = *system.b;
    for (std::size_t i = 0; i < contacts_.size(); ++i) {
      if (kept[i]) continue;
      const Contact& c = contacts_[i];
      const double spring = k * (c.gap - h * c.along(v));
      for (int j = 0; j < c.count; ++j) {
        const CouplingSprings::Entry& e = c.entries[static_cast<std::size_t>(j)];
        const Eigen::Vector3d g = e.weight * c.normal;
        b.segment<3>(3 * e.node) -= h * spring * g;
        for (int a = 0; a < 3; ++a) {
          const Index row = 3 * e.node + a;
          system.springs[row] -= h2k * g[a] * g[a];
          for (int col = 0; col < 3; ++col)
            system.A->coeffRef(row, 3 * e.node + col) -= h2k * g[a] * g[col];
        }
      }
    }
    std::vector<char> springs(system.coupling.size(), 1);
    std::copy(kept.begin(), kept.end(),
              springs.begin() + static_cast<std::ptrdiff_t>(firstSpring_));
    system.coupling.keep(springs);
  }
  std::size_t at = 0;
  std::erase_if(contacts_, [&](const Contact&) { return !kept[at++]; });
  keepContacts_ = held;
  return held ? -released : released;
}

void BodyContact::addMatrix(const StepState& at, StepSystem& system) {
  // Each node's own block (its diagonal went with the springs) to A, the
  // blocks between nodes to the coupling springs.
  const double h2k = at.h * at.h * stiffness_;
  firstSpring_ = system.coupling.size();
  for (const Contact& c : contacts_) {
    for (int j = 0; j < c.count; ++j) {
      const CouplingSprings::Entry& e = c.entries[static_cast<std::size_t>(j)];
      const Eigen::Vector3d g = e.weight * c.normal;
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b)
          if (a != b) system.A->coeffRef(3 * e.node + a, 3 * e.node + b) += h2k * g[a] * g[b];
    }
    system.coupling.add(h2k, c.normal,
                        std::span(c.entries.data(), static_cast<std::size_t>(c.count)));
  }
}

void BodyContact::project(Eigen::VectorXd& x, Eigen::VectorXd& v) const {
  // (Velocities only: moving the nodes too, as the obstacles' friction
  // does, took them off the solved state; with skins off their cages the
  // stiff springs between the bodies took that up as energy, and a bunny
  // dropped onto another went into it and through the floor.)
  frictionForces_.clear();
  for (const Contact& c : contacts_) {
    // The spring at the step's end, as the step linearized it.
    const double normalForce = stiffness_ * std::max(0.0, c.gap - (c.along(x) - c.start));
    if (normalForce == 0) continue;
    Eigen::Vector3d relative = Eigen::Vector3d::Zero();
    double inverseMass = 0;
    for (int j = 0; j < c.count; ++j) {
      const CouplingSprings::Entry& e = c.entries[static_cast<std::size_t>(j)];
      relative += e.weight * v.segment<3>(3 * e.node);
      if (!constraints_.isFixed(e.node)) inverseMass += e.weight * e.weight / mass_[3 * e.node];
    }
    const Eigen::Vector3d tangential = relative - c.normal.dot(relative) * c.normal;
    const double speed = tangential.norm();
    if (speed == 0 || inverseMass == 0) continue;
    const double allowance = h_ * normalForce;  // mu times this: the impulse at most
    const double stopping = speed / inverseMass;
    const double impulse = stopping <= staticFriction_ * allowance
                               ? stopping
                               : std::min(stopping, kineticFriction_ * allowance);
    const Eigen::Vector3d direction = -tangential / speed;
    for (int j = 0; j < c.count; ++j) {
      const CouplingSprings::Entry& e = c.entries[static_cast<std::size_t>(j)];
      if (constraints_.isFixed(e.node)) continue;  // (held: as of infinite mass)
      const Eigen::Vector3d dv = e.weight * impulse / mass_[3 * e.node] * direction;
      v.segment<3>(3 * e.node) += dv;
      frictionForces_.push_back({e.node, mass_[3 * e.node] * dv / h_});
    }
  }
}

void BodyContact::addForceAt(const Eigen::VectorXd& x, const Eigen::VectorXd&,
                             Eigen::VectorXd& force) const {
  std::vector<Contact> contacts;
  std::vector<AabbTree> trees = trees_;
  findContacts(x, contacts, trees);
  for (const Contact& c : contacts)
    for (int j = 0; j < c.count; ++j) {
      const CouplingSprings::Entry& e = c.entries[static_cast<std::size_t>(j)];
      force.segment<3>(3 * e.node) += stiffness_ * c.gap * e.weight * c.normal;
    }
  for (const auto& [node, friction] : frictionForces_) force.segment<3>(3 * node) += friction;
}

}  // namespace tetskin
