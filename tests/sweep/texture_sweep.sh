#!/usr/bin/env bash
# punchsweep sweep of a texture ([texture] in the config): a hexagonal three-level map is
# bit-identical on 1, 2 and 3 ranks, and in tiles of one pressure (run.chunk) on 1 and 3,
# the same map as surface-map's, resumes after kill -9 of mpirun (in tiles) to the map of an
# uninterrupted run without computing the journalled tiles again, and refuses bad keys, a geometry `surface` would refuse and an interrupted map
# without --resume once (rank 0), exit 2, before any curve.
source "$(dirname "$0")/common.sh"
cat > hex.ini <<'INI'
# A hexagonal mould of three levels, in the model's units, on 64 nodes a pitch.
[texture]
lattice = hexagonal
grid = 64
[model]
s = 2
[grid]
l = 1.2
dh = linspace(0.01, 0.06, 6)
dh2 = 0.08
pbar = logspace(0.002, 0.05, 6)
T = 2, 4
[time]
times = 0, 1, 5
# Three load points stepped in time on the same cell (surface --check), the same on any rank.
[reference]
sample = 3
INI
same_texture_maps() {  # every variable bit-identical (NaN payloads too), the same variables
  /usr/bin/python3 - "$1" "$2" <<'PY'
import sys
import h5py
with h5py.File(sys.argv[1]) as a, h5py.File(sys.argv[2]) as b:
    names = sorted(k for k in a if isinstance(a[k], h5py.Dataset))
    bad = [k for k in names if k not in b or a[k].shape != b[k].shape or a[k][()].tobytes() != b[k][()].tobytes()]
    if sorted(k for k in b if isinstance(b[k], h5py.Dataset)) != names or bad:
        sys.exit(f"FAIL: {sys.argv[1]} and {sys.argv[2]} differ in {bad or 'their variables'}")
    for f in (a, b):
        assert f["t_star"].shape == (1, 6, 1, 6, 2, 3) and f["level"].shape == (3,), f["t_star"].shape
        assert int(f.attrs["layout_version"]) == 2
        assert (f["check_regime"][()][..., 0] >= 0).sum() == 3
PY
}
# --dry-run: once from rank 0, nothing written; the six curves to build, then (after the
# run below) in the cache; the grid the map stores.
dry_run() {  # dry_run RANKS: the dry run's stdout in dry.out
  PUNCHSWEEP_CACHE="$work/cache1" run_ranks "$1" sweep --config hex.ini --output dry.nc --dry-run > dry.out 2> dry.err ||
    { echo "FAIL: the dry run"; cat dry.out dry.err; exit 1; }
  if ls dry.nc* > /dev/null 2>&1; then echo "FAIL: the dry run left a file"; exit 1; fi
  [ "$(grep -c -- "--dry-run (a texture's map)" dry.out)" = 1 ] || { echo "FAIL: not one dry run"; cat dry.out; exit 1; }
  grep -q "points: 6 geometries x 12 load points" dry.out || { cat dry.out; exit 1; }
  grep -q "geometry 6 (l = 1.2 R, dh = 0.06 R, dh2 = 0.08 R): 64 x 108 nodes (64 a pitch)" dry.out || { cat dry.out; exit 1; }
}
dry_run 3
grep -q "curves: 6 to build, 0 in the cache" dry.out || { echo "FAIL: the dry run's curves"; cat dry.out; exit 1; }
grep -q "estimated time: about .* on 3 ranks" dry.out || { cat dry.out; exit 1; }
# Each run its own curve cache, so that every one builds its curves.
PUNCHSWEEP_CACHE="$work/cache1" run_ranks 0 sweep --config hex.ini --output one.nc 2> log
dry_run 1
grep -q "curves: 0 to build, 6 in the cache" dry.out || { echo "FAIL: the dry run after the map"; cat dry.out; exit 1; }
# surface --dry-run of one of its geometries: cached; of another dh: to build; refusals as surface's.
hex_surface=(surface --lattice hexagonal --s 2 --l 1.2 --dh2 0.08 --pbar 0.002 --T 2 --times 0,1,5 --dry-run)
PUNCHSWEEP_CACHE="$work/cache1" "$PUNCHSWEEP" "${hex_surface[@]}" --grid 64 --dh 0.06 > s.out
grep -q "curve on 64 x 108 nodes (64 a pitch): about .* MB; in the cache (read, not built)" s.out || { cat s.out; exit 1; }
PUNCHSWEEP_CACHE="$work/cache1" "$PUNCHSWEEP" "${hex_surface[@]}" --grid 64 --dh 0.07 > s.out
grep -q "curve on 64 x 108 nodes (64 a pitch): about .* MB; to build, about .* s on one core" s.out || { cat s.out; exit 1; }
set +e
"$PUNCHSWEEP" "${hex_surface[@]}" --dh 0.07 --supercell 16 --grid 1024 > s.out 2> s.err; rc=$?
set -e
[ "$rc" = 2 ] && grep -q "16384 x 28512 nodes" s.err || { echo "FAIL: surface --dry-run beyond the budget: exit $rc"; cat s.err; exit 1; }
# The costliest curve is dealt first: l = 6 asks --grid auto for more nodes than l = 1.2
# (the dry run's estimates say so), and on one rank it is built first.
cat > order.ini <<'INI'
[texture]
lattice = hexagonal
grid = auto
[model]
s = 2
[grid]
l = 1.2, 6
dh = 0.02
pbar = 0.02
T = 2
[time]
times = 1
INI
PUNCHSWEEP_CACHE="$work/cache_order" run_ranks 0 sweep --config order.ini --output order.nc 2> order.log
[[ "$(sed -n 2p order.log)" == *"geometry 2 (l = 6 R, dh = 0.02 R): curve built"* ]] || { echo "FAIL: not the costliest first"; cat order.log; exit 1; }
/usr/bin/python3 -c "
import h5py, sys
with h5py.File('one.nc') as f:
    assert (f['grid'][()] == 64).all(), f['grid'][()]
"
grep -q "wrote one.nc (6 geometries x 12 load points x 3 levels, 3 times)" log || { cat log; exit 1; }
grep -q "6 of 6 done (100%)" log || { echo "FAIL: no progress line"; cat log; exit 1; }
for n in 2 3; do
  PUNCHSWEEP_CACHE="$work/cache_np$n" run_ranks "$n" sweep --config hex.ini --output "np$n.nc" --quiet
  same_texture_maps one.nc "np$n.nc"
done
# In tiles of one pressure (chunk 4: fewer values than a row's 2 temperatures x 3 times),
# six a geometry: the same map; its variables over the load chunked a tile (a pressure) each.
PUNCHSWEEP_CACHE="$work/cache_tiles" run_ranks 0 sweep --config hex.ini --chunk 4 --output tiles1.nc 2> tiles.log
grep -q "6 geometries (a load curve each) x 12 load points in 36 tiles (6 a geometry) on 1 rank" tiles.log || { cat tiles.log; exit 1; }
grep -q "geometry 1 (l = 1.2 R, dh = 0.01 R, dh2 = 0.08 R), load points 3 to 4 of 12: curve held from the rank's tile before; " tiles.log ||
  { echo "FAIL: a tile's curve not held"; cat tiles.log; exit 1; }
same_texture_maps one.nc tiles1.nc
PUNCHSWEEP_CACHE="$work/cache_tiles3" run_ranks 3 sweep --config hex.ini --run.chunk 4 --output tiles3.nc --quiet
same_texture_maps one.nc tiles3.nc
/usr/bin/python3 -c "
import h5py
with h5py.File('tiles3.nc') as f:
    assert f['t_star'].chunks == (1, 1, 1, 1, 2, 3), f['t_star'].chunks
    assert f['touched'].chunks == (1, 1, 1, 1, 2, 3), f['touched'].chunks
    assert f['X_star'].chunks == (1, 1, 1, 3), f['X_star'].chunks
"
# Each level's touch alone ([output] quantities = regime): the full map's variables but
# what the snapshot times read, the same bits.
PUNCHSWEEP_CACHE="$work/cache_regime" run_ranks 2 sweep --config hex.ini --quantities regime --output regime.nc --quiet
/usr/bin/python3 - one.nc regime.nc <<'PY'
import sys
import h5py
with h5py.File(sys.argv[1]) as full, h5py.File(sys.argv[2]) as regime:
    kept = sorted(k for k in regime if isinstance(regime[k], h5py.Dataset))
    left = sorted(k for k in full if isinstance(full[k], h5py.Dataset) and k not in regime)
    assert left == ["area_fraction", "level_area", "level_load", "level_touched", "touched", "valid"], left
    assert {"t_star", "regime", "X_star", "resolved", "contact_radius", "advised", "check_regime",
            "check_area_fraction"} <= set(kept), kept
    bad = [k for k in kept if full[k][()].tobytes() != regime[k][()].tobytes()]
    assert not bad, bad
PY
# The same keys through surface-map (its spelling of the same run) and on the command line.
PUNCHSWEEP_CACHE="$work/cache_map" run_ranks 2 surface-map --lattice hexagonal --grid 64 --s 2 --l 1.2 \
  --dh 'linspace(0.01, 0.06, 6)' --dh2 0.08 --pbar 'logspace(0.002, 0.05, 6)' --T 2,4 --times 0,1,5 --check-sample 3 --output map.nc --quiet
same_texture_maps one.nc map.nc
PUNCHSWEEP_CACHE="$work/cache_cli" run_ranks 0 sweep --texture.lattice hexagonal --texture.grid 64 --model.s 2 \
  --grid.l 1.2 --grid.dh 'linspace(0.01, 0.06, 6)' --grid.dh2 0.08 --grid.pbar 'logspace(0.002, 0.05, 6)' \
  --grid.T 2,4 --time.times 0,1,5 --reference.sample 3 --output cli.nc --quiet
same_texture_maps one.nc cli.nc

# kill -9 of mpirun once the journal holds its first tile (a pressure of a geometry), then --resume.
map="$work/k.nc"
export PUNCHSWEEP_CACHE="$work/cache_kill"
has_a_geometry() { grep -qa PSRC "$map.partial.journal" 2>/dev/null; }
start_ranks 2 sweep --config hex.ini --chunk 4 --output "$map" --quiet; pid=$!
wait_until 120 "$pid" "$map's journal to hold a tile" -- has_a_geometry || true
kill -9 "$pid" 2>/dev/null || true
wait "$pid" 2>/dev/null || true
wait_until 10 "" "the ranks to end with mpirun" -- gone "--output $map"
test -f "$map.partial.journal" && test ! -e "$map" || { echo "FAIL: the kill came too late to test anything"; exit 1; }
# Without --resume the interrupted map is refused, once, with what to do; in other tiles too.
set +e
run_ranks 2 sweep --config hex.ini --chunk 4 --output "$map" > out 2> err; rc=$?
set -e
[ "$rc" = 2 ] && grep -q "pass --resume to finish it" err && [ "$(grep -c "^punchsweep sweep: " err)" = 1 ] ||
  { echo "FAIL: exit $rc"; cat err; exit 1; }
set +e
run_ranks 2 sweep --config hex.ini --chunk 8 --output "$map" --resume > out 2> err; rc=$?
set -e
[ "$rc" = 2 ] && grep -q "chunk: the existing map has 4; this run asks for 8" err || { echo "FAIL: resumed in other tiles: exit $rc"; cat err; exit 1; }
run_ranks 2 sweep --config hex.ini --chunk 4 --output "$map" --resume 2> resume.log || { cat resume.log; exit 1; }
grep -q "already done (from $map.partial.journal)" resume.log || { echo "FAIL: nothing resumed"; cat resume.log; exit 1; }
test ! -e "$map.partial" && test ! -e "$map.partial.journal"
same_texture_maps one.nc "$map"
# A finished map resumed again: nothing to do; with another configuration: refused.
run_ranks 0 sweep --config hex.ini --chunk 4 --output "$map" --resume 2> again.log
grep -q "already complete" again.log
set +e
run_ranks 0 sweep --config hex.ini --chunk 4 --grid.T 2,5 --output "$map" --resume 2> err; rc=$?
set -e
[ "$rc" = 2 ] && grep -q "T: the existing map has 2, 4; this run asks for 2,5" err || { echo "FAIL: exit $rc"; cat err; exit 1; }

# Bad keys: one line from rank 0, exit 2, nothing written.
refuse() {  # refuse MESSAGE ARGS...
  local message=$1; shift
  set +e
  run_ranks 3 sweep "$@" > out 2> err
  local rc=$?
  set -e
  if [ "$rc" != 2 ]; then echo "FAIL: exit $rc for $*"; cat err; exit 1; fi
  if ! grep -qF -- "$message" err; then echo "FAIL: no '$message' for $*"; cat err; exit 1; fi
  if [ "$(grep -c "^punchsweep sweep: " err)" != 1 ]; then echo "FAIL: not one line for $*"; cat err; exit 1; fi
  if ls bad.nc* >/dev/null 2>&1; then echo "FAIL: $* left a file"; exit 1; fi
}
refuse "unknown key texture.latice" --config hex.ini --texture.latice square --output bad.nc
refuse "--quantities = 'series': valid: regime (each level's touch) or full" --config hex.ini --output.quantities series --output bad.nc
refuse "--check-sample = 73: valid: 1 to the map's 72 load points (6 geometries x 12)" --config hex.ini --reference.sample 73 --output bad.nc
refuse "--dh = '-0.01': height difference of the punch levels dh = -0.01 is outside its range" --config hex.ini --grid.dh=-0.01 --output bad.nc
refuse "run.resume = true and run.overwrite = true" --config hex.ini --resume --overwrite --output bad.nc
refuse "--chunk = 0: valid: an integer >= 1" --config hex.ini --chunk 0 --output bad.nc
refuse "--chunk = '4k' is not an integer: valid: an integer >= 1" --config hex.ini --run.chunk 4k --output bad.nc
# What `surface` would refuse of a geometry is refused before any curve, not by the rank
# that meets it (before, mpirun aborted and left a journal behind).
sed '/^s = 2$/d' hex.ini > no-s.ini
refuse "geometry 1 (l = 1.2 R, dh = 0.01 R, dh2 = 0.08 R): missing required option --s" --config no-s.ini --output bad.nc
refuse "geometry 1 (l = 1.2 R, dh = 0.01 R, dh2 = 0.08 R): the curve's grid, 16384 x 28512 nodes" \
  --config hex.ini --texture.supercell 16 --texture.grid 1024 --output bad.nc
echo "PASS: texture sweeps identical for 1, 2, 3 ranks, in tiles, surface-map and the command line; resumed after kill -9"
