#!/usr/bin/env python3
# SPDX-License-Identifier: AGPL-3.0-or-later
"""Soak of `tetskin simulate` (issue #53): a long run with periodic frames
(the bound 8k bunny written with each) must need no more memory than a run
a tenth as long. Memory that grew with the steps or the frames written
would make the long run's peak resident memory the larger.

  simulate_soak.py TETSKIN OUT_DIR [STEPS]

STEPS (or TETSKIN_SOAK_STEPS; default 3000, CI's short form) is the long
run's length; the short run takes a tenth of it. Both record every 25th
step. Prints both peaks; fails when the long run's exceeds the short one's
by 3 MiB or more, or when either run fails.
"""
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def peak_mib(tetskin, out_dir, steps):
    """Runs simulate for `steps`; its peak resident memory in MiB."""
    pvd = os.path.join(out_dir, f"soak_{steps}.pvd")
    command = [tetskin, "simulate", os.path.join(ROOT, "data", "bunny.json"), "--level", "0",
               "--scenario", "wobble", "--steps", str(steps), "--every", "25",
               "--surface", os.path.join(ROOT, "data", "bunny_8k.obj"), "-o", pvd, "-q"]
    log = os.path.join(out_dir, f"soak_{steps}.log")
    with open(log, "wb") as output:
        child = subprocess.Popen(command, stdout=output, stderr=subprocess.STDOUT)
        # wait4: this child's own resource use (ru_maxrss in KiB on Linux).
        _, status, usage = os.wait4(child.pid, 0)
    if os.waitstatus_to_exitcode(status) != 0:
        with open(log, encoding="utf-8", errors="replace") as output:
            sys.exit(f"simulate --steps {steps} failed:\n{output.read()}")
    return usage.ru_maxrss / 1024.0


def main():
    tetskin, out_dir = sys.argv[1], sys.argv[2]
    steps = int(sys.argv[3] if len(sys.argv) > 3 else os.environ.get("TETSKIN_SOAK_STEPS", 3000))
    os.makedirs(out_dir, exist_ok=True)
    short = peak_mib(tetskin, out_dir, max(steps // 10, 50))
    long = peak_mib(tetskin, out_dir, steps)
    print(f"simulate soak: peak resident memory {short:.1f} MiB over {max(steps // 10, 50)} "
          f"steps, {long:.1f} MiB over {steps} steps")
    if long - short >= 3.0:
        sys.exit(f"memory grew with the run: {long - short:.1f} MiB more over {steps} steps")


if __name__ == "__main__":
    main()
