// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/spatial/AabbTree.h"

#include <algorithm>
#include <numeric>

namespace tetskin {

AabbTree::AabbTree(std::span<const Aabb> boxes) {
  if (boxes.empty()) return;
  boxes_.assign(boxes.begin(), boxes.end());
  ids_.resize(boxes.size());
  std::iota(ids_.begin(), ids_.end(), 0);
  std::vector<Eigen::Vector3d> centers(boxes.size());
  for (std::size_t i = 0; i < boxes.size(); ++i) centers[i] = boxes[i].center();
  nodes_.reserve(2 * boxes.size() / kLeafSize + 2);
  nodes_.emplace_back();
  build(0, 0, static_cast<int>(boxes.size()), centers);
}

void AabbTree::refit(std::span<const Aabb> boxes) {
  for (std::size_t slot = 0; slot < boxes_.size(); ++slot)
    boxes_[slot] = boxes[static_cast<std::size_t>(ids_[slot])];
  // Children come after their parent (build appends them): from the last
  // node back, every child is refitted before its parent.
  for (std::size_t k = nodes_.size(); k-- > 0;) {
    Node& node = nodes_[k];
    Aabb box;
    if (node.count > 0) {
      for (int i = node.first; i < node.first + node.count; ++i)
        box.extend(boxes_[static_cast<std::size_t>(i)]);
    } else {
      box.extend(nodes_[static_cast<std::size_t>(node.first)].box);
      box.extend(nodes_[static_cast<std::size_t>(node.first + 1)].box);
    }
    node.box = box;
  }
}

void AabbTree::build(int node, int first, int count, std::vector<Eigen::Vector3d>& centers) {
  Aabb box;
  for (int i = first; i < first + count; ++i) box.extend(boxes_[static_cast<std::size_t>(i)]);
  nodes_[static_cast<std::size_t>(node)].box = box;
  if (count <= kLeafSize) {
    nodes_[static_cast<std::size_t>(node)].first = first;
    nodes_[static_cast<std::size_t>(node)].count = count;
    return;
  }
  Aabb centerBox;
  for (int i = first; i < first + count; ++i)
    centerBox.extend(centers[static_cast<std::size_t>(i)]);
  int axis = 0;
  (centerBox.max - centerBox.min).maxCoeff(&axis);
  // Sort a permutation of the slots by center along the axis, then apply it.
  std::vector<int> order(static_cast<std::size_t>(count));
  std::iota(order.begin(), order.end(), first);
  const int half = count / 2;
  std::nth_element(order.begin(), order.begin() + half, order.end(), [&](int a, int b) {
    return centers[static_cast<std::size_t>(a)][axis] < centers[static_cast<std::size_t>(b)][axis];
  });
  std::vector<Aabb> boxes(static_cast<std::size_t>(count));
  std::vector<int> ids(static_cast<std::size_t>(count));
  std::vector<Eigen::Vector3d> c(static_cast<std::size_t>(count));
  for (int k = 0; k < count; ++k) {
    const auto from = static_cast<std::size_t>(order[static_cast<std::size_t>(k)]);
    boxes[static_cast<std::size_t>(k)] = boxes_[from];
    ids[static_cast<std::size_t>(k)] = ids_[from];
    c[static_cast<std::size_t>(k)] = centers[from];
  }
  std::copy(boxes.begin(), boxes.end(), boxes_.begin() + first);
  std::copy(ids.begin(), ids.end(), ids_.begin() + first);
  std::copy(c.begin(), c.end(), centers.begin() + first);

  const int left = static_cast<int>(nodes_.size());
  nodes_.emplace_back();
  nodes_.emplace_back();
  nodes_[static_cast<std::size_t>(node)].first = left;
  nodes_[static_cast<std::size_t>(node)].count = 0;
  build(left, first, half, centers);
  build(left + 1, first + half, count - half, centers);
}

}  // namespace tetskin
