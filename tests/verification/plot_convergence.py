#!/usr/bin/env python3
# SPDX-License-Identifier: AGPL-3.0-or-later
"""The verification page's convergence plot: runs the verification suite's
cantilever, Cook's membrane and NAFEMS LE10 (the larger meshes too with
--large), reads the errors they print and plots them against the mesh
size, log-log, with slope-2 and slope-1 guides. Usage:
    plot_convergence.py BUILD_DIR OUT.png [--large]
Exits 1 when a benchmark printed fewer than three meshes."""
import argparse
import pathlib
import re
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

# "cantilever,  4 cells through the depth (  3840 tetrahedra): ... error -17.6%"
# "Cook's membrane, 16 x 16 cells ( 1536 tetrahedra): ... error -12.4%"
# "NAFEMS LE10, k = 2 (  1152 tetrahedra): ... error -39.1%" (2k cells
# through the thickness)
LINE = re.compile(r"^(cantilever|Cook's membrane|NAFEMS LE10),(?: k =)?\s+(\d+)[^(]*"
                  r"\(\s*(\d+) tetrahedra\).*error ([-+0-9.e]+)%$")


def errors(build, large):
    tests = "Cantilever.TheTip*:CooksMembrane.TheLoaded*:NafemsLe10.TheStress*"
    if large:
        tests += ":*.DISABLED_*"
    done = subprocess.run(
        [str(build / "tests" / "verification" / "verification_tests"),
         "--gtest_filter=" + tests] + (["--gtest_also_run_disabled_tests"] if large else []),
        capture_output=True, text=True, check=True)
    found = {}
    for line in done.stdout.splitlines():
        match = LINE.match(line.strip())
        if match:
            name, cells, tets, error = match.groups()
            cells = int(cells) * (2 if name == "NAFEMS LE10" else 1)
            found.setdefault(name, {})[cells] = abs(float(error)) / 100
    return found


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("build", type=pathlib.Path)
    parser.add_argument("out", type=pathlib.Path)
    parser.add_argument("--large", action="store_true")
    args = parser.parse_args()
    found = errors(args.build, args.large)
    labels = {"cantilever": "cantilever, end load (Timoshenko), cells through the depth",
              "Cook's membrane": "Cook's membrane, v(48, 52), cells a side",
              "NAFEMS LE10": "NAFEMS LE10, sigma_yy at D (stress), cells through the plate"}
    fig, ax = plt.subplots(figsize=(6.4, 5.8), dpi=100)
    for name, label in labels.items():
        points = sorted(found.get(name, {}).items())
        if len(points) < 3:
            print(f"{name}: {len(points)} meshes printed, 3 or more needed", file=sys.stderr)
            return 1
        cells = [c for c, _ in points]
        ax.loglog(cells, [e for _, e in points], "o-", label=label)
    # A slope -2 guide through the cantilever's finest point.
    finest = sorted(found["cantilever"].items())[-1]
    guide = [finest[0] / 4, finest[0]]
    ax.loglog(guide, [finest[1] * 16, finest[1]], "k--", linewidth=1, label="order 2")
    plate = sorted(found["NAFEMS LE10"].items())[-1]
    ax.loglog([plate[0] / 4, plate[0]], [plate[1] * 4, plate[1]], "k:", linewidth=1,
              label="order 1")
    ax.set_xlabel("cells along the mesh's edge (h halves to the right)")
    ax.set_ylabel("|relative error|")
    ax.set_title("Linear tetrahedra against the references")
    ax.grid(True, which="both", linewidth=0.3)
    ax.legend(fontsize=8, loc="upper center", bbox_to_anchor=(0.5, -0.16))
    fig.tight_layout()
    args.out.parent.mkdir(parents=True, exist_ok=True)
    tmp = args.out.with_suffix(".tmp.png")
    fig.savefig(tmp)
    tmp.replace(args.out)
    print(f"wrote {args.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
