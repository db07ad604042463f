#!/usr/bin/env bash
# Sweep throughput of the refined localization (shells:200, docs/model.md section 11) beside
# the paper's, side by side in one run, one rank, in points/s: the map's points_per_second
# (the engine's own, first tile to last; the refined model's tables, about 2 s per shape
# exponent s and process, are built before it, while the run estimates its disk space) and
# the wall time of the whole command, tables and start-up included.
# Targets (issue 12): the refined model >= 5e5 points/s per rank with --quantities regime
# and >= 1e4 points/s per rank in full mode.
# Grids:
#   regime     the default grid's ranges, coarser: 4 x 23 x 5 x 24 x 3 = 33,120 points; each
#              (l, s, dh) has 120 (T, pbar) points to share its branch (ShellsBranch);
#   production a slice of sweeps/production.ini (its T and pbar axes whole, 2 of its 40
#              pitches, 10 of its 120 dh, s = 2, 3): 2 x 10 x 20 x 128 x 2 = 102,400 points,
#              2,560 per (l, s, dh) as in the whole map;
#   full       4 x 10 x 5 x 12 x 3 = 7,200 points, times 0, 0.5, 1, 2, 5.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bin=${1:-"$root/build/src/app/punchsweep"}
repeats=${2:-2}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

regime=(--grid.l 'linspace(0.5, 1.25, 4)' --grid.dh 'linspace(0.01, 0.12, 23)' --grid.T 'linspace(2, 10, 5)'
        --grid.pbar 'logspace(0.005, 0.08, 24)' --grid.s 1,2,3 --quantities regime)
production=(--grid.l 'linspace(0.4, 1.6, 2)' --grid.dh 'linspace(0.001, 0.15, 10)' --grid.T 'logspace(1.25, 20, 20)'
            --grid.pbar 'logspace(0.001, 0.1, 128)' --grid.s 2,3 --quantities regime)
full=(--grid.l 'linspace(0.5, 1.25, 4)' --grid.dh 'linspace(0.01, 0.12, 10)' --grid.T 'linspace(2, 10, 5)'
      --grid.pbar 'logspace(0.005, 0.08, 12)' --grid.s 1,2,3 --time.times '0, 0.5, 1, 2, 5' --quantities full)

# shellcheck source=benchmarks/sweep_rate.sh
source "$root/benchmarks/sweep_rate.sh"

printf '%-10s %-10s %-10s %-8s %-9s %s\n' grid paper refined ratio "paper s" "refined s (points/s, one rank, $repeats runs interleaved; s: wall)"
for grid in regime production full; do
  for r in $(seq "$repeats"); do
    case $grid in
      regime) args=("${regime[@]}") ;;
      production) args=("${production[@]}") ;;
      full) args=("${full[@]}") ;;
    esac
    read -r a wa <<<"$(rate "${args[@]}" --model.localization paper)"
    read -r b wb <<<"$(rate "${args[@]}" --model.localization refined)"
    printf '%-10s %-10.3g %-10.3g %-8s %-9s %s\n' "$grid" "$a" "$b" "$(awk -v a="$a" -v b="$b" 'BEGIN { printf "%.4f", b / a }')" "$wa" "$wb"
  done
done
