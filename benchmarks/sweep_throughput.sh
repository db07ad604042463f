#!/usr/bin/env bash
# End-to-end sweep throughput (file written, journal included), in points/s per rank.
# Targets (issue 3): --quantities regime >= 2e6 points/s per rank, full >= 1e4 points/s
# per rank, 2 ranks >= 1.9x one rank on a sweep of a few million points.
# Usage: bash benchmarks/sweep_throughput.sh [punchsweep-binary]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bin=${1:-"$root/build/src/app/punchsweep"}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# 16 x 45 x 17 x 64 x 3 = 2,350,080 points.
big=(--grid.l 'linspace(0.5, 1.25, 16)' --grid.dh 'linspace(0.01, 0.12, 45)' --grid.T 'linspace(2, 10, 17)'
     --grid.pbar 'logspace(0.005, 0.08, 64)' --grid.s 1,2,3)

run() {  # run LABEL RANKS ARGS...: prints points/s overall and per rank; echoes points/s
  local label=$1 ranks=$2; shift 2
  local start end points
  rm -f "$work"/map.h5*
  start=$(date +%s.%N)
  mpirun --oversubscribe -np "$ranks" "$bin" sweep "$@" --quiet --output "$work/map.h5"
  end=$(date +%s.%N)
  points=$(h5ls "$work/map.h5/regime" | sed -E 's/.*\{([0-9, ]+)\}.*/\1/' | tr -d ' ' | tr ',' '*' | bc)
  local rate per_rank
  rate=$(echo "$points / ($end - $start)" | bc -l)
  per_rank=$(echo "$rate / $ranks" | bc -l)
  printf '%-34s %2d rank(s) %9d points %7.2f s %10.3g points/s %10.3g points/s/rank\n' \
    "$label" "$ranks" "$points" "$(echo "$end - $start" | bc -l)" "$rate" "$per_rank" >&2
  echo "$rate"
}

echo "punchsweep sweep throughput on $(nproc) cores ($(uname -n)), end to end with the map written:" >&2
r1=$(run "regime, 2.35e6 points" 1 "${big[@]}" --quantities regime)
r2=$(run "regime, 2.35e6 points" 2 "${big[@]}" --quantities regime)
printf 'speed-up regime, 2 ranks over 1: %.2fx\n' "$(echo "$r2 / $r1" | bc -l)" >&2
f1=$(run "full (5 times), default grid" 1 --quantities full)
f2=$(run "full (5 times), default grid" 2 --quantities full)
printf 'speed-up full, 2 ranks over 1: %.2fx\n' "$(echo "$f2 / $f1" | bc -l)" >&2
