#!/usr/bin/env bash
# Runs every reader's libFuzzer target (a TETSKIN_FUZZ build) for a bounded
# time on the committed corpus, and prints per target what it ran: inputs
# executed, the coverage reached (libFuzzer's edges, "cov") and its corpus
# grown. A crash or a broken invariant stops it with the input written to
# BUILD/fuzz-crashes/ (commit it under tests/fuzz/regressions/TARGET/: the
# regression suite then runs it in every build).
# libFuzzer's seed is FUZZ_SEED (default 1) and a target stops after
# FUZZ_RUNS inputs (default 200000) or SECONDS, whichever comes first. The
# inputs it tries still differ between machines (it orders seeds of equal
# size as the file system lists them), so a failure prints what is needed
# where only its log comes back (CI): the sanitizer's report and the input,
# base64-encoded (`base64 -d` it into tests/fuzz/regressions/TARGET/).
# FUZZ_SEED=0 (a random seed) and a long SECONDS explore further.
# Usage: run_fuzzers.sh BUILD_DIR [SECONDS_PER_TARGET (default 30)]
set -euo pipefail
build=$(cd "$1" && pwd)
seconds=${2:-30}
seed=${FUZZ_SEED:-1}
runs=${FUZZ_RUNS:-200000}
here=$(cd "$(dirname "$0")" && pwd)
crashes="$build/fuzz-crashes"
mkdir -p "$crashes"
printf '%-12s %12s %8s %8s %8s\n' target executions cov features corpus
status=0
for corpus in "$here"/corpus/*/; do
  target=$(basename "$corpus")
  work=$(mktemp -d)
  log="$build/fuzz-$target.log"
  # (A grown corpus lands in $work, not in the committed one.)
  if ! "$build/tests/fuzz/fuzz_$target" "$work" "$corpus" -max_total_time="$seconds" \
      -seed="$seed" -runs="$runs" \
      -dict="$here/dict/$target.dict" -artifact_prefix="$crashes/$target-" \
      -print_final_stats=1 -rss_limit_mb=2048 -timeout=10 >"$log" 2>&1; then
    echo "fuzz_$target FAILED: see $log and $crashes" >&2
    grep -A 24 -m 1 -E '^==[0-9]+==.*ERROR|^SUMMARY|INFO: .* (crash|leak|oom|timeout)' "$log" >&2 ||
      tail -30 "$log" >&2
    for input in "$crashes/$target"-*; do
      [ -f "$input" ] || continue
      echo "input $(basename "$input") ($(stat -c %s "$input") bytes), base64:" >&2
      base64 -w 100 "$input" >&2
    done
    status=1
  fi
  executed=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || echo '?')
  last=$(grep -E '^#[0-9]+' "$log" | tail -1)
  cov=$(echo "$last" | grep -o 'cov: [0-9]*' | grep -o '[0-9]*' || echo '?')
  ft=$(echo "$last" | grep -o 'ft: [0-9]*' | grep -o '[0-9]*' || echo '?')
  units=$(echo "$last" | grep -o 'corp: [0-9]*' | grep -o '[0-9]*' || echo '?')
  printf '%-12s %12s %8s %8s %8s\n' "$target" "$executed" "$cov" "$ft" "$units"
  rm -rf "$work"
done
exit $status
