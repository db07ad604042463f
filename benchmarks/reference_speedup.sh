#!/usr/bin/env bash
# The BEM reference solver old and new, side by side in one run: `punchsweep reference` of
# one viscoelastic point (standard linear solid T = 2.5, s = 2, snapshots 0, 0.5, 1, 2,
# 5 T_eps) by two engines, interleaved, at each grid size: the point's own seconds (the
# JSON's `seconds`, the evaluation without the process's start, about 0.02 s; median of
# the repeats), their ratio, and both engines' solves, CG iterations and t*.
# Target (issue 13): >= 10x per viscoelastic point at N = 256.
# Points: paper   l = 0.75, dh = 0.075, pbar = 0.06 (delayed, t* = 0.874: the paper's point)
#         tight   l = 0.5, dh = 0.01, pbar = 0.2 (immediate, 95% of the cell in contact at
#                 t = 0: where the model is invalid and the BEM must answer)
#         sparse  l = 1.5, dh = 0.2, pbar = 0.002 (never; 3% in contact)
# Usage: benchmarks/reference_speedup.sh [--old BIN | --base REV] [--new BIN] [--sizes "128 256"]
#                                         [--repeats K] [--points "paper tight"]
# Without --old, the engine of revision REV (default 0d1ba73, the solver before issue 13's
# speed work: whole cell, plain CG, fixed step ladder, bisected t*) is built in a scratch
# worktree (about 2 minutes).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
old="" base=0d1ba73 new="$root/build/src/app/punchsweep" sizes="128 256" repeats=3 points="paper tight sparse"
while [ $# -gt 0 ]; do
  case "$1" in
    --old) old=$2; shift 2 ;;
    --base) base=$2; shift 2 ;;
    --new) new=$2; shift 2 ;;
    --sizes) sizes=$2; shift 2 ;;
    --repeats) repeats=$2; shift 2 ;;
    --points) points=$2; shift 2 ;;
    *) echo "reference_speedup.sh: unknown argument $1" >&2; exit 2 ;;
  esac
done
work=$(mktemp -d)
cleanup() {
  if [ -d "$work/base" ]; then git -C "$root" worktree remove --force "$work/base" >/dev/null 2>&1 || true; fi
  rm -rf "$work"
}
trap cleanup EXIT
if [ -z "$old" ]; then
  echo "building the engine of $base (the old solver) ..." >&2
  git -C "$root" worktree add --detach -f "$work/base" "$base" >/dev/null 2>&1
  cmake -S "$work/base" -B "$work/base/build" -DCMAKE_BUILD_TYPE=Release >/dev/null
  cmake --build "$work/base/build" -j2 --target punchsweep >/dev/null
  old="$work/base/build/src/app/punchsweep"
fi
export PUNCHSWEEP_CACHE=off  # the BEM reads no model tables; keep the runs alike

point_args() {
  case "$1" in
    paper) echo "--l 0.75 --dh 0.075 --pbar 0.06" ;;
    tight) echo "--l 0.5 --dh 0.01 --pbar 0.2" ;;
    sparse) echo "--l 1.5 --dh 0.2 --pbar 0.002" ;;
  esac
}

run() {  # run BIN N POINT: "seconds solves iterations regime t_star" of one reference point
  # shellcheck disable=SC2046
  "$1" reference $(point_args "$3") --T 2.5 --s 2 --bem-grid "$2" --format json > "$work/out.json"
  /usr/bin/python3 - "$work/out.json" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
t = d.get("t_star")
print(f"{d['seconds']:.4f} {d['solves']} {d['cg_iterations']} {d['regime']} {'-' if t is None else f'{t:.6f}'}")
PY
}

median() { tr ' ' '\n' | sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }

printf '%-7s %5s %9s %9s %7s   %-30s %s\n' point N "old s" "new s" ratio "old: solves, CG its, regime, t*" "new: the same"
for point in $points; do
  for n in $sizes; do
    old_times="" new_times=""
    for _ in $(seq "$repeats"); do
      read -r s_old solves_old its_old regime_old t_old < <(run "$old" "$n" "$point")
      read -r s_new solves_new its_new regime_new t_new < <(run "$new" "$n" "$point")
      old_times="$old_times $s_old" new_times="$new_times $s_new"
    done
    mo=$(echo $old_times | median) mn=$(echo $new_times | median)
    printf '%-7s %5s %9.4f %9.4f %6.1fx   %-30s %s\n' "$point" "$n" "$mo" "$mn" "$(awk -v a="$mo" -v b="$mn" 'BEGIN { print a / b }')" \
      "$solves_old, $its_old, $regime_old, $t_old" "$solves_new, $its_new, $regime_new, $t_new"
  done
done
