#!/usr/bin/env bash
# SIGTERM / SIGUSR1 (what Slurm sends before a time limit) stop the sweep: finished tiles
# kept, a message telling how to resume, and --resume completes the same map.
source "$(dirname "$0")/common.sh"
grid=(--grid.l 'linspace(0.5, 1.25, 40)' --grid.T 2,5,10 --chunk 1000)
run_ranks 1 sweep "${grid[@]}" --quiet --output clean.h5
for sig in TERM USR1; do
  rm -f s.h5*
  start_ranks 2 sweep "${grid[@]}" --output s.h5 > "stop_$sig.log" 2>&1; pid=$!
  # Well into the run (the first progress line comes after 1 s): a signal that reaches
  # mpirun in its first moments, while it still launches the ranks, is lost.
  while ! grep -q "points/s, ETA" "stop_$sig.log"; do
    kill -0 "$pid" 2>/dev/null || { echo "FAIL: the run ended before it could be signalled"; exit 1; }
    sleep 0.05
  done
  kill -"$sig" "$pid"
  wait "$pid" && { echo "FAIL: SIG$sig did not stop the run"; exit 1; } || true
  grep -q "Resume with: punchsweep sweep .* --resume" "stop_$sig.log" || { echo "FAIL: no resume hint"; cat "stop_$sig.log"; exit 1; }
  test -f s.h5.partial.journal && test ! -e s.h5
  run_ranks 2 sweep "${grid[@]}" --output s.h5 --resume --quiet
  same_maps clean.h5 s.h5
done
echo "PASS: SIGTERM and SIGUSR1 stop cleanly and resume"
