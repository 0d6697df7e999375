# SPDX-License-Identifier: AGPL-3.0-or-later
"""Simulation: step for step as `tetskin simulate`, its state, forces, fixed
nodes, recording and errors."""
import csv
import threading

import numpy as np
import pytest

import tetskin
from conftest import DATA, interrupt_after

vtk_xml = pytest.importorskip("vtkmodules.vtkIOXML")
from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: E402


def frame_points(path):
    reader = vtk_xml.vtkXMLUnstructuredGridReader()
    reader.SetFileName(str(path))
    reader.Update()
    return vtk_to_numpy(reader.GetOutput().GetPoints().GetData()).astype(np.float64)


@pytest.mark.parametrize("solver,levels", [("cg", None), ("multigrid", None), ("multigrid", "dataset")])
def test_python_matches_the_command_step_for_step(tmp_path, cli, bunny, solver, levels):
    steps = 8
    chosen = {} if levels is None else {"coarse_levels": levels}
    cli("simulate", DATA / "bunny.json", "--level", 1, "--steps", steps, "--solver", solver,
        *([] if levels is None else ["--coarse-levels", levels]),
        "--youngs-modulus", 4e5, "-o", tmp_path / "run.pvd", "--log", tmp_path / "log.csv", "-q")
    with open(tmp_path / "log.csv") as f:
        logged = list(csv.DictReader(f))
    sim = tetskin.Simulation(bunny, level=1, scenario="wobble", solver=solver, youngs_modulus=4e5, **chosen)
    np.testing.assert_array_equal(sim.positions, frame_points(tmp_path / "run_frames" / "control_00000.vtu"))
    for k in range(1, steps + 1):
        stats = sim.step()
        assert stats["solver"] == solver
        assert stats["iterations"] == int(logged[k]["iterations"])
        expected = frame_points(tmp_path / "run_frames" / f"control_{k:05d}.vtu")
        np.testing.assert_allclose(sim.positions, expected, rtol=0, atol=1e-12)
    assert sim.steps == steps and sim.time == pytest.approx(steps / 60)


def test_a_free_body_falls_and_fixed_nodes_stay(bunny):
    level = bunny.level(0)
    # sag without a base: nothing held, gravity only
    sim = tetskin.Simulation(bunny, level=0, scenario="sag", base_share=0)
    assert sim.fixed_nodes == []
    sim.fix_nodes([0, 5])
    sim.step(10)
    X = sim.positions
    np.testing.assert_array_equal(X[[0, 5]], level.nodes[[0, 5]])
    free = np.setdiff1d(np.arange(len(X)), [0, 5])
    assert (X[free, 1] < level.nodes[free, 1]).mean() > 0.5  # it sags, down y
    assert sim.fixed_nodes == [0, 5]


def test_solve_static_rests_the_bunny_on_its_held_base(bunny):
    # The bundled bunny's finest level under gravity, its base held: the
    # static solve converges, and a run started there stays at rest (under
    # 1e-6 of the body's size per second over 1 s).
    sim = tetskin.Simulation(bunny, scenario="sag")
    rest = sim.positions
    stats = sim.solve_static()
    assert stats["converged"] and stats["residual"] <= 1e-8 * stats["load"], stats
    assert stats["iterations"] >= 1 and stats["linear_iterations"] > 0
    sagged = sim.positions
    assert sagged[:, 1].mean() < rest[:, 1].mean()  # it sagged
    assert np.abs(sim.velocities).max() == 0 and sim.time == 0
    size = np.linalg.norm(rest.max(axis=0) - rest.min(axis=0))
    fastest = 0.0
    while sim.time < 1.0:
        sim.step()
        fastest = max(fastest, np.linalg.norm(sim.velocities, axis=1).max())
    assert fastest < 1e-6 * size, fastest


def test_solve_static_refuses_a_free_body_under_gravity(bunny):
    sim = tetskin.Simulation(bunny, level=0, scenario="sag", base_share=0)
    with pytest.raises(tetskin.Error, match="there is no static equilibrium: the body is free"):
        sim.solve_static()


def test_the_default_run_is_every_front_ends(bunny):
    # No scenario and no solver: the run request's defaults, those of
    # `tetskin simulate` and the GUI: wobble (its base held), solver auto.
    sim = tetskin.Simulation(bunny, level=0)
    wobble = tetskin.Simulation(bunny, level=0, scenario="wobble")
    assert len(sim.fixed_nodes) > 0 and sim.fixed_nodes == wobble.fixed_nodes
    assert sim.solver == "auto"


def test_a_fixed_box_and_a_load_curve(bunny):
    level = bunny.level(0)
    low = level.nodes[:, 1].min()
    box = [[-100, low - 1, -100], [100, low + 0.5, 100]]
    sim = tetskin.Simulation(bunny, level=0, scenario="sag", base_share=0, fixed_box=box)
    inside = np.flatnonzero(level.nodes[:, 1] <= low + 0.5)
    assert sim.fixed_nodes == sorted(inside.tolist())
    with pytest.raises(tetskin.Error, match="fixed_box: no node of the level lies in"):
        tetskin.Simulation(bunny, level=0, fixed_box=[[0, 100, 0], [1, 101, 1]])
    loads = np.zeros((len(level.nodes), 3))
    with pytest.raises(tetskin.Error, match="load_curve: applies with loads"):
        tetskin.Simulation(bunny, level=0, load_curve=[[0, 0], [1, 1]])
    with pytest.raises(tetskin.Error, match="load_curve: "):
        tetskin.Simulation(bunny, level=0, loads=loads, load_curve=[[1, 0], [0, 1]])
    with pytest.raises(tetskin.Error, match="load_curve"):
        tetskin.Simulation(bunny, level=0, loads=loads, load_curve=[0, 1, 2])
    tetskin.Simulation(bunny, level=0, loads=loads, load_curve=[[0, 0], [1, 1]]).step(2)


def test_surface_loads_by_box_and_by_faces(bunny):
    level = bunny.level(0)
    top = level.nodes[:, 1].max()
    box = [[-100, top - 1.5, -100], [100, top + 1, 100]]
    sim = tetskin.Simulation(bunny, level=0, scenario="sag", pressure=1000.0, load_box=box)
    forces = sim.surface_load_forces()
    assert forces.shape == (len(level.nodes), 3)
    loaded = np.flatnonzero(np.abs(forces).sum(axis=1) > 0)
    assert len(loaded) > 0 and (level.nodes[loaded, 1] >= top - 1.5).all()
    assert forces[:, 1].sum() < 0  # the top pressed down
    sim.step(3)
    assert "load" in sim.energies() and sim.stress().shape == (len(level.elements), 6)

    # A traction on the whole boundary, its faces given as rows of node ids
    # in any order: its total is the traction times the area.
    faces = level.boundary_faces
    corners = level.nodes[faces]
    area = 0.5 * np.linalg.norm(
        np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0]), axis=1).sum()
    traction = np.array([0.0, -10.0, 2.0])
    sim = tetskin.Simulation(bunny, level=0, scenario="sag", traction=traction,
                             load_faces=faces[:, ::-1])
    total = sim.surface_load_forces().sum(axis=0)
    assert np.abs(total - traction * area).max() <= 1e-12 * np.abs(traction).max() * area

    with pytest.raises(tetskin.Error, match="pressure and traction need load_box or load_faces"):
        tetskin.Simulation(bunny, level=0, pressure=5.0)
    with pytest.raises(tetskin.Error, match="load_faces: row 0: node -1 does not exist"):
        tetskin.Simulation(bunny, level=0, pressure=5.0, load_faces=[[-1, 0, 1]])
    with pytest.raises(tetskin.Error, match="load_faces"):
        tetskin.Simulation(bunny, level=0, pressure=5.0, load_faces=[[0, 1]])
    with pytest.raises(tetskin.Error, match="traction: expected 3 numbers"):
        tetskin.Simulation(bunny, level=0, traction=[1, 2], load_box=box)


def test_probe_reads_a_recorded_run_at_points(tmp_path, bunny):
    # A recorded run read at two nodes of the level: the displacement there
    # is the node's own, frame by frame.
    level = bunny.level(0)
    sim = tetskin.Simulation(bunny, level=0, scenario="sag")
    sim.record(tmp_path / "run.pvd")
    sim.step(3)
    sim.stop_recording()
    nodes = [40, 170]
    probe = tetskin.probe(tmp_path / "run.pvd", level.nodes[nodes])
    assert probe["times"].shape == (4,) and probe["displacement"].shape == (4, 2, 3)
    assert probe["stress"].shape == (4, 2, 6) and probe["von_mises"].shape == (4, 2)
    assert np.abs(probe["displacement"][0]).max() == 0
    last = probe["displacement"][-1]
    assert np.abs(last - (sim.positions[nodes] - level.nodes[nodes])).max() < 1e-12
    with pytest.raises(tetskin.Error, match=r"points\[1\]: the point .* lies outside"):
        tetskin.probe(tmp_path / "run.pvd", [[0, 5, 0], [0, 500, 0]])


def test_forces_push_and_state_can_be_set(bunny):
    sim = tetskin.Simulation(bunny, level=0, gravity=[0, 0, 0], scenario="sag")
    rest = sim.positions
    top = int(np.argmax(rest[:, 1]))
    sim.apply_forces([top], [[1e4, 0, 0]])
    sim.step(5)
    assert sim.positions[top, 0] > rest[top, 0]
    assert sim.energies()["kinetic"] > 0
    sim.set_positions(rest)
    sim.set_velocities(np.zeros_like(rest))
    np.testing.assert_array_equal(sim.positions, rest)
    assert sim.energies()["kinetic"] == 0
    stress = sim.von_mises()
    assert stress.shape == (len(bunny.level(0).elements),) and (stress >= 0).all()


def test_record_writes_a_series_with_the_surface(tmp_path, bunny, bunny_8k):
    V, F = bunny_8k
    binding = tetskin.bind(bunny, V, F, level=0)
    sim = tetskin.Simulation(bunny, level=0, scenario="wobble", solver="cg")
    sim.record(tmp_path / "run.pvd", surface=binding, every=2)
    sim.step(4)
    sim.stop_recording()
    sim.step(1)
    text = (tmp_path / "run.pvd").read_text()
    assert text.count("<DataSet") == 6  # frames 0, 2 and 4, control mesh and surface each
    surfaces = sorted((tmp_path / "run_frames").glob("surface_*.vtp"))
    assert len(surfaces) == 3
    last, _ = tetskin.read_surface(surfaces[-1])
    assert np.abs(last - V).max() > 0


def test_record_writes_the_surface_in_pieces(tmp_path, bunny, bunny_8k):
    V, F = bunny_8k
    binding = tetskin.bind(bunny, V, F, level=0)
    sim = tetskin.Simulation(bunny, level=0, scenario="wobble", solver="cg")
    with pytest.raises(tetskin.Error, match="record: pieces: the surface's pieces must be finite and >= 1, got 0"):
        sim.record(tmp_path / "bad.pvd", surface=binding, pieces=0)
    sim.record(tmp_path / "run.pvd", surface=binding, pieces=3)
    sim.step(2)
    sim.stop_recording()
    frames = tmp_path / "run_frames"
    assert len(list(frames.glob("surface_*.pvtp"))) == 3
    assert sorted(p.name for p in frames.glob("surface_00002_piece*.vtp")) == [
        "surface_00002_piece%d.vtp" % k for k in range(3)]
    last, faces = tetskin.read_surface(frames / "surface_00002.pvtp")  # read whole
    assert last.shape == V.shape and (faces == F).all()
    assert np.abs(last - V).max() > 0


def test_a_step_runs_while_another_thread_reads(bunny):
    sim = tetskin.Simulation(bunny, level=1, scenario="wobble", solver="cg")
    seen = []
    worker = threading.Thread(target=lambda: sim.step(6))
    worker.start()
    while worker.is_alive():
        seen.append(sim.positions.shape)
    worker.join()
    assert sim.steps == 6 and all(s == seen[0] for s in seen)


@pytest.mark.parametrize(
    "options, words",
    [
        ({"yung": 1e5}, "Simulation: unknown option 'yung' (known: "),
        ({"poisson": 0.5}, "poisson: Poisson's ratio must lie in (-1, 0.5), got 0.5"),
        ({"young": 1e5, "youngs_modulus": 1e5}, "youngs_modulus and young are the same option"),
        ({"solver": "gmres"}, "solver: unknown solver 'gmres' (known: auto, cg, multigrid)"),
        ({"drop_height": 0.5}, "drop_height: applies to the drop scenario, not to wobble"),
        ({"dt": -1}, "dt: the time step must be"),
        ({"guess_solutions": 2.5}, "guess_solutions: expected a whole number"),
        ({"fixed_nodes": [10**6]}, "fixed_nodes: 1000000 is no node of"),
        ({"loads": np.zeros((3, 3))}, "loads: expected one row per node"),
        ({"young": "soft"}, "young: expected a number, got str"),
        ({"coarse_levels": "octree"}, "coarse_levels: unknown coarse levels 'octree' (known: grid, dataset)"),
        ({"coarse_operators": "rediscretized"}, "rediscretized coarse operators need the dataset's coarse levels"),
    ],
)
def test_bad_options_are_errors_in_the_commands_words(bunny, options, words):
    with pytest.raises(tetskin.Error) as caught:
        tetskin.Simulation(bunny, level=0, scenario="wobble", **options)
    assert words in str(caught.value)


def test_bad_state_and_ids_are_errors_naming_the_argument(bunny):
    sim = tetskin.Simulation(bunny, level=0)
    with pytest.raises(tetskin.Error, match="positions: expected one row per node of level 0"):
        sim.set_positions(np.zeros((3, 3)))
    with pytest.raises(tetskin.Error, match="ids: -1 is no node of level 0"):
        sim.fix_nodes([-1])
    with pytest.raises(tetskin.Error, match="forces: expected one row per id"):
        sim.apply_forces([1, 2], [[0, 0, 1]])
    with pytest.raises(tetskin.Error, match="scenario: unknown scenario 'bounce'"):
        tetskin.Simulation(bunny, scenario="bounce")


def test_ctrl_c_stops_a_long_step_between_steps(bunny):
    sim = tetskin.Simulation(bunny, level=-1, scenario="wobble", solver="cg")
    interrupt_after(0.5)
    with pytest.raises(KeyboardInterrupt):
        sim.step(100000)
    assert 0 < sim.steps < 100000
    sim.step()  # the run goes on from where it stopped


def test_an_old_option_name_is_read_with_a_deprecation_warning(bunny):
    with pytest.warns(DeprecationWarning, match="young: is deprecated, use youngs_modulus"):
        old = tetskin.Simulation(bunny, level=0, young=1e5).run_spec
    assert old == tetskin.Simulation(bunny, level=0, youngs_modulus=1e5).run_spec
    with pytest.raises(tetskin.Error, match="are the same option"):
        tetskin.Simulation(bunny, level=0, young=1e5, youngs_modulus=1e5)
    with pytest.raises(tetskin.Error) as error:
        tetskin.Simulation(bunny, level=0, yung=1e5)
    assert "young," not in str(error.value) and "youngs_modulus" in str(error.value)
    with pytest.warns(DeprecationWarning, match="held_nodes: is deprecated, use fixed_nodes"):
        held = tetskin.Simulation(bunny, level=0, held_nodes=[0, 1]).run_spec
    assert held["parameters"]["fixed_nodes"] == [0, 1]
