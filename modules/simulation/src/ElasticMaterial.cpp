// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/simulation/ElasticMaterial.h"

#include <cmath>
#include <string>

#include "tetskin/core/Error.h"

namespace tetskin {

void validateMaterial(const ElasticMaterial& m) {
  if (!(m.youngsModulus > 0) || !std::isfinite(m.youngsModulus))
    throw Error("Young's modulus must be positive, got " + formatNumber(m.youngsModulus));
  // (-1, 0.5): where isotropic linear elasticity is positive definite;
  // negative ratios are auxetic materials.
  if (!(m.poissonRatio > -1 && m.poissonRatio < 0.5))
    throw Error("Poisson's ratio must lie in (-1, 0.5), got " + formatNumber(m.poissonRatio));
  if (!(m.density > 0) || !std::isfinite(m.density))
    throw Error("density must be positive, got " + formatNumber(m.density));
  if (!(m.massDamping >= 0) || !(m.stiffnessDamping >= 0) || !std::isfinite(m.massDamping) ||
      !std::isfinite(m.stiffnessDamping))
    throw Error("Rayleigh damping coefficients must be >= 0");
}

}  // namespace tetskin
