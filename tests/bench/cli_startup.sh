#!/usr/bin/env bash
# Issue #56's startup benchmark: the CPU time (user + system, the mean of
# RUNS runs) of `tetskin --help` and of `tetskin info` on small files,
# beside the same commands with Netgen's library loaded at start
# (LD_PRELOAD): what they cost while tetskin linked nglib, before Netgen
# became a module loaded when first used. Also the shared libraries each
# loads (the loader's own count, LD_DEBUG=files).
# Usage: tests/bench/cli_startup.sh [BUILD_DIR] [RUNS (default 20)]
set -euo pipefail
cd "$(dirname "$0")/../.."
BUILD=$(realpath "${1:-build}")
RUNS=${2:-20}
TETSKIN=$BUILD/app/cli/tetskin
NGLIB=$(find /usr/lib -name 'libnglib.so*' | head -n 1)
[ -n "$NGLIB" ] || { echo "no libnglib.so under /usr/lib (libnglib-dev)" >&2; exit 1; }

# The mean CPU milliseconds of RUNS runs of a command (getrusage of the children).
cpu_ms() {
  python3 - "$RUNS" "$@" <<'PY'
import os, resource, subprocess, sys
runs, command = int(sys.argv[1]), sys.argv[2:]
before = resource.getrusage(resource.RUSAGE_CHILDREN)
for _ in range(runs):
    subprocess.run(command, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=True)
after = resource.getrusage(resource.RUSAGE_CHILDREN)
cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
print(f"{1000 * cpu / runs:.1f}")
PY
}
libraries() {
  env LD_DEBUG=files "$@" 2>&1 >/dev/null | grep -o 'file=[^ ;]*' | sort -u | wc -l
}

echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')"
echo "commit: $(git rev-parse --short HEAD 2>/dev/null || echo '?')"
printf '%-34s %10s %10s %12s %12s\n' command "cpu ms" libraries "nglib: ms" libraries
for args in "--help" "info data/bunny.json" "info data/bunny.obj"; do
  # shellcheck disable=SC2086
  printf '%-34s %10s %10s %12s %12s\n' "tetskin $args" \
    "$(cpu_ms "$TETSKIN" $args)" "$(libraries "$TETSKIN" $args)" \
    "$(cpu_ms env LD_PRELOAD="$NGLIB" "$TETSKIN" $args)" \
    "$(libraries env LD_PRELOAD="$NGLIB" "$TETSKIN" $args)"
done
