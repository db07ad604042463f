#!/usr/bin/env bash
# The cluster job scripts without a cluster: syntax, a dry run under stub Slurm/PBS
# commands, the Slurm script's time-limit path (USR1 -> clean stop, exit 3, requeue, resumed
# run finishes the same map) and its cancel path (TERM -> clean stop, no requeue).
# tests/jobs/real_slurm.sh runs them under a real Slurm.
source "$(dirname "$0")/../sweep/common.sh"
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
for script in local.sh slurm.sbatch pbs.sh paper-points.sh; do bash -n "$root/jobs/$script"; done

# Stubs: srun runs the step with mpirun; scontrol and qrerun record what they were asked.
mkdir -p stubs
cat > stubs/srun <<'STUB'
#!/bin/bash
[ "$1" != --mpi=list ] || { printf 'MPI plugin types are...\n\tnone\n\tpmix\n'; exit 0; }
# A step that never launches, once where the file SRUN_FAILS_ONCE names exists: srun's
# status 0, as a real srun gives it.
if [ -n "${SRUN_FAILS_ONCE:-}" ] && [ -e "$SRUN_FAILS_ONCE" ]; then
  rm -f "$SRUN_FAILS_ONCE"
  echo "srun: error: task 0 launch failed: Unspecified error" >&2
  exit 0
fi
args=(); for a in "$@"; do case "$a" in --cpu-bind=* | --mpi=* | --ntasks=*) ;; *) args+=("$a") ;; esac; done
echo "srun $*" >> "$STUB_LOG"
exec mpirun --oversubscribe -np "$SLURM_NTASKS" "${args[@]}"
STUB
printf '#!/bin/bash\necho "scontrol $*" >> "$STUB_LOG"\n' > stubs/scontrol
printf '#!/bin/bash\necho "qrerun $*" >> "$STUB_LOG"\n' > stubs/qrerun
chmod +x stubs/*
export PATH="$PWD/stubs:$PATH" STUB_LOG="$PWD/stub.log" PUNCHSWEEP
small=$PWD/small.ini
printf '[grid]\nl = 0.75\ndh = 0.05, 0.1\nT = 2.5\npbar = 0.06\ns = 2\n' > "$small"

# 1) Slurm, dry run: the run folder, provenance and the srun launch.
SLURM_JOB_ID=4242 SLURM_NTASKS=2 SLURM_SUBMIT_DIR="$root" PUNCHSWEEP_RUN="$PWD/slurm-dry" \
  PUNCHSWEEP_EXTRA_ARGS=--dry-run bash "$root/jobs/slurm.sbatch" "$small" > slurm-dry.log 2>&1
grep -q "points: 2 in" slurm-dry/job.log && grep -q "job 4242" slurm-dry/provenance.txt
grep -q "srun --mpi=pmix --ntasks=2 --cpu-bind=cores" stub.log
grep -q "log $PWD/slurm-dry/job.log" slurm-dry.log
test -f slurm-dry/config.ini

# 1b) A step that never launched (srun's status 0, no map): the script launches it again
#     and the map is made; a launch that never runs is a failure (status 1), not a map.
touch srun-fails
SLURM_JOB_ID=4243 SLURM_NTASKS=2 SLURM_SUBMIT_DIR="$root" PUNCHSWEEP_RUN="$PWD/relaunch" SRUN_FAILS_ONCE="$PWD/srun-fails" \
  bash "$root/jobs/slurm.sbatch" "$small" > relaunch.log 2>&1 || { echo "FAIL: the relaunch"; cat relaunch/job.log; exit 1; }
grep -q "launch 1 ended with status 0 and no map: launching again in 10 s" relaunch/job.log &&
  grep -q "launch 1 ran no sweep" relaunch/provenance.txt && grep -q "status 0" relaunch/provenance.txt &&
  test -f relaunch/map.h5 || { echo "FAIL: the relaunch"; cat relaunch/job.log relaunch/provenance.txt; exit 1; }

# 2) PBS, dry run with a node file of two slots.
printf 'localhost\nlocalhost\n' > nodes
PBS_JOBID=77.server PBS_O_WORKDIR="$root" PBS_NODEFILE="$PWD/nodes" CONFIG="$small" PUNCHSWEEP_RUN="$PWD/pbs-dry" \
  PUNCHSWEEP_EXTRA_ARGS=--dry-run bash "$root/jobs/pbs.sh" > pbs-dry.log 2>&1
grep -q "points: 2 in" pbs-dry/job.log && grep -q "ranks 2" pbs-dry/provenance.txt

# 3) Outside Slurm, a real small map with mpirun.
PUNCHSWEEP_RUN="$PWD/local" bash "$root/jobs/slurm.sbatch" "$small" > local.log 2>&1
test -f local/map.h5 && grep -q "status 0" local/provenance.txt && test -s local/explore.html && test -s local/summary.txt
same_maps local/map.h5 relaunch/map.h5  # the relaunched map of 1b) is the same map

# 4) The local main job: map, pictures, summary and provenance in the run folder.
printf '[grid]\nl = 0.5, 0.75, 1\ndh = linspace(0.02, 0.12, 6)\nT = 2, 5\npbar = logspace(0.005, 0.08, 5)\ns = 1, 2\n' > local.ini
bash "$root/jobs/local.sh" local.ini "$PWD/main-job" > main-job.log 2>&1 || { cat main-job.log; exit 1; }
for f in map.h5 regime_map.png critical_dh.png explore.html summary.txt provenance.txt config.ini; do
  test -s "main-job/$f" || { echo "FAIL: jobs/local.sh left no $f"; cat main-job.log; exit 1; }
done
grep -q "punchsweep: map $PWD/main-job/map.h5" main-job.log
grep -q "completed: yes" main-job/summary.txt

# 4b) Issue 22: the shipped material config (a material path relative to the config's own
#     folder) into a run folder elsewhere: the map, its pictures (a material map has no T
#     axis) and the material file recorded in the run folder; the folder resumes by itself.
bash "$root/jobs/local.sh" "$root/sweeps/materials/nbr.ini" "$PWD/elsewhere/nbr" > nbr-job.log 2>&1 ||
  { echo "FAIL: jobs/local.sh with sweeps/materials/nbr.ini"; cat nbr-job.log; exit 1; }
for f in map.h5 regime_map.png critical_dh.png explore.html summary.txt config.ini materials/nbr_linder2011.ini; do
  test -s "elsewhere/nbr/$f" || { echo "FAIL: the material job left no $f"; cat nbr-job.log; exit 1; }
done
cmp "$root/materials/nbr_linder2011.ini" elsewhere/nbr/materials/nbr_linder2011.ini
bash "$root/jobs/local.sh" "$root/sweeps/materials/nbr.ini" "$PWD/elsewhere/nbr" > nbr-again.log 2>&1
grep -q "already complete" nbr-again.log || { echo "FAIL: the material run folder did not resume"; cat nbr-again.log; exit 1; }
# 4c) Issue 35 item 6: another config into that run folder is refused before anything there
#     is written: its config, materials and map stay as they were.
before=$(cd elsewhere/nbr && sha256sum config.ini materials/* map.h5)
set +e; bash "$root/jobs/local.sh" local.ini "$PWD/elsewhere/nbr" > other.log 2>&1; code=$?; set -e
[ "$code" = 2 ] || { echo "FAIL: another config into a run folder: exit $code"; cat other.log; exit 1; }
grep -q "was made with another configuration" other.log || { echo "FAIL: the refusal does not say why"; cat other.log; exit 1; }
[ "$(cd elsewhere/nbr && sha256sum config.ini materials/* map.h5)" = "$before" ] ||
  { echo "FAIL: the refused run changed the run folder"; cat other.log; exit 1; }
[ -z "$(ls -A elsewhere/nbr | grep '^\.config-')" ] || { echo "FAIL: a staged config was left behind"; exit 1; }
# 4d) Ctrl-C while the config is being staged (a slow Python here) leaves no .config-* in
#     the run folder and exits 130.
printf '#!/bin/bash\nsleep 30\nexec /usr/bin/python3 "$@"\n' > slow_python
chmod +x slow_python
# (A background job of a script ignores SIGINT; the launcher restores it, as a terminal has it,
# and puts the job in its own process group, which a terminal's Ctrl-C signals whole.)
PUNCHSWEEP_PYTHON="$PWD/slow_python" /usr/bin/python3 -c 'import os, signal, sys
signal.signal(signal.SIGINT, signal.SIG_DFL)
os.setpgid(0, 0)
os.execvp("bash", ["bash", *sys.argv[1:]])' "$root/jobs/local.sh" local.ini "$PWD/interrupted" > interrupted.log 2>&1 &
job=$!
for _ in $(seq 100); do ls -A interrupted 2> /dev/null | grep -q '^\.config-' && break; sleep 0.1; done
ls -A interrupted | grep -q '^\.config-' || { echo "FAIL: no staged config to interrupt"; cat interrupted.log; exit 1; }
kill -INT -- "-$job"
set +e; wait "$job"; code=$?; set -e
[ "$code" = 130 ] || { echo "FAIL: Ctrl-C while staging: exit $code"; cat interrupted.log; exit 1; }
[ -z "$(ls -A interrupted | grep '^\.config-')" ] || { echo "FAIL: Ctrl-C left a staged config"; ls -A interrupted; exit 1; }
# 4e) A config the engine refuses (an unknown key), and one that does not exist: the engine's
#     message, a non-zero exit, and no run folder (no config.ini, no provenance.txt).
printf '[grid]\nl = 0.75\nbogus_key = 1\n' > refused.ini
for config in refused.ini missing.ini; do
  set +e; bash "$root/jobs/local.sh" "$config" "$PWD/refused-run" > refused.log 2>&1; code=$?; set -e
  [ "$code" != 0 ] || { echo "FAIL: jobs/local.sh with $config: exit 0"; cat refused.log; exit 1; }
  [ ! -e refused-run ] || { echo "FAIL: jobs/local.sh with $config left a run folder"; ls -A refused-run; exit 1; }
  grep -q "nothing was written" refused.log || { echo "FAIL: the refusal of $config does not say so"; cat refused.log; exit 1; }
done
# 4f) A texture's config ([texture], a cell file named relative to the config's folder),
#     run from elsewhere: the run folder holds the map, its config with the cell copied to
#     inputs/, the summary per level, texture.png and explore.html; run again, it is complete;
#     another configuration into the folder is refused and the folder left as it was.
mkdir -p texture-cfg/cells
cp "$root/examples/cells/hexagonal_two_level.ini" texture-cfg/cells/
printf '[texture]   # a honeycomb cell\ncell = cells/hexagonal_two_level.ini\ngrid = 32\n[model]\nR = 80um\n[grid]\npbar = 0.005, 0.01, 0.02\nT = 2, 4\n[time]\ntimes = 0, 1\n' > texture-cfg/texture.ini
(cd / && bash "$root/jobs/local.sh" "$OLDPWD/texture-cfg/texture.ini" "$OLDPWD/texture-run") > texture.log 2>&1 ||
  { echo "FAIL: jobs/local.sh with a texture's config"; cat texture.log; exit 1; }
for f in map.h5 config.ini inputs/hexagonal_two_level.ini summary.txt texture.png explore.html provenance.txt; do
  test -s "texture-run/$f" || { echo "FAIL: the texture's run left no $f"; cat texture.log; exit 1; }
done
grep -q "^cell = inputs/hexagonal_two_level.ini" texture-run/config.ini && grep -q "level 1 of 2" texture-run/summary.txt &&
  grep -q "pictures $PWD/texture-run/texture.png" texture.log || { echo "FAIL: the texture's run folder"; cat texture.log texture-run/config.ini; exit 1; }
bash "$root/jobs/local.sh" texture-cfg/texture.ini "$PWD/texture-run" > texture2.log 2>&1 && grep -q "is already complete" texture2.log ||
  { echo "FAIL: the texture's run again"; cat texture2.log; exit 1; }
sed 's/T = 2, 4/T = 2, 5/' texture-cfg/texture.ini > texture-cfg/other.ini
set +e; bash "$root/jobs/local.sh" texture-cfg/other.ini "$PWD/texture-run" > texture3.log 2>&1; code=$?; set -e
[ "$code" = 2 ] && grep -q "T: the existing map has 2, 4; this run asks for 2, 5" texture3.log && grep -q "^T = 2, 4" texture-run/config.ini ||
  { echo "FAIL: another texture config into the run folder: exit $code"; cat texture3.log; exit 1; }
grep -q "no such file" refused.log || { echo "FAIL: a missing config is not named"; cat refused.log; exit 1; }
set +e; bash "$root/jobs/local.sh" refused.ini "$PWD/refused-run" > refused.log 2>&1; set -e
grep -q "punchsweep sweep: .*unknown key grid.bogus_key" refused.log ||
  { echo "FAIL: the engine's message on a refused config is not shown"; cat refused.log; exit 1; }
SLURM_JOB_ID=6161 SLURM_NTASKS=2 SLURM_SUBMIT_DIR="$root" PUNCHSWEEP_RUN="$PWD/elsewhere/slurm-nbr" \
  bash "$root/jobs/slurm.sbatch" "$root/sweeps/materials/nbr.ini" > slurm-nbr.log 2>&1 ||
  { echo "FAIL: slurm.sbatch with sweeps/materials/nbr.ini"; cat slurm-nbr.log; exit 1; }
test -s elsewhere/slurm-nbr/map.h5

# 5) The time limit under "Slurm": USR1 to the batch script stops the sweep (exit 3), the
#    job requeues itself, and the requeued job completes the same map as a clean run.
cfg=$PWD/longer.ini
printf '[grid]\nl = linspace(0.5, 1.25, 40)\nT = 2, 5, 10\n[run]\nchunk = 1000\n' > "$cfg"
SLURM_JOB_ID=5151 SLURM_NTASKS=2 SLURM_SUBMIT_DIR="$root" PUNCHSWEEP_RUN="$PWD/limit" \
  bash "$root/jobs/slurm.sbatch" "$cfg" > limit1.log 2>&1 & job=$!
progress() { grep -q "points/s, ETA" "$1/job.log" 2> /dev/null; }
wait_until 120 "$job" "the job's first progress" -- progress limit ||
  { echo "FAIL: the job ended before the time limit"; cat limit/job.log; exit 1; }
kill -USR1 "$job"
status=0; wait "$job" || status=$?
[ "$status" = 3 ] || { echo "FAIL: expected exit 3 after USR1, got $status"; cat limit/job.log; exit 1; }
grep -q "scontrol requeue 5151" stub.log || { echo "FAIL: no requeue"; cat stub.log; exit 1; }
test -f limit/map.h5.partial.journal
SLURM_JOB_ID=5151 SLURM_NTASKS=2 SLURM_RESTART_COUNT=1 SLURM_SUBMIT_DIR="$root" PUNCHSWEEP_RUN="$PWD/limit" \
  bash "$root/jobs/slurm.sbatch" "$cfg" > limit2.log 2>&1
grep -q "already done" limit/job.log
run_ranks 1 sweep --config "$cfg" --quiet --output clean.h5
same_maps clean.h5 limit/map.h5

# 6) scancel's TERM to the batch script: the sweep stops cleanly (exit 3) and the job is not
#    requeued.
: > "$STUB_LOG"
SLURM_JOB_ID=7171 SLURM_NTASKS=2 SLURM_SUBMIT_DIR="$root" PUNCHSWEEP_RUN="$PWD/cancel" \
  bash "$root/jobs/slurm.sbatch" "$cfg" > cancel1.log 2>&1 & job=$!
wait_until 120 "$job" "the job's first progress" -- progress cancel ||
  { echo "FAIL: the job ended before it could be cancelled"; cat cancel/job.log; exit 1; }
kill -TERM "$job"
status=0; wait "$job" || status=$?
[ "$status" = 3 ] || { echo "FAIL: expected exit 3 after TERM, got $status"; cat cancel/job.log; exit 1; }
grep -q "status 3 (cancelled)" cancel/provenance.txt
! grep -q "scontrol requeue" "$STUB_LOG" || { echo "FAIL: a cancelled job requeued itself"; cat "$STUB_LOG"; exit 1; }
echo "PASS: job scripts parse, dry-run under stub Slurm/PBS, survive a time limit, and end on a cancel"
