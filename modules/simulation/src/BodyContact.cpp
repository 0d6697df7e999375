// SPDX-License-Identifier: AGPL-3.0-or-later
#include "BodyContact.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "tetskin/core/Geometry.h"
#include "tetskin/core/Parallel.h"
#include "tetskin/spatial/PathCrossing.h"
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
      kineticFriction_(settings.kineticFriction),
      vertexTriangles_(vertexTriangleAdjacency(triangles_, restSkin_.rows())) {
  bodyTriangles_.resize(selfContact_.size());
  for (Index t = 0; t < triangles_.rows(); ++t)
    bodyTriangles_[static_cast<std::size_t>(body_[static_cast<std::size_t>(triangles_(t, 0))])]
        .push_back(static_cast<int>(t));
  for (const std::vector<int>& chosen : bodyTriangles_)
    trees_.emplace_back(triangleBoxes(restSkin_, triangles_, chosen));
  // Across each triangle's edges and around each vertex: the neighbours a
  // pseudo-normal takes.
  neighbours_ = Triangles::Constant(triangles_.rows(), 3, -1);
  std::map<std::pair<int, int>, int> edges;  // (a, b) as a triangle runs it: that triangle
  for (Index t = 0; t < triangles_.rows(); ++t)
    for (int k = 0; k < 3; ++k)
      edges[{triangles_(t, (k + 1) % 3), triangles_(t, (k + 2) % 3)}] = static_cast<int>(t);
  for (Index t = 0; t < triangles_.rows(); ++t)
    for (int k = 0; k < 3; ++k) {
      const auto across = edges.find({triangles_(t, (k + 2) % 3), triangles_(t, (k + 1) % 3)});
      if (across != edges.end()) neighbours_(t, k) = across->second;
    }
  // Each vertex to the first of its triangles (in its body's tree's
  // numbering), which stands for it in forEachLeafNear.
  std::vector<char> owned(static_cast<std::size_t>(restSkin_.rows()), 0);
  for (const std::vector<int>& chosen : bodyTriangles_) {
    std::vector<std::array<int, 3>>& owner = ownedVertices_.emplace_back(chosen.size());
    for (std::size_t i = 0; i < chosen.size(); ++i)
      for (int k = 0; k < 3; ++k) {
        const int vertex = triangles_(chosen[i], k);
        owner[i][static_cast<std::size_t>(k)] =
            owned[static_cast<std::size_t>(vertex)] ? -1 : vertex;
        owned[static_cast<std::size_t>(vertex)] = 1;
      }
  }
}

Eigen::Vector3d BodyContact::pseudoNormal(const Points3& skin, int triangle,
                                          const Eigen::Vector3d& barycentric) const {
  const auto corner = [&](int t, int k) { return skin.row(triangles_(t, k)).transpose(); };
  const auto faceNormal = [&](int t) {
    return triangleNormal(corner(t, 0), corner(t, 1), corner(t, 2));
  };
  const TriangleFeature feature = closestFeature(barycentric);
  if (feature.kind == TriangleFeature::Face) return faceNormal(triangle);
  if (feature.kind == TriangleFeature::Edge) {
    const int across = neighbours_(triangle, feature.corner);
    return faceNormal(triangle) + (across >= 0 ? faceNormal(across) : Eigen::Vector3d::Zero());
  }
  const int vertex = triangles_(triangle, feature.corner);
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (int at = vertexTriangles_.offsets[static_cast<std::size_t>(vertex)];
       at != vertexTriangles_.offsets[static_cast<std::size_t>(vertex) + 1]; ++at) {
    const int t = vertexTriangles_.triangles[static_cast<std::size_t>(at)];
    const int k = triangles_(t, 0) == vertex ? 0 : triangles_(t, 1) == vertex ? 1 : 2;
    sum +=
        triangleAngle(corner(t, k), corner(t, (k + 1) % 3), corner(t, (k + 2) % 3)) * faceNormal(t);
  }
  return sum;
}

bool BodyContact::mayMeet(Index v, int t, bool sameBody) const {
  const int a = triangles_(t, 0), b = triangles_(t, 1), c = triangles_(t, 2);
  if (a == v || b == v || c == v) return false;
  if (!sameBody) return true;
  const double neighbourhood = kNeighbourhood * thickness_;
  return closestPointOnTriangle(restSkin_.row(v).transpose(), restSkin_.row(a).transpose(),
                                restSkin_.row(b).transpose(), restSkin_.row(c).transpose())
             .squaredDistance >= neighbourhood * neighbourhood;
}

std::vector<char> BodyContact::verticesNearOtherBodies(
    const std::vector<AabbTree>& trees, double margin,
    const std::function<bool(std::size_t, std::size_t)>& pair) const {
  // A body at a time, so that each writes only its own vertices.
  std::vector<char> near(static_cast<std::size_t>(restSkin_.rows()), 0);
  parallelFor<std::size_t>(0, trees.size(), 1, [&](const IndexRange<std::size_t>& range) {
    for (std::size_t b = range.begin(); b != range.end(); ++b)
      for (std::size_t other = 0; other < trees.size(); ++other) {
        if (other == b || !pair(b, other)) continue;
        trees[b].forEachLeafNear(trees[other], margin, [&](std::span<const int> ids) {
          for (int i : ids)
            for (int vertex : ownedVertices_[b][static_cast<std::size_t>(i)])
              if (vertex >= 0) near[static_cast<std::size_t>(vertex)] = 1;
        });
      }
  });
  return near;
}

std::vector<Aabb> BodyContact::bodyBoxes(const Points3& skin) const {
  std::vector<Aabb> boxes(selfContact_.size());
  for (Index v = 0; v < skin.rows(); ++v)
    boxes[static_cast<std::size_t>(body_[static_cast<std::size_t>(v)])].extend(
        skin.row(v).transpose().eval());
  for (Aabb& box : boxes) box = box.inflated(thickness_);
  return boxes;
}

std::optional<BodyContact::Contact> BodyContact::contactWith(
    const Points3& skin, const Eigen::VectorXd& x, Index v, int triangle,
    const ClosestPointOnTriangle& closest) const {
  const double d = std::sqrt(closest.squaredDistance);
  Contact c;
  c.vertex = static_cast<int>(v);
  c.triangle = triangle;
  const Eigen::Vector3d a = skin.row(triangles_(triangle, 0)).transpose();
  const Eigen::Vector3d b = skin.row(triangles_(triangle, 1)).transpose();
  const Eigen::Vector3d e = skin.row(triangles_(triangle, 2)).transpose();
  const Eigen::Vector3d face = (b - a).cross(e - a).normalized();  // outward
  const Eigen::Vector3d away = skin.row(v).transpose() - closest.point;
  // Outside the triangle's skin the vertex is pushed away from it, inside
  // (it went through) back out: the distance is signed by the side, so
  // that a vertex that has passed a triangle is not pushed on. The side is
  // the pseudo-normal's of the feature q lies on (exact for a closed skin
  // that does not cross itself). The face's normal alone is rounding's
  // beside an edge or a corner, where p - q lies in the face's plane; with
  // it taken as outside unless p - q lay within 60 degrees of the inward
  // normal (the first rule), a vertex behind a fold's edge was pushed on,
  // deeper in: three piled bunnies sank into each other (2,400 active
  // contacts growing to 22,800 in ten steps, few vertices ever beyond the
  // shell). (A vertex on the triangle itself is pushed along the face's
  // normal.)
  const double side = away.dot(pseudoNormal(skin, triangle, closest.barycentric)) < 0 ? -1.0 : 1.0;
  c.normal = d > 1e-12 * thickness_ ? Eigen::Vector3d(side * away / d) : face;
  c.gap = thickness_ - side * d;
  if (!c.normal.allFinite()) return std::nullopt;  // a degenerate triangle touched at a point
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
    const int corner = triangles_(triangle, k);
    for (int j = 0; j < controlsPerVertex_; ++j)
      addNode(controls_(corner, j), -closest.barycentric[k] * weights_(corner, j));
  }
  c.start = c.along(x);
  return c;
}

void BodyContact::findContacts(const Eigen::VectorXd& x, std::vector<Contact>& out,
                               std::vector<AabbTree>& trees, Points3* skinOut) const {
  out.clear();
  const Eigen::Map<const Points3> control(x.data(), x.size() / 3, 3);
  Points3 skin;
  skin_->deformPositions(control, skin);
  parallelFor<std::size_t>(0, trees.size(), 1, [&](const IndexRange<std::size_t>& range) {
    for (std::size_t b = range.begin(); b != range.end(); ++b)
      trees[b].refit(triangleBoxes(skin, triangles_, bodyTriangles_[b]));
  });
  // Each body's skin's box, grown by the thickness: a vertex of a body that
  // does not meet itself and lies in no other body's box has nothing to
  // meet (bodies apart cost a box test per vertex, not a tree search).
  const std::vector<Aabb> boxes = bodyBoxes(skin);
  // The vertices that may lie within the thickness of another body's skin
  // (of bodies whose boxes come that near). The rest are not searched: in a pile, most of a body's
  // vertices lie in another body's box, but far from its skin.
  const std::vector<char> nearOther =
      verticesNearOtherBodies(trees, thickness_, [&](std::size_t b, std::size_t other) {
        return boxes[other].overlaps(trees[b].bounds().inflated(thickness_));
      });
  // Per vertex its closest triangle within the thickness, in parallel,
  // each in its own slot: the contacts come out in vertex order on any
  // number of threads. Nearest boxes first, the reach shrinking to the
  // closest triangle found over every tree the vertex searches (branch and
  // bound).
  struct Hit {
    int triangle = -1;
    ClosestPointOnTriangle closest;
  };
  std::vector<Hit> hits(static_cast<std::size_t>(skin.rows()));
  parallelFor<Index>(0, skin.rows(), 256, [&](const IndexRange<Index>& range) {
    for (Index v = range.begin(); v != range.end(); ++v) {
      const int body = body_[static_cast<std::size_t>(v)];
      if (!nearOther[static_cast<std::size_t>(v)] && !selfContact_[static_cast<std::size_t>(body)])
        continue;
      const Eigen::Vector3d p = skin.row(v).transpose();
      Hit& hit = hits[static_cast<std::size_t>(v)];
      double best = thickness_ * thickness_;
      for (std::size_t other = 0; other < trees.size(); ++other) {
        const bool sameBody = static_cast<int>(other) == body;
        if (sameBody ? !selfContact_[other] : !boxes[other].contains(p)) continue;
        const std::vector<int>& chosen = bodyTriangles_[other];
        trees[other].forEachNear(p, best, [&](int i, double&) {
          const int t = chosen[static_cast<std::size_t>(i)];
          const ClosestPointOnTriangle closest = closestPointOnTriangle(
              p, skin.row(triangles_(t, 0)).transpose(), skin.row(triangles_(t, 1)).transpose(),
              skin.row(triangles_(t, 2)).transpose());
          if (closest.squaredDistance >= best || !mayMeet(v, t, sameBody)) return;
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
    if (const std::optional<Contact> c = contactWith(skin, x, v, hit.triangle, hit.closest))
      out.push_back(*c);
  }
  if (skinOut) *skinOut = std::move(skin);
}

int BodyContact::addCrossings(const Eigen::VectorXd& x, const Eigen::VectorXd& end) {
  const Eigen::Map<const Points3> control(end.data(), end.size() / 3, 3);
  Points3 skinEnd;
  skin_->deformPositions(control, skinEnd);
  // A vertex without a contact lay at least the shell's thickness from
  // every triangle it may meet at the step's start (else the search would
  // have found it). Its distance to a triangle shrinks by no more than its
  // own motion and the farthest the triangle's corners move: two bodies
  // whose skins' vertices move less than the shell between them cannot
  // cross (a pile at rest costs no continuous detection).
  const std::size_t bodies = trees_.size();
  std::vector<double> moved(bodies, 0.0);
  for (Index v = 0; v < skinEnd.rows(); ++v) {
    double& most = moved[static_cast<std::size_t>(body_[static_cast<std::size_t>(v)])];
    most = std::max(most, (skinEnd.row(v) - stepSkin_.row(v)).norm());
  }
  // (And two bodies whose boxes over the step, grown by the shell, do not
  // overlap cannot either: bodies falling apart cost no swept trees.)
  std::vector<Aabb> boxes = bodyBoxes(stepSkin_);
  const std::vector<Aabb> boxesAtEnd = bodyBoxes(skinEnd);
  for (std::size_t b = 0; b < boxes.size(); ++b) boxes[b].extend(boxesAtEnd[b]);
  const auto mayCrossBetween = [&](std::size_t b, std::size_t other) {
    return (other == b ? selfContact_[b] != 0 : boxes[b].overlaps(boxes[other])) &&
           moved[b] + moved[other] >= thickness_;
  };
  std::vector<char> sweeps(bodies, 0);  // the bodies in a pair that may cross
  for (std::size_t b = 0; b < bodies; ++b)
    for (std::size_t other = 0; other < bodies; ++other)
      if (mayCrossBetween(b, other)) sweeps[b] = sweeps[other] = 1;
  if (std::find(sweeps.begin(), sweeps.end(), 1) == sweeps.end()) return 0;
  // The trees over each triangle's box at the start and at the end.
  if (sweptTrees_.size() != trees_.size()) sweptTrees_ = trees_;
  parallelFor<std::size_t>(0, trees_.size(), 1, [&](const IndexRange<std::size_t>& range) {
    for (std::size_t b = range.begin(); b != range.end(); ++b) {
      if (!sweeps[b]) continue;
      std::vector<Aabb> swept = triangleBoxes(stepSkin_, triangles_, bodyTriangles_[b]);
      const std::vector<Aabb> atEnd = triangleBoxes(skinEnd, triangles_, bodyTriangles_[b]);
      for (std::size_t i = 0; i < swept.size(); ++i) swept[i].extend(atEnd[i]);
      sweptTrees_[b].refit(swept);
    }
  });
  // The vertices whose paths may cross another body's skin: those of the
  // leaves of their body's swept tree that overlap another's swept
  // triangles (each triangle's box over the step holds it throughout, and
  // a vertex's path lies in its triangles' boxes).
  const std::vector<char> mayCross =
      verticesNearOtherBodies(sweptTrees_, 0, [&](std::size_t b, std::size_t other) {
        return mayCrossBetween(b, other) && boxes[other].overlaps(sweptTrees_[b].bounds());
      });
  std::vector<char> hasContact(static_cast<std::size_t>(stepSkin_.rows()), 0);
  for (const Contact& c : contacts_) hasContact[static_cast<std::size_t>(c.vertex)] = 1;
  // Per vertex without a contact, the triangle its path crosses first.
  std::vector<int> crossed(static_cast<std::size_t>(stepSkin_.rows()), -1);
  const auto corner = [&](const Points3& skin, int t, int k) {
    return skin.row(triangles_(t, k)).transpose();
  };
  parallelFor<Index>(0, stepSkin_.rows(), 256, [&](const IndexRange<Index>& range) {
    for (Index v = range.begin(); v != range.end(); ++v) {
      const int body = body_[static_cast<std::size_t>(v)];
      // (A vertex with a contact in the step is its contact's.)
      if (hasContact[static_cast<std::size_t>(v)] ||
          (!mayCross[static_cast<std::size_t>(v)] && !selfContact_[static_cast<std::size_t>(body)]))
        continue;
      const Eigen::Vector3d p0 = stepSkin_.row(v).transpose(), p1 = skinEnd.row(v).transpose();
      const Aabb path{p0.cwiseMin(p1), p0.cwiseMax(p1)};
      double first = 2;  // the crossing's time in the step, from 0 to 1
      for (std::size_t other = 0; other < trees_.size(); ++other) {
        const bool sameBody = static_cast<int>(other) == body;
        if (!mayCrossBetween(static_cast<std::size_t>(body), other) ||
            (!sameBody && !boxes[other].overlaps(path)))
          continue;
        const std::vector<int>& chosen = bodyTriangles_[other];
        sweptTrees_[other].forEachOverlap(path, [&](int i) {
          const int t = chosen[static_cast<std::size_t>(i)];
          const double when = crossingTime(
              p0, p1, {corner(stepSkin_, t, 0), corner(stepSkin_, t, 1), corner(stepSkin_, t, 2)},
              {corner(skinEnd, t, 0), corner(skinEnd, t, 1), corner(skinEnd, t, 2)});
          if (when >= first || !mayMeet(v, t, sameBody)) return;
          first = when;
          crossed[static_cast<std::size_t>(v)] = t;
        });
      }
    }
  });
  // Each a contact as of the step's start (outside its triangle, perhaps
  // farther than the shell: a gap below zero), out of the step for
  // updateActiveSet to take in.
  int added = 0;
  for (Index v = 0; v < stepSkin_.rows(); ++v) {
    const int t = crossed[static_cast<std::size_t>(v)];
    if (t < 0) continue;
    const ClosestPointOnTriangle closest =
        closestPointOnTriangle(stepSkin_.row(v).transpose(), corner(stepSkin_, t, 0),
                               corner(stepSkin_, t, 1), corner(stepSkin_, t, 2));
    std::optional<Contact> c = contactWith(stepSkin_, x, v, t, closest);
    if (!c) continue;
    c->active = false;
    contacts_.push_back(*c);
    ++added;
  }
  return added;
}

int BodyContact::addForce(const StepState& at, StepSystem& system) {
  h_ = at.h;
  // (After updateActiveSet, the same step again with the contacts kept.)
  if (!keepContacts_) {
    findContacts(at.x, contacts_, trees_, &stepSkin_);
    // A vertex whose contact ended the last step pulling starts this one
    // out of it: a pair parting over several steps is not taken in and
    // let go again on every step (updateActiveSet checks both ways).
    if (!letGo_.empty())
      for (Contact& c : contacts_) c.active = !letGo_[static_cast<std::size_t>(c.vertex)];
  }
  keepContacts_ = false;
  int active = 0;
  for (const Contact& c : contacts_)
    if (c.active) {
      ++active;
      addShare(c, at.v, 1.0, system, false);
    }
  return active;
}

void BodyContact::addShare(const Contact& c, const Eigen::VectorXd& v, double sign,
                           StepSystem& system, bool intoSystem) const {
  // addForce puts in the force and the springs' diagonal, which the
  // assembly adds to A and (times h) to b; an assembled step (intoSystem)
  // takes b and A's blocks directly.
  const double h = h_, k = stiffness_, h2k = h * h * k;
  const double spring = sign * k * (c.gap - h * c.along(v));
  for (int j = 0; j < c.count; ++j) {
    const CouplingSprings::Entry& e = c.entries[static_cast<std::size_t>(j)];
    const Eigen::Vector3d g = e.weight * c.normal;
    if (!intoSystem) {
      system.force.segment<3>(3 * e.node) += spring * g;
      for (int a = 0; a < 3; ++a) system.addSpring(3 * e.node + a, sign * h2k * g[a] * g[a]);
      continue;
    }
    system.b->segment<3>(3 * e.node) += h * spring * g;
    for (int a = 0; a < 3; ++a) {
      const Index row = 3 * e.node + a;
      system.springsSized()[row] += sign * h2k * g[a] * g[a];
      for (int col = 0; col < 3; ++col)
        system.A->coeffRef(row, 3 * e.node + col) += sign * h2k * g[a] * g[col];
    }
  }
}

BodyContact::ActiveSetChange BodyContact::updateActiveSet(const Eigen::VectorXd& x,
                                                          const Eigen::VectorXd& v,
                                                          const Eigen::VectorXd& dv,
                                                          StepSystem& system, bool crossings) {
  // Vertices whose path over the solved step crosses a skin become
  // contacts, out of the step: those that would end it pushing come in.
  ActiveSetChange result;
  if (crossings) result.crossed = addCrossings(x, x + h_ * (v + dv));
  const Eigen::VectorXd end = v + dv;
  // Per contact: 1 let go (in, pulling at the solved end), 2 taken in
  // (out, pushing there), 0 as it is.
  std::vector<char> change(contacts_.size(), 0);
  for (std::size_t k = 0; k < contacts_.size(); ++k) {
    const Contact& c = contacts_[k];
    const double spring = c.gap - h_ * c.along(end);
    if (c.active ? spring >= 0 : spring <= 0) continue;
    change[k] = c.active ? 1 : 2;
    ++(c.active ? result.released : result.taken);
    for (int j = 0; j < c.count; ++j)
      result.reassemble =
          result.reassemble || constraints_.isFixed(c.entries[static_cast<std::size_t>(j)].node);
  }
  if (result.released + result.taken == 0) return result;
  for (std::size_t k = 0; k < contacts_.size(); ++k)
    if (change[k]) contacts_[k].active = change[k] == 2;
  if (result.reassemble) {
    // A held node's rows were rewritten by the constraints: the step is
    // assembled again, its next addForce taking the contacts as they are.
    keepContacts_ = true;
    return result;
  }
  // Out: their share taken from b, A's blocks and the springs' diagonal
  // (the nodes free: their rows are as assembled), and their coupling
  // springs dropped; in: the same added, and a coupling spring each.
  std::vector<char> kept(system.coupling.size(), 1);
  for (std::size_t k = 0; k < contacts_.size(); ++k) {
    Contact& c = contacts_[k];
    if (change[k] == 1) {
      addShare(c, v, -1.0, system, true);
      kept[static_cast<std::size_t>(c.spring)] = 0;
      c.spring = -1;
    } else if (change[k] == 2) {
      addShare(c, v, 1.0, system, true);
    }
  }
  if (result.released > 0) {
    // (keep() numbers the springs kept anew, in their order.)
    std::vector<int> renumbered(kept.size(), -1);
    int next = 0;
    for (std::size_t s = 0; s < kept.size(); ++s)
      if (kept[s]) renumbered[s] = next++;
    system.coupling.keep(kept);
    for (Contact& c : contacts_)
      if (c.spring >= 0) c.spring = renumbered[static_cast<std::size_t>(c.spring)];
  }
  const double h2k = h_ * h_ * stiffness_;
  for (std::size_t k = 0; k < contacts_.size(); ++k)
    if (change[k] == 2) addSpring(contacts_[k], h2k, system, false);  // (A's blocks: above)
  return result;
}

void BodyContact::addSpring(Contact& c, double h2k, StepSystem& system, bool ownBlocks) {
  // Each node's own block (its diagonal went with the springs) to A, the
  // blocks between nodes to the coupling springs.
  for (int j = 0; ownBlocks && j < c.count; ++j) {
    const CouplingSprings::Entry& e = c.entries[static_cast<std::size_t>(j)];
    const Eigen::Vector3d g = e.weight * c.normal;
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b)
        if (a != b) system.A->coeffRef(3 * e.node + a, 3 * e.node + b) += h2k * g[a] * g[b];
  }
  c.spring = static_cast<int>(system.coupling.size());
  system.coupling.add(h2k, c.normal,
                      std::span(c.entries.data(), static_cast<std::size_t>(c.count)));
}

void BodyContact::addMatrix(const StepState& at, StepSystem& system) {
  const double h2k = at.h * at.h * stiffness_;
  for (Contact& c : contacts_)
    if (c.active) addSpring(c, h2k, system, true);
}

void BodyContact::project(Eigen::VectorXd& x, Eigen::VectorXd& v) const {
  // (Velocities only: moving the nodes too, as the obstacles' friction
  // does, took them off the solved state; with skins off their cages the
  // stiff springs between the bodies took that up as energy, and a bunny
  // dropped onto another went into it and through the floor.)
  frictionForces_.clear();
  letGo_.assign(static_cast<std::size_t>(controls_.rows()), 0);

  for (const Contact& c : contacts_) {
    // The spring at the step's end, as the step linearized it.
    const double end = c.gap - (c.along(x) - c.start);
    if (end < 0) letGo_[static_cast<std::size_t>(c.vertex)] = 1;
    if (!c.active) continue;
    const double normalForce = stiffness_ * std::max(0.0, end);
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
  findContacts(x, contacts, trees, nullptr);
  for (const Contact& c : contacts)
    for (int j = 0; j < c.count; ++j) {
      const CouplingSprings::Entry& e = c.entries[static_cast<std::size_t>(j)];
      force.segment<3>(3 * e.node) += stiffness_ * c.gap * e.weight * c.normal;
    }
  for (const auto& [node, friction] : frictionForces_) force.segment<3>(3 * node) += friction;
}

}  // namespace tetskin
