// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/core/ElasticMaterial.h"

#include <string>

#include "tetskin/core/Error.h"

namespace tetskin {

std::array<MaterialField, 5> materialFields() {
  using namespace material_option;
  return {{{&kYoungsModulus, &ElasticMaterial::youngsModulus},
           {&kPoissonRatio, &ElasticMaterial::poissonRatio},
           {&kDensity, &ElasticMaterial::density},
           {&kMassDamping, &ElasticMaterial::massDamping},
           {&kStiffnessDamping, &ElasticMaterial::stiffnessDamping}}};
}

std::optional<MaterialProblem> materialProblem(const ElasticMaterial& m) {
  for (const MaterialField& f : materialFields())
    if (auto what = f.option->problem(m.*f.field)) return MaterialProblem{f.option->key, *what};
  return std::nullopt;
}

std::string describe(const ElasticMaterial& m) {
  return "E " + formatNumber(m.youngsModulus) + " Pa, nu " + formatNumber(m.poissonRatio) +
         ", density " + formatNumber(m.density) + " kg/m^3, alpha " + formatNumber(m.massDamping) +
         ", beta " + formatNumber(m.stiffnessDamping);
}

void validateMaterial(const ElasticMaterial& material) {
  if (const auto problem = materialProblem(material)) throw Error(problem->what);
}

}  // namespace tetskin
