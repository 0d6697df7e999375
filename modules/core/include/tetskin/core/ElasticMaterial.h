// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Isotropic linear-elastic material with lumped mass and Rayleigh damping:
// what the simulation needs of a body, and what a dataset config records
// for it (section `elasticity`, keys as in materialProblem()).

#include <array>
#include <optional>
#include <string>

#include "tetskin/core/OptionSchema.h"

namespace tetskin {

// The material's options (OptionSchema.h): config keys, command-line flags,
// ranges and defaults.
namespace material_option {
// The default: the bunny (10 m, 100 kg/m^3) sags about 5% under gravity.
inline constexpr NumberOption kYoungsModulus{
    "youngs_modulus",      "--youngs-modulus", "--young", "Young's modulus",
    "Young's modulus, Pa", above(0),           2.0e5};
// (-1, 0.5): where isotropic linear elasticity is positive definite;
// negative ratios are auxetic materials.
inline constexpr NumberOption kPoissonRatio{"poisson_ratio",
                                            "--poisson-ratio",
                                            "--poisson",
                                            "Poisson's ratio",
                                            "Poisson's ratio, in (-1, 0.5)",
                                            between(-1, 0.5, false, false),
                                            0.3};
inline constexpr NumberOption kDensity{"density",         "--density", "",   "density",
                                       "density, kg/m^3", above(0),    100.0};
inline constexpr NumberOption kMassDamping{"mass_damping",
                                           "--mass-damping",
                                           "--alpha",
                                           "Rayleigh mass damping (alpha)",
                                           "Rayleigh mass damping, 1/s",
                                           atLeast(0),
                                           0.1};
inline constexpr NumberOption kStiffnessDamping{"stiffness_damping",
                                                "--stiffness-damping",
                                                "--beta",
                                                "Rayleigh stiffness damping (beta)",
                                                "Rayleigh stiffness damping, s",
                                                atLeast(0),
                                                0.01};
}  // namespace material_option

struct ElasticMaterial {
  double youngsModulus = material_option::kYoungsModulus.defaultValue;  // Pa
  double poissonRatio = material_option::kPoissonRatio.defaultValue;
  double density = material_option::kDensity.defaultValue;  // kg / m^3
  double massDamping =
      material_option::kMassDamping.defaultValue;  // Rayleigh alpha: C = alpha M + beta K
  double stiffnessDamping = material_option::kStiffnessDamping.defaultValue;  // Rayleigh beta, s

  double lameLambda() const {
    return youngsModulus * poissonRatio / ((1 + poissonRatio) * (1 - 2 * poissonRatio));
  }
  double lameMu() const { return youngsModulus / (2 * (1 + poissonRatio)); }
};

// The first non-physical value of `material`: its key (snake_case, as in a
// dataset config's `elasticity` section: youngs_modulus, poisson_ratio,
// density, mass_damping, stiffness_damping) and what is wrong, e.g.
// {"poisson_ratio", "Poisson's ratio must lie in (-1, 0.5), got 0.5"};
// nullopt when all are valid. The one check of the ranges.
struct MaterialProblem {
  std::string key;
  std::string what;
};
std::optional<MaterialProblem> materialProblem(const ElasticMaterial& material);

// Each option of the material with its field, in the order above.
struct MaterialField {
  const NumberOption* option;
  double ElasticMaterial::*field;
};
std::array<MaterialField, 5> materialFields();

// One line for people: "E 200000 Pa, nu 0.3, density 100 kg/m^3, alpha
// 0.1, beta 0.01".
std::string describe(const ElasticMaterial& material);

// Throws Error (materialProblem's `what`) for a non-physical value.
void validateMaterial(const ElasticMaterial& material);

}  // namespace tetskin
