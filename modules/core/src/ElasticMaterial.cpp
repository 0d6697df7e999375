// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/core/ElasticMaterial.h"

#include <cmath>
#include <string>

#include "tetskin/core/Error.h"

namespace tetskin {

std::optional<MaterialProblem> materialProblem(const ElasticMaterial& m) {
  auto problem = [](const char* key, const std::string& what, double value) {
    return MaterialProblem{key, what + ", got " + formatNumber(value)};
  };
  if (!(m.youngsModulus > 0) || !std::isfinite(m.youngsModulus))
    return problem("youngs_modulus", "Young's modulus must be finite and positive",
                   m.youngsModulus);
  // (-1, 0.5): where isotropic linear elasticity is positive definite;
  // negative ratios are auxetic materials.
  if (!(m.poissonRatio > -1 && m.poissonRatio < 0.5))
    return problem("poisson_ratio", "Poisson's ratio must lie in (-1, 0.5)", m.poissonRatio);
  if (!(m.density > 0) || !std::isfinite(m.density))
    return problem("density", "density must be finite and positive", m.density);
  if (!(m.massDamping >= 0) || !std::isfinite(m.massDamping))
    return problem("mass_damping", "Rayleigh mass damping (alpha) must be finite and >= 0",
                   m.massDamping);
  if (!(m.stiffnessDamping >= 0) || !std::isfinite(m.stiffnessDamping))
    return problem("stiffness_damping", "Rayleigh stiffness damping (beta) must be finite and >= 0",
                   m.stiffnessDamping);
  return std::nullopt;
}

std::string describe(const ElasticMaterial& m) {
  return "E " + formatNumber(m.youngsModulus) + " Pa, nu " + formatNumber(m.poissonRatio) +
         ", density " + formatNumber(m.density) + " kg/m^3, alpha " + formatNumber(m.massDamping) +
         ", beta " + formatNumber(m.stiffnessDamping);
}

void validateMaterial(const ElasticMaterial& material) {
  if (const auto problem = materialProblem(material)) throw Error(problem->what);
}

}  // namespace tetskin
