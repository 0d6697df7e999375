// SPDX-License-Identifier: AGPL-3.0-or-later
#include "MaterialOptions.h"

#include <string>

#include "OptionChecks.h"
#include "tetskin/core/Error.h"

namespace tetskin::cli {

void addMaterialOptions(CLI::App& cmd, MaterialOverrides& material) {
  // (The range is the material's to check, after the config's values are
  // taken: MaterialOverrides::over names the option.)
  const auto fields = materialFields();
  for (std::size_t i = 0; i < fields.size(); ++i) {
    const NumberOption& schema = *fields[i].option;
    addFlagOf(cmd, schema, material.values[i],
              std::string(schema.help) +
                  " (without a config value: " + formatNumber(schema.defaultValue) + ")",
              finiteNumber())
        ->group(kMaterialGroup);
  }
}

CLI::Option* addTimeStepOption(CLI::App& cmd, double& timeStep) {
  return addNumberOption(cmd, simulation_option::kTimeStep, timeStep);
}

}  // namespace tetskin::cli
