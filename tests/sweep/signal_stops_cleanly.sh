#!/usr/bin/env bash
# SIGTERM / SIGUSR1 (what Slurm sends before a time limit) stop the sweep: finished tiles
# kept, a message telling how to resume, and --resume completes the same map.
source "$(dirname "$0")/common.sh"
grid=(--grid.l 'linspace(0.5, 1.25, 40)' --grid.T 2,5,10 --chunk 1000)
run_ranks 1 sweep "${grid[@]}" --quiet --output clean.h5
# The pid of rank N of the run started by mpirun $1.
rank_pid() {
  local p
  for p in $(pgrep -P "$1"); do
    if tr '\0' '\n' < "/proc/$p/environ" 2>/dev/null | grep -qx "OMPI_COMM_WORLD_RANK=$2"; then echo "$p"; return; fi
  done
}
# TERM, USR1 to mpirun (which passes them to the ranks; USR1 lets exit code 3 through,
# TERM ends mpirun with 1), and TERM to a worker rank alone (it asks rank 0 to stop all).
for case in TERM USR1 worker-TERM; do
  sig=${case#worker-}
  rm -f s.h5*
  start_ranks 2 sweep "${grid[@]}" --output s.h5 > "stop_$case.log" 2>&1; pid=$!
  # Well into the run (the first progress line comes after 1 s): a signal that reaches
  # mpirun in its first moments, while it still launches the ranks, is lost.
  while ! grep -q "points/s, ETA" "stop_$case.log"; do
    kill -0 "$pid" 2>/dev/null || { echo "FAIL: the run ended before it could be signalled"; exit 1; }
    sleep 0.05
  done
  target=$pid
  if [ "$case" = worker-TERM ]; then target=$(rank_pid "$pid" 1); fi
  test -n "$target" || { echo "FAIL: no rank 1 under mpirun $pid"; exit 1; }
  kill -"$sig" "$target"
  set +e; wait "$pid"; code=$?; set -e
  if [ "$case" = TERM ]; then expected=1; else expected=3; fi
  test "$code" = "$expected" || { echo "FAIL ($case): exit $code, expected $expected"; cat "stop_$case.log"; exit 1; }
  grep -q "Resume with: punchsweep sweep .* --resume" "stop_$case.log" || { echo "FAIL: no resume hint"; cat "stop_$case.log"; exit 1; }
  if [ "$case" = worker-TERM ]; then
    grep -q "received by rank 1" "stop_$case.log" || { echo "FAIL: the worker's signal is not named"; exit 1; }
  fi
  test -f s.h5.partial.journal && test ! -e s.h5
  run_ranks 2 sweep "${grid[@]}" --output s.h5 --resume --quiet
  same_maps clean.h5 s.h5
done
echo "PASS: SIGTERM and SIGUSR1 to mpirun, and SIGTERM to a worker, stop cleanly and resume"
