# SPDX-License-Identifier: AGPL-3.0-or-later
"""load_dataset, Dataset, Level and build."""
import json

import numpy as np
import pytest

import tetskin
from conftest import DATA, TEST_DATA, interrupt_after


def test_levels_count_from_the_coarsest_and_negative_from_the_finest(bunny):
    assert bunny.levels == len(bunny) == 3
    assert bunny.level(-1).index == 2 and bunny.level(-3).index == 0
    assert bunny.level().index == 2
    with pytest.raises(tetskin.Error, match="level 3 does not exist"):
        bunny.level(3)
    with pytest.raises(tetskin.Error, match="level -4 does not exist"):
        bunny.level(-4)


def test_a_level_matches_the_files_and_the_config(bunny):
    config = json.loads((DATA / "bunny.json").read_text())
    first = 0
    for k, entry in enumerate(config["levels"]):
        level = bunny.level(k)
        assert level.nodes.shape == (entry["nodes"][1], 3)  # [first, count]
        assert level.elements.shape == (entry["elements"][1], 4)
        assert entry["nodes"][0] == first
        assert level.elements.min() == 0 and level.elements.max() == len(level.nodes) - 1
        assert level.first_node == first
        np.testing.assert_array_equal(bunny.nodes[first : first + len(level.nodes)], level.nodes)
        first += len(level.nodes)
    assert len(bunny.nodes) == first


def test_level_arrays_are_read_only_views(bunny):
    level = bunny.level(0)
    nodes = level.nodes
    assert not nodes.flags.writeable
    assert nodes.base is not None  # a view, kept alive by the level
    with pytest.raises(ValueError):
        nodes[0, 0] = 1
    again = level.nodes
    assert again.__array_interface__["data"][0] == nodes.__array_interface__["data"][0]


def test_volume_is_the_elements_and_the_boundary_encloses_it(bunny):
    level = bunny.level(1)
    X, T = level.nodes, level.elements
    a, b, c, d = (X[T[:, i]] for i in range(4))
    volumes = np.einsum("ij,ij->i", np.cross(b - a, c - a), d - a) / 6
    assert (volumes > 0).all()
    assert level.volume == pytest.approx(volumes.sum(), rel=1e-12)
    # The divergence theorem over the outward boundary triangles gives it again.
    p, q, r = (X[level.boundary_faces[:, i]] for i in range(3))
    enclosed = np.einsum("ij,ij->i", p, np.cross(q, r)).sum() / 6
    assert enclosed == pytest.approx(level.volume, rel=1e-9)


def test_a_tetrahedral_mesh_from_elsewhere_is_a_one_level_dataset():
    dataset = tetskin.load_dataset(TEST_DATA / "gmsh" / "sphere_coarse_v41.msh")
    assert dataset.levels == 1
    assert dataset.level(0).elements.shape[1] == 4


def test_a_missing_or_malformed_dataset_is_an_error_naming_it(tmp_path):
    with pytest.raises(tetskin.Error, match="nothing.json"):
        tetskin.load_dataset(tmp_path / "nothing.json")
    with pytest.raises(tetskin.Error, match="truncated.mesh"):
        tetskin.load_dataset(TEST_DATA / "truncated.mesh")


def test_build_makes_the_dataset_the_command_makes(tmp_path, cli):
    progress = []
    built = tetskin.build(
        [TEST_DATA / "cube_0.obj"], tmp_path / "py" / "cube", levels=2, min_elements=50,
        max_elements=400, size_to_targets=True, jobs=1,
        progress=lambda stage, done, total: progress.append((stage, done, total)))
    cli("build", TEST_DATA / "cube_0.obj", "-o", tmp_path / "cli" / "cube", "--levels", 2,
        "--min-elements", 50, "--max-elements", 400, "--size-to-targets", "--jobs", 1, "-q")
    made = tetskin.load_dataset(tmp_path / "cli" / "cube.json")
    assert built.levels == made.levels == 2
    for k in range(2):
        np.testing.assert_array_equal(built.level(k).nodes, made.level(k).nodes)
        np.testing.assert_array_equal(built.level(k).elements, made.level(k).elements)
    assert progress and all(done <= total for _, done, total in progress)
    assert (tmp_path / "py" / "cube.node").exists()
    # Each level measured against the input, as the config records it.
    for k in range(2):
        fidelity = built.level(k).fidelity
        assert fidelity["faithful"]
        assert 0 <= fidelity["input_to_level_mean"] <= fidelity["input_to_level_max"]
        assert fidelity["input_to_level_mean"] <= fidelity["bound_mean"]
        assert fidelity["element_size"] > 0
    assert tetskin.load_dataset(TEST_DATA / "gmsh" / "sphere_coarse_v41.msh").level(0).fidelity is None


def test_build_refuses_unknown_options_and_bad_values(tmp_path):
    with pytest.raises(tetskin.Error, match="build: unknown option 'qualitys'"):
        tetskin.build(TEST_DATA / "cube_0.obj", tmp_path / "x", qualitys=[1.5])
    with pytest.raises(tetskin.Error, match="qualities: each must be > 1.0"):
        tetskin.build(TEST_DATA / "cube_0.obj", tmp_path / "x", qualities=[0.9])
    with pytest.raises(tetskin.Error, match="unknown mesher 'tetgem'"):
        tetskin.build(TEST_DATA / "cube_0.obj", tmp_path / "x", mesher="tetgem")
    assert not (tmp_path / "x.json").exists()


def test_ctrl_c_stops_a_build_and_leaves_no_dataset(tmp_path):
    interrupt_after(1.0)
    with pytest.raises(KeyboardInterrupt):
        tetskin.build(DATA / "bunny.obj", tmp_path / "big", levels=4, max_elements=100000,
                      decimate=True, jobs=1)
    assert not (tmp_path / "big.json").exists()
