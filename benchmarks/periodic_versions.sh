#!/usr/bin/env bash
# The periodic model of two builds side by side (issue 34: the small-spot table and its
# hand-over must keep the regime sweep and classify at their rates), one rank, alternating
# runs, in points/s (the map's points_per_second: first tile to last):
#   box      regime sweep over the paper's box, 7 x 111 x 9 x 200 x 3 = 4,195,800 points
#            (periodic_throughput.sh's grid: many of its points now read the small-spot table
#            or the hand-over);
#   wide     regime sweep over the physical range, l 0.05-20, dh 1e-4-0.3, pbar 1e-8-1e-2,
#            T 2-10, s 1-3: 12 x 60 x 5 x 120 x 3 = 1,296,000 points;
#   classify punchsweep.classify over the box grid (4.2e6 points), at 200,000 scattered points
#            of the wide range (cl-scat; each its own touchdown) and of the box (cl-bscat,
#            python_classify.py's), with each build's module.
# Usage: benchmarks/periodic_versions.sh OLD_BUILD NEW_BUILD [REPEATS]
#   (build folders: BUILD/src/app/punchsweep and BUILD/python)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
old=$(cd "$1" && pwd)
new=$(cd "$2" && pwd)
repeats=${3:-3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
py=/usr/bin/python3
[ -x "$py" ] || py=$(command -v python3)

box=(--grid.l 'linspace(0.5, 1.25, 7)' --grid.dh 'linspace(0.01, 0.12, 111)' --grid.T 'linspace(2, 10, 9)'
     --grid.pbar 'logspace(0.005, 0.08, 200)' --grid.s 1,2,3 --quantities regime)
wide=(--grid.l 'logspace(0.05, 20, 12)' --grid.dh 'logspace(1e-4, 0.3, 60)' --grid.T 'linspace(2, 10, 5)'
      --grid.pbar 'logspace(1e-8, 1e-2, 120)' --grid.s 1,2,3 --quantities regime)

# shellcheck source=benchmarks/sweep_rate.sh
source "$root/benchmarks/sweep_rate.sh"

classify() {  # classify BUILD: "box scattered" points/s with that build's module
  PYTHONPATH="$1/python" taskset -c "$core" "$py" - <<'EOF'
import time, numpy as np, punchsweep
l = np.linspace(0.5, 1.25, 7)[:, None, None, None, None]
dh = np.linspace(0.01, 0.12, 111)[None, :, None, None, None]
T = np.linspace(2, 10, 9)[None, None, :, None, None]
pbar = np.geomspace(0.005, 0.08, 200)[None, None, None, :, None]
s = np.array([1.0, 2.0, 3.0])[None, None, None, None, :]
punchsweep.classify(0.75, 0.05, 2.0, 0.01, 2.0)  # tables loaded before the clock starts
t = time.perf_counter(); c = punchsweep.classify(l, dh, T, pbar, s); box = c["regime"].size / (time.perf_counter() - t)
rng = np.random.default_rng(1); n = 200000
args = (np.exp(rng.uniform(np.log(0.05), np.log(20), n)), np.exp(rng.uniform(np.log(1e-4), np.log(0.3), n)),
        rng.uniform(2, 10, n), np.exp(rng.uniform(np.log(1e-8), np.log(1e-2), n)), rng.integers(1, 4, n).astype(float))
t = time.perf_counter(); c = punchsweep.classify(*args); scattered = n / (time.perf_counter() - t)
args = (rng.uniform(0.5, 1.25, n), rng.uniform(0.01, 0.12, n), rng.uniform(2, 10, n),
        np.exp(rng.uniform(np.log(0.005), np.log(0.08), n)), rng.integers(1, 4, n).astype(float))
t = time.perf_counter(); c = punchsweep.classify(*args); box_scattered = n / (time.perf_counter() - t)
print(f"{box:.4g} {scattered:.4g} {box_scattered:.4g}")
EOF
}

# Every run pinned to one core (the last), old and new alternating, which first alternating
# too; each row's median ratio at the end.
core=$(( $(nproc) - 1 ))
pin=(taskset -c "$core")
printf '%-9s %-11s %-11s %s\n' run old new new/old
: >"$work/ratios"
for r in $(seq "$repeats"); do
  for grid in box wide; do
    case $grid in box) args=("${box[@]}") ;; wide) args=("${wide[@]}") ;; esac
    one() { "${pin[@]}" bash -c "$(declare -f rate); bin='$1/src/app/punchsweep' work='$work' rate $(printf '%q ' "${args[@]}")"; }
    # Which goes first alternates (a second run of the same build was up to 9% faster).
    if (( r % 2 )); then read -r a _ <<<"$(one "$old")"; read -r b _ <<<"$(one "$new")"
    else read -r b _ <<<"$(one "$new")"; read -r a _ <<<"$(one "$old")"; fi
    printf '%-9s %-11.4g %-11.4g %.3f\n' "$grid" "$a" "$b" "$(awk -v a="$a" -v b="$b" 'BEGIN { print b / a }')" | tee -a "$work/ratios"
  done
  if (( r % 2 )); then read -r oa os ob <<<"$(classify "$old")"; read -r na ns nb <<<"$(classify "$new")"
  else read -r na ns nb <<<"$(classify "$new")"; read -r oa os ob <<<"$(classify "$old")"; fi
  printf '%-9s %-11.4g %-11.4g %.3f\n' "cl-box" "$oa" "$na" "$(awk -v a="$oa" -v b="$na" 'BEGIN { print b / a }')" | tee -a "$work/ratios"
  printf '%-9s %-11.4g %-11.4g %.3f\n' "cl-scat" "$os" "$ns" "$(awk -v a="$os" -v b="$ns" 'BEGIN { print b / a }')" | tee -a "$work/ratios"
  printf '%-9s %-11.4g %-11.4g %.3f\n' "cl-bscat" "$ob" "$nb" "$(awk -v a="$ob" -v b="$nb" 'BEGIN { print b / a }')" | tee -a "$work/ratios"
done
echo "median new/old:"
for row in box wide cl-box cl-scat cl-bscat; do
  awk -v r="$row" '$1 == r { print $4 }' "$work/ratios" | sort -g |
    awk -v r="$row" '{ v[NR] = $1 } END { printf "  %-9s %.3f (of %d runs)\n", r, (NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2), NR }'
done
