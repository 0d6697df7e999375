// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/meshing/TargetSizing.h"

#include <algorithm>
#include <cmath>

#include "tetskin/core/Error.h"

namespace tetskin {

namespace {

double boundForFactor(double volume, double unboundedElements, double target, double factor) {
  if (!(volume > 0.0) || !std::isfinite(volume))
    throw Error("sizing needs a positive enclosed volume, got " + formatNumber(volume));
  if (!(unboundedElements >= 0.0 && unboundedElements < target) || !std::isfinite(target))
    throw Error("sizing needs a target above the unbounded mesh's " +
                formatNumber(unboundedElements) + " elements, got " + formatNumber(target));
  return factor * volume / (target - unboundedElements);
}

}  // namespace

double firstVolumeBound(double volume, double unboundedElements, double target, double factor) {
  if (!(factor > 0.0) || !std::isfinite(factor))
    throw Error("sizing needs a positive factor, got " + formatNumber(factor));
  return boundForFactor(volume, unboundedElements, target, factor);
}

double nextVolumeBound(double volume, double unboundedElements, double target, double bound,
                       double elements) {
  // A bound that added no element (elements <= n0) gives k = 0: the clamp
  // then takes the smallest step allowed.
  const double factor = std::max(0.0, (elements - unboundedElements) * bound / volume);
  const double next =
      factor > 0.0 ? boundForFactor(volume, unboundedElements, target, factor) : 0.0;
  return std::clamp(next, bound / kMaxBoundStep, bound * kMaxBoundStep);
}

double edgeForVolumeBound(double volumeBound) {
  // A regular tetrahedron of edge h has volume h^3 / (6 sqrt 2).
  return std::cbrt(6.0 * std::sqrt(2.0) * volumeBound);
}

bool closeToTarget(double elements, double target) {
  return std::abs(elements - target) <= kSizingTolerance * target;
}

}  // namespace tetskin
