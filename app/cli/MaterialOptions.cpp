// SPDX-License-Identifier: AGPL-3.0-or-later
#include "MaterialOptions.h"

#include <map>
#include <string>

#include "OptionChecks.h"
#include "tetskin/core/Error.h"

namespace tetskin::cli {

void addMaterialOptions(CLI::App& cmd, MaterialArgs& a) {
  const ElasticMaterial defaults;
  auto option = [&](const char* name, std::optional<double>& value, const char* what,
                    double fallback) {
    cmd.add_option(name, value,
                   std::string(what) + " (without a config value: " + formatNumber(fallback) + ")")
        ->check(finiteNumber())
        ->group(kMaterialGroup);
  };
  option("--young", a.young, "Young's modulus, Pa", defaults.youngsModulus);
  option("--poisson", a.poisson, "Poisson's ratio, in (-1, 0.5)", defaults.poissonRatio);
  option("--density", a.density, "density, kg/m^3", defaults.density);
  option("--alpha", a.alpha, "Rayleigh mass damping, 1/s", defaults.massDamping);
  option("--beta", a.beta, "Rayleigh stiffness damping, s", defaults.stiffnessDamping);
}

CLI::Option* addTimeStepOption(CLI::App& cmd, double& timeStep) {
  return cmd.add_option("--dt", timeStep, "time step in seconds")
      ->capture_default_str()
      ->check(positiveNumber());
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
  if (const auto problem = materialProblem(m)) {
    const std::map<std::string, std::string> options = {{"youngs_modulus", "--young"},
                                                        {"poisson_ratio", "--poisson"},
                                                        {"density", "--density"},
                                                        {"mass_damping", "--alpha"},
                                                        {"stiffness_damping", "--beta"}};
    const auto option = options.find(problem->key);
    throw Error((option == options.end() ? problem->key : option->second) + ": " + problem->what);
  }
  return m;
}

}  // namespace tetskin::cli
