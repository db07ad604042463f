#!/usr/bin/env bash
# The periodic model (issue 23) beside the paper's and the refined localization, side by side
# in one run, one rank, in points/s: the map's points_per_second (the engine's own, first tile
# to last) and the wall time of the whole command.
# Goals (issue 23): periodic >= the paper model's rate in regime mode, >= 1e6 points/s/rank.
# Grids:
#   regime   7 x 111 x 9 x 200 x 3 = 4,195,800 points over the default grid's ranges, finer
#            (python_classify.py's grid), --quantities regime;
#   full     the default grid (sweeps/default.ini: 7 x 23 x 9 x 24 x 3 = 104,328 points,
#            times 0, 0.5, 1, 2, 5), --quantities full.
# Usage: benchmarks/periodic_throughput.sh [BINARY] [REPEATS]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bin=${1:-"$root/build/src/app/punchsweep"}
repeats=${2:-2}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

regime=(--grid.l 'linspace(0.5, 1.25, 7)' --grid.dh 'linspace(0.01, 0.12, 111)' --grid.T 'linspace(2, 10, 9)'
        --grid.pbar 'logspace(0.005, 0.08, 200)' --grid.s 1,2,3 --quantities regime)
full=(--config "$root/sweeps/default.ini" --quantities full)

# shellcheck source=benchmarks/sweep_rate.sh
source "$root/benchmarks/sweep_rate.sh"

printf '%-7s %-10s %-10s %-10s %-16s %s\n' grid paper refined periodic "periodic/paper" "wall s: paper refined periodic (points/s, one rank)"
for grid in regime full; do
  for r in $(seq "$repeats"); do
    case $grid in
      regime) args=("${regime[@]}") ;;
      full) args=("${full[@]}") ;;
    esac
    read -r a wa <<<"$(rate "${args[@]}" --model.localization paper)"
    read -r b wb <<<"$(rate "${args[@]}" --model.localization refined)"
    read -r c wc <<<"$(rate "${args[@]}" --model.localization periodic)"
    printf '%-7s %-10.3g %-10.3g %-10.3g %-16s %s %s %s\n' "$grid" "$a" "$b" "$c" \
      "$(awk -v a="$a" -v c="$c" 'BEGIN { printf "%.3f", c / a }')" "$wa" "$wb" "$wc"
  done
done
