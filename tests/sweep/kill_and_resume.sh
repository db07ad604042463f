#!/usr/bin/env bash
# kill -9 of mpirun (or of one rank) mid-run, then --resume, gives the same map as a clean
# run, without recomputing finished tiles.
source "$(dirname "$0")/common.sh"
grid=(--grid.l 'linspace(0.5, 1.25, 6)' --grid.T 2,5,10 --chunk 1000)
run_ranks 2 sweep "${grid[@]}" --quiet --output clean.h5

journal_bytes() { stat -c %s k.h5.partial.journal 2>/dev/null || echo 0; }
wait_for_progress() {  # until the journal holds more than $1 bytes, or the run ended
  while [ "$(journal_bytes)" -le "$1" ] && kill -0 "$2" 2>/dev/null; do sleep 0.02; done
}

# 1) kill -9 of mpirun itself, twice, at different moments.
for threshold in 100000 1500000; do
  start_ranks 2 sweep "${grid[@]}" --quiet --output k.h5 --resume; pid=$!
  wait_for_progress "$threshold" "$pid"
  kill -9 "$pid" 2>/dev/null || true
  wait "$pid" 2>/dev/null || true
  sleep 0.3
  if pgrep -f "$PUNCHSWEEP sweep" >/dev/null; then echo "FAIL: ranks outlived mpirun"; exit 1; fi
done
test -f k.h5.partial.journal || { echo "FAIL: the kill came too late to test anything"; exit 1; }
done_before=$(journal_bytes)

# 2) kill -9 of one rank (the worker).
start_ranks 2 sweep "${grid[@]}" --quiet --output k.h5 --resume; pid=$!
wait_for_progress $((done_before + 200000)) "$pid"
pkill -9 -f -n "$PUNCHSWEEP sweep" || true
wait "$pid" 2>/dev/null || true
sleep 0.3
pkill -9 -f "$PUNCHSWEEP sweep" 2>/dev/null || true

# 3) Resume to the end: it must say how much was already done, and match the clean map.
run_ranks 2 sweep "${grid[@]}" --output k.h5 --resume 2> resume.log || { cat resume.log; exit 1; }
grep -q "already done" resume.log || { echo "FAIL: resume did not restore tiles"; cat resume.log; exit 1; }
test ! -e k.h5.partial && test ! -e k.h5.partial.journal
same_maps clean.h5 k.h5
echo "PASS: killed runs resumed to a bit-identical map"
