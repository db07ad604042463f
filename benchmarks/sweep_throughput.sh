#!/usr/bin/env bash
# End-to-end sweep throughput (file written, journal included), in points/s per rank.
# Targets (issue 3): --quantities regime >= 2e6 points/s per rank, full >= 1e4 points/s
# per rank, 2 ranks >= 1.9x one rank on a sweep of a few million points.
# Two rates per run: end to end (wall time of the command, mpirun launch included: ~0.3 s
# here, most of it Open MPI probing for network transports this machine lacks) and the
# engine's own (the map's points_per_second: first tile handed out to last tile written).
# Usage: bash benchmarks/sweep_throughput.sh [punchsweep-binary]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bin=${1:-"$root/build/src/app/punchsweep"}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# 16 x 45 x 17 x 64 x 3 = 2,350,080 points (about a second per rank in regime mode), and the
# same ranges four times finer in l and dh: 64 x 180 x 17 x 64 x 3 = 37,601,280 points, a
# sweep long enough (~20 s on one rank) that mpirun's start-up no longer hides the engine.
big=(--grid.l 'linspace(0.5, 1.25, 16)' --grid.dh 'linspace(0.01, 0.12, 45)' --grid.T 'linspace(2, 10, 17)'
     --grid.pbar 'logspace(0.005, 0.08, 64)' --grid.s 1,2,3)
huge=(--grid.l 'linspace(0.5, 1.25, 64)' --grid.dh 'linspace(0.01, 0.12, 180)' --grid.T 'linspace(2, 10, 17)'
      --grid.pbar 'logspace(0.005, 0.08, 64)' --grid.s 1,2,3)

attribute() { h5dump -a "/$1" "$work/map.h5" | sed -n 's/.*(0): \(.*\)/\1/p'; }

run() {  # run LABEL RANKS ARGS...: prints points/s end to end and the engine's own; echoes the engine's
  local label=$1 ranks=$2; shift 2
  local start end points
  rm -f "$work"/map.h5*
  start=$(date +%s.%N)
  mpirun --oversubscribe -np "$ranks" "$bin" sweep "$@" --quiet --output "$work/map.h5"
  end=$(date +%s.%N)
  points=$(h5ls "$work/map.h5/regime" | sed -E 's/.*\{([0-9, ]+)\}.*/\1/' | tr -d ' ' | tr ',' '*' | bc)
  # The map's own figure: from the first tile handed out to the last written (no launch).
  local engine
  engine=$(attribute points_per_second)
  awk -v label="$label" -v r="$ranks" -v n="$points" -v s="$start" -v e="$end" -v g="$engine" 'BEGIN {
    printf "%-30s %d rank(s) %8d points %6.2f s  end to end %9.3g points/s (%9.3g /rank)  engine %9.3g points/s (%9.3g /rank)\n",
           label, r, n, e - s, n / (e - s), n / (e - s) / r, g, g / r }' >&2
  echo "$engine"
}

echo "punchsweep sweep throughput on $(nproc) cores ($(uname -n)), end to end with the map written:" >&2
r1=$(run "regime, 2.35e6 points" 1 "${big[@]}" --quantities regime)
r2=$(run "regime, 2.35e6 points" 2 "${big[@]}" --quantities regime)
awk -v a="$r1" -v b="$r2" 'BEGIN { printf "speed-up regime, 2 ranks over 1 (engine): %.2fx\n", b / a }' >&2
h1=$(run "regime, 3.76e7 points" 1 "${huge[@]}" --quantities regime)
h2=$(run "regime, 3.76e7 points" 2 "${huge[@]}" --quantities regime)
awk -v a="$h1" -v b="$h2" 'BEGIN { printf "speed-up regime 3.76e7, 2 ranks over 1 (engine): %.2fx\n", b / a }' >&2
f1=$(run "full (5 times), default grid" 1 --quantities full)
f2=$(run "full (5 times), default grid" 2 --quantities full)
awk -v a="$f1" -v b="$f2" 'BEGIN { printf "speed-up full, 2 ranks over 1 (engine): %.2fx\n", b / a }' >&2
