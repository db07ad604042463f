#!/usr/bin/env bash
# kill -9 of mpirun (or of one rank) mid-run, then --resume, gives the same map as a clean
# run, without recomputing finished tiles.
source "$(dirname "$0")/common.sh"
grid=(--grid.l 'linspace(0.5, 1.25, 6)' --grid.T 2,5,10 --chunk 1000)
run_ranks 2 sweep "${grid[@]}" --quiet --output clean.h5

# The map by its absolute path: it is in this test's own command lines only, so pgrep and
# pkill below never touch the sweeps of tests running beside this one.
map="$work/k.h5"
mine() { pgrep -f -- "--output $map" || true; }
journal_bytes() { stat -c %s "$map.partial.journal" 2>/dev/null || echo 0; }
wait_for_progress() {  # until the journal holds more than $1 bytes, or the run ended
  while [ "$(journal_bytes)" -le "$1" ] && kill -0 "$2" 2>/dev/null; do sleep 0.02; done
}

# 1) kill -9 of mpirun itself, twice, at different moments.
for threshold in 100000 1500000; do
  start_ranks 2 sweep "${grid[@]}" --quiet --output "$map" --resume; pid=$!
  wait_for_progress "$threshold" "$pid"
  kill -9 "$pid" 2>/dev/null || true
  wait "$pid" 2>/dev/null || true
  for _ in $(seq 50); do [ -z "$(mine)" ] && break; sleep 0.1; done  # up to 5 s on a busy machine
  if [ -n "$(mine)" ]; then echo "FAIL: ranks outlived mpirun: $(ps -o pid,ppid,args -p "$(mine | paste -sd,)")"; exit 1; fi
done
test -f "$map.partial.journal" || { echo "FAIL: the kill came too late to test anything"; exit 1; }
done_before=$(journal_bytes)

# 2) kill -9 of one rank (the worker).
start_ranks 2 sweep "${grid[@]}" --quiet --output "$map" --resume; pid=$!
wait_for_progress $((done_before + 200000)) "$pid"
pkill -9 -f -n -- "--output $map" || true  # the newest of this run's processes: a rank
wait "$pid" 2>/dev/null || true
for _ in $(seq 50); do [ -z "$(mine)" ] && break; sleep 0.1; done

# 3) Resume to the end: it must say how much was already done, and match the clean map.
run_ranks 2 sweep "${grid[@]}" --output "$map" --resume 2> resume.log || { cat resume.log; exit 1; }
grep -q "already done" resume.log || { echo "FAIL: resume did not restore tiles"; cat resume.log; exit 1; }
test ! -e "$map.partial" && test ! -e "$map.partial.journal"
same_maps clean.h5 "$map"
echo "PASS: killed runs resumed to a bit-identical map"
