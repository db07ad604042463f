#!/usr/bin/env bash
# jobs/slurm.sbatch and jobs/pbs.sh under a real Slurm: a single-node cluster on this
# machine (munged, slurmctld, slurmd from Debian's packages, as root, no systemd), every
# daemon started here stopped by its PID at the end. Checks, each job with 2 tasks:
#   1. the quick start of docs/running.md, submitted from outside the checkout: the whole
#      run folder, and the map equals the same sweep without Slurm;
#   2. scancel ends the job: cancelled, not requeued, the finished tiles kept;
#   3. scontrol requeue of that job resumes it to the same map as an uninterrupted run;
#   4. a real time limit (--time=1 --signal=B:USR1@58): the job stops, requeues itself
#      and resumes to the same map;
#   5. kill -9 of a rank: the job fails, keeps its tiles; scontrol requeue resumes it;
#   6. jobs/pbs.sh through Slurm's Torque wrappers (qsub, qstat).
# Skips (exit 77) where Slurm is not installed, this is not root, or the daemons do not start.
source "$(dirname "$0")/../sweep/common.sh"
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
skip() { echo "SKIP: $*"; exit 77; }

[ "$(id -u)" = 0 ] || skip "a test Slurm needs root (it runs slurmd and the jobs as root)"
for c in munged slurmctld slurmd sbatch srun scontrol scancel squeue sinfo qsub qstat; do
  command -v "$c" > /dev/null || skip "$c is not installed (cmake/install-deps.sh installs slurm-wlm, munge, slurm-wlm-torque)"
done
cores=$(getconf _NPROCESSORS_ONLN)
[ "$cores" -ge 2 ] || skip "this machine has $cores core; the jobs take 2 tasks"

# The cluster: its own munge key and socket, ports and folders, so that nothing of a Slurm
# already on this machine is read or disturbed.
daemons=()
stop_daemons() {
  local pid
  if [ -n "${SLURM_CONF:-}" ] && [ -f "$SLURM_CONF" ]; then
    scancel --full --quiet --user=root 2> /dev/null || true
  fi
  for pid in "${daemons[@]}"; do kill -TERM "$pid" 2> /dev/null || true; done
  for pid in "${daemons[@]}"; do
    for _ in $(seq 50); do kill -0 "$pid" 2> /dev/null || break; sleep 0.1; done
    kill -KILL "$pid" 2> /dev/null || true
  done
}
run=
cleanup() {
  local code=$?
  if [ "$code" != 0 ] && [ "$code" != 77 ] && [ -n "${SLURM_CONF:-}" ]; then
    echo "--- the test Slurm at the failure:"
    squeue 2>&1 || true
    scontrol show job 2>&1 | grep -E "JobId=|JobState|Restarts|RunTime|EligibleTime" || true
    tail -15 "$work/slurm/slurmctld.log" 2>&1 || true
    tail -15 "$work/slurm/slurmd.log" 2>&1 || true
    tail -n 5 "$work"/*/job.log "$work"/*/provenance.txt 2>&1 || true
  fi
  stop_daemons
  [ -z "$run" ] || rm -rf "$run"
  pkill -9 -f "$work" 2> /dev/null || true
  rm -rf "$work"
}
trap cleanup EXIT
mkdir -p slurm/state slurm/spool slurm/tmp submit
head -c 1024 /dev/urandom > slurm/munge.key
chmod 600 slurm/munge.key
munged -F -f --socket="$work/slurm/munge.sock" --key-file="$work/slurm/munge.key" --pid-file="$work/slurm/munged.pid" \
  --seed-file="$work/slurm/munged.seed" --log-file="$work/slurm/munged.log" > slurm/munged.out 2>&1 &
daemons+=($!)
port=$(( 20000 + $$ % 20000 ))
host=$(hostname -s)
export SLURM_CONF=$work/slurm/slurm.conf
cat > "$SLURM_CONF" << EOF
ClusterName=punchsweeptest
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$port
SlurmdPort=$(( port + 1 ))
AuthType=auth/munge
AuthInfo=socket=$work/slurm/munge.sock
SlurmUser=root
SlurmdUser=root
StateSaveLocation=$work/slurm/state
SlurmdSpoolDir=$work/slurm/spool
TmpFS=$work/slurm/tmp
SlurmctldPidFile=$work/slurm/slurmctld.pid
SlurmdPidFile=$work/slurm/slurmd.pid
SlurmctldLogFile=$work/slurm/slurmctld.log
SlurmdLogFile=$work/slurm/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
MpiDefault=none
ReturnToService=2
KillWait=5
MinJobAge=600
NodeName=$host NodeAddr=127.0.0.1 CPUs=$cores State=UNKNOWN
PartitionName=test Nodes=$host Default=YES MaxTime=INFINITE State=UP
EOF
wait_until 10 "${daemons[0]}" "munged's socket" -- test -S slurm/munge.sock || skip "munged did not start: $(cat slurm/munged.out)"
slurmctld -D -c -f "$SLURM_CONF" > slurm/slurmctld.out 2>&1 &
daemons+=($!)
slurmd -D -f "$SLURM_CONF" > slurm/slurmd.out 2>&1 &
daemons+=($!)
node_idle() { [ "$(sinfo -h -o %T 2> /dev/null)" = idle ]; }
for _ in $(seq 300); do node_idle && break; sleep 0.1; done
node_idle || skip "the test Slurm did not come up: $(tail -3 slurm/slurmctld.out slurm/slurmd.out)"
echo "a Slurm of one node ($host, $cores cores) on ports $port-$((port + 1))"

state() { scontrol show job "$1" | sed -n 's/.*JobState=\([A-Z_]*\).*/\1/p'; }
restarts() { scontrol show job "$1" | sed -n 's/.*Restarts=\([0-9]*\).*/\1/p'; }
is_state() { [ "$(state "$1")" = "$2" ]; }
restarted() { [ "$(restarts "$1")" = "$2" ]; }
ended() { case "$(state "$1")" in COMPLETED | FAILED | CANCELLED | TIMEOUT | NODE_FAIL) true ;; *) false ;; esac; }
# A requeued job waits two minutes (Slurm's own delay) before it may start: start it now,
# once its last run has left the node (started sooner, slurmd refused the new run with
# "Job credential revoked", the old run's credential being revoked after). The node shows
# idle as soon as the job is requeued, while the last run's batch step may still be ending
# (a job that requeues itself): wait for its slurmstepd to go too, then for the next second,
# as the revocation's time is in whole seconds and a credential of the same second is refused.
last_run_gone() { ! pgrep -f "slurmstepd: \[$1\.batch\]" > /dev/null; }
after_second() { [ "$(date +%s)" -gt "$1" ]; }
release() {
  wait_until 30 "" "job $1 back in the queue" -- is_state "$1" PENDING
  wait_until 60 "" "the node to be idle after job $1's last run" -- node_idle
  wait_until 60 "" "job $1's last batch step to leave the node" -- last_run_gone "$1"
  local gone
  gone=$(date +%s)
  wait_until 3 "" "the second after job $1's last run left" -- after_second "$gone"
  scontrol update JobId="$1" StartTime=now
}
# Before the next submission: the node idle and every step of the jobs before gone from it,
# then the next second. (PMIx's folders of a step go under TmpFS, this Slurm's own: under
# /tmp a cancelled run's spmix_appdir_0_2.0 made the next test Slurm's job 2 fail to launch.)
no_steps() { ! pgrep -f "slurmstepd:" > /dev/null; }
node_free() {
  wait_until 60 "" "the node to be idle" -- node_idle
  wait_until 60 "" "the last job's steps to leave the node" -- no_steps
  local gone
  gone=$(date +%s)
  wait_until 3 "" "the second after the last job's steps left" -- after_second "$gone"
}
progress() { grep -q "points/s, ETA" "$1/job.log" 2> /dev/null; }
show() { echo "--- job $1:"; scontrol show job "$1" | head -8; cat "$2/job.log" "$2/provenance.txt" 2> /dev/null; }

small=$work/submit/small.ini
printf '[grid]\nl = 0.5, 0.75, 1\ndh = linspace(0.02, 0.12, 6)\nT = 2, 5\npbar = logspace(0.005, 0.08, 5)\ns = 1, 2\n' > "$small"
long=$work/submit/long.ini
printf '[grid]\nl = linspace(0.5, 1.25, 120)\nT = 2, 5, 10\n[run]\nchunk = 1000\n' > "$long"
run_ranks 2 sweep --config "$small" --quiet --output clean-small.h5
run_ranks 2 sweep --config "$long" --quiet --output clean-long.h5

# 1) The quick start, from a folder outside the checkout, with a relative config path.
cd submit
job=$(sbatch --parsable --ntasks=2 "$root/jobs/slurm.sbatch" small.ini)
run=$root/runs/small-$job  # removed at the end
wait_until 120 "" "job $job to end" -- ended "$job"
is_state "$job" COMPLETED || { show "$job" "$run"; echo "FAIL: the quick start's job is $(state "$job")"; exit 1; }
for f in map.h5 config.ini provenance.txt job.log summary.txt regime_map.png critical_dh.png explore.html; do
  test -s "$run/$f" || { show "$job" "$run"; echo "FAIL: the Slurm job left no $f in $run"; exit 1; }
done
grep -q "run folder $run, log $run/job.log" "punchsweep-$job.log" || { echo "FAIL: Slurm's log does not say where the run is"; exit 1; }
grep -q "tasks 2" "$run/provenance.txt" && grep -q -- "--mpi=pmix" "$run/provenance.txt" ||
  { echo "FAIL: not 2 tasks with PMIx"; cat "$run/provenance.txt"; exit 1; }
grep -q "completed: yes" "$run/summary.txt"
same_maps "$work/clean-small.h5" "$run/map.h5"
cd "$work"

node_free
# 2) scancel while it runs: cancelled, not requeued, the tiles kept.
job=$(PUNCHSWEEP_RUN=$work/cancel sbatch --parsable --ntasks=2 "$root/jobs/slurm.sbatch" "$long")
wait_until 120 "" "job $job's first progress" -- progress cancel
scancel "$job"
wait_until 60 "" "job $job to end" -- ended "$job"
sleep 2  # a job that requeued itself would show it by now (it did at once before)
is_state "$job" CANCELLED && restarted "$job" 0 ||
  { show "$job" cancel; echo "FAIL: scancel left the job $(state "$job"), restarts $(restarts "$job")"; exit 1; }
grep -q "status 3 (cancelled)" cancel/provenance.txt && test -s cancel/map.h5.partial.journal && test ! -e cancel/map.h5

# 3) scontrol requeue resumes it.
scontrol requeue "$job"
release "$job"
wait_until 120 "" "job $job to end" -- ended "$job"
is_state "$job" COMPLETED || { show "$job" cancel; echo "FAIL: the requeued job is $(state "$job")"; exit 1; }
grep -q "resuming" cancel/job.log
same_maps clean-long.h5 cancel/map.h5

# 4) A real time limit: one minute, the warning 58 s before it (Slurm sends it within about
#    30 s). The job stops, requeues itself, and the requeued job completes the map.
node_free
longer=$work/submit/longer.ini
printf '[grid]\nl = linspace(0.5, 1.25, 900)\nT = 2, 5, 10\n[run]\nchunk = 1000\n' > "$longer"
job=$(PUNCHSWEEP_RUN=$work/limit sbatch --parsable --ntasks=2 --time=1 --signal=B:USR1@58 "$root/jobs/slurm.sbatch" "$longer")
wait_until 150 "" "job $job to requeue itself at its time limit" -- restarted "$job" 1
grep -q "status 3 (time-limit)" limit/provenance.txt || { show "$job" limit; echo "FAIL: not stopped by the time limit"; exit 1; }
grep -q "requeueing job $job" limit/job.log
scontrol update JobId="$job" TimeLimit=10  # the rest of the map in one go
release "$job"
wait_until 300 "" "job $job to end" -- ended "$job"
is_state "$job" COMPLETED || { show "$job" limit; echo "FAIL: the job after its time limit is $(state "$job")"; exit 1; }
run_ranks 2 sweep --config "$longer" --quiet --output clean-longer.h5
same_maps clean-longer.h5 limit/map.h5

node_free
# 5) kill -9 of a rank: the job fails and keeps its tiles; scontrol requeue resumes it.
job=$(PUNCHSWEEP_RUN=$work/killed sbatch --parsable --ntasks=2 "$root/jobs/slurm.sbatch" "$long")
wait_until 120 "" "job $job's first progress" -- progress killed
rank=$(pgrep -f "sweep --config $work/killed/config.ini" | tail -1)
test -n "$rank" && kill -9 "$rank"
wait_until 60 "" "job $job to end" -- ended "$job"
is_state "$job" FAILED && restarted "$job" 0 || { show "$job" killed; echo "FAIL: after kill -9 the job is $(state "$job")"; exit 1; }
grep -q "scontrol requeue $job" killed/job.log
scontrol requeue "$job"
release "$job"
wait_until 120 "" "job $job to end" -- ended "$job"
is_state "$job" COMPLETED || { show "$job" killed; echo "FAIL: the job requeued after kill -9 is $(state "$job")"; exit 1; }
same_maps clean-long.h5 killed/map.h5

node_free
# 6) PBS through Slurm's Torque wrappers: qsub turns -l and -v into sbatch options.
cd submit
job=$(qsub -V -l select=1:ncpus=2:mpiprocs=2 -v "CONFIG=small.ini,PUNCHSWEEP_RUN=$work/pbs,PUNCHSWEEP_ROOT=$root" \
  "$root/jobs/pbs.sh")
job=${job%%.*}
qstat_done() { [ "$(qstat -f "$1" 2> /dev/null | sed -n 's/^[[:space:]]*job_state = \([A-Z]\).*/\1/p')" = C ]; }
wait_until 120 "" "PBS job $job to end" -- qstat_done "$job"
cd "$work"
is_state "$job" COMPLETED || { show "$job" pbs; echo "FAIL: the PBS job is $(state "$job")"; exit 1; }
for f in map.h5 summary.txt regime_map.png explore.html; do test -s "pbs/$f" || { show "$job" pbs; echo "FAIL: no pbs/$f"; exit 1; }; done
same_maps clean-small.h5 pbs/map.h5
echo "PASS: jobs/slurm.sbatch under a real Slurm: quick start, scancel, requeue, time limit, kill -9; jobs/pbs.sh via qsub"
