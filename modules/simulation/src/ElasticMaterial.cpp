// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/simulation/ElasticMaterial.h"

#include <cmath>
#include <string>

#include "tetskin/core/Error.h"

namespace tetskin {

void validateMaterial(const ElasticMaterial& m) {
  if (!(m.youngsModulus > 0) || !std::isfinite(m.youngsModulus))
    throw Error("Young's modulus must be finite and positive, got " +
                formatNumber(m.youngsModulus));
  // (-1, 0.5): where isotropic linear elasticity is positive definite;
  // negative ratios are auxetic materials.
  if (!(m.poissonRatio > -1 && m.poissonRatio < 0.5))
    throw Error("Poisson's ratio must lie in (-1, 0.5), got " + formatNumber(m.poissonRatio));
  if (!(m.density > 0) || !std::isfinite(m.density))
    throw Error("density must be finite and positive, got " + formatNumber(m.density));
  if (!(m.massDamping >= 0) || !std::isfinite(m.massDamping))
    throw Error("Rayleigh mass damping (alpha) must be finite and >= 0, got " +
                formatNumber(m.massDamping));
  if (!(m.stiffnessDamping >= 0) || !std::isfinite(m.stiffnessDamping))
    throw Error("Rayleigh stiffness damping (beta) must be finite and >= 0, got " +
                formatNumber(m.stiffnessDamping));
}

}  // namespace tetskin
