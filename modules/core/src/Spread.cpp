// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/core/Spread.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

namespace tetskin {
namespace {

std::size_t rankOf(std::size_t count, double p) {
  const double rank = std::ceil(p * static_cast<double>(count)) - 1;
  return std::min(static_cast<std::size_t>(std::max(rank, 0.0)), count - 1);
}

}  // namespace

double percentileOfSorted(std::span<const double> sorted, double p) {
  if (sorted.empty()) return 0;
  return sorted[rankOf(sorted.size(), p)];
}

Spread spreadOf(std::vector<double>& values) {
  Spread s;
  if (values.empty()) return s;
  // (NaN last: a comparison that orders it keeps nth_element well defined.)
  const auto less = [](double a, double b) { return std::isnan(b) ? !std::isnan(a) : a < b; };
  const auto at = [&](double p) {
    const auto k = values.begin() + static_cast<std::ptrdiff_t>(rankOf(values.size(), p));
    std::nth_element(values.begin(), k, values.end(), less);
    return *k;
  };
  s.max = at(1.0);
  s.p99 = at(0.99);
  s.median = at(0.5);
  return s;
}

}  // namespace tetskin
