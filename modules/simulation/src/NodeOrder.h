// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Breadth-first node orders: consecutive nodes are neighbours or nearly, so
// a sweep in this order, over a matrix numbered in it, reads nearby rows
// and nearby entries of the vectors (few cache misses), and a level's
// neighbours lie within one level before or after it (a narrow band).

#include <cstddef>
#include <vector>

namespace tetskin {

// All `count` nodes of a graph, breadth first, each connected component
// from a pseudo-peripheral node (the last reached by a first search from the
// component's lowest node), which keeps the levels narrow as in
// Cuthill-McKee. `forNeighbours(v, visit)` calls visit(u) for each
// neighbour u of v.
template <typename ForNeighbours>
std::vector<int> breadthFirstOrder(int count, ForNeighbours&& forNeighbours) {
  std::vector<int> order;
  order.reserve(static_cast<std::size_t>(count));
  std::vector<char> seen(static_cast<std::size_t>(count), 0);
  // Appends the component of `start` breadth first; the queue is the tail of
  // `order`.
  auto search = [&](int start) {
    const std::size_t first = order.size();
    seen[static_cast<std::size_t>(start)] = 1;
    order.push_back(start);
    for (std::size_t next = first; next < order.size(); ++next)
      forNeighbours(order[next], [&](int u) {
        if (!seen[static_cast<std::size_t>(u)]) {
          seen[static_cast<std::size_t>(u)] = 1;
          order.push_back(u);
        }
      });
    return first;
  };
  for (int start = 0; start < count; ++start) {
    if (seen[static_cast<std::size_t>(start)]) continue;
    const std::size_t first = search(start);
    const int far = order.back();
    for (std::size_t i = first; i < order.size(); ++i) seen[static_cast<std::size_t>(order[i])] = 0;
    order.resize(first);
    search(far);
  }
  return order;
}

}  // namespace tetskin
