# Shared by the sweep shell tests: the binary, mpirun as the test machine needs it, and
# an h5diff comparison of every variable of two maps (attributes such as wall_seconds
# legitimately differ, so whole-file h5diff is not the criterion).
set -euo pipefail
: "${PUNCHSWEEP:?set PUNCHSWEEP to the punchsweep binary}"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1
work=$(mktemp -d "${TMPDIR:-/tmp}/punchsweep-test.XXXXXX")
trap 'pkill -9 -f "$work" 2>/dev/null || true; rm -rf "$work"' EXIT
cd "$work"

run_ranks() {  # run_ranks N ARGS...: mpirun -np N, or a plain process for N = 0
  local n=$1; shift
  if [ "$n" = 0 ]; then "$PUNCHSWEEP" "$@"; else mpirun --oversubscribe -np "$n" "$PUNCHSWEEP" "$@"; fi
}

start_ranks() {  # start_ranks N ARGS...: like run_ranks, in the background; $! is mpirun itself
  local n=$1; shift
  (exec mpirun --oversubscribe -np "$n" "$PUNCHSWEEP" "$@") &
}

same_maps() {  # same_maps A B: every variable bit-identical (h5diff exact, NaN == NaN)
  local a=$1 b=$2 v status=0
  for v in regime valid t_star h_0 h_inf a1_inf a2_inf area_fraction_inf a1 a2 P1 P2 area_fraction \
           bem_regime bem_converged bem_iterations bem_residual bem_t_star bem_a1 bem_a2 bem_P1 bem_P2 \
           bem_area_fraction answer_regime answer_t_star answer_source; do
    if h5ls "$a/$v" >/dev/null 2>&1; then
      if ! h5diff "$a" "$b" "/$v" "/$v" >/dev/null; then
        echo "FAIL: /$v differs between $a and $b"; status=1
      fi
    fi
  done
  return $status
}

wait_until() {  # wait_until SECONDS PID WHAT -- COMMAND...: poll COMMAND every 20 ms until it
  # succeeds (0). Returns 1 if process PID (empty: none) ends first; fails the test, naming
  # WHAT, after SECONDS. The one way these tests wait for a run to reach a state: no sleep
  # that guesses how long it takes, no loop without an end.
  local seconds=$1 pid=$2 what=$3; shift 4
  local deadline=$(( $(date +%s) + seconds ))
  until "$@"; do
    if [ -n "$pid" ] && ! kill -0 "$pid" 2>/dev/null; then return 1; fi
    if [ "$(date +%s)" -ge "$deadline" ]; then echo "FAIL: waited $seconds s for $what"; exit 1; fi
    sleep 0.02
  done
}

file_larger() {  # file_larger FILE BYTES: FILE exists and holds more than BYTES
  [ "$(stat -c %s "$1" 2>/dev/null || echo 0)" -gt "$2" ]
}

gone() {  # gone PATTERN: no process of this test's command lines matches PATTERN
  ! pgrep -f -- "$1" > /dev/null
}
