#!/usr/bin/env bash
# Sweep throughput of the refined localization (shells:200, docs/model.md section 11) beside
# the paper's, side by side in one run, one rank, in points/s (the map's points_per_second:
# the engine's own, first tile to last; the refined model's tables, about 2 s per shape
# exponent s, are built inside it).
# Targets (issue 12): the refined model >= 5e5 points/s per rank with --quantities regime
# and >= 1e4 points/s per rank in full mode.
# Grids: the default grid's ranges, coarser: 4 x 23 x 5 x 24 x 3 = 33,120 points (regime),
# 4 x 10 x 5 x 12 x 3 = 7,200 points (full, times 0, 0.5, 1, 2, 5).
# Usage: bash benchmarks/localization_throughput.sh [punchsweep-binary] [repeats]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bin=${1:-"$root/build/src/app/punchsweep"}
repeats=${2:-2}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

regime=(--grid.l 'linspace(0.5, 1.25, 4)' --grid.dh 'linspace(0.01, 0.12, 23)' --grid.T 'linspace(2, 10, 5)'
        --grid.pbar 'logspace(0.005, 0.08, 24)' --grid.s 1,2,3 --quantities regime)
full=(--grid.l 'linspace(0.5, 1.25, 4)' --grid.dh 'linspace(0.01, 0.12, 10)' --grid.T 'linspace(2, 10, 5)'
      --grid.pbar 'logspace(0.005, 0.08, 12)' --grid.s 1,2,3 --time.times '0, 0.5, 1, 2, 5' --quantities full)

rate() {  # rate ARGS...: the engine's points/s of one sweep
  "$bin" sweep "$@" --quiet --overwrite --output "$work/map.h5"
  h5dump -a /points_per_second "$work/map.h5" | sed -n 's/.*(0): \(.*\)/\1/p'
}

printf '%-8s %-10s %-10s %s\n' mode paper refined "ratio (points/s, one rank, $repeats runs interleaved)"
for mode in regime full; do
  for r in $(seq "$repeats"); do
    if [ "$mode" = regime ]; then args=("${regime[@]}"); else args=("${full[@]}"); fi
    a=$(rate "${args[@]}" --model.localization paper)
    b=$(rate "${args[@]}" --model.localization refined)
    printf '%-8s %-10.3g %-10.3g %s\n' "$mode" "$a" "$b" "$(awk -v a="$a" -v b="$b" 'BEGIN { printf "%.4f", b / a }')"
  done
done
