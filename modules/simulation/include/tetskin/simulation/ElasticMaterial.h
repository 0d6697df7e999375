// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Isotropic linear-elastic material with lumped mass and Rayleigh damping.

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

// Throws Error for non-physical values.
void validateMaterial(const ElasticMaterial& material);

}  // namespace tetskin
