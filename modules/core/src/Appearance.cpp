// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/core/Appearance.h"

#include <cmath>

#include "tetskin/core/Error.h"
#include "tetskin/core/NumberText.h"

namespace tetskin {

std::optional<FurParameterProblem> furParameterProblem(const FurParameters& p) {
  using namespace fur_option;
  std::optional<FurParameterProblem> problem;
  // (The words of every range check of a config: outOfRange's.)
  auto check = [&](const NumberOption& option, double value, double max) {
    if (problem) return;
    NumberRange range = option.range;
    range.max = max;
    if (!range.contains(value))
      problem = FurParameterProblem{
          option.key, outOfRange(range.min, range.max, !range.minIncluded, formatNumber(value))};
  };
  for (const auto& [option, value] :
       {std::pair{&kShells, static_cast<double>(p.shells)}, std::pair{&kLength, p.length},
        std::pair{&kDensity, p.density},
        std::pair{&kTextureSize, static_cast<double>(p.textureSize)},
        std::pair{&kTextureRepeats, p.textureRepeats}, std::pair{&kRootShade, p.rootShade},
        std::pair{&kDrag, p.drag}, std::pair{&kMaxBend, p.maxBend}, std::pair{&kVelvet, p.velvet},
        std::pair{&kBaseDarkening, p.baseDarkening}})
    check(*option, value, option->range.max);
  check(kMinShells, p.minShells, p.shells);
  return problem;
}

}  // namespace tetskin
