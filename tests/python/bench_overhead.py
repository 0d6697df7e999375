# SPDX-License-Identifier: AGPL-3.0-or-later
"""What calling TetSkin from Python costs: tetskin.deform and
Simulation.step against the same C++ calls on the same objects, timed in
C++ (tetskin._tetskin._native) in the same run, call by call in turn.

    PYTHONPATH=build/lib/python3/dist-packages python3 tests/python/bench_overhead.py [--json]

The bundled bunny: the ~12.7k-element level, the 64k-vertex surface bound to
it. Prints the median of the rounds and each round's ratio.
"""
import json
import pathlib
import statistics
import sys
import time

import numpy as np

import tetskin
from tetskin._tetskin import _native

DATA = pathlib.Path(__file__).resolve().parents[2] / "data"
ROUNDS = 7


def python_seconds(call, calls):
    start = time.perf_counter()
    for _ in range(calls):
        call()
    return (time.perf_counter() - start) / calls


def main():
    dataset = tetskin.load_dataset(DATA / "bunny.json")
    level = dataset.level(-1)
    V, F = tetskin.read_surface(DATA / "bunny_64k.obj")
    binding = tetskin.bind(dataset, V, F, level=-1)
    rng = np.random.default_rng(0)
    control = dataset.nodes + 1e-3 * rng.standard_normal(dataset.nodes.shape)
    out = (np.empty_like(V), np.empty_like(V))
    sim = tetskin.Simulation(dataset, level=-1, scenario="wobble", solver="cg")
    sim.step(10)  # past the start's transient

    # Alternating single calls (C++, then Python), so that both see the same
    # machine and, for the steps, the same stretch of the motion.
    rows = {"deform": [], "deform (out=)": [], "Simulation.step": []}
    for _ in range(ROUNDS):
        for name, native, call, calls in [
            ("deform", lambda: _native.deform_seconds(binding, control, 1),
             lambda: tetskin.deform(binding, control), 40),
            ("deform (out=)", lambda: _native.deform_seconds(binding, control, 1),
             lambda: tetskin.deform(binding, control, out=out), 40),
            ("Simulation.step", lambda: _native.step_seconds(sim, 1), sim.step, 10),
        ]:
            cpp = py = 0.0
            for _ in range(calls):
                cpp += native()
                py += python_seconds(call, 1)
            rows[name].append((py / calls, cpp / calls))

    result = {
        "level": {"nodes": int(len(level.nodes)), "elements": int(len(level.elements))},
        "surface_vertices": int(len(V)),
        "rounds": ROUNDS,
        "calls": {},
    }
    print(f"level {level.index}: {len(level.elements)} elements; surface {len(V)} vertices; "
          f"{ROUNDS} interleaved rounds")
    print(f"{'call':18} {'python ms':>10} {'c++ ms':>10} {'overhead':>9}  per round")
    for name, pairs in rows.items():
        ratios = [p / c - 1 for p, c in pairs]
        py_ms = statistics.median(p for p, _ in pairs) * 1e3
        cpp_ms = statistics.median(c for _, c in pairs) * 1e3
        overhead = statistics.median(ratios)
        result["calls"][name] = {"python_ms": py_ms, "cpp_ms": cpp_ms, "overhead": overhead,
                                 "overhead_per_round": ratios}
        print(f"{name:18} {py_ms:10.3f} {cpp_ms:10.3f} {overhead:+9.1%}  "
              + " ".join(f"{r:+.1%}" for r in ratios))
    if "--json" in sys.argv:
        print(json.dumps(result, indent=2))


if __name__ == "__main__":
    main()
