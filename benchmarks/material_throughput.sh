#!/usr/bin/env bash
# Sweep throughput of a 10-term Prony material beside the standard linear solid, side by
# side in one run, one rank, in points/s (the map's points_per_second: the engine's own).
# Targets (issue 11): a 10-term Prony material >= 1e6 points/s per rank with --quantities
# regime and >= 1e4 points/s per rank in full mode.
# The material is materials/silicone_elite_double32.ini (10 terms, 5e-8 s to 0.49 s) with a
# made-up WLF shift, so that a 17-value temperature axis gives the grid of the SLS's 17 T
# values: the same 2,350,080 points (regime) and 24,480 (full) for both.
# With a baseline binary (an older build), its Prony rates run interleaved with the same
# runs and the ratio new/baseline is printed beside them.
# Usage: bash benchmarks/material_throughput.sh [punchsweep-binary] [repeats] [baseline-binary]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bin=${1:-"$root/build/src/app/punchsweep"}
repeats=${2:-3}
baseline=${3:-}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
{ cat "$root/materials/silicone_elite_double32.ini"
  printf '[shift]\nkind = wlf\nC1 = 17.44\nC2 = 51.6\nT_ref = 20\n'; } > "$work/silicone_wlf.ini"

common=(--grid.l 'linspace(0.5, 1.25, 16)' --grid.dh 'linspace(0.01, 0.12, 45)' --grid.pbar 'logspace(0.005, 0.08, 64)'
        --grid.s 1,2,3)
full=(--grid.l 'linspace(0.5, 1.25, 4)' --grid.dh 'linspace(0.01, 0.12, 10)' --grid.pbar 'logspace(0.005, 0.08, 12)'
      --grid.s 1,2,3 --time.times '0, 0.5, 1, 2, 5')
sls=(--grid.T 'linspace(2, 10, 17)')
material=(--model.material "$work/silicone_wlf.ini" --grid.temperature 'linspace(20, 60, 17)')

rate() {  # rate ARGS...: the engine's points/s of one sweep (BIN overrides the binary)
  "${BIN:-$bin}" sweep "$@" --quiet --overwrite --output "$work/map.h5"
  h5dump -a /points_per_second "$work/map.h5" | sed -n 's/.*(0): \(.*\)/\1/p'
}

printf '%-8s %-22s %s\n' mode law "points/s (one rank), $repeats runs interleaved"
for mode in regime full; do
  for r in $(seq "$repeats"); do
    if [ "$mode" = regime ]; then
      args=("${common[@]}")
    else
      args=("${full[@]}")
    fi
    a=$(rate "${args[@]}" "${sls[@]}" --quantities "$mode")
    b=$(rate "${args[@]}" "${material[@]}" --quantities "$mode")
    printf '%-8s %-22s %.3g\n%-8s %-22s %.3g' "$mode" "sls (T axis)" "$a" "$mode" "prony 10 (temperature)" "$b"
    if [ -n "$baseline" ]; then
      c=$(BIN=$baseline rate "${args[@]}" "${material[@]}" --quantities "$mode")
      printf '   baseline %.3g, ratio %s' "$c" "$(awk -v b="$b" -v c="$c" 'BEGIN { printf "%.2f", b / c }')"
    fi
    printf '\n'
  done
done
