#!/usr/bin/env bash
# A texture map whose readings outweigh its curve (issue 49: "schedule curves as units of
# work ... and spread their readings as tiles"): one hexagonal three-level geometry of the
# TPE mould at 64 nodes a pitch (a 0.5 s curve) x 100,000 load points (500 pressures x 200
# temperatures, 3 times), on 1 and 2 ranks, with this build and another (the commit before,
# where a geometry was one unit of work), side by side, each run with a fresh curve cache.
# Prints the wall seconds of each and whether the maps are the same bits.
# Usage: bash benchmarks/texture_map_tiles.sh [PUNCHSWEEP] [OTHER_PUNCHSWEEP] [TEMPERATURES]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
new=${1:-"$root/build/src/app/punchsweep"}
old=${2:-}
temperatures=${3:-200}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cat > "$work/map.ini" <<INI
[texture]
lattice = hexagonal
grid = 64
[model]
material = $root/examples/dma_exports/tpe_a_truth.ini
R = 60um
s = 2
[grid]
l = 200um
dh = 2um
dh2 = 5um
pressure = logspace(1kPa, 50kPa, 500)
temperature = linspace(10, 50, $temperatures)
[time]
times = 1s, 1min, 1h
INI
run() {  # run NAME BINARY RANKS: wall seconds of one map
  local start end
  rm -rf "$work/cache"
  start=$(date +%s%N)
  PUNCHSWEEP_CACHE="$work/cache" mpirun --oversubscribe -n "$3" "$2" sweep --config "$work/map.ini" --output "$work/$1.nc" --quiet
  end=$(date +%s%N)
  awk -v ns=$((end - start)) -v name="$1" 'BEGIN {printf "%-10s %6.1f s\n", name, ns / 1e9}'
}
for ranks in 1 2; do
  [ -n "$old" ] && run "old_np$ranks" "$old" "$ranks"
  run "new_np$ranks" "$new" "$ranks"
done
/usr/bin/python3 - "$work" ${old:+old} <<'PY'
import sys, glob, h5py
work = sys.argv[1]
maps = sorted(glob.glob(f"{work}/*.nc"))
with h5py.File(maps[0]) as a:
    for other in maps[1:]:
        with h5py.File(other) as b:
            same = all(a[k][()].tobytes() == b[k][()].tobytes() for k in a if isinstance(a[k], h5py.Dataset))
            print(f"{other.rsplit('/', 1)[1]} {'the same bits as' if same else 'DIFFERS from'} {maps[0].rsplit('/', 1)[1]}")
PY
