#!/usr/bin/env bash
# The probe of issue 22, repeated: two runs into one output, and symbolic links planted at
# the names a sweep writes.
# - Race: a sweep killed with -9, then two --resume runs at once (and two fresh starts,
#   and two --overwrite runs): exactly one runs, the other is refused with exit 2 naming
#   the running one, and the map that results reads and equals an uninterrupted run.
# - Links: a symbolic link at F.h5.partial, F.h5.partial.journal, F.h5 or F.h5.lock
#   (pointing at a file, or dangling) is refused with exit 2 before anything is written:
#   the link's target is unchanged (or still absent).
# - A reader holding the stale .partial open does not stop --resume, nor is its file cut.
source "$(dirname "$0")/common.sh"
rounds=${PROBE_ROUNDS:-4}
# The refined model: the kill needs a sweep still running 0.6 s after its start (the periodic
# model finishes this grid in less).
grid=(--grid.l 0.5,0.75,1 --grid.dh 'linspace(0.01,0.12,12)' --grid.T 2.5,5,8 --grid.pbar 'logspace(0.005,0.08,16)'
      --grid.s 1,2,3 --chunk 100 --model.localization refined)
run_ranks 0 sweep "${grid[@]}" --quiet --output clean.h5

# Runs A and B at once into r.h5 with the extra options given; both must end, one with 0
# and one with 2 (the refusal naming the running sweep), and r.h5 must equal clean.h5.
race() {
  local what=$1; shift
  "$PUNCHSWEEP" sweep "${grid[@]}" --output r.h5 "$@" > a.log 2>&1 & local a=$!
  "$PUNCHSWEEP" sweep "${grid[@]}" --output r.h5 "$@" > b.log 2>&1 & local b=$!
  set +e; wait $a; local ca=$?; wait $b; local cb=$?; set -e
  local codes
  codes=$(printf '%s\n' "$ca" "$cb" | sort | tr '\n' ' ')
  if [ "$codes" != "0 2 " ]; then
    echo "FAIL ($what): exit codes $ca and $cb, expected one 0 and one 2"; cat a.log b.log; exit 1
  fi
  grep -h "another sweep is writing this map (pid [0-9]* on .*punchsweep sweep" a.log b.log >/dev/null ||
    { echo "FAIL ($what): the refusal does not name the running sweep"; cat a.log b.log; exit 1; }
  test ! -e r.h5.partial.journal && test ! -e r.h5.lock || { echo "FAIL ($what): files left behind"; ls -la; exit 1; }
  same_maps clean.h5 r.h5 || { echo "FAIL ($what): the map differs from an uninterrupted run"; exit 1; }
}

for round in $(seq "$rounds"); do
  rm -f r.h5 r.h5.*
  "$PUNCHSWEEP" sweep "${grid[@]}" --output r.h5 --quiet > /dev/null 2>&1 & pid=$!
  # Killed once a tile is in its journal (past its header), so there is something to resume.
  wait_until 120 "$pid" "r.h5's journal" -- file_larger r.h5.partial.journal 0 ||
    { echo "FAIL: the run ended before it could be killed"; exit 1; }
  header=$(stat -c %s r.h5.partial.journal)
  wait_until 120 "$pid" "a tile in r.h5's journal" -- file_larger r.h5.partial.journal "$header" ||
    { echo "FAIL: the run ended before it could be killed"; exit 1; }
  kill -9 "$pid" 2>/dev/null || true
  wait "$pid" 2>/dev/null || true
  race "two --resume after kill -9, round $round" --resume --quiet
  rm -f r.h5 r.h5.*
  race "two fresh starts, round $round" --quiet
  race "two --overwrite, round $round" --overwrite --quiet
done
echo "race: $rounds rounds of (kill -9 + two --resume, two fresh, two --overwrite): one run each, maps equal"

small=(--grid.l 0.75 --grid.dh 0.05,0.075 --grid.T 2.5 --grid.pbar 0.06 --grid.s 2)
for round in $(seq "$rounds"); do
  for name in m.h5.partial m.h5.partial.journal m.h5 m.h5.lock; do
    for kind in file dangling; do
      rm -rf m.h5* target
      if [ "$kind" = file ]; then echo "precious $round" > target; fi
      ln -s "$PWD/target" "$name"
      for mode in "" --overwrite --resume; do
        set +e; "$PUNCHSWEEP" sweep "${small[@]}" --output m.h5 $mode --quiet > link.log 2>&1; code=$?; set -e
        test "$code" = 2 || { echo "FAIL: a link at $name ($kind, '$mode'): exit $code, expected 2"; cat link.log; exit 1; }
        grep -q "symbolic link" link.log || { echo "FAIL: the refusal does not say why"; cat link.log; exit 1; }
        if [ "$kind" = file ]; then
          test "$(cat target)" = "precious $round" || { echo "FAIL: $name's target was written"; exit 1; }
        else
          test ! -e target || { echo "FAIL: a dangling $name created its target"; exit 1; }
        fi
        test -L "$name" || { echo "FAIL: the link $name was replaced"; exit 1; }
      done
    done
  done
done
echo "links: $rounds rounds of links at 4 names x (file, dangling) x (fresh, --overwrite, --resume): refused, targets untouched"
# A reader that holds the stale .partial of a killed run open (h5py, as a user peeking at
# it): --resume creates the map anew beside it instead of truncating it under the reader
# (which failed with an HDF5 error and MPI_ABORT), and the reader's copy stays readable.
for round in $(seq "$rounds"); do
  rm -f r.h5 r.h5.*
  # Stopped by SIGTERM (which flushes the .partial, so that it can be read).
  "$PUNCHSWEEP" sweep "${grid[@]}" --output r.h5 --quiet > /dev/null 2>&1 & pid=$!
  wait_until 120 "$pid" "r.h5's journal" -- file_larger r.h5.partial.journal 0 ||
    { echo "FAIL: the run ended before it could be stopped"; exit 1; }
  header=$(stat -c %s r.h5.partial.journal)
  wait_until 120 "$pid" "a tile in r.h5's journal" -- file_larger r.h5.partial.journal "$header" ||
    { echo "FAIL: the run ended before it could be stopped"; exit 1; }
  kill -TERM "$pid" 2>/dev/null || true
  wait "$pid" 2>/dev/null || true
  if [ -e r.h5 ]; then echo "FAIL: the run finished before it could be stopped"; exit 1; fi
  /usr/bin/python3 - <<'PY' > reader.log 2>&1 & reader=$!
import time, h5py
with h5py.File("r.h5.partial", "r") as f:
    before = sorted(f.keys()), dict(f.attrs)["identity"]
    print("open", flush=True)
    time.sleep(4)
    after = sorted(f.keys()), dict(f.attrs)["identity"]
    assert before == after, "the reader's file changed under it"
    print("read", len(after[0]), "variables", flush=True)
PY
  while ! grep -q open reader.log; do
    kill -0 "$reader" 2>/dev/null || { echo "FAIL: the reader could not open the .partial"; cat reader.log; exit 1; }
    sleep 0.05
  done
  "$PUNCHSWEEP" sweep "${grid[@]}" --output r.h5 --resume --quiet || { echo "FAIL: --resume beside a reader"; exit 1; }
  wait "$reader" || { echo "FAIL: the reader's copy could not be read"; cat reader.log; exit 1; }
  grep -q "^read" reader.log || { echo "FAIL: the reader did not read"; cat reader.log; exit 1; }
  same_maps clean.h5 r.h5 || { echo "FAIL: the map resumed beside a reader differs"; exit 1; }
done
echo "reader: $rounds rounds of --resume while a reader holds the stale .partial: map equal, reader unharmed"
echo "PASS: one run per output, and no file written through a link"
