// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/core/Appearance.h"

#include <cmath>

#include "tetskin/core/Error.h"
#include "tetskin/core/NumberText.h"

namespace tetskin {

std::optional<FurParameterProblem> furParameterProblem(const FurParameters& p) {
  std::optional<FurParameterProblem> problem;
  auto check = [&](const char* key, double value, double min, double max,
                   bool minExclusive = false) {
    if (problem) return;
    if (!std::isfinite(value) || value < min || value > max || (minExclusive && value == min))
      problem = FurParameterProblem{key, outOfRange(min, max, minExclusive, formatNumber(value))};
  };
  check("shells", p.shells, 1, 256);
  check("length", p.length, 0, 1, true);
  check("density", p.density, 0, 1);
  check("texture_size", p.textureSize, 8, 4096);
  check("texture_repeats", p.textureRepeats, 0, 1000, true);
  check("root_shade", p.rootShade, 0, 1);
  check("drag", p.drag, 0, 10);
  check("max_bend", p.maxBend, 0, 1);
  check("velvet", p.velvet, 0, 1);
  check("base_darkening", p.baseDarkening, 0, 1);
  check("min_shells", p.minShells, 1, p.shells);
  return problem;
}

}  // namespace tetskin
