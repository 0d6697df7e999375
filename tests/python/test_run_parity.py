# SPDX-License-Identifier: AGPL-3.0-or-later
"""The front ends' parity: the same request from the command line
(`simulate`, `render` with --frames' run), the GUI (its Simulation dock) and
Python yields the same run, field by field (RunSpecJson.h: every option,
after the dataset config and the defaults). A front end whose default
drifted (render once ran cg where simulate ran auto; Python once ran a free
body where the others ran wobble) fails here. No front end keeps a default
of its own on purpose.

The GUI is compared where it is built (TETSKIN_GUI); it needs a display, as
every GUI test does.
"""
import json
import os
import subprocess

import pytest

import tetskin
from conftest import DATA

DATASET = str(DATA / "bunny.json")


def differences(a, b, path=""):
    """The fields in which two run specs differ, as 'path: a != b' lines."""
    if isinstance(a, dict) and isinstance(b, dict):
        lines = []
        for key in sorted(set(a) | set(b)):
            lines += differences(a.get(key, "<missing>"), b.get(key, "<missing>"), f"{path}/{key}")
        return lines
    return [] if a == b else [f"{path}: {a!r} != {b!r}"]


def printed_run(exe, *args):
    done = subprocess.run([exe, *map(str, args)], capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout)


@pytest.fixture(scope="module")
def front_ends(cli):
    """For each front end, a function from (scenario or None, level or None)
    to its printed run spec; the GUI's when it is built."""
    exe = os.environ["TETSKIN_CLI"]

    def level_args(level):
        return [] if level is None else ["--level", level]

    def scenario_args(scenario):
        return [] if scenario is None else ["--scenario", scenario]

    ends = {
        "simulate": lambda s, l: printed_run(
            exe, "simulate", DATASET, "--print-run", *scenario_args(s), *level_args(l)),
        "render --frames": lambda s, l: printed_run(
            exe, "render", DATASET, "--print-run", *scenario_args(s), *level_args(l)),
        "python": lambda s, l: tetskin.Simulation(
            tetskin.load_dataset(DATASET), **({} if l is None else {"level": l}),
            scenario=s).run_spec,
    }
    gui = os.environ.get("TETSKIN_GUI")
    if gui:
        def gui_run(s, l):
            assert l is None, "the GUI's command line runs the dataset's finest level"
            return printed_run(gui, DATASET, "--print-run", *scenario_args(s))
        ends["gui"] = gui_run
    return ends


@pytest.mark.parametrize("scenario", [None, "drop", "sag", "twist"])
def test_every_front_end_resolves_the_same_run(front_ends, scenario):
    specs = {name: run(scenario, None) for name, run in front_ends.items()}
    reference = specs["simulate"]
    assert reference["scenario"] == scenario or (scenario is None and reference["scenario"] == "wobble")
    assert reference["options"]["solver"] == "auto"
    for name, spec in specs.items():
        assert differences(reference, spec) == [], f"{name} differs from simulate"


def test_a_level_and_material_given_resolve_the_same_run(cli):
    from_cli = json.loads(cli("simulate", DATASET, "--print-run", "--level", "0", "--youngs-modulus",
                              "1e5", "--time-step", "0.01", "--solver", "multigrid", "--base-share", "0.2"))
    from_python = tetskin.Simulation(tetskin.load_dataset(DATASET), level=0, youngs_modulus=1e5,
                                     time_step=0.01, solver="multigrid", base_share=0.2).run_spec
    assert differences(from_cli, from_python) == []
    assert from_cli["options"]["material"]["youngs_modulus"] == 1e5
    assert from_cli["options"]["time_step"] == 0.01
    assert from_cli["parameters"]["base_share"] == 0.2
    assert from_cli["level"] == 0


def test_surface_loads_resolve_to_the_same_faces(cli):
    """A pressure by box and a traction by face set: the same faces, values
    and winding from the command line and from Python."""
    faces_file = str(DATA.parent / "tests" / "data" / "bunny_base.faces")
    for cli_args, keywords in [
            (["--pressure", "1000", "--load-box", "-100,4,-100,100,100,100"],
             {"pressure": 1000.0, "load_box": [[-100, 4, -100], [100, 100, 100]]}),
            (["--traction", "0,-100,0", "--load-faces", faces_file],
             {"traction": [0, -100, 0], "load_faces": faces_file})]:
        from_cli = json.loads(cli("simulate", DATASET, "--print-run", "--level", "0", *cli_args))
        from_python = tetskin.Simulation(tetskin.load_dataset(DATASET), level=0,
                                         **keywords).run_spec
        assert differences(from_cli, from_python) == []
        loads = from_cli["parameters"]["surface_loads"]
        assert len(loads) == 1 and len(loads[0]["faces"]) > 0
    assert len(loads[0]["faces"]) == 2 and loads[0]["traction"] == [0, -100, 0]


def test_a_scene_resolves_the_same_run_in_every_front_end(cli):
    """A scene file (bodies, obstacles, contact) is one run for simulate,
    Python's Scene and the GUI (which opens it in its Simulation dock)."""
    scene = str(DATA / "scenes" / "bunny-in-bowl.json")
    specs = {
        "simulate": json.loads(cli("simulate", scene, "--print-run")),
        "python": tetskin.Scene(scene).run_spec,
    }
    gui = os.environ.get("TETSKIN_GUI")
    if gui:
        specs["gui"] = printed_run(gui, scene, "--print-run")
    reference = specs["simulate"]
    assert reference["scenario"] == "free"
    assert len(reference["options"]["obstacles"]) == 1
    for name, spec in specs.items():
        assert differences(reference, spec) == [], f"{name} differs from simulate"
