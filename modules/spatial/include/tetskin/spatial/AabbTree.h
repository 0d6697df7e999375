// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// A bounding-volume hierarchy over axis-aligned boxes of primitives (triangles,
// tetrahedra). Built once (median split on the longest axis), queried from
// many threads at once: queries are const and allocate nothing on the heap.
//
// Queries:
//   forEachOverlap(box, f)         f(id) for every primitive whose box overlaps `box`
//   forEachNear(p, radius2, f)     f(id, radius2) for the primitives whose box lies
//                                  within sqrt(radius2) of p, nearest boxes first;
//                                  f may shrink radius2 (branch and bound), so an
//                                  exact nearest search is forEachNear + a distance.
//   anyOverlap(box)                whether some primitive's box overlaps `box`
//   forEachLeafNear(other, m, f)   f(ids) for each leaf of this tree whose box, grown
//                                  by m, overlaps a primitive box of `other`: what of
//                                  one surface may lie within m of another, found
//                                  without a query per primitive

#include <array>
#include <span>
#include <vector>

#include "tetskin/spatial/Aabb.h"

namespace tetskin {

class AabbTree {
 public:
  AabbTree() = default;
  // Input: one box per primitive; the queries report a primitive by its
  // index in `boxes`.
  explicit AabbTree(std::span<const Aabb> boxes);

  bool empty() const { return nodes_.empty(); }
  // New boxes for the same primitives (one per primitive, in the order
  // the tree was built with), the hierarchy kept: a deforming surface's
  // tree refitted each step instead of built anew. Queries stay exact; they
  // slow down as the primitives move away from where the tree grouped them.
  void refit(std::span<const Aabb> boxes);
  std::size_t primitiveCount() const { return ids_.size(); }
  const Aabb& bounds() const { return nodes_.front().box; }

  template <typename F>
  void forEachOverlap(const Aabb& query, F&& f) const {
    overlapsUntil(query, [&](int id) {
      f(id);
      return false;
    });
  }

  bool anyOverlap(const Aabb& query) const {
    return overlapsUntil(query, [](int) { return true; });
  }

  template <typename F>
  void forEachLeafNear(const AabbTree& other, double margin, F&& f) const {
    if (nodes_.empty() || other.empty()) return;
    // A subtree is dropped as soon as nothing of `other` lies near its box.
    std::array<int, kMaxDepth> stack;
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
      const Node& node = nodes_[static_cast<std::size_t>(stack[--top])];
      if (!other.anyOverlap(node.box.inflated(margin))) continue;
      if (node.count > 0) {
        f(std::span<const int>(ids_.data() + node.first, static_cast<std::size_t>(node.count)));
      } else {
        stack[top++] = node.first;
        stack[top++] = node.first + 1;
      }
    }
  }

  template <typename F>
  void forEachNear(const Eigen::Vector3d& p, double& radius2, F&& f) const {
    if (nodes_.empty()) return;
    struct Entry {
      int node;
      double d2;
    };
    std::array<Entry, kMaxDepth> stack;
    int top = 0;
    stack[top++] = {0, nodes_.front().box.squaredDistance(p)};
    while (top > 0) {
      const Entry e = stack[--top];
      if (e.d2 > radius2) continue;
      const Node& node = nodes_[static_cast<std::size_t>(e.node)];
      if (node.count > 0) {
        for (int i = node.first; i < node.first + node.count; ++i)
          if (boxes_[static_cast<std::size_t>(i)].squaredDistance(p) <= radius2)
            f(ids_[static_cast<std::size_t>(i)], radius2);
        continue;
      }
      const double dl = nodes_[static_cast<std::size_t>(node.first)].box.squaredDistance(p);
      const double dr = nodes_[static_cast<std::size_t>(node.first + 1)].box.squaredDistance(p);
      // Push the farther child first so the nearer one is visited first.
      if (dl <= dr) {
        stack[top++] = {node.first + 1, dr};
        stack[top++] = {node.first, dl};
      } else {
        stack[top++] = {node.first, dl};
        stack[top++] = {node.first + 1, dr};
      }
    }
  }

 private:
  // Visits the primitives whose boxes overlap `query` until stop(id) says
  // true; returns whether it did.
  template <typename F>
  bool overlapsUntil(const Aabb& query, F&& stop) const {
    if (nodes_.empty()) return false;
    std::array<int, kMaxDepth> stack;
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
      const Node& node = nodes_[static_cast<std::size_t>(stack[--top])];
      if (!node.box.overlaps(query)) continue;
      if (node.count > 0) {
        for (int i = node.first; i < node.first + node.count; ++i)
          if (boxes_[static_cast<std::size_t>(i)].overlaps(query) &&
              stop(ids_[static_cast<std::size_t>(i)]))
            return true;
      } else {
        stack[top++] = node.first;
        stack[top++] = node.first + 1;
      }
    }
    return false;
  }

  // Leaves hold up to kLeafSize primitives; the split is a median, so the
  // depth stays near log2(n / kLeafSize) and a fixed stack suffices.
  static constexpr int kLeafSize = 4;
  static constexpr int kMaxDepth = 128;

  struct Node {
    Aabb box;
    int first = 0;  // leaf: first primitive slot; inner: index of the left child
    int count = 0;  // > 0 for leaves
  };

  void build(int node, int first, int count, std::vector<Eigen::Vector3d>& centers);

  std::vector<Node> nodes_;
  std::vector<Aabb> boxes_;  // in leaf order
  std::vector<int> ids_;     // primitive id per slot
};

}  // namespace tetskin
