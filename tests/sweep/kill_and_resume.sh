#!/usr/bin/env bash
# kill -9 of mpirun (or of one rank) mid-run, then --resume, gives the same map as a clean
# run, without recomputing finished tiles.
source "$(dirname "$0")/common.sh"
grid=(--grid.l 'linspace(0.5, 1.25, 6)' --grid.T 2,5,10 --chunk 1000)
run_ranks 2 sweep "${grid[@]}" --quiet --output clean.h5

# The map by its absolute path: it is in this test's own command lines only, so pgrep and
# pkill below never touch the sweeps of tests running beside this one.
map="$work/k.h5"
journal_bytes() { stat -c %s "$map.partial.journal" 2>/dev/null || echo 0; }
wait_for_progress() {  # until the journal holds more than $1 bytes, or the run ($2) ended
  wait_until 300 "$2" "$map's journal past $1 bytes" -- file_larger "$map.partial.journal" "$1" || true
}

# 1) kill -9 of mpirun itself, twice, at different moments.
for threshold in 100000 1500000; do
  start_ranks 2 sweep "${grid[@]}" --quiet --output "$map" --resume; pid=$!
  wait_for_progress "$threshold" "$pid"
  kill -9 "$pid" 2>/dev/null || true
  wait "$pid" 2>/dev/null || true
  wait_until 10 "" "the ranks to end with mpirun" -- gone "--output $map"  # a busy machine takes seconds
done
test -f "$map.partial.journal" || { echo "FAIL: the kill came too late to test anything"; exit 1; }
done_before=$(journal_bytes)

# 2) kill -9 of one rank (the worker).
start_ranks 2 sweep "${grid[@]}" --quiet --output "$map" --resume; pid=$!
wait_for_progress $((done_before + 200000)) "$pid"
pkill -9 -f -n -- "--output $map" || true  # the newest of this run's processes: a rank
wait "$pid" 2>/dev/null || true
wait_until 10 "" "the other rank to end" -- gone "--output $map"

# 3) Resume to the end: it must say how much was already done, and match the clean map.
run_ranks 2 sweep "${grid[@]}" --output "$map" --resume 2> resume.log || { cat resume.log; exit 1; }
grep -q "already done" resume.log || { echo "FAIL: resume did not restore tiles"; cat resume.log; exit 1; }
test ! -e "$map.partial" && test ! -e "$map.partial.journal"
same_maps clean.h5 "$map"
echo "PASS: killed runs resumed to a bit-identical map"
