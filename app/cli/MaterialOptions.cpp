// SPDX-License-Identifier: AGPL-3.0-or-later
#include "MaterialOptions.h"

#include <string>

#include "OptionChecks.h"
#include "tetskin/core/Error.h"

namespace tetskin::cli {

void addMaterialOptions(CLI::App& cmd, MaterialArgs& a) {
  // (The range is the material's to check, after the config's values are
  // taken: MaterialOverrides::over names the option.)
  auto option = [&](const NumberOption& schema, std::optional<double>& value) {
    cmd.add_option(schema.flag, value,
                   std::string(schema.help) +
                       " (without a config value: " + formatNumber(schema.defaultValue) + ")")
        ->check(finiteNumber())
        ->group(kMaterialGroup);
  };
  using namespace material_option;
  option(kYoungsModulus, a.young);
  option(kPoissonRatio, a.poisson);
  option(kDensity, a.density);
  option(kMassDamping, a.alpha);
  option(kStiffnessDamping, a.beta);
}

CLI::Option* addTimeStepOption(CLI::App& cmd, double& timeStep) {
  return addNumberOption(cmd, simulation_option::kTimeStep, timeStep);
}

MaterialOverrides overridesOf(const MaterialArgs& a) {
  MaterialOverrides m;
  using namespace material_option;
  for (auto [option, value] :
       {std::pair{&kYoungsModulus, a.young}, std::pair{&kPoissonRatio, a.poisson},
        std::pair{&kDensity, a.density}, std::pair{&kMassDamping, a.alpha},
        std::pair{&kStiffnessDamping, a.beta}})
    if (value) m.set(*option, *value);
  return m;
}

}  // namespace tetskin::cli
