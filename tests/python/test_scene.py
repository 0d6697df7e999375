# SPDX-License-Identifier: AGPL-3.0-or-later
"""Scene: a scene file or dict run as `tetskin simulate SCENE.json` runs it,
its skin kept out of the bowl, its run the command's, and bad scenes
refused naming the field."""
import json

import numpy as np
import pytest

import tetskin
from conftest import DATA

SCENE = DATA / "scenes" / "bunny-in-bowl.json"


def scene_dict(level=0):
    """The bundled scene as a dict, its paths made absolute."""
    scene = json.loads(SCENE.read_text())
    body = scene["bodies"][0]
    body["dataset"] = str((SCENE.parent / body["dataset"]).resolve())
    body["surface"] = str((SCENE.parent / body["surface"]).resolve())
    body["level"] = level
    for obstacle in scene["obstacles"]:
        obstacle["surface"] = str(SCENE.parent / obstacle["surface"])
    return scene


def test_the_skin_settles_in_the_bowl_without_entering_it():
    scene = tetskin.Scene(scene_dict(), mass_damping=2.0)
    assert scene.scene_steps == 240
    assert scene.run_spec["scenario"] == "free"
    assert scene.run_spec["options"]["material"]["mass_damping"] == 2.0
    scene.step(400)
    penetration, forces = scene.skin_contact()
    skin = scene.skin_positions()
    assert penetration.shape == (skin.shape[0],) and forces.shape == skin.shape
    diagonal = np.linalg.norm(skin.max(axis=0) - skin.min(axis=0))
    assert 0 < penetration.max() < 0.005 * diagonal
    # Measured independently: the depth in the bowl's exact inner sphere.
    radius = np.linalg.norm(skin, axis=1)
    near = (penetration > -0.5) & (-skin[:, 1] > 0.5 * radius)
    assert np.allclose(penetration[near], radius[near] - 9, atol=0.01)
    # At rest: the contact forces hold the weight (gravity along -y).
    support = scene.contact_forces().sum(axis=0)
    assert support[1] > 0 and abs(support[0]) < 0.01 * support[1]


def test_the_scene_runs_as_the_command_runs_it(cli):
    printed = json.loads(cli("simulate", SCENE, "--level", 0, "--time-step", 0.01, "--print-run"))
    scene = tetskin.Scene(scene_dict(), time_step=0.01)
    ours = scene.run_spec
    # (An obstacle's name says where it came from: the file, or "scene".)
    for run in (ours, printed):
        for obstacle in run["options"]["obstacles"]:
            obstacle.pop("name")
    assert ours["options"] == printed["options"]
    assert ours["parameters"] == printed["parameters"] and ours["level"] == printed["level"]


def test_a_path_reads_relative_to_the_file():
    scene = tetskin.Scene(SCENE)
    assert scene.level == 1 and scene.run_spec["options"]["obstacles"][0]["kinetic_friction"] == 0.4


def test_bad_scenes_name_the_field():
    bad = scene_dict()
    bad["bodies"][0]["colour"] = "red"
    with pytest.raises(tetskin.Error, match="/bodies/0/colour: is not a known field"):
        tetskin.Scene(bad)
    bad = scene_dict()
    bad["obstacles"][0]["surface"] = "nowhere.obj"
    with pytest.raises(tetskin.Error, match="/obstacles/0/surface: .*nowhere.obj: no such file"):
        tetskin.Scene(bad)
    with pytest.raises(tetskin.Error, match="Scene: unknown option 'stepz'"):
        tetskin.Scene(scene_dict(), stepz=3)


def test_several_bodies_step_as_one_and_meet_skin_to_skin():
    """A bunny dropped onto another comes to lie on it; alone, it falls to
    the floor. run_spec's bodies say where each body's nodes lie."""
    bunny = str((DATA / "bunny.json").resolve())
    lower = {"dataset": bunny, "level": 0}
    upper = {"dataset": bunny, "level": 0, "translate": [0.5, 10.5, 0], "velocity": [0, -3, 0],
             "material": {"youngs_modulus": 4e5}}
    # (The skins are the coarse level's boundaries: their mean edge, the
    # default shell, is thicker than the ears; a 0.3 shell is not.)
    scene = {"format": "tetskin-scene", "version": 1, "floor": {"height": 0},
             "skin_contact": {"thickness": 0.3}, "bodies": [lower, upper]}
    both = tetskin.Scene(scene, mass_damping=1.0)
    bodies = both.run_spec["bodies"]
    assert [b["name"] for b in bodies] == ["/bodies/0", "/bodies/1"]
    first, count = bodies[1]["nodes"]
    assert both.positions.shape == (first + count, 3) and first == count
    assert bodies[1]["material"]["youngs_modulus"] == 4e5
    assert bodies[0]["material"]["youngs_modulus"] == 2e5
    both.step(90)
    resting = both.positions[first:, 1].min()
    alone = tetskin.Scene(dict(scene, bodies=[upper]), mass_damping=1.0)
    alone.step(90)
    fallen = alone.positions[:, 1].min()
    assert fallen < 3 < 5 < resting, (fallen, resting)
