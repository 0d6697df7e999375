// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// How a set of values spreads, as the reports print it: the nearest-rank
// percentile (the smallest value with at least p of the values at or below
// it), and the median, 99th percentile and maximum together. Used by the
// binding summary and by the comparison of levels.

#include <span>
#include <vector>

namespace tetskin {

// The nearest-rank percentile p (in [0, 1]) of `sorted`, ascending; 0 for
// no values.
double percentileOfSorted(std::span<const double> sorted, double p);

struct Spread {
  double median = 0, p99 = 0, max = 0;
};

// The spread of `values` (reordered: partially sorted in place). NaN values
// count as larger than any other, so a NaN shows as the maximum.
Spread spreadOf(std::vector<double>& values);

}  // namespace tetskin
