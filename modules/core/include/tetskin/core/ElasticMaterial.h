// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Isotropic linear-elastic material with lumped mass and Rayleigh damping:
// what the simulation needs of a body, and what a dataset config records
// for it (section `elasticity`, keys as in materialProblem()).

#include <optional>
#include <string>

namespace tetskin {

struct ElasticMaterial {
  double youngsModulus = 2.0e5;    // Pa: the bunny (10 m, 100 kg/m^3) sags about 5% under gravity
  double poissonRatio = 0.3;       // (-1, 0.5)
  double density = 100.0;          // kg / m^3
  double massDamping = 0.1;        // Rayleigh alpha: C = alpha M + beta K
  double stiffnessDamping = 0.01;  // Rayleigh beta, seconds

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

// One line for people: "E 200000 Pa, nu 0.3, density 100 kg/m^3, alpha
// 0.1, beta 0.01".
std::string describe(const ElasticMaterial& material);

// Throws Error (materialProblem's `what`) for a non-physical value.
void validateMaterial(const ElasticMaterial& material);

}  // namespace tetskin
