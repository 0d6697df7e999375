// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The check a contact's coefficients share, whatever meets what (an
// obstacle, the skins): Coulomb friction with 0 <= mu_k <= mu_s and a
// penalty stiffness >= 0 (0: automatic), all finite.

#include <optional>
#include <string>

namespace tetskin {

// "friction must satisfy 0 <= kinetic <= static, got static 0.2 and
// kinetic 0.3" or "the stiffness must be finite and >= 0 (0: automatic),
// got -1" (the caller names whose); nullopt when all is well.
std::optional<std::string> contactCoefficientProblem(double staticFriction, double kineticFriction,
                                                     double stiffness);

}  // namespace tetskin
