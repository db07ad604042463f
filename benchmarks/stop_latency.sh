#!/usr/bin/env bash
# How long a stop signal takes to end a sweep in the middle of a long tile (issue 22: one
# tile of 16 BEM points at N = 256, seconds of work, given up inside). The test
# tests/sweep/stop_inside_a_tile.sh asserts the behaviour; this measures the time, which
# depends on the machine and its load.
# Usage: benchmarks/stop_latency.sh [PUNCHSWEEP] [REPEATS]   (prints one line a repeat)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
binary=$(realpath "${1:-$root/build/src/app/punchsweep}")
repeats=${2:-5}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
grid=(--grid.l 0.75 --grid.dh 0.03,0.05,0.075,0.1 --grid.T 2.5,6 --grid.pbar 0.03,0.06 --grid.s 2
      --reference bem --bem-grid 256 --time.times 0,1,5 --chunk 1000)
for k in $(seq "$repeats"); do
  rm -f s.h5*
  "$binary" sweep "${grid[@]}" --output s.h5 > stop.log 2>&1 & pid=$!
  until grep -qs "points in" stop.log; do kill -0 "$pid" 2>/dev/null || exit 1; sleep 0.05; done
  sleep 0.5  # into the tile's BEM points
  start=$(date +%s.%N)
  kill -TERM "$pid"
  wait "$pid" || true
  echo "repeat $k: stopped $(echo "$(date +%s.%N) - $start" | bc) s after SIGTERM"
done
