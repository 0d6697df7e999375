// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// A resolved run (RunSpec) written out field by field as JSON: what
// `tetskin simulate --print-run`, `tetskin render --print-run`,
// `tetskin-gui --print-run` and Python's Simulation.run_spec show, so that a
// user sees what a run will be before it runs, and the front ends' parity
// test compares them (tests/python/test_run_parity.py).
//
// Keys are the options' schema keys (OptionSchema.h: "time_step",
// "poisson_ratio", ...), enums their schema names ("auto", "full"). Output
// (one JSON object, keys sorted, 2-space indent):
//   dataset, level, scenario, initial_velocity [x, y, z] (m/s)
//   parameters: the scenario's numbers by key, fixed_nodes (ids), loads
//     (nodeCount x 3 rows, N; [] for none), load_curve ({points: [[t, f]],
//     after: "hold"|"repeat"}), load_seconds (null: for ever),
//     surface_loads ([{pressure (Pa), traction [x, y, z] (Pa), faces
//     [[a, b, c]] (the level's node ids, wound outward)}])
//   options: material (by key), time_step, gravity [x, y, z] (m/s^2), up,
//     floor_height (null: no floor), floor_stiffness, friction, tangent,
//     solver, tolerance, guess_solutions, coarse_reuse, coarse_operators,
//     coarse_levels, single_precision_cycle, smoother, max_iterations,
//     custom_preconditioner (bool), contact_points, obstacles (per
//     obstacle: name, translation, rotation [w, x, y, z], scale, motion
//     [{time, translation, rotation}], static_friction, kinetic_friction,
//     stiffness (0: automatic))

#include <string>

#include "tetskin/session/SimulationSession.h"

namespace tetskin {

std::string runSpecJson(const RunSpec& spec);

}  // namespace tetskin
