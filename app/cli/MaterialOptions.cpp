// SPDX-License-Identifier: AGPL-3.0-or-later
#include "MaterialOptions.h"

#include <string>

#include "OptionChecks.h"
#include "tetskin/core/Error.h"

namespace tetskin::cli {

void addMaterialOptions(CLI::App& cmd, MaterialArgs& a) {
  // (The range is the material's to check, after the config's values are
  // taken: materialOf names the option.)
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

ElasticMaterial materialOf(const MaterialArgs& a, const ElasticMaterial& config) {
  ElasticMaterial m = config;
  m.youngsModulus = a.young.value_or(m.youngsModulus);
  m.poissonRatio = a.poisson.value_or(m.poissonRatio);
  m.density = a.density.value_or(m.density);
  m.massDamping = a.alpha.value_or(m.massDamping);
  m.stiffnessDamping = a.beta.value_or(m.stiffnessDamping);
  // A config's values were checked as it was read: a problem now is an
  // option's, named as the user typed it.
  if (const auto problem = materialProblem(m))
    for (const MaterialField& field : materialFields())
      if (problem->key == field.option->key)
        throw Error(std::string(field.option->flag) + ": " + problem->what);
  return m;
}

}  // namespace tetskin::cli
