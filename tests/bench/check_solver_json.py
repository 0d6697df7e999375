# SPDX-License-Identifier: AGPL-3.0-or-later
"""Checks solver_bench's --json output: every cell (level x material x
solver) is there, with a run per repetition and its figures.
Usage: check_solver_json.py FILE REPETITIONS"""
import json
import sys

MATERIALS = ["E 2e5", "E 2e6", "E 2e7", "E 2e6, nu 0.45"]
SOLVERS = ["cg", "multigrid", "mg-gauss-seidel", "auto", "cholmod", "cholmod-pcg/10", "amg-pcg/4"]

data = json.load(open(sys.argv[1]))
repetitions = int(sys.argv[2])
assert data["repetitions"] == repetitions, data["repetitions"]
level = data["levels"]["bunny level 2"]
assert level["elements"] == 12713, level["elements"]
for material in MATERIALS:
    row = level["materials"][material]
    assert row["difficulty"] > 0, material
    for solver in SOLVERS:
        cell = row["solvers"][solver]
        assert not cell.get("failed"), (material, solver, cell["runs"][0]["error"])
        assert len(cell["runs"]) == repetitions, (material, solver)
        assert cell["ms_per_step"] > 0 and cell["iterations"] >= 1, (material, solver)
        for run in cell["runs"]:
            assert run["element_pass_ms"] > 0 and run["solve_ms"] > 0, (material, solver)
        # A direct solve needs one iteration: CG preconditioned by the exact inverse.
        if solver == "cholmod":
            assert cell["iterations"] == 1, cell["iterations"]
print("PASS: every cell of", len(MATERIALS), "materials x", len(SOLVERS), "solvers")
