#!/bin/bash
# A punchsweep map (a regime map, or a texture's: a config with [texture]) on a PBS Pro or Torque cluster:
#   qsub -v CONFIG=/path/to/config.ini[,PUNCHSWEEP_ROOT=/path/to/checkout] jobs/pbs.sh
# One run folder per job (runs/<config>-<job id>; PUNCHSWEEP_RUN names another) with the
# config, provenance, the log (job.log), the map, and at the end the summary, pictures and
# explorer page; --resume always (a rerun continues the map). Ranks: one per line of
# $PBS_NODEFILE. PBS sends SIGTERM before the walltime kill, and qdel does too: the sweep
# stops cleanly (exit 3) either way, and the job asks to be rerun (qrerun) only where the
# stop came within 15 minutes of its walltime. docs/running.md says what was tested.
#PBS -N punchsweep
#PBS -l select=1:ncpus=32:mpiprocs=32
#PBS -l walltime=04:00:00
#PBS -r y
#PBS -j oe
set -euo pipefail
started=$(date +%s)

# The checkout: PUNCHSWEEP_ROOT, else the folder above this file where PBS runs it from
# the checkout, else the submit folder (PBS runs a copy of the script from its spool).
root=
for candidate in "${PUNCHSWEEP_ROOT:-}" "$(dirname "$0")/.." "${PBS_O_WORKDIR:-}"; do
  if [ -n "$candidate" ] && [ -f "$candidate/jobs/run_folder.sh" ]; then
    root=$(cd "$candidate" && pwd)
    break
  fi
done
if [ -z "$root" ]; then
  echo "punchsweep: cannot find the punchsweep checkout; qsub -v PUNCHSWEEP_ROOT=/path/to/it,..." >&2
  exit 2
fi
# Relative paths from the submit folder (Torque starts a job in $HOME).
[ -z "${PBS_O_WORKDIR:-}" ] || cd "$PBS_O_WORKDIR"
# shellcheck source=jobs/run_folder.sh
source "$root/jobs/run_folder.sh"
config=$(realpath "${CONFIG:-$root/sweeps/production.ini}")
job=${PBS_JOBID:-local-$(date -u +%Y%m%d-%H%M%S)}
run=${PUNCHSWEEP_RUN:-$root/runs/$(basename "$config" .ini)-${job%%.*}}
binary=${PUNCHSWEEP:-$root/build/src/app/punchsweep}
extra=(${PUNCHSWEEP_EXTRA_ARGS:-})
ranks=$( [ -n "${PBS_NODEFILE:-}" ] && wc -l < "$PBS_NODEFILE" || getconf _NPROCESSORS_ONLN )
rank_environment

mkdir -p "$run"
run=$(realpath "$run")
log_to_run "$run"
# The config and its material files, copied on the first start; a rerun resumes from the copy.
[ -f "$run/config.ini" ] || prepare_run "$config" "$run" "$binary" || exit 2
echo "start $(date -u +%Y-%m-%dT%H:%M:%SZ) job ${PBS_JOBID:-none} host $(hostname) ranks $ranks $("$binary" --version)" >> "$run/provenance.txt"

hostfile=()
[ -n "${PBS_NODEFILE:-}" ] && hostfile=(--hostfile "$PBS_NODEFILE")
mpirun "${hostfile[@]}" -np "$ranks" --bind-to core "$binary" sweep --config "$run/config.ini" \
  --output "$run/map.h5" --resume "${extra[@]}" &
step=$!
# mpirun passes USR1 to every rank and lets the sweep's exit code 3 through; on TERM it
# would end with 1 (after the ranks drained), and the job would not be rerun.
trap 'kill -USR1 "$step" 2>/dev/null || true' TERM USR1
wait_step "$step"
trap - TERM USR1
echo "end $(date -u +%Y-%m-%dT%H:%M:%SZ) status $status" >> "$run/provenance.txt"

# The walltime in seconds: Torque's PBS_WALLTIME, else the job's record (HH:MM:SS).
walltime() {
  if [ -n "${PBS_WALLTIME:-}" ]; then echo "$PBS_WALLTIME"; return; fi
  qstat -f "${PBS_JOBID:-}" 2> /dev/null | sed -n 's/^[[:space:]]*Resource_List.walltime = \([0-9:]*\).*/\1/p' | head -1 |
    awk -F: '{ s = 0; for (i = 1; i <= NF; i++) s = 60 * s + $i; if (NF) print s }'
}
if [ "$status" = 3 ] && [ -n "${PBS_JOBID:-}" ]; then
  limit=$(walltime || true)
  if [ -n "$limit" ] && [ $(( $(date +%s) - started )) -ge $(( limit - 900 )) ] && command -v qrerun > /dev/null; then
    echo "punchsweep: walltime near; rerunning job $PBS_JOBID to resume $run/map.h5"
    qrerun "$PBS_JOBID"
    exit 3
  fi
  echo "punchsweep: stopped before the walltime (qdel?); not rerun. To continue: qsub -v PUNCHSWEEP_RUN=$run,CONFIG=$config jobs/pbs.sh"
fi
if [ "$status" = 0 ] && [ -f "$run/map.h5" ]; then
  echo "punchsweep: map $run/map.h5"
  finish_run "$run"
fi
exit "$status"
