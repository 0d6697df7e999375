// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The material options of the commands that simulate (`simulate`, `render
// --frames`): each overrides one value of the dataset config's elasticity
// section, and --time-step the time step.

#include <CLI/CLI.hpp>
#include <optional>

#include "tetskin/core/ElasticMaterial.h"
#include "tetskin/session/RunRequest.h"
#include "tetskin/simulation/Simulation.h"

namespace tetskin::cli {

// The --help heading of the material options.
inline constexpr const char* kMaterialGroup =
    "Material (default: the dataset config's elasticity section)";

// Adds --youngs-modulus, --poisson-ratio, --density, --mass-damping and --stiffness-damping (the
// group kMaterialGroup) to `cmd`, each setting its value of `material` (in materialFields()'s
// order). Their ranges are materialProblem's, checked by MaterialOverrides::over.
void addMaterialOptions(CLI::App& cmd, MaterialOverrides& material);

// Adds --time-step (seconds, > 0) to `cmd`, setting `timeStep`.
CLI::Option* addTimeStepOption(CLI::App& cmd, double& timeStep);

}  // namespace tetskin::cli
