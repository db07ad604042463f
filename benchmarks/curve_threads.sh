#!/usr/bin/env bash
# One load curve on one thread and on several, side by side in one run: `punchsweep surface`
# of each cell below under OMP_NUM_THREADS=1 and =N, interleaved, the curve's own seconds
# (the JSON's curve.seconds; median of the repeats), their ratio, and whether the two
# answers are equal to the bit (every JSON number but the seconds).
# Cells: hex2-256  two-level hexagonal, 256 nodes a pitch (its quarter: the cosine transform)
#        hex3-256  three-level hexagonal, 256 (its half: cosine along x, FFTW rows along y)
#        square-512  two-level square, --curve cell, 512 (its quarter)
#        super-64  4 x 4 scattered hexagonal supercell, 64 a pitch (the whole grid: FFTW 2-D)
# Usage: [THREADS=N] [REPEATS=K] [CELLS="hex2-256 super-64"] benchmarks/curve_threads.sh [BIN]
# (defaults: the machine's cores, 3, every cell; build/src/app/punchsweep)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bin=${1:-"$root/build/src/app/punchsweep"}
threads=${THREADS:-$(nproc)} repeats=${REPEATS:-3} cells=${CELLS:-"hex2-256 hex3-256 square-512 super-64"}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export PUNCHSWEEP_CACHE=off  # every run builds its curve

cell_args() {
  case "$1" in
    hex2-256) echo "--lattice hexagonal --l 1.2 --dh 0.05 --pbar 0.02 --grid 256" ;;
    hex3-256) echo "--lattice hexagonal --l 1.2 --dh 0.03 --dh2 0.08 --pbar 0.005 --grid 256" ;;
    square-512) echo "--lattice square --l 1.2 --dh 0.05 --pbar 0.02 --grid 512 --curve cell" ;;
    super-64) echo "--lattice hexagonal --l 1.2 --dh 0.05 --pbar 0.02 --supercell 4 --scatter normal:0.01 --grid 64" ;;
    *) echo "curve_threads.sh: unknown cell $1" >&2; exit 2 ;;
  esac
}

printf "%-11s %9s %9s %7s %s\n" cell "1 thread" "$threads thr." ratio answers
for cell in $cells; do
  for k in $(seq "$repeats"); do
    for n in 1 "$threads"; do
      # shellcheck disable=SC2046
      OMP_NUM_THREADS=$n "$bin" surface $(cell_args "$cell") --T 2.5 --s 2 --format json > "$work/$cell.$n.$k.json" 2>> "$work/progress.log"
    done
  done
  /usr/bin/python3 - "$work" "$cell" "$threads" "$repeats" <<'PY'
import json, statistics, sys
work, cell, threads, repeats = sys.argv[1], sys.argv[2], sys.argv[3], int(sys.argv[4])
def load(n, k):
    return json.load(open(f"{work}/{cell}.{n}.{k}.json"))
def answer(d):
    d = dict(d); d["curve"] = {k: v for k, v in d["curve"].items() if k != "seconds"}
    return json.dumps(d, sort_keys=True)
one = [load(1, k) for k in range(1, repeats + 1)]
many = [load(threads, k) for k in range(1, repeats + 1)]
t1 = statistics.median(d["curve"]["seconds"] for d in one)
tn = statistics.median(d["curve"]["seconds"] for d in many)
same = all(answer(d) == answer(one[0]) for d in one + many)
print(f"{cell:<11} {t1:8.2f}s {tn:8.2f}s {t1 / tn:6.2f}x {'equal to the bit' if same else 'DIFFER'}")
PY
done
