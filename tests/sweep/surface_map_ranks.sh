#!/usr/bin/env bash
# punchsweep surface-map: one curve per geometry dealt round the ranks, the loads read off
# each; the map is bit-identical for 1, 3 and 4 ranks (oversubscribed) and a plain
# process; bad input is refused once (rank 0), exit 2, with nothing written.
source "$(dirname "$0")/common.sh"
# Three levels on the square lattice (the cell's own curves, 24 nodes a pitch) and the
# paper's lattice (the periodic tables): 6 and 4 geometries.
three=(--lattice square --l 0.6,0.8,1.0 --dh 0.02,0.04 --dh2 0.05 --s 2 --grid 24
       --pbar 'logspace(0.002, 0.05, 4)' --T 2,4 --times 0,1,5)
# The second with a box of tolerances (t_star_low/high, regime_low/high gathered too).
two=(--l 0.75,1.5 --dh 'linspace(0.01, 0.03, 2)' --s 2 --pbar 'logspace(1e-5, 0.05, 6)' --T 2.5 --times 0,1,5,50
     --tolerance 'pbar=10%, T=0.2')
same_surface_maps() {  # every variable bit-identical (NaN payloads too)
  /usr/bin/python3 - "$1" "$2" <<'PY'
import sys
import h5py
import numpy as np
with h5py.File(sys.argv[1]) as a, h5py.File(sys.argv[2]) as b:
    names = sorted(k for k in a if isinstance(a[k], h5py.Dataset))
    bad = [k for k in names if k not in b or a[k].shape != b[k].shape
           or a[k][()].tobytes() != b[k][()].tobytes()]
    if sorted(k for k in b if isinstance(b[k], h5py.Dataset)) != names or bad:
        sys.exit(f"FAIL: {sys.argv[1]} and {sys.argv[2]} differ in {bad or 'their variables'}")
PY
}
for name in three two; do
  declare -n args=$name
  run_ranks 0 surface-map "${args[@]}" --output "one_$name.nc" 2> log
  grep -q "wrote one_$name.nc" log
  for n in 1 3 4; do
    run_ranks "$n" surface-map "${args[@]}" --output "np${n}_$name.nc" 2> log
    same_surface_maps "one_$name.nc" "np${n}_$name.nc"
  done
done
# The paper's lattice reads the tables; three levels solve the cell.
tables() { /usr/bin/python3 -c "import h5py, sys; print(sorted(set(h5py.File(sys.argv[1])['from_tables'][()].ravel())))" "$1"; }
test "$(tables one_two.nc)" = "[1]"
test "$(tables one_three.nc)" = "[0]"
# Bad input: one line from rank 0, exit 2, no map.
refuse() {  # refuse MESSAGE ARGS...
  local message=$1; shift
  set +e
  run_ranks 3 surface-map "$@" > out 2> err
  local rc=$?
  set -e
  if [ "$rc" != 2 ]; then echo "FAIL: exit $rc for $*"; cat err; exit 1; fi
  if ! grep -qF -- "$message" err; then echo "FAIL: no '$message' for $*"; cat err; exit 1; fi
  if [ "$(grep -c "^punchsweep surface-map: " err)" != 1 ]; then echo "FAIL: not one line for $*"; cat err; exit 1; fi
  if ls bad.nc* >/dev/null 2>&1; then echo "FAIL: $* left a file"; exit 1; fi
}
refuse "--output FILE is required" "${two[@]}"
refuse "--dh = '-0.01,0.02': height difference of the punch levels dh = -0.01 is outside its range" --l 0.75 --dh=-0.01,0.02 --s 2 --pbar 0.01 --T 2.5 --output bad.nc
refuse "--check is not a map's" "${two[@]}" --check --output bad.nc
refuse "'dh' is no load input of a surface map" --l 0.75 --dh 0.02 --s 2 --pbar 0.01 --T 2.5 --tolerance dh=0.001 --output bad.nc
refuse "--pbar (or --pressure with a material) is required" --l 0.75 --dh 0.02 --s 2 --T 2.5 --output bad.nc
refuse "one_two.nc exists; pass --overwrite to replace it" "${two[@]}" --output one_two.nc
run_ranks 3 surface-map "${two[@]}" --output one_two.nc --overwrite 2> log
same_surface_maps one_two.nc np1_two.nc
echo "PASS: surface maps identical for 1, 3, 4 ranks and a plain process; bad input refused once"
