// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/simulation/CouplingSprings.h"

namespace tetskin {

void CouplingSprings::clear() {
  stiffness_.clear();
  direction_.clear();
  starts_.assign(1, 0);
  entries_.clear();
  for (const Index node : touched_) isTouched_[static_cast<std::size_t>(node)] = 0;
  touched_.clear();
}

void CouplingSprings::add(double stiffness, const Eigen::Vector3d& direction,
                          std::span<const Entry> entries) {
  stiffness_.push_back(stiffness);
  direction_.push_back(direction);
  for (const Entry& e : entries) {
    entries_.push_back(e);
    const auto node = static_cast<std::size_t>(e.node);
    if (node >= isTouched_.size()) isTouched_.resize(node + 1, 0);
    if (!isTouched_[node]) {
      isTouched_[node] = 1;
      touched_.push_back(e.node);
    }
  }
  starts_.push_back(entries_.size());
}

void CouplingSprings::product(const double* x, double* y) const {
  for (const Index node : touched_)
    for (Index a = 0; a < 3; ++a) y[3 * node + a] = 0;
  for (std::size_t k = 0; k < stiffness_.size(); ++k) {
    const Eigen::Vector3d& n = direction_[k];
    // u.x, and per entry its own share a_j n.x_j, which the diagonal
    // block (in A) accounts for.
    double along = 0;
    for (std::size_t i = starts_[k]; i != starts_[k + 1]; ++i)
      along +=
          entries_[i].weight * n.dot(Eigen::Map<const Eigen::Vector3d>(x + 3 * entries_[i].node));
    for (std::size_t i = starts_[k]; i != starts_[k + 1]; ++i) {
      const Entry& e = entries_[i];
      const double own = e.weight * n.dot(Eigen::Map<const Eigen::Vector3d>(x + 3 * e.node));
      Eigen::Map<Eigen::Vector3d>(y + 3 * e.node) += stiffness_[k] * e.weight * (along - own) * n;
    }
  }
}

void CouplingSprings::keep(const std::vector<char>& kept) {
  std::size_t to = 0, entry = 0;
  for (std::size_t k = 0; k < stiffness_.size(); ++k) {
    if (!kept[k]) continue;
    stiffness_[to] = stiffness_[k];
    direction_[to] = direction_[k];
    const std::size_t first = entry;
    for (std::size_t i = starts_[k]; i != starts_[k + 1]; ++i) entries_[entry++] = entries_[i];
    starts_[to] = first;
    ++to;
  }
  stiffness_.resize(to);
  direction_.resize(to);
  starts_.resize(to + 1);
  starts_[to] = entry;
  entries_.resize(entry);
  // (Nodes no spring touches any more stay in touched_: product() writes
  // them zero, which C is there.)
}

void CouplingSprings::eliminate(const std::vector<char>& fixedDofs,
                                const Eigen::VectorXd& prescribed, Eigen::VectorXd& b) {
  std::vector<Entry> kept;
  std::size_t start = 0;
  for (std::size_t k = 0; k < stiffness_.size(); ++k) {
    const Eigen::Vector3d& n = direction_[k];
    double held = 0;  // the held nodes' part of u.dv
    const std::size_t first = kept.size();
    for (std::size_t i = starts_[k]; i != starts_[k + 1]; ++i) {
      const Entry& e = entries_[i];
      if (fixedDofs[3 * static_cast<std::size_t>(e.node)])
        held += e.weight * n.dot(prescribed.segment<3>(3 * e.node));
      else
        kept.push_back(e);
    }
    for (std::size_t i = first; i != kept.size(); ++i)
      b.segment<3>(3 * kept[i].node) -= stiffness_[k] * kept[i].weight * held * n;
    starts_[k] = start;
    start = kept.size();
  }
  starts_.back() = start;
  entries_ = std::move(kept);
  // (Held nodes stay in touched_: their y entries are written zero.)
}

}  // namespace tetskin
