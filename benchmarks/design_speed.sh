#!/usr/bin/env bash
# How long `punchsweep design` takes to answer docs/design.md's question (issue 37: "a
# design answer over a temperature range and a tolerance box in under a second"): two
# requirements, 9 temperatures, 2 pressure corners, the true TPE-A; and four requirements
# over a 4-corner box (pressure and l). Wall time of the whole
# process (start, reading the material, the answer), the median of REPEATS runs, beside
# `punchsweep point` at one point (the process's own cost).
# Usage: bash benchmarks/design_speed.sh [PUNCHSWEEP] [REPEATS]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bin=${1:-"$root/build/src/app/punchsweep"}
repeats=${2:-21}
material="$root/examples/dma_exports/tpe_a_truth.ini"
geometry=(--material "$material" --R 80um --l 250um --s 2)
median() {  # median COMMAND...: the median wall time in ms of REPEATS runs
  local times=()
  for _ in $(seq "$repeats"); do
    local start end
    start=$(date +%s%N)
    "$@" > /dev/null
    end=$(date +%s%N)
    times+=($(( (end - start) / 1000 )))
  done
  printf '%s\n' "${times[@]}" | sort -n | awk '{a[NR]=$1} END {printf "%.1f ms", a[int((NR+1)/2)]/1000}'
}
echo "point, one point:                   $(median "$bin" point "${geometry[@]}" --dh 8um --pressure 30kPa --temperature 20)"
echo "design, docs/design.md's question:  $(median "$bin" design "${geometry[@]}" --temperature 20..40C \
  --require 'touch within 1s at 30kPa' --require 'never at 5kPa' --tolerance 'dh=0.5um, pressure=10%')"
echo "design, 4 requirements, 4 corners:  $(median "$bin" design "${geometry[@]}" --temperature 20..40C \
  --require 'touch within 1s at 30kPa' --require 'never at 5kPa' --require 'touch at once at 60kPa' \
  --require 'no touch within 1min at 10kPa' --tolerance 'dh=0.2um, pressure=10%, l=2%')"
