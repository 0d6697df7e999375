# SPDX-License-Identifier: AGPL-3.0-or-later
"""Shared fixtures of the Python suite (run by CTest: tests/python/CMakeLists.txt).

TETSKIN_CLI names the built `tetskin` executable, against which the module is
compared; TETSKIN_SOURCE_DIR the source tree (its data/ and tests/data/).
"""
import os
import pathlib
import signal
import subprocess
import threading

import numpy as np
import pytest

import tetskin

SOURCE = pathlib.Path(os.environ.get("TETSKIN_SOURCE_DIR", pathlib.Path(__file__).parents[2]))
DATA = SOURCE / "data"
TEST_DATA = SOURCE / "tests" / "data"


@pytest.fixture(scope="session")
def cli():
    """Runs `tetskin ARGS...`, failing the test with its stderr when it fails."""
    exe = os.environ.get("TETSKIN_CLI")
    if not exe:
        pytest.skip("TETSKIN_CLI is not set")

    def run(*args):
        done = subprocess.run([exe, *map(str, args)], capture_output=True, text=True)
        assert done.returncode == 0, done.stderr
        return done.stdout

    return run


@pytest.fixture(scope="session")
def bunny():
    return tetskin.load_dataset(DATA / "bunny.json")


@pytest.fixture(scope="session")
def bunny_8k():
    return tetskin.read_surface(DATA / "bunny_8k.obj")


def rotation(angle, axis=2):
    c, s = np.cos(angle), np.sin(angle)
    r = np.eye(3)
    i, j = [k for k in range(3) if k != axis]
    r[i, i], r[i, j], r[j, i], r[j, j] = c, -s, s, c
    return r


def interrupt_after(seconds):
    """Sends this process SIGINT (Ctrl-C) after `seconds`, with Python's own
    handler installed (a job started in the background ignores SIGINT)."""
    signal.signal(signal.SIGINT, signal.default_int_handler)
    timer = threading.Timer(seconds, lambda: os.kill(os.getpid(), signal.SIGINT))
    timer.start()
    return timer
