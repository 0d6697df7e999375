// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/simulation/ElasticMaterial.h"

#include <cmath>
#include <string>

#include "tetskin/core/Error.h"

namespace tetskin {

void validateMaterial(const ElasticMaterial& m) {
  if (!(m.youngsModulus > 0) || !std::isfinite(m.youngsModulus))
    throw Error("Young's modulus must be positive, got " + std::to_string(m.youngsModulus));
  if (!(m.poissonRatio >= 0 && m.poissonRatio < 0.5))
    throw Error("Poisson's ratio must lie in [0, 0.5), got " + std::to_string(m.poissonRatio));
  if (!(m.density > 0) || !std::isfinite(m.density))
    throw Error("density must be positive, got " + std::to_string(m.density));
  if (!(m.massDamping >= 0) || !(m.stiffnessDamping >= 0) || !std::isfinite(m.massDamping) ||
      !std::isfinite(m.stiffnessDamping))
    throw Error("Rayleigh damping coefficients must be >= 0");
}

}  // namespace tetskin
