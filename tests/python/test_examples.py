# SPDX-License-Identifier: AGPL-3.0-or-later
"""The examples of doc/user/python.md, run as the page shows them: each
```python block after an "<!-- example: NAME -->" line, in a fresh folder
that holds the checkout's data/."""
import os
import re
import subprocess
import sys

import pytest

from conftest import DATA, SOURCE

PAGE = SOURCE / "doc" / "user" / "python.md"
EXAMPLES = dict(re.findall(r"<!-- example: (\w+) -->\n```python\n(.*?)```", PAGE.read_text(), re.S))


def test_the_page_has_its_examples():
    assert set(EXAMPLES) == {"complete", "sweep"}


@pytest.mark.parametrize("name", sorted(EXAMPLES))
def test_example_runs(tmp_path, name):
    (tmp_path / "data").symlink_to(DATA)
    script = tmp_path / f"{name}.py"
    script.write_text(EXAMPLES[name])
    done = subprocess.run([sys.executable, str(script)], cwd=tmp_path, capture_output=True,
                          text=True, env=dict(os.environ))
    assert done.returncode == 0, done.stderr
    print(done.stdout)
    if name == "complete":
        for made in ["out/bunny.json", "out/bunny_8k_binding.vtp", "out/wobble.pvd",
                     "out/bunny_8k_last.vtp"]:
            assert (tmp_path / made).exists(), made
        assert len(list((tmp_path / "out" / "wobble_frames").glob("surface_*.vtp"))) == 11
    else:
        sways = [float(line.split()[-2]) for line in done.stdout.splitlines()]
        assert len(sways) == 4 and sways == sorted(sways, reverse=True)  # stiffer sways less
