# SPDX-License-Identifier: AGPL-3.0-or-later
"""read_surface and write_surface: round trips, shapes, dtypes, errors."""
import numpy as np
import pytest

import tetskin
from conftest import DATA, TEST_DATA


def test_read_gives_float64_vertices_and_int32_triangles(bunny_8k):
    V, F = bunny_8k
    assert V.shape == (4001, 3) and V.dtype == np.float64
    assert F.shape == (7998, 3) and F.dtype == np.int32
    assert F.min() == 0 and F.max() == len(V) - 1
    assert V.flags.c_contiguous and V.flags.writeable


@pytest.mark.parametrize("ending", [".obj", ".ply", ".vtp", ".stl"])
def test_write_then_read_round_trips(tmp_path, bunny_8k, ending):
    V, F = bunny_8k
    path = tmp_path / ("bunny" + ending)
    tetskin.write_surface(path, V, F)
    V2, F2 = tetskin.read_surface(path)
    if ending == ".stl":  # STL keeps float32 corners, merged by position
        assert len(F2) == len(F)
        np.testing.assert_allclose(V2[F2], V[F], atol=1e-6 * np.ptp(V))
    else:
        np.testing.assert_array_equal(F2, F)
        np.testing.assert_array_equal(V2, V)


def test_write_takes_lists_and_other_number_types(tmp_path):
    path = tmp_path / "t.obj"
    tetskin.write_surface(path, [[0, 0, 0], [1, 0, 0], [0, 1, 0]], np.array([[0, 1, 2]], np.int64))
    V, F = tetskin.read_surface(str(path))
    np.testing.assert_array_equal(V, [[0, 0, 0], [1, 0, 0], [0, 1, 0]])
    np.testing.assert_array_equal(F, [[0, 1, 2]])


@pytest.mark.parametrize(
    "V, F, words",
    [
        (np.zeros((3, 2)), [[0, 1, 2]], "V: expected an (n, 3) array, got shape (3, 2)"),
        (np.zeros(3), [[0, 1, 2]], "V: expected an (n, 3) array, got shape (3,)"),
        (np.zeros((3, 3), complex), [[0, 1, 2]], "V: expected real numbers, got complex128"),
        (np.zeros((3, 3)), [[0.0, 1.0, 2.0]], "F: expected whole numbers"),
        (np.array([[0, 0, np.nan], [1, 0, 0], [0, 1, 0]]), [[0, 1, 2]], "V: row 0 is not finite"),
        (np.zeros((3, 3)), [[0, 1, 3]], "triangle 0"),
        ("not an array", [[0, 1, 2]], "V: expected"),
    ],
)
def test_bad_arrays_are_errors_naming_the_argument(tmp_path, V, F, words):
    path = tmp_path / "bad.obj"
    with pytest.raises(tetskin.Error, match=None) as caught:
        tetskin.write_surface(path, V, F)
    assert words in str(caught.value)
    assert not path.exists()


def test_a_malformed_file_names_the_file_and_line():
    with pytest.raises(tetskin.Error) as caught:
        tetskin.read_surface(TEST_DATA / "bad_index.obj")
    assert "bad_index.obj:" in str(caught.value)


def test_error_is_a_value_error_and_a_runtime_error():
    assert issubclass(tetskin.Error, ValueError) and issubclass(tetskin.Error, RuntimeError)
    with pytest.raises(ValueError):
        tetskin.read_surface(DATA / "no_such_file.obj")
