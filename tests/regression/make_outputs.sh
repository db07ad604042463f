#!/usr/bin/env bash
# Writes the regression outputs of one punchsweep binary into OUTDIR (see README.md), all
# under the paper's localization (the default before issue 12; pinned outputs of its path):
#   default.h5        the embedded default grid, full quantities, one process
#   fig9_5.h5         sweeps/paper/fig9_5.ini, full quantities (101 snapshot times), one process
#   production_slice.h5  a regime-only slice of sweeps/production.ini (368,640 points), 2 ranks
#   bem.h5            a small grid with the BEM reference on a random sample, 2 ranks
#   point_*.json      `punchsweep point --format json` at the paper's points, default and
#                     extended snapshot times
# Usage: bash tests/regression/make_outputs.sh BINARY OUTDIR
# OUTDIR is created; it must not already hold any of these files. Timings go to stderr.
set -euo pipefail
if [ $# -ne 2 ]; then
  echo "usage: $0 BINARY OUTDIR" >&2
  exit 2
fi
bin=$(realpath "$1")
out=$2
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
test -x "$bin" || { echo "$0: $bin is not an executable" >&2; exit 2; }
mkdir -p "$out"
out=$(cd "$out" && pwd)
if compgen -G "$out/*.h5" >/dev/null || compgen -G "$out/point_*.json" >/dev/null; then
  echo "$0: $out already holds outputs; use an empty folder" >&2
  exit 2
fi

export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1

step() {  # step NAME COMMAND...: runs it and reports its wall time on stderr
  local name=$1 t0 t1; shift
  t0=$(date +%s.%N)
  "$@"
  t1=$(date +%s.%N)
  awk -v n="$name" -v a="$t0" -v b="$t1" 'BEGIN { printf "  %-18s %6.2f s\n", n, b - a }' >&2
}
all0=$(date +%s.%N)

# a) The default grid (104,328 points), full quantities, one process.
step default "$bin" sweep --model.localization paper --output "$out/default.h5" --quiet

# b) Fig. 9.5 of the paper: 18 points, full quantities at 101 snapshot times, as the ini says.
step fig9_5 "$bin" sweep --config "$root/sweeps/paper/fig9_5.ini" --output "$out/fig9_5.h5" --quiet

# c) A regime-only slice of the production grid on 2 ranks: production's dh (120), pbar (128)
#    and s (4) axes, with l and T cut to 3 and 2 values: 368,640 points, 24 tiles of 16384 (12 per rank).
step production_slice mpirun --oversubscribe -np 2 "$bin" sweep --config "$root/sweeps/production.ini" \
  --model.localization paper --quantities regime --grid.l 'linspace(0.4, 1.6, 3)' --grid.T 'logspace(1.25, 20, 2)' --chunk 16384 \
  --output "$out/production_slice.h5" --quiet

# d) The BEM reference beside the model: 48 points, the BEM at a random sample of 10 of them
#    (seed 1), on a 32 x 32 grid, tiles of 4 points, 2 ranks.
step bem mpirun --oversubscribe -np 2 "$bin" sweep --model.localization paper --grid.l 0.75,1 --grid.dh 0.05,0.075,0.1 --grid.T 2.5,6 \
  --grid.pbar 0.025,0.06 --grid.s 1,2 --time.times 0,0.5,1,2,5 \
  --reference bem --bem-grid 32 --reference.sample 10 --reference.seed 1 --chunk 4 \
  --output "$out/bem.h5" --quiet

# e) Single points (pbar, l, dh, T, s) from the paper, with the default and extended times.
points=(
  "0.06 0.75 0.075 2.5 2"
  "0.025 0.75 0.05 2.5 2"
  "0.01 0.75 0.04 5 2"
  "0.02 1.0 0.03 4 1"
  "0.03 0.9 0.06 6 3"
  "0.06 0.75 0.05 2.5 2"
)
point_all() {
  local p pbar l dh T s name
  for p in "${points[@]}"; do
    read -r pbar l dh T s <<<"$p"
    name="point_pbar${pbar}_l${l}_dh${dh}_T${T}_s${s}"
    "$bin" point --localization paper --pbar "$pbar" --l "$l" --dh "$dh" --T "$T" --s "$s" --format json \
      > "$out/$name.json"
    "$bin" point --localization paper --pbar "$pbar" --l "$l" --dh "$dh" --T "$T" --s "$s" --times 0,0.5,1,2,5,10 \
      --format json > "$out/${name}_times.json"
  done
}
step points point_all

all1=$(date +%s.%N)
awk -v a="$all0" -v b="$all1" 'BEGIN { printf "  %-18s %6.2f s\n", "total", b - a }' >&2
