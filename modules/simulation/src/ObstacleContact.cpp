// SPDX-License-Identifier: AGPL-3.0-or-later
#include "ObstacleContact.h"

#include <algorithm>
#include <cmath>
#include <set>

#include "ElasticForce.h"
#include "tetskin/core/Parallel.h"

namespace tetskin {

ObstacleContact::ObstacleContact(std::vector<Obstacle> obstacles, const Eigen::VectorXd& mass,
                                 double automaticStiffness, double searchRadius)
    : obstacles_(std::move(obstacles)), mass_(mass), radius_(searchRadius) {
  for (const Obstacle& o : obstacles_)
    stiffness_.push_back(o.stiffness > 0 ? o.stiffness : automaticStiffness);
  points_.resize(static_cast<std::size_t>(mass.size() / 3));
  for (std::size_t i = 0; i < points_.size(); ++i) {
    points_[i].nodes[0] = static_cast<Index>(i);
    points_[i].weights[0] = 1;
  }
  firstSkinPoint_ = static_cast<Index>(points_.size());
}

double ObstacleContact::automaticStiffness(CorotatedFem& fem) {
  return 100.0 * stiffestRestDiagonal(fem);
}

void ObstacleContact::setSkin(std::unique_ptr<SurfaceDeformer> deformer,
                              const SurfaceBinding& binding, ContactPoints mode) {
  skin_ = std::move(deformer);
  clearance_.clear();  // (of other points)
  skinCollides_ = mode != ContactPoints::Cage;
  if (!skinCollides_) return;
  if (mode == ContactPoints::Skin) points_.clear();
  firstSkinPoint_ = static_cast<Index>(points_.size());
  // Each skin vertex's spring is the share of the obstacle's stiffness that
  // keeps the skin as stiff as the nodes it is bound to would be.
  std::set<Index> bound;
  const int count = binding.controlsPerVertex();
  for (Index v = 0; v < binding.vertexCount(); ++v)
    for (int j = 0; j < count; ++j) bound.insert(binding.controlIds(v, j));
  const double share = static_cast<double>(bound.size()) /
                       static_cast<double>(std::max<Index>(1, binding.vertexCount()));
  for (Index v = 0; v < binding.vertexCount(); ++v) {
    Point p;
    p.count = count;
    p.share = share;
    for (int j = 0; j < count; ++j) {
      p.nodes[static_cast<std::size_t>(j)] = binding.controlIds(v, j);
      p.weights[static_cast<std::size_t>(j)] = binding.weights(v, j);
    }
    points_.push_back(p);
  }
}

const Points3& ObstacleContact::pointPositions(const Eigen::VectorXd& x, Search& search) const {
  const Index nodes = x.size() / 3;
  const Eigen::Map<const Points3> control(x.data(), nodes, 3);
  const Index skinPoints = skinCollides_ ? skin_->vertexCount() : 0;
  search.positions.resize(static_cast<Index>(points_.size()), 3);
  if (firstSkinPoint_ > 0) search.positions.topRows(firstSkinPoint_) = control;
  if (skinPoints > 0) {
    skin_->deformPositions(control, search.skinPositions);
    search.positions.bottomRows(skinPoints) = search.skinPositions;
  }
  return search.positions;
}

void ObstacleContact::findContacts(const Eigen::VectorXd& x, double t, double h,
                                   std::vector<Contact>& out, Search& search,
                                   std::vector<Clearance>* clearance) const {
  out.clear();
  const Points3& positions = pointPositions(x, search);
  const Index count = positions.rows();
  search.hits.resize(static_cast<std::size_t>(count));
  if (clearance && clearance->size() != obstacles_.size()) clearance->assign(obstacles_.size(), {});
  for (std::size_t o = 0; o < obstacles_.size(); ++o) {
    const Obstacle& obstacle = obstacles_[o];
    const ObstaclePose now = obstacle.poseAt(t), next = obstacle.poseAt(t + h);
    // (A moving obstacle's distances change with it: every point is looked up.)
    Clearance* kept = clearance && obstacle.motion.empty() ? &(*clearance)[o] : nullptr;
    if (kept && kept->distance.size() != count) {
      kept->distance = Eigen::VectorXd::Zero(count);
      kept->at = positions;
    }
    // The lookups, in parallel: each point's own slot, so the contacts come
    // out in point order whatever the threads.
    parallelFor<Index>(0, count, 256, [&](const IndexRange<Index>& range) {
      for (Index i = range.begin(); i != range.end(); ++i) {
        std::optional<SurfacePoint>& hit = search.hits[static_cast<std::size_t>(i)];
        if (kept && kept->distance[i] > 0 &&
            (positions.row(i) - kept->at.row(i)).norm() < kept->distance[i]) {
          hit.reset();  // still outside
          continue;
        }
        hit = closestPointOf(obstacle, t, positions.row(i).transpose(), radius_);
        if (kept) {
          kept->distance[i] = hit ? std::max(hit->distance, 0.0) : radius_;
          kept->at.row(i) = positions.row(i);
        }
      }
    });
    for (Index i = 0; i < count; ++i) {
      const std::optional<SurfacePoint>& hit = search.hits[static_cast<std::size_t>(i)];
      if (!hit || hit->distance > 0) continue;  // touching counts, as on the floor
      const Point& point = points_[static_cast<std::size_t>(i)];
      const Eigen::Vector3d surfaceVelocity =
          h > 0 ? Eigen::Vector3d((next.toWorld(now.toLocal(hit->point)) - hit->point) / h)
                : Eigen::Vector3d::Zero();
      Contact c{static_cast<int>(i),
                static_cast<int>(o),
                -hit->distance,
                hit->normal,
                surfaceVelocity,
                {},
                0,
                stiffness_[o] * point.share};
      for (int j = 0; j < point.count; ++j)
        c.gradient[static_cast<std::size_t>(j)] =
            point.weights[static_cast<std::size_t>(j)] * c.normal;
      out.push_back(c);
    }
  }
  // A skin point pushes each of its nodes along the node's mean skin
  // contact normal (over all skin contacts at it, by |w_j|), so that the
  // friction that stops the node's tangential motion moves none of its
  // points along their push (ObstacleContact.h).
  if (skinCollides_) {
    std::vector<Eigen::Vector3d>& nodeNormals = search.nodeNormals;
    nodeNormals.assign(static_cast<std::size_t>(x.size() / 3), Eigen::Vector3d::Zero());
    for (const Contact& c : out)
      if (c.point >= firstSkinPoint_) {
        const Point& point = points_[static_cast<std::size_t>(c.point)];
        for (int j = 0; j < point.count; ++j)
          nodeNormals[static_cast<std::size_t>(point.nodes[static_cast<std::size_t>(j)])] +=
              std::abs(point.weights[static_cast<std::size_t>(j)]) * c.normal;
      }
    for (Contact& c : out)
      if (c.point >= firstSkinPoint_) {
        const Point& point = points_[static_cast<std::size_t>(c.point)];
        for (int j = 0; j < point.count; ++j) {
          const Eigen::Vector3d& sum =
              nodeNormals[static_cast<std::size_t>(point.nodes[static_cast<std::size_t>(j)])];
          if (sum.norm() > 0)
            c.gradient[static_cast<std::size_t>(j)] =
                point.weights[static_cast<std::size_t>(j)] * sum.normalized();
        }
      }
  }
  for (Contact& c : out) c.start = c.along(points_[static_cast<std::size_t>(c.point)], x);
}

int ObstacleContact::addForce(const StepState& at, StepSystem& system) {
  h_ = at.h;
  t_ = at.t;
  // (In a still world the obstacles' surfaces do not move over the step.)
  findContacts(at.x, at.t, at.still ? 0.0 : at.h, contacts_, search_, &clearance_);
  const double h = at.h;
  for (const Contact& c : contacts_) {
    const Point& point = points_[static_cast<std::size_t>(c.point)];
    const double k = c.stiffness;
    const double spring = k * (c.depth + h * c.normal.dot(c.velocity) - h * c.along(point, at.v));
    for (int j = 0; j < point.count; ++j) {
      const Index node = point.nodes[static_cast<std::size_t>(j)];
      const Eigen::Vector3d& g = c.gradient[static_cast<std::size_t>(j)];
      system.force.segment<3>(3 * node) += spring * g;
      for (int a = 0; a < 3; ++a) system.addSpring(3 * node + a, h * h * k * g[a] * g[a]);
    }
  }
  return static_cast<int>(contacts_.size());
}

void ObstacleContact::addMatrix(const StepState& at, StepSystem& system) {
  // The entries of h^2 k g_j g_l^T off the diagonal (the diagonal went
  // with the springs), between nodes of one element, which the pattern
  // holds.
  const double h2 = at.h * at.h;
  for (const Contact& c : contacts_) {
    const Point& point = points_[static_cast<std::size_t>(c.point)];
    for (int j = 0; j < point.count; ++j)
      for (int l = 0; l < point.count; ++l) {
        const Eigen::Vector3d& gj = c.gradient[static_cast<std::size_t>(j)];
        const Eigen::Vector3d& gl = c.gradient[static_cast<std::size_t>(l)];
        const Index row = 3 * point.nodes[static_cast<std::size_t>(j)];
        const Index column = 3 * point.nodes[static_cast<std::size_t>(l)];
        for (int a = 0; a < 3; ++a)
          for (int b = 0; b < 3; ++b)
            if (row != column || a != b)
              system.A->coeffRef(row + a, column + b) += h2 * c.stiffness * gj[a] * gl[b];
      }
  }
}

void ObstacleContact::project(Eigen::VectorXd& x, Eigen::VectorXd& v) const {
  // Friction is gathered per node from all the contacts that act on it and
  // applied once: points bound to shared nodes would otherwise each spend
  // the whole stopping impulse on the same nodes, overshoot, and chatter.
  const std::size_t nodes = static_cast<std::size_t>(x.size() / 3);
  if (friction_.size() != nodes) friction_.assign(nodes, {});
  frictionForces_.clear();
  std::vector<Index> touched;
  for (const Contact& c : contacts_) {
    const Point& point = points_[static_cast<std::size_t>(c.point)];
    const Obstacle& obstacle = obstacles_[static_cast<std::size_t>(c.obstacle)];
    // The spring's force at the step's end, as the step linearized it.
    const double normalForce = c.stiffness * std::max(0.0, c.depth + h_ * c.normal.dot(c.velocity) -
                                                               (c.along(point, x) - c.start));
    if (normalForce == 0) continue;
    for (int j = 0; j < point.count; ++j) {
      const Index node = point.nodes[static_cast<std::size_t>(j)];
      const double share = point.weights[static_cast<std::size_t>(j)] * normalForce;
      if (share <= 0) continue;
      NodeFriction& f = friction_[static_cast<std::size_t>(node)];
      if (f.total == 0) touched.push_back(node);
      f.normalForce += normalForce * c.gradient[static_cast<std::size_t>(j)];
      f.surfaceVelocity += share * c.velocity;
      f.staticFriction += share * obstacle.staticFriction;
      f.kineticFriction += share * obstacle.kineticFriction;
      f.total += share;
    }
  }
  for (const Index node : touched) {
    NodeFriction& f = friction_[static_cast<std::size_t>(node)];
    const double normalForce = f.normalForce.norm();
    if (normalForce > 0) {
      // The node's tangential velocity relative to the surfaces it touches
      // may change by mu h f_n / m: all of it when mu_s allows (sticking),
      // mu_k's share of it otherwise (sliding).
      const Eigen::Vector3d normal = f.normalForce / normalForce;
      const Eigen::Vector3d relative = v.segment<3>(3 * node) - f.surfaceVelocity / f.total;
      const Eigen::Vector3d tangential = relative - normal.dot(relative) * normal;
      const double speed = tangential.norm();
      const double allowance = h_ * normalForce / mass_[3 * node];
      if (speed > 0) {
        const double change = speed <= f.staticFriction / f.total * allowance
                                  ? speed
                                  : std::min(speed, f.kineticFriction / f.total * allowance);
        const Eigen::Vector3d dv = -change / speed * tangential;
        v.segment<3>(3 * node) += dv;
        x.segment<3>(3 * node) += h_ * dv;
        frictionForces_.push_back({node, mass_[3 * node] * dv / h_});
      }
    }
    f = NodeFriction{};
  }
}

void ObstacleContact::addForceAt(const Eigen::VectorXd& x, const Eigen::VectorXd&,
                                 Eigen::VectorXd& force) const {
  std::vector<Contact> contacts;
  Search search;
  findContacts(x, t_, 0, contacts, search, nullptr);
  for (const Contact& c : contacts) {
    const Point& point = points_[static_cast<std::size_t>(c.point)];
    for (int j = 0; j < point.count; ++j)
      force.segment<3>(3 * point.nodes[static_cast<std::size_t>(j)]) +=
          c.stiffness * c.depth * c.gradient[static_cast<std::size_t>(j)];
  }
  for (const auto& [node, friction] : frictionForces_) force.segment<3>(3 * node) += friction;
}

void ObstacleContact::skinContact(const Eigen::VectorXd& x, double t, Eigen::VectorXd& penetration,
                                  Points3& force) const {
  penetration.resize(0);
  force.resize(0, 3);
  if (!skin_) return;
  const Eigen::Map<const Points3> control(x.data(), x.size() / 3, 3);
  Points3 skin;
  skin_->deformPositions(control, skin);
  penetration = Eigen::VectorXd::Constant(skin.rows(), -radius_);
  force = Points3::Zero(skin.rows(), 3);
  const double share = skinCollides_ && !points_.empty() ? points_.back().share : 0;
  for (Index v = 0; v < skin.rows(); ++v)
    for (std::size_t o = 0; o < obstacles_.size(); ++o) {
      const auto hit = closestPointOf(obstacles_[o], t, skin.row(v).transpose(), radius_);
      if (!hit || -hit->distance <= penetration[v]) continue;
      penetration[v] = -hit->distance;
      force.row(v) =
          hit->distance < 0
              ? Eigen::RowVector3d(stiffness_[o] * share * -hit->distance * hit->normal.transpose())
              : Eigen::RowVector3d::Zero();
    }
}

}  // namespace tetskin
